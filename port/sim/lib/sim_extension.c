/* Layering a test's extension over a simulated drive, and the plain store
 * of a port's own rows. sim_drive.c's HAL asks the extension. */
#include "sim_extension.h"

#include <stddef.h>

#include <math.h>

void daran_sim_drive_extend(daran_sim_drive_t *d, const daran_sim_extension_t *ext, void *ctx)
{
    d->ext = ext;
    d->ext_ctx = ext != NULL ? ctx : NULL;
}

daran_result_t daran_sim_drive_set_port_value(daran_sim_drive_t *d, daran_prop_t prop,
                                              daran_value_t value)
{
    daran_prop_type_t type = daran_sim_prop_type(prop);
    if (!daran_sim_is_port_prop(prop) || (type == DARAN_TYPE_F32 && !isfinite(value.f32)) ||
        (type == DARAN_TYPE_BOOL && value.u32 > 1u)) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    d->model.cfg[prop] = value;
    return DARAN_OK;
}

/* A test's own properties on a simulated drive, without editing it: an
 * extension (daran_sim_extension_t, sim_drive.h) asked before the model, and
 * the plain store the model keeps for a port's own rows
 * (DARAN_PORT_PROPERTY_LIST) that no extension serves.
 *
 * Portable C99: no stdio, no heap. */
#ifndef DARAN_SIM_EXTENSION_H
#define DARAN_SIM_EXTENSION_H

#include "sim_drive.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Layer @p ext over drive @p d: from now on its get and set are asked first
 * for every property, its tick runs after every control tick; @p ctx is
 * passed to each. Both must outlive their use by the drive. Replaces the
 * extension set before; NULL removes it (the model serves everything
 * again). Survives reboots and power cycles; daran_sim_drive_init() removes
 * it. O(1), cannot fail. */
void daran_sim_drive_extend(daran_sim_drive_t *d, const daran_sim_extension_t *ext, void *ctx);

/* Put @p value into the plain store of port row @p prop (a row of the
 * build's DARAN_PORT_PROPERTY_LIST, see daran_sim_is_port_prop()): what a
 * read answers when no extension serves the row. For a read-only row (a
 * reading: `w` refuses it) this is how a test sets what `r` shows; it
 * stays across reboots. A read-write row is a setting: `w` sets it too,
 * `ss` saves it, `se` and a reboot make it 0. A float must be finite, a
 * bool 0 or 1. DARAN_OK; DARAN_ERR_BAD_ARGUMENT (nothing changed) for any
 * other row or value. O(1). */
DARAN_NODISCARD daran_result_t daran_sim_drive_set_port_value(daran_sim_drive_t *d,
                                                              daran_prop_t prop,
                                                              daran_value_t value);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_EXTENSION_H */

/* Multi-motor commands: `ms` stores a preset in the instance; mt/mq/mp/mv/mc
 * start it as t/q/p/v/c on every drive of the bus at once. The text of their
 * lines is read here; the presets and their starts are the request layer's
 * (request_preset.c). */
#include "handlers.h"

#if DARAN_ENABLE_MULTI_MOTOR

daran_result_t daran_parse_preset(const daran_request_t *request,
                                                      float *values)
{
    for (uint8_t i = 0; i < DARAN_PRESET_VALUES; i++) {
        daran_field_t field = daran_field_at(request, 2u + i);
        daran_result_t result = daran_field_f32(&field, &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    return DARAN_OK;
}

daran_result_t daran_cmd_ms(daran_drive_t *drive, const daran_request_t *request)
{
    float values[DARAN_PRESET_VALUES];
    daran_result_t result = daran_parse_preset(request, values);
    if (result == DARAN_OK) {
        daran_store_preset(drive, values, DARAN_PRESET_FROM_LINE);
    }
    return result;
}

daran_result_t daran_parse_start(const daran_request_t *request, bool *rel)
{
    uint32_t flag = 0;
    if (request->fields->count == 3u) { /* mt, mq, mp: 0 absolute, 1 relative */
        daran_field_t field = daran_field_at(request, 2);
        daran_result_t result = daran_field_mode(&field, (1u << 0) | (1u << 1), &flag);
        if (result != DARAN_OK) {
            return result;
        }
    }
    *rel = flag != 0u;
    return DARAN_OK;
}

daran_result_t daran_cmd_start(daran_drive_t *drive, const daran_request_t *request)
{
    bool rel;
    daran_result_t result = daran_parse_start(request, &rel);
    return result != DARAN_OK ? result
                              : daran_start_preset(drive, (daran_shape_t)request->command->arg,
                                                   drive->preset, rel, request->motor == 0u);
}

#endif /* DARAN_ENABLE_MULTI_MOTOR */

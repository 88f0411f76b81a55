/* What every command handler needs: values from fields. */
#include "handlers.h"
#include "number.h"

daran_result_t daran_field_f32(const daran_field_t *field, float *out)
{
    return daran_parse_f32(field->text, field->len, out);
}

daran_result_t daran_field_mode(const daran_field_t *field, uint32_t allowed, uint32_t *out)
{
    uint64_t mode;
    daran_result_t result = daran_parse_u64(field->text, field->len, &mode);
    if (result == DARAN_ERR_INVALID_VALUE) {
        return result;
    }
    if (result != DARAN_OK || mode >= 32u || ((allowed >> mode) & 1u) == 0u) {
        return DARAN_ERR_INVALID_MODE;
    }
    *out = (uint32_t)mode;
    return DARAN_OK;
}

daran_result_t daran_field_motor(const daran_field_t *field, uint8_t *out)
{
    /* Nearly every line carries a plain one- or two-digit id. */
    const char *text = field->text;
    if (field->len == 1u && text[0] >= '0' && text[0] <= '9' &&
        (unsigned)(text[0] - '0') <= DARAN_MOTOR_ID_MAX) {
        *out = (uint8_t)(text[0] - '0');
        return DARAN_OK;
    }
    uint64_t id;
    if (daran_parse_u64(field->text, field->len, &id) != DARAN_OK || id > DARAN_MOTOR_ID_MAX) {
        return DARAN_ERR_INVALID_MOTOR;
    }
    *out = (uint8_t)id;
    return DARAN_OK;
}

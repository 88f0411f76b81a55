/* The CAN codec's encoder (can_codec.h): what a gateway's bridge sends,
 * written by the same layout table the front end decodes with. */
#include "can_codec.h"

#if DARAN_ENABLE_CAN_BRIDGE

bool daran_can_encode_values(daran_can_layout_t layout, const float *values, uint8_t *data)
{
    unsigned fields = daran_can_layouts[layout];
    if ((fields & DARAN_CAN_NO_F32) == 0u) {
        daran_can_put_f32(data, values[0]);
    }
    bool fits = true;
    for (unsigned i = 1; i <= 2u; i++, fields >>= 2) {
        uint8_t *at = data + 2u + 2u * i;
        unsigned kind = fields & 3u;
        if (kind >= DARAN_CAN_FIELD_MODE) {
            /* a mode the line checked already: 1, 2 or 6 */
            uint32_t mode = (uint32_t)values[i];
            daran_can_put_u16(at, kind == DARAN_CAN_FIELD_TORQUE_MODE && mode == 2u ? 6u : mode);
        } else {
            fits = daran_can_put_scaled(at, values[i], kind == DARAN_CAN_FIELD_SCALED_SATURATED) && fits;
        }
    }
    return fits;
}

uint32_t daran_can_subcode_of(daran_action_t action)
{
    return action == DARAN_ACTION_FEED_WATCHDOG ? DARAN_CAN_SUB_FEED
                                                : (uint32_t)action + DARAN_CAN_SUB_SAVE;
}

#endif /* DARAN_ENABLE_CAN_BRIDGE */

/* The CAN codec (can_codec.h), what a drive's front end needs of it: the
 * value frames' layouts as one table and the one loop that decodes them,
 * the reading of a mode or flag field, exact scaling. The encoder a
 * gateway's bridge needs is can_encode.c, counted with the bridge. */
#include "can_codec.h"

#include "compiler.h"
#include "request.h"

#if DARAN_ENABLE_CAN

DARAN_STATIC_ASSERT(DARAN_SHAPE_FILTERED == 0 && DARAN_SHAPE_TRAPEZOID == 1 &&
                        DARAN_SHAPE_PASSTHROUGH == 2 && DARAN_SHAPE_VELOCITY == 3 &&
                        DARAN_SHAPE_TORQUE == 4 &&
                        (int)DARAN_CAN_LAYOUT_TORQUE == (int)DARAN_SHAPE_TORQUE &&
                        DARAN_CAN_TORQUE - DARAN_CAN_TRACK == DARAN_SHAPE_TORQUE &&
                        DARAN_CAN_SUB_START_IMPEDANCE - DARAN_CAN_SUB_START_TRACK ==
                            DARAN_SHAPE_IMPEDANCE,
                    can_codes_follow_the_shape_order);
DARAN_STATIC_ASSERT(DARAN_ACTION_SAVE_CONFIG == 0 && DARAN_ACTION_ESTOP == 5 &&
                        DARAN_CAN_SUB_ESTOP - DARAN_CAN_SUB_SAVE == DARAN_ACTION_ESTOP,
                    can_subcodes_follow_the_action_order);

#define LAYOUT(at4, at6) (uint8_t)((at4) | (at6) << 2)
const uint8_t daran_can_layouts[] = {
    [DARAN_CAN_LAYOUT_TRACK] = LAYOUT(DARAN_CAN_FIELD_SCALED_SATURATED, DARAN_CAN_FIELD_SCALED),
    [DARAN_CAN_LAYOUT_TRAPEZOID] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_SCALED),
    [DARAN_CAN_LAYOUT_PASSTHROUGH] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_SCALED),
    [DARAN_CAN_LAYOUT_VELOCITY] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_MODE),
    [DARAN_CAN_LAYOUT_TORQUE] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_TORQUE_MODE),
    [DARAN_CAN_LAYOUT_PRESET] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_SCALED),
    [DARAN_CAN_LAYOUT_GAINS] = LAYOUT(DARAN_CAN_FIELD_SCALED, DARAN_CAN_FIELD_SCALED) | DARAN_CAN_NO_F32,
};

uint32_t daran_can_whole_of(uint32_t raw)
{
    return raw >= 100u && raw % 100u == 0u ? raw / 100u : raw;
}

void daran_can_decode_values(daran_can_layout_t layout, const uint8_t *data, float *values)
{
    unsigned fields = daran_can_layouts[layout];
    values[0] = daran_can_get_f32(data); /* GAINS: its sub-code's bits, unused */
    /* the two 16-bit fields' kinds, then a stop bit: one loop, not one
     * decoder per field */
    const uint8_t *at = data + 4;
    for (unsigned kinds = (fields & 0xFu) | 0x10u; kinds != 1u; kinds >>= 2, at += 2) {
        unsigned kind = kinds & 3u;
        *++values = kind >= DARAN_CAN_FIELD_MODE ? (float)daran_can_whole_of(daran_can_get_u16(at))
                                                 : daran_can_get_scaled(at);
    }
}

int daran_can_put_scaled(uint8_t *bytes, float value, int saturate)
{
    /* Exactly: value * 100.0f + 0.5f rounds twice, and a value within an ulp
     * of a half count went up. |value| = m * 2^-shift with m < 2^24, so
     * m * 100 < 2^31 is exact in 32 bits and one shift rounds it, half away
     * from zero. Below 2^-8 (subnormals and zeros too) x 100 is under 0.4,
     * which rounds to 0; from 2^9 up (inf and NaN too) it is past the limit:
     * the shift in between is 15..31. */
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    uint32_t negative = bits >> 31;
    uint32_t biased = bits >> 23 & 0xFFu;
    uint32_t limit = 32767u + negative;
    uint32_t magnitude = 0;
    if (biased >= 136u) {
        magnitude = limit + 1u;
    } else if (biased >= 119u) {
        uint32_t shift = 150u - biased;
        magnitude = (((bits & 0x7FFFFFu) | 0x800000u) * 100u + ((1u << shift) >> 1)) >> shift;
    }
    int fits = magnitude <= limit;
    if (!fits) {
        magnitude = limit;
    }
    daran_can_put_u16(bytes, negative != 0u ? 0u - magnitude : magnitude);
    return saturate || fits;
}

#endif /* DARAN_ENABLE_CAN */

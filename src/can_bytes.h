/* The fields of a CAN frame's data: little-endian integers, f32 bits, and
 * the s16 x 100 "scaled" fields (C3). Inline: can.c and can_bridge.c read
 * and write the same layouts. */
#ifndef DARAN_CAN_BYTES_H
#define DARAN_CAN_BYTES_H

#include <stdint.h>
#include <string.h>

static inline uint16_t daran_can_get_u16(const uint8_t *bytes)
{
    return (uint16_t)(bytes[0] | (unsigned)bytes[1] << 8);
}

static inline uint32_t daran_can_get_u32(const uint8_t *bytes)
{
    return (uint32_t)bytes[0] | (uint32_t)bytes[1] << 8 | (uint32_t)bytes[2] << 16 |
           (uint32_t)bytes[3] << 24;
}

static inline float daran_can_get_f32(const uint8_t *bytes)
{
    uint32_t bits = daran_can_get_u32(bytes);
    float value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

/* A scaled field: raw / 100, correctly rounded (C3). */
static inline float daran_can_get_scaled(const uint8_t *bytes)
{
    return (float)(int16_t)daran_can_get_u16(bytes) / 100.0f;
}

static inline void daran_can_put_u16(uint8_t *bytes, uint32_t value)
{
    bytes[0] = (uint8_t)value;
    bytes[1] = (uint8_t)(value >> 8);
}

static inline void daran_can_put_u32(uint8_t *bytes, uint32_t value)
{
    daran_can_put_u16(bytes, value);
    daran_can_put_u16(bytes + 2, value >> 16);
}

static inline void daran_can_put_f32(uint8_t *bytes, float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    daran_can_put_u32(bytes, bits);
}

/* value x 100 rounded to the nearest, ties away from zero (C3): false when
 * it leaves the s16 range, unless @p saturate, which clamps it (a status
 * frame's fields, 2.7; `t`'s ignored velocity, C3); infinity and NaN
 * saturate by their sign. One copy, in
 * can.c, for the front end and the bridge. */
int daran_can_put_scaled(uint8_t *bytes, float value, int saturate);

#endif /* DARAN_CAN_BYTES_H */

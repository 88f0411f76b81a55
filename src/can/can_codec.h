/* The CAN codec: the vendor protocol's frames as data (docs/can.md section
 * 2), shared by the front end (can.c decodes what a drive receives) and the
 * bridge (can_bridge.c encodes what a gateway sends). A leaf: it knows the
 * identifier rule, the codes, the layouts of the value frames, the mode and
 * action maps, and nothing of a drive. */
#ifndef DARAN_CAN_CODEC_H
#define DARAN_CAN_CODEC_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "daran_can.h"
#include "daran_hal.h"

/* An identifier: the node in bits 10..5, the code in bits 4..0. */
#define DARAN_CAN_ID(node, code) ((uint32_t)(node) << 5 | (uint32_t)(code))
#define DARAN_CAN_NODE_OF(id) ((uint32_t)(id) >> 5)
#define DARAN_CAN_CODE_OF(id) ((uint32_t)(id) & 0x1Fu)

/* The command codes and the system sub-codes. */
#define DARAN_CAN_SYSTEM 0x08u
#define DARAN_CAN_PRESET 0x0Cu
#define DARAN_CAN_TRACK 0x19u
#define DARAN_CAN_TRAPEZOID 0x1Au
#define DARAN_CAN_PASSTHROUGH 0x1Bu
#define DARAN_CAN_VELOCITY 0x1Cu
#define DARAN_CAN_TORQUE 0x1Du
#define DARAN_CAN_READ 0x1Eu
#define DARAN_CAN_WRITE 0x1Fu
#define DARAN_CAN_STATUS 0x01u /* bit 0 of a status frame's code; T is bit 1, E bit 2 */

#define DARAN_CAN_SUB_RESTORE 0x00u
#define DARAN_CAN_SUB_SAVE 0x01u
#define DARAN_CAN_SUB_ESTOP 0x06u
#define DARAN_CAN_SUB_FIRMWARE 0x07u
#define DARAN_CAN_SUB_START_TRACK 0x10u
#define DARAN_CAN_SUB_START_IMPEDANCE 0x15u
#define DARAN_CAN_SUB_FEED 0x20u

/* The type codes of a read or write (bytes 2..3). */
#define DARAN_CAN_TYPE_F32 0u
#define DARAN_CAN_TYPE_U16 1u
#define DARAN_CAN_TYPE_S16 2u
#define DARAN_CAN_TYPE_U32 3u
#define DARAN_CAN_TYPE_S32 4u

/* The motion codes 0x019..0x01D and the start sub-codes 0x10..0x15 follow
 * the motion shapes' order (t q p v c, then the impedance start's d):
 * shape = code - DARAN_CAN_TRACK = sub-code - DARAN_CAN_SUB_START_TRACK
 * (can_codec.c checks it). */

/* The value frames' layouts: bytes 0..3 an f32, then two 16-bit fields at
 * bytes 4 and 6, each a scaled value (x 100, s16) or a mode. The first five
 * are the motion codes' in shape order; a preset carries p1 p2 p3; the
 * impedance start, kp and kd after its sub-code. */
typedef enum daran_can_layout {
    DARAN_CAN_LAYOUT_TRACK,
    DARAN_CAN_LAYOUT_TRAPEZOID,
    DARAN_CAN_LAYOUT_PASSTHROUGH,
    DARAN_CAN_LAYOUT_VELOCITY,
    DARAN_CAN_LAYOUT_TORQUE,
    DARAN_CAN_LAYOUT_PRESET,
    DARAN_CAN_LAYOUT_GAINS
} daran_can_layout_t;

/* What the 16-bit fields at bytes 4 and 6 of a layout hold, and the table
 * of them (can_codec.c) the decoder and the encoder read. */
#define DARAN_CAN_FIELD_SCALED 0u
#define DARAN_CAN_FIELD_SCALED_SATURATED 1u /* encoded clamped: `t`'s velocity, which drives ignore (C3) */
#define DARAN_CAN_FIELD_MODE 2u             /* a velocity mode, raw or x 100 (C1) */
#define DARAN_CAN_FIELD_TORQUE_MODE 3u      /* a torque mode: the line's 2 is 6 on the bus (C40);
                                               decoded as a mode field, both run the ramp */
#define DARAN_CAN_NO_F32 0x10u /* bytes 0..3 are not a value (the impedance start's sub-code) */
extern const uint8_t daran_can_layouts[];

/* The three values of a frame of @p layout as the ASCII line would give
 * them, a mode field as the whole number it carries (C1; the shape's
 * check refuses a mode it has not); GAINS reads its sub-code into
 * values[0]. */
void daran_can_decode_values(daran_can_layout_t layout, const uint8_t *data, float *values);
/* Encode three values (a mode as the ASCII line writes it) into @p data:
 * false when a scaled value leaves the s16 range, except `t`'s velocity,
 * which is saturated (C3); GAINS writes bytes 4..7 only. */
bool daran_can_encode_values(daran_can_layout_t layout, const float *values, uint8_t *data);

/* The whole number a mode or flag field carries, raw or x 100 (C1, C2):
 * 2 and 200 are both 2. Which modes a shape takes is the shape's check
 * (daran_shape_check()), as for a line: the torque ramp's 2 (the vendor's
 * C libraries) and 6 run the same move. */
uint32_t daran_can_whole_of(uint32_t raw);

/* The system sub-code of a HAL action a frame can ask for (C36), and back:
 * false for a sub-code that is no action. */
uint32_t daran_can_subcode_of(daran_action_t action);
static inline bool daran_can_action_of(uint32_t subcode, daran_action_t *action)
{
    *action = (daran_action_t)(subcode - DARAN_CAN_SUB_SAVE);
    return subcode - DARAN_CAN_SUB_SAVE <= DARAN_CAN_SUB_ESTOP - DARAN_CAN_SUB_SAVE;
}

/* Little-endian fields of a frame's data. */
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
 * saturate by their sign. */
int daran_can_put_scaled(uint8_t *bytes, float value, int saturate);

/* A read or write frame's data: a property's address and type code, and
 * (a write, a read's reply) its value's bits. */
static inline void daran_can_put_property(uint8_t *data, uint32_t address, uint32_t type,
                                          uint32_t bits)
{
    daran_can_put_u16(data, address);
    daran_can_put_u16(data + 2, type);
    daran_can_put_u32(data + 4, bits);
}

#endif /* DARAN_CAN_CODEC_H */

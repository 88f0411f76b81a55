/* The CAN fuzz target's built-in seeds: what the vendor's clients send
 * (can.md section 6.6), the settings that wake the heartbeat, the node
 * guard and the automatic status reply, a duplicate id and frames of the
 * wrong shape, as records of fuzz_can_target.c. Written out by
 * `<name>_replay --write-seeds DIR`, run by `<name>_replay --seeds`. */
#include <string.h>

#include "daran_fuzz.h"

/* One record: wait (ms), shape (DLC, flags), id, eight data bytes. */
#define REC(wait, shape, id, d0, d1, d2, d3, d4, d5, d6, d7) \
    wait, shape, (id) & 0xFF, (id) >> 8, d0, d1, d2, d3, d4, d5, d6, d7
#define FRAME(id, d0, d1, d2, d3, d4, d5, d6, d7) REC(0, 8, id, d0, d1, d2, d3, d4, d5, d6, d7)
#define LATER(wait, id, d0, d1, d2, d3, d4, d5, d6, d7) REC(wait, 8, id, d0, d1, d2, d3, d4, d5, d6, d7)

static const uint8_t reads[] = {
    FRAME(0x01E, 0x19, 0x79, 0x03, 0x00, 0, 0, 0, 0), /* get_id(), broadcast */
    FRAME(0x03E, 0, 0, 0, 0, 0, 0, 0, 0),             /* get_state(1): fast read */
    FRAME(0x03E, 0x77, 0x94, 0x00, 0x00, 0, 0, 0, 0), /* pos_estimate */
    FRAME(0x03E, 0x03, 0x00, 0x03, 0x00, 0, 0, 0, 0), /* serial_number_l */
    FRAME(0x03E, 0xFF, 0xFF, 0x00, 0x00, 0, 0, 0, 0), /* no such address */
};

static const uint8_t heartbeat[] = {
    FRAME(0x03F, 0x0C, 0x52, 0x03, 0x00, 10, 0, 0, 0),     /* can.config.heartbeat_ms 10 */
    LATER(35, 0x03E, 0, 0, 0, 0, 0, 0, 0, 0),
    FRAME(0x03F, 0x19, 0x79, 0x03, 0x00, 5, 0, 0, 0),      /* can_node_id 5 */
    LATER(25, 0x0BE, 0, 0, 0, 0, 0, 0, 0, 0),
};

static const uint8_t guard[] = {
    FRAME(0x03F, 0x0B, 0x52, 0x03, 0x00, 20, 0, 0, 0),     /* can.config.timeout_ms 20 */
    LATER(15, 0x01E, 0, 0, 0, 0, 0, 0, 0, 0),              /* fed by a broadcast */
    LATER(30, 0x05E, 0, 0, 0, 0, 0, 0, 0, 0),              /* another node's: trips */
    FRAME(0x028, 0x04, 0, 0, 0, 0, 0, 0, 0),               /* sc */
    FRAME(0x03F, 0x33, 0x75, 0x03, 0x00, 8, 0, 0, 0),      /* requested_state 8 */
    LATER(5, 0x039, 0x00, 0x00, 0xB4, 0x42, 0, 0, 0xE8, 0x03),
};

static const uint8_t motions[] = {
    FRAME(0x03F, 0xEE, 0x79, 0x03, 0x00, 1, 0, 0, 0),      /* enable_reply_state 1 */
    FRAME(0x039, 0x00, 0x00, 0xB4, 0x42, 0, 0, 0xE8, 0x03), /* set_angle(1, 90, 0, 10, 0) */
    LATER(3, 0x03A, 0x00, 0x00, 0x16, 0xC3, 0xE8, 0x03, 0xF4, 0x01),
    FRAME(0x03B, 0x00, 0x00, 0xF0, 0x41, 0xF4, 0x01, 0x1E, 0x00),
    FRAME(0x03C, 0x00, 0x00, 0xA0, 0x41, 0x96, 0x00, 0x01, 0x00),
    FRAME(0x03D, 0xCD, 0xCC, 0x4C, 0xBF, 0x32, 0x00, 0x06, 0x00),
    FRAME(0x03C, 0x00, 0x00, 0xA0, 0x41, 0x96, 0x00, 0x07, 0x00), /* mode 7 */
};

static const uint8_t presets[] = {
    FRAME(0x02C, 0x9A, 0x99, 0x99, 0xBF, 0x14, 0x00, 0x58, 0x02), /* preset_torque(1, -1.2, 0.2, 6) */
    FRAME(0x008, 0x14, 0, 0, 0, 0, 0, 0, 0),
    FRAME(0x02C, 0x00, 0x00, 0xF0, 0x41, 0xF4, 0x01, 0x32, 0x00), /* impedance_control(1, ...) */
    FRAME(0x008, 0x15, 0, 0, 0, 0x14, 0x00, 0x05, 0x00),
    FRAME(0x02C, 0x00, 0x00, 0xF0, 0x42, 0xF4, 0x01, 0xE8, 0x03), /* ms 1 120 5 10 */
    FRAME(0x028, 0x11, 0, 0, 0, 0x01, 0x00, 0, 0),               /* mq 1 1 */
    LATER(20, 0x028, 0x10, 0, 0, 0, 0, 0, 0, 0),                  /* a start without a preset */
};

static const uint8_t system_commands[] = {
    FRAME(0x028, 0x05, 0, 0, 0, 0, 0, 0, 0), /* sz */
    FRAME(0x028, 0x01, 0, 0, 0, 0, 0, 0, 0), /* ss */
    FRAME(0x028, 0x06, 0, 0, 0, 0, 0, 0, 0), /* st */
    FRAME(0x028, 0x04, 0, 0, 0, 0, 0, 0, 0), /* sc */
    FRAME(0x028, 0x20, 0, 0, 0, 0, 0, 0, 0), /* feed only */
    FRAME(0x028, 0x02, 0, 0, 0, 0, 0, 0, 0), /* se */
    FRAME(0x028, 0x03, 0, 0, 0, 0, 0, 0, 0), /* sr */
    FRAME(0x028, 0x30, 0, 0, 0, 0, 0, 0, 0), /* no such sub-code */
};

static const uint8_t odd_frames[] = {
    FRAME(0x023, 0, 0, 0xB4, 0x42, 0, 0, 0, 0),            /* another drive with id 1 */
    REC(0, 0, 0x009, 0, 0, 0, 0, 0, 0, 0, 0),              /* send_command(): DLC 0 */
    REC(0, 7, 0x048, 0x06, 0, 0, 0, 0, 0, 0, 0),           /* DLC 7 */
    REC(0, 0x98, 0x03E, 0, 0, 0, 0, 0, 0, 0, 0),           /* remote */
    REC(0, 0xA8, 0x03E, 0, 0, 0, 0, 0, 0, 0, 0),           /* extended id */
    FRAME(0x03F, 0x19, 0x79, 0x03, 0x00, 0, 0, 0, 0),      /* can_node_id 0 */
    FRAME(0x02E, 0, 0, 0, 0, 0, 0, 0, 0),                  /* unknown code */
};

static const struct {
    const uint8_t *bytes;
    size_t len;
} seeds[] = {
    {reads, sizeof reads},       {heartbeat, sizeof heartbeat},
    {guard, sizeof guard},       {motions, sizeof motions},
    {presets, sizeof presets},   {system_commands, sizeof system_commands},
    {odd_frames, sizeof odd_frames},
};

size_t daran_fuzz_can_seed(size_t index, uint8_t *out, size_t cap)
{
    if (index >= sizeof seeds / sizeof seeds[0] || seeds[index].len > cap) {
        return 0;
    }
    memcpy(out, seeds[index].bytes, seeds[index].len);
    return seeds[index].len;
}

/* The CAN side of a conformance check: a daran_can_t bound to the check's
 * drive, whose port description gets the test port's CAN functions (its
 * can_send wrapped so every frame the drive sends is seen and then handed
 * on),
 * frames given through the port's receive path (can_deliver), drive time
 * passed a millisecond at a time with a poll after each, and the frames and
 * HAL calls of each step in the check's transcript. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conformance.h"

#if DARAN_ENABLE_CAN

#define SENT_MAX 256u
#define WAIT_EFFECTS_MAX 64u
#define WAIT_SHOWN 12u

static struct can_harness {
    daran_can_t can;
    daran_can_frame_t sent[SENT_MAX];
    bool taken[SENT_MAX]; /* the port's send answered true */
    uint32_t sent_at[SENT_MAX];
    size_t n_sent;
    size_t n_lost; /* past SENT_MAX */
    uint32_t now;  /* ms into the current wait */
    daran_call_t effects[WAIT_EFFECTS_MAX];
    uint32_t effects_at[WAIT_EFFECTS_MAX];
    size_t n_effects;
} c;

static bool wrapped_send(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    const daran_test_port_t *port = conf_port();
    bool taken = port->hal->can_send(port->ctx, frame);
    if (c.n_sent < SENT_MAX) {
        c.sent[c.n_sent] = *frame;
        c.taken[c.n_sent] = taken;
        c.sent_at[c.n_sent] = c.now;
        c.n_sent++;
    } else {
        c.n_lost++;
    }
    return taken;
}

static uint32_t wrapped_now(void *ctx)
{
    (void)ctx;
    const daran_test_port_t *port = conf_port();
    return port->hal->now_ms(port->ctx);
}

static void wrapped_hook(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    (void)ctx;
    const daran_test_port_t *port = conf_port();
    if (port->hal->can_system != NULL) {
        port->hal->can_system(port->ctx, subcode, data1, data2);
    }
}

static void clear_sent(void)
{
    c.n_sent = 0;
    c.n_lost = 0;
    c.n_effects = 0;
    c.now = 0;
}

/* Bind a fresh front end; false (the check failed) when it cannot run. */
static bool bind_can(void)
{
    clear_sent();
    /* the port's CAN functions, its transmit wrapped to see every frame */
    daran_hal_t *hal = conf_drive_port();
    hal->can_send = wrapped_send;
    hal->now_ms = wrapped_now;
    hal->can_system = wrapped_hook;
    daran_result_t result = daran_can_init(&c.can, conf_drive());
    if (result != DARAN_OK) {
        conf_fail("daran_can_init() to accept the drive and the test port's CAN functions (it answered %s)",
                  daran_result_phrase(result));
        return false;
    }
    /* the front end reads can.config.protocol once, at init, as at boot */
    daran_value_t protocol;
    if (conf_in_build(DARAN_PROP_CAN_PROTOCOL) &&
        conf_read_value(DARAN_PROP_CAN_PROTOCOL, CONF_ID, &protocol, false) && protocol.u32 != 1u) {
        conf_fail("`can.config.protocol` to read 1 after reset(), the factory default (can.md C15); "
                  "with %lu the CAN front end ignores the bus",
                  (unsigned long)protocol.u32);
        return false;
    }
    return !conf_failed();
}

bool conf_can_begin(conf_req_t req, const char *subject)
{
    return conf_begin(req, subject) && bind_can();
}

bool conf_can_restart(void)
{
    return conf_restart() && bind_can();
}

daran_can_frame_t conf_can_frame(unsigned node, unsigned code, const uint8_t data[8])
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = (uint32_t)(node << 5 | code);
    frame.dlc = 8;
    if (data != NULL) {
        memcpy(frame.data, data, sizeof frame.data);
    }
    return frame;
}

static void describe_frame(const daran_can_frame_t *f, char *buf, size_t size)
{
    int n = snprintf(buf, size, "0x%03lX", (unsigned long)f->id);
    size_t used = n > 0 ? (size_t)n : 0u;
    for (unsigned i = 0; i < 8u && used + 4u < size; i++) {
        n = snprintf(buf + used, size - used, " %02x", f->data[i]);
        used += n > 0 ? (size_t)n : 0u;
    }
    if (f->dlc != 8u || f->flags != 0u) {
        (void)snprintf(buf + used, size - used, " (DLC %u%s%s%s)", f->dlc,
                       (f->flags & DARAN_CAN_FRAME_REMOTE) != 0u ? ", remote" : "",
                       (f->flags & DARAN_CAN_FRAME_EXTENDED) != 0u ? ", extended id" : "",
                       (f->flags & DARAN_CAN_FRAME_FD) != 0u ? ", FD" : "");
    }
}

static void transcript_sent(size_t from)
{
    if (c.n_sent == from) {
        conf_transcript("    frames sent: none\n");
        return;
    }
    conf_transcript("    frames sent:\n");
    for (size_t i = from; i < c.n_sent; i++) {
        char text[96];
        describe_frame(&c.sent[i], text, sizeof text);
        conf_transcript("      %s%s\n", text, c.taken[i] ? "" : "  (the port's send answered false)");
    }
}

void conf_can_deliver(const daran_can_frame_t *frame)
{
    const daran_test_port_t *port = conf_port();
    conf_rec_clear();
    clear_sent();
    char text[96];
    describe_frame(frame, text, sizeof text);
    conf_transcript("  > frame %s\n", text);
    if (port->can_deliver != NULL) {
        port->can_deliver(port->ctx, &c.can, frame);
    } else {
        (void)daran_can_receive(&c.can, frame);
    }
    (void)daran_can_poll(&c.can);
    transcript_sent(0);
    conf_transcript_calls();
}

void conf_can_wait(uint32_t ms)
{
    const daran_recorder_t *rec = conf_rec();
    clear_sent();
    for (uint32_t t = 1; t <= ms; t++) {
        conf_rec_clear();
        conf_port()->advance(conf_port()->ctx, 1u);
        c.now = t;
        (void)daran_can_poll(&c.can);
        for (size_t i = 0; i < rec->n_calls && c.n_effects < WAIT_EFFECTS_MAX; i++) {
            if (rec->calls[i].kind != DARAN_CALL_GET) {
                c.effects[c.n_effects] = rec->calls[i];
                c.effects_at[c.n_effects] = t;
                c.n_effects++;
            }
        }
    }
    conf_rec_clear();
    conf_transcript("  (drive time: %lu ms, daran_can_poll() after every ms)\n", (unsigned long)ms);
    if (c.n_sent == 0u) {
        conf_transcript("    frames sent: none\n");
    }
    for (size_t i = 0; i < c.n_sent && i < WAIT_SHOWN; i++) {
        char text[96];
        describe_frame(&c.sent[i], text, sizeof text);
        conf_transcript("    at %3lu ms sent %s%s\n", (unsigned long)c.sent_at[i], text,
                        c.taken[i] ? "" : "  (the port's send answered false)");
    }
    if (c.n_sent > WAIT_SHOWN) {
        conf_transcript("    ... %lu frames in all\n", (unsigned long)(c.n_sent + c.n_lost));
    }
    if (c.n_effects == 0u) {
        conf_transcript("    HAL setters, moves and actions: none\n");
    }
    for (size_t i = 0; i < c.n_effects && i < WAIT_SHOWN; i++) {
        char call[256];
        (void)daran_call_describe(&c.effects[i], call, sizeof call);
        conf_transcript("    at %3lu ms HAL %s\n", (unsigned long)c.effects_at[i], call);
    }
}

size_t conf_can_sent_count(void)
{
    return c.n_sent + c.n_lost;
}

const daran_can_frame_t *conf_can_sent(size_t i)
{
    return &c.sent[i < SENT_MAX ? i : SENT_MAX - 1u];
}

uint32_t conf_can_sent_at(size_t i)
{
    return c.sent_at[i < SENT_MAX ? i : SENT_MAX - 1u];
}

size_t conf_can_wait_actions(daran_action_t kind, uint32_t *first_at)
{
    size_t count = 0;
    for (size_t i = 0; i < c.n_effects; i++) {
        if (c.effects[i].kind == DARAN_CALL_ACTION && c.effects[i].action == kind) {
            if (count == 0u && first_at != NULL) {
                *first_at = c.effects_at[i];
            }
            count++;
        }
    }
    return count;
}

size_t conf_can_wait_effects(void)
{
    return c.n_effects;
}

bool conf_can_expect_nothing_sent(void)
{
    if (conf_can_sent_count() == 0u) {
        return true;
    }
    conf_fail("no frame back (the drive sent %lu)", (unsigned long)conf_can_sent_count());
    return false;
}

bool conf_can_expect_taken(void)
{
    for (size_t i = 0; i < c.n_sent; i++) {
        if (!c.taken[i]) {
            conf_fail("the port's send to take every frame the drive sent (it answered false for "
                      "frame %lu of %lu; the drive drops such a frame, unsent)",
                      (unsigned long)i + 1u, (unsigned long)c.n_sent);
            return false;
        }
    }
    return true;
}

/* A value `r` reads now from drive @p id, or 0 for a row this build lacks
 * (the front end sends 0 for it). */
static bool read_now(daran_prop_t prop, unsigned id, daran_value_t *out)
{
    out->u64 = 0;
    return !conf_in_build(prop) || conf_read_value(prop, id, out, false);
}

/* The s16 x 100 field the drive must send for @p value (2.7: rounded,
 * saturated), compared with the one it sent. */
static bool scaled_matches(int16_t raw, float value)
{
    double want = (double)value * 100.0;
    if (isnan(want)) {
        return true;
    }
    if (want >= 32767.0) {
        return raw == 32767;
    }
    if (want <= -32768.0) {
        return raw == -32768;
    }
    return fabs((double)raw - want) <= 0.5 + 1e-6;
}

bool conf_can_expect_status(unsigned node)
{
    if (conf_can_sent_count() != 1u) {
        conf_fail("one status frame from node %u (the drive sent %lu frames)", node,
                  (unsigned long)conf_can_sent_count());
        return false;
    }
    daran_can_frame_t f = c.sent[0];
    unsigned code = (unsigned)(f.id & 0x1Fu);
    if (f.dlc != 8u || f.flags != 0u || f.id > 0x7FFu || (f.id >> 5) != node || (code & 0x19u) != 1u) {
        conf_fail("a status frame from node %u: id %u << 5 | 1 | T << 1 | E << 2, DLC 8, standard",
                  node, node);
        return false;
    }
    daran_value_t pos, vel, torque, done, error;
    if (!read_now(DARAN_PROP_POS_ESTIMATE, node, &pos) ||
        !read_now(DARAN_PROP_VEL_ESTIMATE, node, &vel) ||
        !read_now(DARAN_PROP_TORQUE_ESTIMATE, node, &torque) ||
        !read_now(DARAN_PROP_TRAJECTORY_DONE, node, &done) ||
        !read_now(DARAN_PROP_AXIS_ERROR, node, &error)) {
        return false;
    }
    bool ok = true;
    if (((code & 2u) != 0u) != (done.u32 != 0u)) {
        conf_fail("the status frame's T bit to be controller.trajectory_done, %u", (unsigned)done.u32);
        ok = false;
    }
    if (((code & 4u) != 0u) != (error.u32 != 0u)) {
        conf_fail("the status frame's E bit to say whether axis0.error (%lu) is not 0",
                  (unsigned long)error.u32);
        ok = false;
    }
    uint32_t bits = (uint32_t)f.data[0] | (uint32_t)f.data[1] << 8 | (uint32_t)f.data[2] << 16 |
                    (uint32_t)f.data[3] << 24;
    if (bits != pos.u32) {
        conf_fail("the status frame's f32 position to be output_shaft.pos_estimate, %.9g",
                  (double)pos.f32);
        ok = false;
    }
    int16_t raw_vel = (int16_t)(uint16_t)(f.data[4] | f.data[5] << 8);
    int16_t raw_torque = (int16_t)(uint16_t)(f.data[6] | f.data[7] << 8);
    if (!scaled_matches(raw_vel, vel.f32)) {
        conf_fail("the status frame's velocity (s16 x 100, rounded, saturated) to be "
                  "output_shaft.vel_estimate, %.9g (it carries %d)",
                  (double)vel.f32, raw_vel);
        ok = false;
    }
    if (!scaled_matches(raw_torque, torque.f32)) {
        conf_fail("the status frame's torque (s16 x 100, rounded, saturated) to be "
                  "output_shaft.torque_estimate, %.9g (it carries %d)",
                  (double)torque.f32, raw_torque);
        ok = false;
    }
    return ok;
}

#else
/* Without the front end check_can.c only skips: nothing here (ISO C wants a
 * declaration in every file). */
typedef int conf_can_harness_compiled_out_t;
#endif /* DARAN_ENABLE_CAN */

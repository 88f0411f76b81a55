/* The ACME X1's own host test: its protocol layer (the core built for
 * acme_options.h) against daran-ascii's simulated drive, compiled for the
 * same core (daran_ascii_add_sim). The fan is the X1's own property; an
 * extension serves it over the simulated motor and cools the power stage
 * with it, the way the X1's firmware would. Plain C: prints each check and
 * "N passed, N failed", exits non-zero on a failure. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "daran_sim.h"

static daran_sim_drive_t sim;
static daran_drive_t drive;
static char reply[1024];
static size_t reply_len;
static int passed;
static int failed;

static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "PASS" : "FAIL", what);
    if (ok) {
        passed++;
    } else {
        failed++;
    }
}

static void collect(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (reply_len + len < sizeof reply) {
        memcpy(reply + reply_len, line, len);
        reply_len += len;
        reply[reply_len] = '\0';
    }
}

static const daran_hal_t collect_port = {DARAN_SIM_HAL_FUNCTIONS, .write = collect};

static const char *send(const char *line)
{
    reply_len = 0;
    reply[0] = '\0';
    (void)daran_process_line(&drive, line, strlen(line));
    return reply;
}

static void run_ms(unsigned ms)
{
    for (unsigned i = 0; i < ms; i++) {
        daran_sim_drive_tick(&sim);
    }
}

/* The fan: duty in 0..1 (the core has checked the range), and a count of
 * the writes the firmware made. */
typedef struct fan {
    float duty;
    unsigned writes;
} fan_t;

static daran_result_t fan_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    if (prop != DARAN_PROP_FAN_DUTY) {
        return DARAN_SIM_NOT_MINE;
    }
    out->f32 = ((const fan_t *)ctx)->duty;
    return DARAN_OK;
}

static daran_result_t fan_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    if (prop != DARAN_PROP_FAN_DUTY) {
        return DARAN_SIM_NOT_MINE;
    }
    fan_t *fan = ctx;
    fan->duty = value.f32;
    fan->writes++;
    return DARAN_OK;
}

int main(void)
{
    static fan_t fan;
    static const daran_sim_extension_t fan_extension = {fan_get, fan_set, NULL};

    daran_sim_drive_init(&sim, 0u, 1000u);
    daran_sim_drive_extend(&sim, &fan_extension, &fan);
    check(daran_init(&drive, &collect_port, &sim) == DARAN_OK,
          "the X1's core binds to the simulated drive (same options header)");

    check(strcmp(send("w axis0.fan.duty 0.75"), "") == 0 && fan.duty == 0.75f && fan.writes == 1,
          "w axis0.fan.duty 0.75 reaches the X1's fan");
    check(strncmp(send("r axis0.fan.duty"), "0.75", 4) == 0, "r axis0.fan.duty reads it back");
    check(strncmp(send("w axis0.fan.duty 1.25"), "error: value out of range", 25) == 0 &&
              fan.writes == 1,
          "a duty above 1 is refused by the core, the fan untouched");
    check(strncmp(send("r axis0.encoder.pos_abs"), "error: invalid property", 23) == 0,
          "the absolute encoder the X1 lacks answers invalid property");
    check(strstr(send("h 1 properties axis0.fan"), "axis0.fan.duty f32 rw - 0..1") != NULL,
          "discovery lists the fan with its 0..1 range");

    /* the shaft: a trapezoid to 90 deg, then a stall injected by the test */
    check(strcmp(send("q 1 90 30 100"), "") == 0, "q 1 90 30 100 is accepted");
    run_ms(6000);
    send("r axis0.output_shaft.pos_estimate");
    float pos = 0.0f;
    check(sscanf(reply, "%f", &pos) == 1 && fabsf(pos - 90.0f) < 0.5f,
          "the simulated shaft arrives at 90 deg");
    check(daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_STALL) == DARAN_OK,
          "the test injects a stall");
    run_ms(2);
    check(strncmp(send("t 1 0"), "error: motor fault", 18) == 0,
          "after the stall a motion command answers motor fault");
    check(strcmp(send("sc 1"), "") == 0 && strcmp(send("w axis0.requested_state 8"), "") == 0 &&
              strcmp(send("t 1 0"), "") == 0,
          "sc and closed loop: motion is accepted again");

    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

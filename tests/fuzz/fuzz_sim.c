/* Harness 4: protocol lines and simulator directives through the simulated
 * multi-drop bus (port/sim's library API), checking the physical model after
 * every control tick.
 *
 * Input: byte 0 picks the drive count (1..3) and the tick rate; then lines. A line starting
 * with '!' is a directive as daran-sim reads it (`!advance S`, at most 2 s
 * each and 2500 ticks per input; `!power-cycle [ID]`; `!fault ID overtemp|
 * undervoltage|stall|overspeed|nvm-corrupt`); any other line goes down the line to every
 * drive. Invariants checked:
 *  - 4: every reply line is well-formed;
 *  - the model stays finite: position, velocity, torques, setpoints,
 *    integrator, temperatures, bus voltage and current;
 *  - the commanded torque never exceeds the torque limit in force
 *    (daran_sim_model_torque_limit, derating included); an idle drive
 *    commands and delivers no torque;
 *  - speed: with the default tuning and limits, in a position or velocity
 *    mode without a large torque feed-forward, after 3 s with no new line,
 *    |velocity| <= the velocity limit + 2 % + 1 r/min. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_hal.h"
#include "sim_bus.h"

/* 250 Hz keeps an input fast enough for fuzzing; 1 in 4 inputs runs the
 * default 1 kHz. The budget bounds the time one input may take. */
#define MAX_TICKS_PER_INPUT 2500u
#define QUIET_SECONDS 3u

static uint32_t tick_hz;

static daran_sim_bus_t bus;
static daran_sim_model_t defaults; /* a fresh model, for the default tuning */
static uint32_t quiet[DARAN_SIM_MAX_DRIVES];
static uint32_t last_mode[DARAN_SIM_MAX_DRIVES];

static void sink(void *ctx, uint32_t drive_id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)drive_id;
    size_t start = 0;
    for (size_t i = 0; i < len; i++) {
        if (bytes[i] == '\n') {
            fuzz_check_reply_line(bytes + start, i + 1u - start);
            start = i + 1u;
        }
    }
    FUZZ_CHECK(start == len, "drive %u left a partial reply line", drive_id);
}

static bool finite_model(const daran_sim_model_t *m)
{
    const float v[] = {m->raw_pos_deg, m->vel_rpm,    m->torque_nm,  m->torque_cmd,
                       m->pos_sp,      m->vel_sp,     m->integrator, m->motor_temp_c,
                       m->fet_temp_c,  m->vbus_v,     m->ibus_a,     m->filt_ref,
                       m->filt_err,    m->filt_vel,   m->input_pos,  m->input_vel,
                       m->input_torque};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        if (!isfinite(v[i])) {
            return false;
        }
    }
    return true;
}

static bool default_tuning(const daran_sim_model_t *m)
{
    static const daran_prop_t props[] = {
        DARAN_PROP_POS_GAIN,          DARAN_PROP_VEL_GAIN,         DARAN_PROP_VEL_INTEGRATOR_GAIN,
        DARAN_PROP_LOAD_INERTIA,      DARAN_PROP_CURRENT_LIM,      DARAN_PROP_MOTOR_TORQUE_LIM,
        DARAN_PROP_SHAFT_TORQUE_LIM,  DARAN_PROP_TORQUE_CONSTANT,
        DARAN_PROP_CURRENT_CONTROL_BANDWIDTH};
    for (size_t i = 0; i < sizeof props / sizeof props[0]; i++) {
        if (m->cfg[props[i]].u32 != defaults.cfg[props[i]].u32) {
            return false;
        }
    }
    return daran_sim_model_torque_limit(m) == daran_sim_model_torque_limit(&defaults);
}

static void tick_and_check(void)
{
    float lim[DARAN_SIM_MAX_DRIVES];
    for (uint32_t i = 0; i < bus.count; i++) {
        lim[i] = daran_sim_model_torque_limit(&bus.node[i].sim.model);
    }
    daran_sim_bus_tick(&bus);
    for (uint32_t i = 0; i < bus.count; i++) {
        const daran_sim_model_t *m = &bus.node[i].sim.model;
        FUZZ_CHECK(finite_model(m),
                   "drive %u: model not finite at tick %llu (pos %g vel %g torque %g)", i + 1u,
                   (unsigned long long)bus.ticks, (double)m->raw_pos_deg, (double)m->vel_rpm,
                   (double)m->torque_cmd);
        if (m->state == DARAN_STATE_CLOSED_LOOP) {
            FUZZ_CHECK(fabsf(m->torque_cmd) <= lim[i] * (1.0f + 1e-6f) + 1e-6f,
                       "drive %u: torque %g over its limit %g", i + 1u, (double)m->torque_cmd,
                       (double)lim[i]);
        } else {
            FUZZ_CHECK(m->torque_cmd == 0.0f && m->torque_nm == 0.0f,
                       "drive %u: idle but torque %g / %g", i + 1u, (double)m->torque_cmd,
                       (double)m->torque_nm);
        }
        bool speed_mode = m->mode == DARAN_SIM_MODE_PASSTHROUGH ||
                          m->mode == DARAN_SIM_MODE_FILTER || m->mode == DARAN_SIM_MODE_TRAPEZOID ||
                          m->mode == DARAN_SIM_MODE_VELOCITY ||
                          m->mode == DARAN_SIM_MODE_VELOCITY_RAMP;
        uint32_t mode_state = (uint32_t)m->mode * 16u + m->state;
        if (m->state != DARAN_STATE_CLOSED_LOOP || !speed_mode || mode_state != last_mode[i] ||
            !default_tuning(m) || fabsf(m->torque_ff) > 0.25f * lim[i]) {
            quiet[i] = 0;
        } else if (quiet[i] < QUIET_SECONDS * tick_hz) {
            quiet[i]++;
        } else {
            float vlim = daran_sim_model_vel_limit_rpm(m);
            FUZZ_CHECK(fabsf(m->vel_rpm) <= vlim * 1.02f + 1.0f,
                       "drive %u: settled at %g r/min, limit %g (mode %d)", i + 1u,
                       (double)m->vel_rpm, (double)vlim, (int)m->mode);
        }
        last_mode[i] = mode_state;
    }
}

/* Drive indexes a directive's ID names (its can_node_id; 0 = all). */
static size_t select_drives(const char *id_text, uint32_t *sel)
{
    char *end;
    long id = strtol(id_text, &end, 10);
    size_t n = 0;
    if (*end != '\0' || id < 0) {
        return 0;
    }
    for (uint32_t i = 0; i < bus.count; i++) {
        if (id == 0 || daran_sim_drive_id(&bus.node[i].sim) == (uint32_t)id) {
            sel[n++] = i;
        }
    }
    return n;
}

static void directive(char *text, uint32_t *budget)
{
    char *argv[4] = {NULL, NULL, NULL, NULL};
    int argc = 0;
    for (char *tok = strtok(text, " \t\r"); tok != NULL && argc < 4; tok = strtok(NULL, " \t\r")) {
        argv[argc++] = tok;
    }
    if (argc == 0) {
        return;
    }
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    if (strcmp(argv[0], "advance") == 0 && argc == 2) {
        char *end;
        double s = strtod(argv[1], &end);
        if (*end != '\0' || !(s >= 0.0)) {
            return;
        }
        uint32_t ticks = s > 2.0 ? 2u * tick_hz : (uint32_t)(s * tick_hz + 0.5);
        if (ticks > *budget) {
            ticks = *budget;
        }
        *budget -= ticks;
        for (uint32_t t = 0; t < ticks; t++) {
            tick_and_check();
        }
    } else if (strcmp(argv[0], "power-cycle") == 0 && argc <= 2) {
        size_t n = select_drives(argc == 2 ? argv[1] : "0", sel);
        for (size_t i = 0; i < n; i++) {
            daran_sim_bus_power_cycle(&bus, sel[i]);
        }
    } else if (strcmp(argv[0], "fault") == 0 && argc == 3) {
        size_t n = select_drives(argv[1], sel);
        for (size_t i = 0; i < n; i++) {
            daran_sim_drive_t *d = &bus.node[sel[i]].sim;
            if (strcmp(argv[2], "overtemp") == 0) {
                daran_sim_model_fault(&d->model, DARAN_SIM_FAULT_OVERTEMP);
            } else if (strcmp(argv[2], "undervoltage") == 0) {
                daran_sim_model_fault(&d->model, DARAN_SIM_FAULT_UNDERVOLTAGE);
            } else if (strcmp(argv[2], "stall") == 0) {
                daran_sim_model_fault(&d->model, DARAN_SIM_FAULT_STALL);
            } else if (strcmp(argv[2], "overspeed") == 0) {
                daran_sim_model_fault(&d->model, DARAN_SIM_FAULT_OVERSPEED);
            } else if (strcmp(argv[2], "nvm-corrupt") == 0) {
                (void)daran_sim_drive_corrupt_nvm(d);
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1u) {
        return 0;
    }
    tick_hz = (data[0] & 0x30u) == 0x30u ? 1000u : 250u;
    daran_sim_model_init(&defaults, tick_hz);
    uint32_t drives = 1u + data[0] % 3u;
    if (daran_sim_bus_init(&bus, drives, tick_hz) != DARAN_OK) {
        fuzz_fail("bus init refused %u drives", drives);
    }
    memset(quiet, 0, sizeof quiet);
    memset(last_mode, 0, sizeof last_mode);
    uint32_t budget = MAX_TICKS_PER_INPUT;

    const char *text = (const char *)data + 1;
    size_t len = size - 1u;
    size_t start = 0;
    char buf[512];
    for (size_t i = 0; i <= len; i++) {
        if (i < len && text[i] != '\n') {
            continue;
        }
        size_t n = i - start;
        if (n > 0u && text[start] == '!' && n < sizeof buf) {
            memcpy(buf, text + start + 1, n - 1u);
            buf[n - 1u] = '\0';
            if (strlen(buf) == n - 1u) {
                directive(buf, &budget);
            }
        } else if (n > 0u && text[start] != '!') {
            /* the line and its '\n' (the last line of the input without one
             * is sent unfinished, as a cut-off host would) */
            daran_sim_bus_send(&bus, text + start, i < len ? n + 1u : n);
            memset(quiet, 0, sizeof quiet);
        }
        (void)daran_sim_bus_collect(&bus, sink, NULL);
        start = i + 1u;
    }
    return 0;
}

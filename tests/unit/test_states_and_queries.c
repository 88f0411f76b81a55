/* Unit tests of drive states (estop, faults, idle; D16, D18, D21, D22; any
 * bit of axis0.error blocks motion, config_warnings never does, spec 10.4)
 * and of the query commands f, g, i, e (the seven error registers), h
 * (D23-D25). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

/* Motion lines, each with the preset its start needs ("" for none). */
typedef struct motion { const char *preset; const char *line; } motion_t;

static const motion_t motions[] = {
    {"", "t 1 10"},          {"", "q 1 10 30 10"},      {"", "p 1 10"},
    {"", "v 1 10"},          {"", "v 1 10 5 2"},        {"", "c 1 1"},
    {"", "c 1 1 2 6"},       {"", "d 1 0 0 0 0 0"},     {"ms 1 10 0 5", "mt 1 0"},
    {"ms 1 10 2 10", "mq 1 1"}, {"ms 1 10 0 0", "mp 1 0"}, {"ms 1 10 0 1", "mv 1"},
    {"ms 1 1 0 1", "mc 1"},  {"", "t 0 10"},            {"ms 1 10 0 5", "mt 0 0"},
};
#define N_MOTIONS (sizeof motions / sizeof motions[0])

static void set_state(mock_t *m, uint32_t flags, uint32_t st)
{
    m->props[DARAN_PROP_AXIS_ERROR].u32 = flags;
    m->props[DARAN_PROP_CURRENT_STATE].u32 = st;
    m->props[DARAN_PROP_REQUESTED_STATE].u32 = st;
}

static void send_preset(mock_t *m, const motion_t *mo)
{
    if (mo->preset[0]) {
        mock_send_line(m, mo->preset);
        ASSERT_REPLY(m, "");
    }
}

static void estop_case(const void *row_arg)
{
    const motion_t *mo = row_arg;
    SKIP_LINE_IF_NO_MULTI(mo->line);
    mock_t *m = mock_new();
    send_preset(m, mo);
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, mo->line, "estop active");
}

/* Every bit of axis0.error but the e-stop's answers motor fault (spec 10.4):
 * the ones this library names, bits no one names, and the old warning bit 5. */
static const uint32_t blocking_flags[] = {
    DARAN_FLAG_WATCHDOG, DARAN_FLAG_OVERTEMP, DARAN_FLAG_MOTOR_FAILED,
    DARAN_FLAG_CONTROLLER_FAILED, DARAN_FLAG_UNDERVOLTAGE, 1u << 0, 1u << 5, 1u << 8,
    1u << 31, DARAN_FLAG_WATCHDOG | DARAN_FLAG_OVERTEMP, ~(uint32_t)DARAN_FLAG_ESTOP,
};

static void fault_case(const void *row_arg)
{
    const motion_t *mo = row_arg;
    SKIP_LINE_IF_NO_MULTI(mo->line);
    for (size_t i = 0; i < sizeof blocking_flags / sizeof blocking_flags[0]; i++) {
        mock_t *m = mock_new();
        send_preset(m, mo);
        set_state(m, blocking_flags[i], DARAN_STATE_IDLE);
        ASSERT_ERROR(m, mo->line, "motor fault");
        /* a flag blocks even if the state still reads closed loop */
        set_state(m, blocking_flags[i], DARAN_STATE_CLOSED_LOOP);
        ASSERT_ERROR(m, mo->line, "motor fault");
    }
}

static void idle_case(const void *row_arg)
{
    const motion_t *mo = row_arg;
    SKIP_LINE_IF_NO_MULTI(mo->line);
    mock_t *m = mock_new();
    send_preset(m, mo);
    (void)ASSERT_SET(m, "w axis1.requested_state 1", DARAN_PROP_REQUESTED_STATE);
    ASSERT_ERROR(m, mo->line, "motor idle");
    /* a warning changes nothing: still idle */
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
    ASSERT_ERROR(m, mo->line, "motor idle");
}

static void nvm_warning_case(const void *row_arg)
{
    const motion_t *mo = row_arg;
    SKIP_LINE_IF_NO_MULTI(mo->line);
    mock_t *m = mock_new();
    send_preset(m, mo);
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
    ASSERT_MOVE(m, mo->line);
    /* whatever warning bits are set */
    send_preset(m, mo);
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = 0xFFFFFFFFu;
    ASSERT_MOVE(m, mo->line);
}

/* The other registers say why; only axis0.error decides (the port sets the
 * summary bits 6 and 9 when motor.error / controller.error are set). */
static void other_registers_case(const void *row_arg)
{
    const motion_t *mo = row_arg;
    SKIP_LINE_IF_NO_MULTI(mo->line);
    mock_t *m = mock_new();
    send_preset(m, mo);
    m->props[DARAN_PROP_MOTOR_ERROR].u32 = DARAN_MOTOR_ERROR_STALL;
    m->props[DARAN_PROP_CONTROLLER_ERROR].u32 = DARAN_CONTROLLER_ERROR_OVERSPEED;
    m->props[DARAN_PROP_FET_THERMISTOR_ERROR].u32 = DARAN_THERMISTOR_ERROR_OVERTEMP;
    m->props[DARAN_PROP_CAN_ERROR].u32 = 0xFFFFFFFFu;
    ASSERT_MOVE(m, mo->line);
    send_preset(m, mo);
    m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_MOTOR_FAILED;
    ASSERT_ERROR(m, mo->line, "motor fault");
}

static void test_estop_wins_over_every_other_flag(void)
{
    mock_t *m = mock_new();
    set_state(m, 0xFFFFFFFFu, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "t 1 10", "estop active");
}

static void test_commands_other_than_motion_work_in_estop(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    (void)ASSERT_SET(m, "w axis1.controller.config.pos_gain 5", DARAN_PROP_POS_GAIN);
    ASSERT_SILENT(m, "ms 1 1 2 3");
    ASSERT_ACTION(m, "ss 1", DARAN_ACTION_SAVE_CONFIG);
    ASSERT_ACTION(m, "se 1", DARAN_ACTION_ERASE_CONFIG);
    ASSERT_ACTION(m, "sz 1", DARAN_ACTION_SET_ZERO);
    ASSERT_ACTION(m, "u 1", DARAN_ACTION_FEED_WATCHDOG);
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 1"));
    mock_send_line(m, "e 1");
    ASSERT_REPLY(m, "axis: 16384\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 0\n");
    ASSERT_NO_EFFECT(m);
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.current_state"));
    (void)ASSERT_QUERY(m, "g 1");
    (void)ASSERT_QUERY(m, "i 1");
    ASSERT_ACTION(m, "sc 1", DARAN_ACTION_CLEAR_ERRORS);
}

static void test_after_estop_clear_keeps_the_drive_idle_until_closed_loop(void)
{
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, "t 1 10", "estop active");
    ASSERT_ACTION(m, "sc 1", DARAN_ACTION_CLEAR_ERRORS);
    ASSERT_ERROR(m, "t 1 10", "motor idle");
    daran_value_t v = ASSERT_SET(m, "w axis1.requested_state 8", DARAN_PROP_REQUESTED_STATE);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, v.u32);
    ASSERT_MOVE(m, "t 1 10");
}

static void test_closed_loop_request_is_refused_while_a_flag_is_set(void)
{
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, "w axis1.requested_state 8", "estop active");
    ASSERT_ERROR(m, "w axis0.requested_state 8", "estop active");
    /* idle may still be requested */
    (void)ASSERT_SET(m, "w axis1.requested_state 1", DARAN_PROP_REQUESTED_STATE);
    set_state(m, DARAN_FLAG_OVERTEMP, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "w axis1.requested_state 8", "motor fault");
    set_state(m, 1u << 5, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "w axis1.requested_state 8", "motor fault");
    /* a warning is not a flag */
    set_state(m, 0, DARAN_STATE_IDLE);
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
    (void)ASSERT_SET(m, "w axis1.requested_state 8", DARAN_PROP_REQUESTED_STATE);
}

static void test_axis_error_cleared_by_a_write_of_0_leaves_the_drive_idle(void)
{
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, "w axis1.error 1", "value out of range");
    ASSERT_ERROR(m, "t 1 10", "estop active");
    daran_value_t v = ASSERT_SET(m, "w axis1.error 0", DARAN_PROP_AXIS_ERROR);
    TEST_ASSERT_EQUAL_INT64(0, v.u32);
    /* D33: clearing does not close the loop */
    ASSERT_ERROR(m, "t 1 10", "motor idle");
    (void)ASSERT_SET(m, "w axis1.requested_state 8", DARAN_PROP_REQUESTED_STATE);
    ASSERT_MOVE(m, "t 1 10");
}

static void test_sc_clears_the_warnings_in_the_mock_and_the_drive_keeps_running(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.config_warnings"));
    ASSERT_MOVE(m, "t 1 10");
    ASSERT_ACTION(m, "sc 1", DARAN_ACTION_CLEAR_ERRORS);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.config_warnings"));
    ASSERT_MOVE(m, "t 1 10");
}

static void test_closed_loop_request_checks_its_value_first(void)
{
    mock_t *m = mock_new();
    set_state(m, DARAN_FLAG_ESTOP, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "w axis1.requested_state 9", "value out of range");
    ASSERT_ERROR(m, "w axis1.requested_state x", "invalid value");
}

/* ---- watchdog (D22) ---- */

static void test_accepted_motion_feeds_the_watchdog_after_its_move(void)
{
    mock_t *m = mock_new();
    for (size_t i = 0; i < N_MOTIONS; i++) {
        if (!DARAN_ENABLE_MULTI_MOTOR && mock_uses_multi(motions[i].line))
            continue;
        send_preset(m, &motions[i]);
        ASSERT_MOVE(m, motions[i].line); /* checks move then FEED_WATCHDOG */
    }
}

static void test_refused_motion_does_not_feed_the_watchdog(void)
{
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "t 1 10 0 -1", "value out of range");
    TEST_ASSERT_EQUAL_INT64(0, mock_count_action(m, DARAN_ACTION_FEED_WATCHDOG));
    set_state(m, 0, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "t 1 10", "motor idle");
    TEST_ASSERT_EQUAL_INT64(0, mock_count_action(m, DARAN_ACTION_FEED_WATCHDOG));
}

static void test_u_feeds_the_watchdog_in_any_state(void)
{
    mock_t *m = mock_new();
    ASSERT_ACTION(m, "u 1", DARAN_ACTION_FEED_WATCHDOG);
    ASSERT_ACTION(m, "u 0", DARAN_ACTION_FEED_WATCHDOG);
    set_state(m, DARAN_FLAG_WATCHDOG, DARAN_STATE_IDLE);
    ASSERT_ACTION(m, "u 1", DARAN_ACTION_FEED_WATCHDOG);
    ASSERT_SILENT(m, "u 2");
}

/* ---- presets (D16, D18) ---- */

static void test_a_start_consumes_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_MOVE(m, "mt 1 0");
    ASSERT_ERROR(m, "mt 1 0", "no preset");
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_MOVE(m, "mt 0 0");
    ASSERT_ERROR(m, "mp 1 0", "no preset");
    ASSERT_SILENT(m, "mt 0 0");
}

static void test_one_preset_serves_any_start_kind(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 1");
    const daran_move_t *mv = ASSERT_MOVE(m, "mc 1");
    TEST_ASSERT_EQUAL_INT64(DARAN_MOVE_TORQUE, mv->kind);
    TEST_ASSERT_TRUE(mv->torque_nm == 10.0f);
    ASSERT_ERROR(m, "mv 1", "no preset");
}

static void test_a_start_refused_by_state_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, "mt 1 0", "estop active");
    ASSERT_ERROR(m, "mt 0 0", "estop active");
    ASSERT_ACTION(m, "sc 1", DARAN_ACTION_CLEAR_ERRORS);
    ASSERT_ERROR(m, "mt 1 0", "motor idle");
    (void)ASSERT_SET(m, "w axis1.requested_state 8", DARAN_PROP_REQUESTED_STATE);
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
    TEST_ASSERT_TRUE(mv->rate == 5.0f);
}

static void test_a_start_refused_by_its_values_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 100 0.03 1"); /* peak 1,111 r/min: beyond vel_limit (10.5) */
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 100.0f);
    ASSERT_SILENT(m, "ms 1 10 0 -1");
    ASSERT_ERROR(m, "mt 1 0", "value out of range");
    mv = ASSERT_MOVE(m, "mp 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
    /* spec 10.1: duration 0 with a distance is infeasible, and keeps the preset too */
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
    ASSERT_SILENT(m, "ms 1 20 0 10");
    ASSERT_ERROR(m, "mq 1 0", "trajectory infeasible");
    mv = ASSERT_MOVE(m, "mt 1 0");
    TEST_ASSERT_TRUE(mv->pos_deg == 20.0f);
}

static void test_start_without_preset_answers_by_id(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const own[] = {"mt 1 0", "mq 1 1", "mp 1 0", "mv 1", "mc 1"};
    static const char *const all[] = {"mt 0 0", "mq 0 1", "mp 0 0", "mv 0", "mc 0"};
    for (size_t i = 0; i < 5; i++) {
        ASSERT_ERROR(m, own[i], "no preset");
        ASSERT_SILENT(m, all[i]);
    }
    /* whatever the state (D18) */
    set_state(m, DARAN_FLAG_ESTOP, DARAN_STATE_IDLE);
    for (size_t i = 0; i < 5; i++) {
        ASSERT_ERROR(m, own[i], "estop active");
        ASSERT_SILENT(m, all[i]);
    }
    set_state(m, 0, DARAN_STATE_IDLE);
    ASSERT_ERROR(m, "mt 1 0", "motor idle");
    ASSERT_SILENT(m, "mt 0 0");
}

static void test_preset_is_accepted_in_any_state(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    set_state(m, DARAN_FLAG_UNDERVOLTAGE, DARAN_STATE_IDLE);
    ASSERT_SILENT(m, "ms 1 10 0 5");
    set_state(m, 0, DARAN_STATE_CLOSED_LOOP);
    ASSERT_MOVE(m, "mt 1 0");
}

/* ---- queries ---- */

static void test_f_answers_position_and_velocity(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = -45.5f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = 12.25f;
    TEST_ASSERT_EQUAL_STRING("-45.5 12.25\n", ASSERT_QUERY(m, "f 1"));
    char want[64];
    mock_reply_line(want, sizeof want, "-45.5 12.25", true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "f 1 *87"));
}

static void test_g_answers_bus_voltage_and_current(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 23.5f;
    m->props[DARAN_PROP_IQ_MEASURED].f32 = -1.25f;
    TEST_ASSERT_EQUAL_STRING("23.5 -1.25\n", ASSERT_QUERY(m, "g 1"));
}

static void test_i_answers_three_decimal_integers(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_STRING("10203 7 1234567890123\n", ASSERT_QUERY(m, "i 1"));
    m->props[DARAN_PROP_FW_VERSION].u32 = UINT32_MAX;
    m->props[DARAN_PROP_HW_VERSION].u32 = 0;
    m->props[DARAN_PROP_SERIAL_NUMBER].u64 = UINT64_MAX;
    TEST_ASSERT_EQUAL_STRING("4294967295 0 18446744073709551615\n", ASSERT_QUERY(m, "i 1"));
    char want[80];
    mock_reply_line(want, sizeof want, "4294967295 0 18446744073709551615", true);
    char line[32];
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, mock_with_checksum(line, sizeof line, "i 1")));
}

/* ---- e: the seven error registers (spec 10.4, D24) ---- */

/* The registers `e` answers, in its order, with the names it writes. */
static const daran_prop_t e_registers[7] = {
    DARAN_PROP_AXIS_ERROR,       DARAN_PROP_MOTOR_ERROR,           DARAN_PROP_ENCODER_ERROR,
    DARAN_PROP_CONTROLLER_ERROR, DARAN_PROP_FET_THERMISTOR_ERROR,  DARAN_PROP_MOTOR_THERMISTOR_ERROR,
    DARAN_PROP_CAN_ERROR,
};
static const char *const e_names[7] = {"axis", "motor", "encoder", "controller",
                                       "fet_thermistor", "motor_thermistor", "can"};

typedef struct e_case {
    const char *why;
    uint32_t values[7]; /* in e_registers order */
} e_case_t;

static const e_case_t e_cases[] = {
    {"all_zero", {0, 0, 0, 0, 0, 0, 0}},
    {"estop", {DARAN_FLAG_ESTOP, 0, 0, 0, 0, 0, 0}},
    {"a_stall",
     {DARAN_FLAG_MOTOR_FAILED, DARAN_MOTOR_ERROR_STALL, 0, 0, 0, 0, 0}},
    {"an_overspeed",
     {DARAN_FLAG_CONTROLLER_FAILED, 0, 0, DARAN_CONTROLLER_ERROR_OVERSPEED, 0, 0, 0}},
    {"both_thermistors",
     {DARAN_FLAG_OVERTEMP, 0, 0, 0, DARAN_THERMISTOR_ERROR_OVERTEMP,
      DARAN_THERMISTOR_ERROR_OVERTEMP, 0}},
    {"watchdog_and_undervoltage", {DARAN_FLAG_WATCHDOG | DARAN_FLAG_UNDERVOLTAGE, 0, 0, 0, 0, 0, 0}},
    {"a_distinct_value_in_each", {1, 2, 3, 4, 5, 6, 7}},
    {"every_bit_everywhere",
     {0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu}},
    {"only_can", {0, 0, 0, 0, 0, 0, 1u << 31}},
};

/* The whole `e` reply for @p values, one "name: value" line each. */
static void e_reply(char *buf, size_t size, const uint32_t *values, bool checksum)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < 7; i++) {
        char payload[48];
        snprintf(payload, sizeof payload, "%s: %lu", e_names[i], (unsigned long)values[i]);
        mock_reply_line(buf + k, size - k, payload, checksum);
        k += strlen(buf + k);
    }
}

static void e_case_run(const void *row_arg)
{
    const e_case_t *c = row_arg;
    mock_t *m = mock_new();
    for (size_t i = 0; i < 7; i++)
        m->props[e_registers[i]].u32 = c->values[i];
    /* a warning never shows in e */
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = DARAN_WARNING_NVM_CORRUPT;
    char want[512], line[32];
    e_reply(want, sizeof want, c->values, false);
    static const char *const lines[] = {"e 1", "e 0", "e 1 ", "E 1"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        mock_send_line(m, lines[i]);
        mock_check(m->n_writes == 7, m, __FILE__, __LINE__, "expected 7 lines, got %zu", m->n_writes);
        ASSERT_REPLY(m, want);
        ASSERT_NO_EFFECT(m);
    }
    /* each line carries its own checksum when the request had one */
    e_reply(want, sizeof want, c->values, true);
    mock_send_line(m, mock_with_checksum(line, sizeof line, "e 1"));
    mock_check(m->n_writes == 7, m, __FILE__, __LINE__, "expected 7 lines, got %zu", m->n_writes);
    ASSERT_REPLY(m, want);
    ASSERT_NO_EFFECT(m);
}

static void test_e_lines_are_in_the_vendor_order_with_the_vendor_names(void)
{
    mock_t *m = mock_new();
    mock_send_line(m, "e 1");
    ASSERT_REPLY(m, "axis: 0\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 0\n");
    m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP | DARAN_FLAG_OVERTEMP;
    m->props[DARAN_PROP_MOTOR_THERMISTOR_ERROR].u32 = DARAN_THERMISTOR_ERROR_OVERTEMP;
    m->props[DARAN_PROP_CAN_ERROR].u32 = 4294967295u;
    mock_send_line(m, "e 1");
    ASSERT_REPLY(m, "axis: 278528\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 1\ncan: 4294967295\n");
    /* "e 1 *N": each line's N is the XOR of its payload and the space, worked
     * out by hand (Python: functools.reduce(operator.xor, map(ord, "axis: 278528 "))) */
    char line[16];
    mock_send_line(m, mock_with_checksum(line, sizeof line, "e 1"));
    ASSERT_REPLY(m, "axis: 278528 *59\nmotor: 0 *97\nencoder: 0 *126\ncontroller: 0 *22\n"
                    "fet_thermistor: 0 *55\nmotor_thermistor: 1 *42\ncan: 4294967295 *91\n");
}

/* A register that cannot be read makes the whole reply one error line when
 * the report would otherwise hide a fault: axis0.error itself, or a
 * register whose summary bit in axis0.error is set (D24). */
static void test_e_with_a_failing_register_read_answers_only_motor_fault(void)
{
    for (size_t i = 0; i < 6; i++) { /* can.error (last) has no summary bit */
        mock_t *m = mock_new();
        m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP | DARAN_FLAG_MOTOR_FAILED |
                                             DARAN_FLAG_ENCODER_FAILED |
                                             DARAN_FLAG_CONTROLLER_FAILED | DARAN_FLAG_OVERTEMP;
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, (int)e_registers[i]);
        mock_send_line(m, "e 1");
        mock_check(m->n_writes == 1, m, __FILE__, __LINE__, "register %s: one line, got %zu",
                   e_names[i], m->n_writes);
        ASSERT_REPLY(m, "error: motor fault\n");
        ASSERT_NO_EFFECT(m);
        /* checksummed, the error line carries one */
        char line[16], want[48];
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, (int)e_registers[i]);
        mock_send_line(m, mock_with_checksum(line, sizeof line, "e 1"));
        ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "error: motor fault", true));
        /* a HAL result that is not a protocol error is a motor fault too (D26) */
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_BAD_ARGUMENT, (int)e_registers[i]);
        mock_send_line(m, "e 1");
        ASSERT_REPLY(m, "error: motor fault\n");
        /* the next e answers in full */
        mock_send_line(m, "e 1");
        mock_check(m->n_writes == 7, m, __FILE__, __LINE__, "expected 7 lines");
    }
}

/* A port whose hardware lacks a register answers `motor fault` (or
 * `invalid property`) for it: with axis0.error's summary bit for it clear,
 * `e` reports it as 0 instead of refusing the whole report (D24). */
static void test_e_reads_a_failing_register_that_axis_error_vouches_for_as_0(void)
{
    for (size_t i = 1; i < 7; i++) {
        mock_t *m = mock_new();
        m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP;
        m->props[e_registers[i]].u32 = 5;
        mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_MOTOR_FAULT, (int)e_registers[i]);
        mock_send_line(m, "e 1");
        mock_check(m->n_writes == 7, m, __FILE__, __LINE__, "register %s: 7 lines, got %zu",
                   e_names[i], m->n_writes);
        char want[32];
        snprintf(want, sizeof want, "\n%s: 0\n", e_names[i]);
        mock_check(strstr(m->out, want) != NULL, m, __FILE__, __LINE__,
                   "register %s does not read 0", e_names[i]);
        ASSERT_NO_EFFECT(m);
    }
}

/* A port that left a register out of its table answers invalid property
 * for it: e writes that register as 0 (D24). */
static void test_e_reads_a_register_the_port_left_out_as_0(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_ENCODER_ERROR].u32 = 9;
    m->props[DARAN_PROP_CAN_ERROR].u32 = 3;
    mock_fail(m, MOCK_FAIL_GET, 1, DARAN_ERR_INVALID_PROPERTY, DARAN_PROP_ENCODER_ERROR);
    mock_send_line(m, "e 1");
    ASSERT_REPLY(m, "axis: 0\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 3\n");
}

static const char *const help_words[] = {"t",  "q",  "p",  "v",  "c",  "d",  "ms", "mt", "mq",
                                         "mp", "mv", "mc", "r",  "w",  "ss", "se", "sr", "sc",
                                         "sz", "st", "h",  "f",  "g",  "i",  "e",  "u",
#if DARAN_ENABLE_UPDATE
                                         "ub", "uw", "uv", "ug", "uy", "ua", "uq"
#endif
};
#define N_HELP (sizeof help_words / sizeof help_words[0])

static void check_help(mock_t *m, bool checksum)
{
    char *p = m->out;
    /* the words this build has, in table order */
    const char *words[N_HELP];
    size_t n = 0;
    for (size_t i = 0; i < N_HELP; i++)
        if (DARAN_ENABLE_MULTI_MOTOR || !mock_uses_multi(help_words[i]))
            words[n++] = help_words[i];
    mock_check(m->n_writes == n, m, __FILE__, __LINE__, "expected %zu help lines, got %zu", n,
               m->n_writes);
    mock_check(m->n_calls == 0, m, __FILE__, __LINE__, "h has no effect");
    for (size_t i = 0; i < n; i++) {
        char *end = strchr(p, '\n');
        TEST_ASSERT_NOT_NULL(end);
        *end = '\0';
        size_t wl = strlen(words[i]);
        mock_check(strncmp(p, words[i], wl) == 0 && (p[wl] == ' ' || p[wl] == '\0'), m,
                   __FILE__, __LINE__, "help line %zu is \"%s\", expected word \"%s\"", i, p,
                   words[i]);
        mock_check(strncmp(p, "error", 5) != 0, m, __FILE__, __LINE__, "help, not an error");
        if (checksum) {
            char *star = strrchr(p, '*');
            TEST_ASSERT_NOT_NULL(star);
            unsigned sum = (unsigned)strtoul(star + 1, NULL, 10);
            *star = '\0';
            mock_check(star > p && star[-1] == ' ' && mock_xor(p) == sum, m, __FILE__, __LINE__,
                       "help line %zu: bad reply checksum", i);
        }
        p = end + 1;
    }
    TEST_ASSERT_EQUAL_INT64('\0', *p);
}

static void test_h_answers_one_line_per_command_in_table_order(void)
{
    mock_t *m = mock_new();
#if !DARAN_ENABLE_HELP
    ASSERT_ERROR(m, "h 1", "unknown command");
    return;
#endif
    mock_send_line(m, "h 1");
    check_help(m, false);
    mock_send_line(m, "h 0");
    check_help(m, false);
}

static void test_h_lines_each_carry_a_checksum_when_requested(void)
{
    mock_t *m = mock_new();
    char line[32];
    mock_send_line(m, mock_with_checksum(line, sizeof line, "h 1"));
#if !DARAN_ENABLE_HELP
    char want[64];
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "error: unknown command", true));
    return;
#endif
    check_help(m, true);
}

static void test_queries_for_another_drive_are_silent(void)
{
    mock_t *m = mock_new();
    static const char *const lines[] = {"f 2", "g 2", "i 2", "e 2", "f 63",
#if DARAN_ENABLE_HELP
                                        "h 2",
#endif
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        ASSERT_SILENT(m, lines[i]);
    }
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    for (size_t i = 0; i < N_MOTIONS; i++) {
        void *st = (void *)(uintptr_t)&motions[i];
        mock_suite_add(&s, estop_case, st, "test_\"%s\"_in_estop_answers_estop_active",
                       motions[i].line);
        mock_suite_add(&s, fault_case, st, "test_\"%s\"_with_a_fault_flag_answers_motor_fault",
                       motions[i].line);
        mock_suite_add(&s, idle_case, st, "test_\"%s\"_while_idle_answers_motor_idle",
                       motions[i].line);
        mock_suite_add(&s, nvm_warning_case, st, "test_\"%s\"_runs_with_only_nvm_corrupt_set",
                       motions[i].line);
        mock_suite_add(&s, other_registers_case, st,
                       "test_\"%s\"_is_decided_by_axis0.error_alone", motions[i].line);
    }
    ADD(test_estop_wins_over_every_other_flag);
    ADD(test_commands_other_than_motion_work_in_estop);
    ADD(test_after_estop_clear_keeps_the_drive_idle_until_closed_loop);
    ADD(test_closed_loop_request_is_refused_while_a_flag_is_set);
    ADD(test_closed_loop_request_checks_its_value_first);
    ADD(test_axis_error_cleared_by_a_write_of_0_leaves_the_drive_idle);
    ADD(test_sc_clears_the_warnings_in_the_mock_and_the_drive_keeps_running);
    ADD(test_accepted_motion_feeds_the_watchdog_after_its_move);
    ADD(test_refused_motion_does_not_feed_the_watchdog);
    ADD(test_u_feeds_the_watchdog_in_any_state);
    ADD(test_a_start_consumes_the_preset);
    ADD(test_one_preset_serves_any_start_kind);
    ADD(test_a_start_refused_by_state_keeps_the_preset);
    ADD(test_a_start_refused_by_its_values_keeps_the_preset);
    ADD(test_start_without_preset_answers_by_id);
    ADD(test_preset_is_accepted_in_any_state);
    ADD(test_f_answers_position_and_velocity);
    ADD(test_g_answers_bus_voltage_and_current);
    ADD(test_i_answers_three_decimal_integers);
    for (size_t i = 0; i < sizeof e_cases / sizeof e_cases[0]; i++)
        mock_suite_add(&s, e_case_run, (void *)(uintptr_t)&e_cases[i],
                       "test_e_with_%s_answers_seven_register_lines", e_cases[i].why);
    ADD(test_e_lines_are_in_the_vendor_order_with_the_vendor_names);
    ADD(test_e_with_a_failing_register_read_answers_only_motor_fault);
    ADD(test_e_reads_a_failing_register_that_axis_error_vouches_for_as_0);
    ADD(test_e_reads_a_register_the_port_left_out_as_0);
    ADD(test_h_answers_one_line_per_command_in_table_order);
    ADD(test_h_lines_each_carry_a_checksum_when_requested);
    ADD(test_queries_for_another_drive_are_silent);
    mock_suite_run(&s);
    return UNITY_END();
}

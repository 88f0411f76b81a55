/* Unit tests of numbers inside request fields: the float grammar and its
 * correct rounding (spec section 5, D14), exact integers for motor ids,
 * modes and integer properties (D7, D12, D13). One case per table row. */
#include <math.h>
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

/* ---- floats ---- */

static const char *const floats_accepted[] = {
    "1", "-1.5", "+.5", "5.", "1e3", "1E-3", "0", "-0", "00012.50", "0.1", "1e-45", "-1e-45",
    "1e-50", "3.4028235e38", "-3.4028235e38", "1.17549435e-38", ".5e+2", "5.E1", "+7", "1e+3",
    "123456789012345678901234567890", "0.000000000000000000000000000000000000001",
    "16777217", "1.00000005960464477539062500000000001",
    "1234567890123456789012345678901234567890123456789012345678901234567890e-60",
    "1e38", "2e38", "-1e38", "0.00000000000000000000000000000000000001e76",
};

static void float_accepted_case(const void *row_arg)
{
    const char *text = row_arg;
    mock_t *m = mock_new();
    char line[256];
    float want = strtof(text, NULL);
    snprintf(line, sizeof line, "t 1 %s", text);
    if (strlen(line) > DARAN_LINE_MAX) {
        TEST_IGNORE(); /* a build with a shorter line cannot carry this number */
    }
    const daran_move_t *mv = ASSERT_MOVE(m, line);
    mock_check(memcmp(&mv->pos_deg, &want, sizeof want) == 0, m, __FILE__, __LINE__,
               "pos_deg: expected %a, got %a", (double)want, (double)mv->pos_deg);
    /* the same number as a property value */
    snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", text);
    if (strlen(line) > DARAN_LINE_MAX)
        return;
    daran_value_t v = ASSERT_SET(m, line, DARAN_PROP_INPUT_POS);
    mock_check(memcmp(&v.f32, &want, sizeof want) == 0, m, __FILE__, __LINE__,
               "value: expected %a, got %a", (double)want, (double)v.f32);
}

static const char *const floats_invalid[] = {
    ".", "e5", "5e", "1..2", "0x10", "nan", "inf", "1,5", "--1", "+", "-", "1e", "1e+", "1.2.3",
    "NaN", "INF", "infinity", "-inf", "1f", "+-1", "1e5.0", "e", "0b1", "1_000", ".e1", "-.e1",
    "1e--1", "abc", "1x", "0x1p3",
};

static void float_invalid_case(const void *row_arg)
{
    const char *text = row_arg;
    mock_t *m = mock_new();
    char line[64];
    snprintf(line, sizeof line, "t 1 %s", text);
    ASSERT_ERROR(m, line, "invalid value");
    snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", text);
    ASSERT_ERROR(m, line, "invalid value");
    snprintf(line, sizeof line, "d 1 0 0 0 0 %s", text);
    ASSERT_ERROR(m, line, "invalid value");
}

static const char *const floats_out_of_range[] = {
    "1e39", "-1e39", "3.5e38", "1e400", "3.4028236e38", "-3.4028236e38",
    "340282356779733661637539395458142568448", "1000000000000000000000000000000000000000",
};

static void float_out_of_range_case(const void *row_arg)
{
    const char *text = row_arg;
    mock_t *m = mock_new();
    char line[80];
    snprintf(line, sizeof line, "t 1 %s", text);
    ASSERT_ERROR(m, line, "value out of range");
    snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", text);
    ASSERT_ERROR(m, line, "value out of range");
    snprintf(line, sizeof line, "c 1 %s", text);
    ASSERT_ERROR(m, line, "value out of range");
}

static void test_every_float_field_of_every_command_uses_the_grammar(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    static const char *const lines[] = {
        "t 1 x",        "t 1 10 x",       "t 1 10 0 x",     "q 1 x",          "q 1 10 x",
        "q 1 10 5 x",   "p 1 x",          "p 1 10 x",       "p 1 10 0 x",     "v 1 x",
        "v 1 10 x",     "c 1 x",          "c 1 1 x",        "d 1 x 0 0 0 0",  "d 1 0 x 0 0 0",
        "d 1 0 0 x 0 0", "d 1 0 0 0 x 0", "d 1 0 0 0 0 x",  "ms 1 x 0 0",     "ms 1 0 x 0",
        "ms 1 0 0 x",
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        ASSERT_ERROR(m, lines[i], "invalid value");
    }
}

static void test_a_long_decimal_is_rounded_correctly(void)
{
    mock_t *m = mock_new();
    /* just above the halfway point between 1 and the next float32 */
    const daran_move_t *mv = ASSERT_MOVE(m, "t 1 1.000000059604644775390625000000000000000000000000001");
    TEST_ASSERT_TRUE(mv->pos_deg == strtof("1.000000059604644775390625000000000000000000000000001", NULL));
    TEST_ASSERT_TRUE(mv->pos_deg > 1.0f);
    /* exactly halfway: ties to even gives 1 */
    mv = ASSERT_MOVE(m, "t 1 1.000000059604644775390625");
    TEST_ASSERT_TRUE(mv->pos_deg == 1.0f);
}

/* ---- motor ids (D7) ---- */

typedef struct id_case {
    uint32_t drive_id;
    const char *text;
    int expect; /* 1: answered, 0: silent, -1: invalid motor */
} id_case_t;

static const id_case_t id_cases[] = {
    {1, "1", 1},     {1, "+1", 1},   {1, "1.0", 1},   {1, "01", 1},    {1, "1e0", 1},
    {1, "10e-1", 1}, {1, "001", 1},  {1, "1.", 1},    {1, "0.1e1", 1}, {1, "-0", 1},
    {1, "0", 1},     {1, "0.0", 1},  {1, "+0", 1},    {5, "5", 1},     {5, "05", 1},
    {5, "5e0", 1},   {5, "50e-1", 1}, {5, "5.0", 1},  {5, "+5", 1},    {1, "63", 0},
    {1, "2", 0},     {1, "6.3e1", 0}, {1, "1.5", -1}, {1, "-1", -1},   {1, "64", -1},
    {1, "x", -1},    {1, "1e2", -1}, {1, "99999999999999999999999", -1},
    {1, "0x1", -1},  {1, "1e-1", -1}, {1, ".", -1},   {1, "nan", -1},  {1, "-0.5", -1},
    {1, "63.5", -1}, {1, "1,0", -1}, {1, "255", -1},  {1, "256", -1},  {1, "1e39", -1},
    /* 2^64 + 1 and 2^64 must not wrap around to ids 1 and 0 */
    {1, "18446744073709551617", -1}, {1, "18446744073709551616", -1},
    {1, "18446744073709551617.0", -1}, {1, "1.8446744073709551617e19", -1},
};

static void id_case_run(const void *row_arg)
{
    const id_case_t *c = row_arg;
    mock_t *m = mock_new_id(c->drive_id);
    char line[64];
    snprintf(line, sizeof line, "f %s", c->text);
    if (c->expect == 1) {
        TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, line));
    }
    else if (c->expect == 0) {
        ASSERT_SILENT(m, line);
    }
    else {
        ASSERT_ERROR(m, line, "invalid motor");
    }
    /* the same id on a motion command */
    snprintf(line, sizeof line, "t %s 10", c->text);
    if (c->expect == 1) {
        ASSERT_MOVE(m, line);
    }
    else if (c->expect == 0) {
        ASSERT_SILENT(m, line);
    }
    else {
        ASSERT_ERROR(m, line, "invalid motor");
    }
}

static void test_axis_path_ids_follow_the_motor_id_rule(void)
{
    mock_t *m = mock_new_id(5);
    TEST_ASSERT_EQUAL_STRING("5\n", ASSERT_QUERY(m, "r axis5.config.can_node_id"));
    TEST_ASSERT_EQUAL_STRING("5\n", ASSERT_QUERY(m, "r axis05.config.can_node_id"));
    TEST_ASSERT_EQUAL_STRING("5\n", ASSERT_QUERY(m, "r axis0.config.can_node_id"));
    ASSERT_SILENT(m, "r axis6.config.can_node_id");
    ASSERT_ERROR(m, "r axis64.config.can_node_id", "invalid motor");
    ASSERT_ERROR(m, "r axis.config.can_node_id", "invalid motor");
    ASSERT_ERROR(m, "r axisx.config.can_node_id", "invalid motor");
    ASSERT_ERROR(m, "r axis-1.config.can_node_id", "invalid motor");
}

/* ---- modes (D12) ---- */

typedef struct mode_case {
    const char *line;
    const char *error; /* NULL: accepted with kind */
    daran_move_kind_t kind;
} mode_case_t;

static const mode_case_t mode_cases[] = {
    {"v 1 20 3 2.0", NULL, DARAN_MOVE_VELOCITY_RAMP},
    {"v 1 20 0 1.0", NULL, DARAN_MOVE_VELOCITY},
    {"v 1 20 3 1e0", NULL, DARAN_MOVE_VELOCITY},
    {"v 1 20 3 +2", NULL, DARAN_MOVE_VELOCITY_RAMP},
    {"v 1 20 -5 1", NULL, DARAN_MOVE_VELOCITY},
    {"c 1 5 3 6.0", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"c 1 5 3 2", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"c 1 5 3 60e-1", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"c 1 5 0 1", NULL, DARAN_MOVE_TORQUE},
    /* spec 10.1: a ramp of 0 is a ramp that holds the setpoint */
    {"v 1 20 0 2", NULL, DARAN_MOVE_VELOCITY_RAMP},
    {"v 1 20 -0 2.0", NULL, DARAN_MOVE_VELOCITY_RAMP},
    {"c 1 5 0 6", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"c 1 5 0 2", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"c 1 5 0.0 6.0", NULL, DARAN_MOVE_TORQUE_RAMP},
    {"v 1 20 0 1.5", "invalid value", 0},
    {"v 1 20 0 x", "invalid value", 0},
    {"v 1 20 x 7", "invalid value", 0},
    {"v 1 20 0 -1", "invalid mode", 0},
    {"v 1 20 0 3", "invalid mode", 0},
    {"v 1 20 0 0", "invalid mode", 0},
    {"v 1 20 0 6", "invalid mode", 0},
    {"v 1 20 0 99999999999999999999", "invalid mode", 0},
    {"v 1 20 3 18446744073709551617", "invalid mode", 0},
    {"c 1 5 3 18446744073709551622", "invalid mode", 0},
    {"v 1 20 0 7", "invalid mode", 0},
    {"v 1 20 3 8", "invalid mode", 0},
    {"v 1 20 3 255", "invalid mode", 0},
    {"v 1 20 3 258", "invalid mode", 0},
    {"c 1 5 3 8", "invalid mode", 0},
    {"c 1 5 3 262", "invalid mode", 0},
    {"v 1 20 -5 2", "value out of range", 0},
    {"v 1 20 -1e-45 2", "value out of range", 0},
    {"c 1 5 0 3", "invalid mode", 0},
    {"c 1 5 0 4", "invalid mode", 0},
    {"c 1 5 0 0", "invalid mode", 0},
    {"c 1 5 -1 6", "value out of range", 0},
    {"c 1 5 -1 2", "value out of range", 0},
    {"c 1 5 -1e-45 6", "value out of range", 0},
    {"c 1 5 0 6.5", "invalid value", 0},
    {"mq 1 2", "invalid mode", 0},
    {"mq 1 -1", "invalid mode", 0},
    {"mq 1 0.5", "invalid value", 0},
    {"mt 1 x", "invalid value", 0},
    {"mp 1 3", "invalid mode", 0},
};

static void mode_case_run(const void *row_arg)
{
    const mode_case_t *c = row_arg;
    SKIP_LINE_IF_NO_MULTI(c->line);
    mock_t *m = mock_new();
    if (c->error == NULL) {
        const daran_move_t *mv = ASSERT_MOVE(m, c->line);
        TEST_ASSERT_EQUAL_INT64(c->kind, mv->kind);
    } else {
        ASSERT_ERROR(m, c->line, c->error);
    }
}

static void test_start_mode_accepts_integral_floats(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    const daran_move_t *mv = ASSERT_MOVE(m, "mt 1 0.0");
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mv = ASSERT_MOVE(m, "mt 1 1.0");
    TEST_ASSERT_TRUE(mv->pos_deg == 20.0f);
    ASSERT_SILENT(m, "ms 1 10 0 5");
    mv = ASSERT_MOVE(m, "mt 1 1e0");
    TEST_ASSERT_TRUE(mv->pos_deg == 30.0f);
}

/* ---- integer and bool properties (D13) ---- */

typedef struct int_prop_case {
    const char *line;
    const char *error; /* NULL: accepted */
    daran_prop_t prop;
    uint32_t value;
} int_prop_case_t;

static const int_prop_case_t int_prop_cases[] = {
    {"w config.uart_baudrate 9600.0 1", NULL, DARAN_PROP_UART_BAUDRATE, 9600},
    {"w config.uart_baudrate 9.6e3", NULL, DARAN_PROP_UART_BAUDRATE, 9600},
    {"w config.uart_baudrate 96000e-1 0", NULL, DARAN_PROP_UART_BAUDRATE, 9600},
    {"w config.uart_baudrate +19200", NULL, DARAN_PROP_UART_BAUDRATE, 19200},
    {"w config.uart_baudrate 9600.5 1", "invalid value", 0, 0},
    {"w config.uart_baudrate x 1", "invalid value", 0, 0},
    {"w config.uart_baudrate -9600 1", "value out of range", 0, 0},
    {"w axis0.config.can_node_id 7.0", NULL, DARAN_PROP_CAN_NODE_ID, 7},
    {"w axis0.config.can_node_id -1", "value out of range", 0, 0},
    {"w axis0.config.can_node_id 1e20", "value out of range", 0, 0},
    {"w axis0.config.can_node_id 99999999999999999999999", "value out of range", 0, 0},
    {"w axis0.config.can_node_id 4294967297", "value out of range", 0, 0},
    {"w axis0.config.can_node_id abc", "invalid value", 0, 0},
    {"w axis0.config.can_node_id 18446744073709551621", "value out of range", 0, 0},
    {"w axis1.config.enable_watchdog 18446744073709551617", "value out of range", 0, 0},
    {"w axis1.config.enable_watchdog 18446744073709551616", "value out of range", 0, 0},
    {"w axis0.config.can_node_id 2.5", "invalid value", 0, 0},
    {"w axis1.config.enable_watchdog 1.0", NULL, DARAN_PROP_ENABLE_WATCHDOG, 1},
    {"w axis1.config.enable_watchdog -0", NULL, DARAN_PROP_ENABLE_WATCHDOG, 0},
    {"w axis1.config.enable_watchdog 0e5", NULL, DARAN_PROP_ENABLE_WATCHDOG, 0},
    {"w axis1.config.enable_watchdog 0.5", "invalid value", 0, 0},
    {"w axis1.config.enable_watchdog 2", "value out of range", 0, 0},
    {"w axis1.config.enable_watchdog -1", "value out of range", 0, 0},
    {"w axis1.config.enable_watchdog nan", "invalid value", 0, 0},
    {"w axis1.requested_state 8.0", NULL, DARAN_PROP_REQUESTED_STATE, 8},
    {"w axis1.requested_state 1e0", NULL, DARAN_PROP_REQUESTED_STATE, 1},
    {"w axis1.requested_state 8.5", "invalid value", 0, 0},
};

static void int_prop_case_run(const void *row_arg)
{
    const int_prop_case_t *c = row_arg;
    mock_t *m = mock_new();
    if (c->error == NULL) {
        daran_value_t v = ASSERT_SET(m, c->line, c->prop);
        TEST_ASSERT_EQUAL_INT64(c->value, v.u32);
    } else {
        ASSERT_ERROR(m, c->line, c->error);
    }
}

static void test_non_finite_values_are_never_accepted_for_properties(void)
{
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "w axis1.output_shaft.input_pos nan", "invalid value");
    ASSERT_ERROR(m, "w axis1.output_shaft.input_pos inf", "invalid value");
    ASSERT_ERROR(m, "w axis1.output_shaft.input_pos -inf", "invalid value");
    ASSERT_ERROR(m, "w axis1.output_shaft.input_pos 1e39", "value out of range");
    ASSERT_ERROR(m, "w axis1.fet_thermistor.config.temp_limit_upper 1e39", "value out of range");
}

/* Decimal strings of every shape the grammar allows, from a fixed seed; each
 * must reach the HAL bit-identical to a correct strtof. */
static uint32_t rnd_state = 12345u;
static uint32_t rnd(void)
{
    rnd_state = rnd_state * 1664525u + 1013904223u;
    return rnd_state >> 8;
}

static void random_decimal(char *buf, size_t size)
{
    size_t k = 0;
    uint32_t shape = rnd();
    if (shape & 1u)
        buf[k++] = (shape & 2u) ? '-' : '+';
    size_t int_digits = rnd() % 22, frac_digits = rnd() % 22;
    if (int_digits == 0 && frac_digits == 0)
        int_digits = 1;
    for (size_t i = 0; i < int_digits; i++)
        buf[k++] = (char)('0' + rnd() % 10);
    if (frac_digits > 0 || (shape & 4u)) {
        buf[k++] = '.';
        for (size_t i = 0; i < frac_digits; i++)
            buf[k++] = (char)('0' + rnd() % 10);
    }
    if (shape & 8u) {
        buf[k++] = (shape & 16u) ? 'e' : 'E';
        int ex = (int)(rnd() % 90) - 60;
        k += (size_t)snprintf(buf + k, size - k, (shape & 32u) ? "%+d" : "%d", ex);
    }
    buf[k] = '\0';
}

static void test_random_decimals_reach_the_hal_correctly_rounded(void)
{
    mock_t *m = mock_new();
    for (int i = 0; i < 4000; i++) {
        char num[80], line[128];
        random_decimal(num, sizeof num);
        float want = strtof(num, NULL);
        snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", num);
        if (!isfinite(want)) {
            ASSERT_ERROR(m, line, "value out of range");
            continue;
        }
        daran_value_t v = ASSERT_SET(m, line, DARAN_PROP_INPUT_POS);
        mock_check(memcmp(&v.f32, &want, sizeof want) == 0, m, __FILE__, __LINE__,
                   "\"%s\": expected %a, got %a", num, (double)want, (double)v.f32);
    }
}

/* Decimals at and around the exact midpoint between two neighbouring
 * float32 values, written with every digit (up to what a line holds), with
 * a far-out extra digit, and cut short: ties-to-even and sticky digits. */
static void test_midpoints_between_floats_round_to_nearest_even(void)
{
    mock_t *m = mock_new();
    uint32_t seed = 424242u;
    for (int i = 0; i < 1500; i++) {
        seed = seed * 1664525u + 1013904223u;
        /* exponents from 2^-30 to 2^40 keep the exact midpoint within a line */
        uint32_t bits = (seed & 0x007FFFFFu) | ((uint32_t)(97 + (seed >> 24) % 70) << 23);
        float lo;
        memcpy(&lo, &bits, sizeof lo);
        float hi = nextafterf(lo, INFINITY);
        double mid = ((double)lo + (double)hi) / 2.0;
        char exact[128], num[160], line[200];
        snprintf(exact, sizeof exact, "%.70f", mid);
        /* trim trailing zeros: the decimal is exact */
        size_t n = strlen(exact);
        while (n > 0 && exact[n - 1] == '0')
            n--;
        if (n > 0 && exact[n - 1] == '.')
            n--;
        if (n == 0 || n > 90)
            continue;
        exact[n] = '\0';
        const char *variants[3] = {"", "00000000000000001", NULL};
        for (int v = 0; v < 3; v++) {
            if (v < 2) {
                snprintf(num, sizeof num, "%s%s%s", exact, strchr(exact, '.') || v == 0 ? "" : ".",
                         variants[v]);
            } else {
                /* just below the midpoint: the last digit one less, then many nines */
                snprintf(num, sizeof num, "%s", exact);
                size_t k = strlen(num);
                if (num[k - 1] == '0' || !strchr(num, '.'))
                    continue;
                num[k - 1] = (char)(num[k - 1] - 1);
                strcat(num, "9999999999");
            }
            float want = strtof(num, NULL);
            snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", num);
            if (strlen(line) > DARAN_LINE_MAX)
                continue;
            daran_value_t got = ASSERT_SET(m, line, DARAN_PROP_INPUT_POS);
            mock_check(memcmp(&got.f32, &want, sizeof want) == 0, m, __FILE__, __LINE__,
                       "\"%s\": expected %a, got %a", num, (double)want, (double)got.f32);
        }
    }
}

/* Long random digit strings, up to the line limit. */
static void test_long_random_decimals_are_correctly_rounded(void)
{
    mock_t *m = mock_new();
    for (int i = 0; i < 1500; i++) {
        char num[100], line[140];
        size_t room = DARAN_LINE_MAX - 36 < 90 ? DARAN_LINE_MAX - 36 : 90;
        size_t len = 20 + rnd() % (room - 20), dot = rnd() % len, k = 0;
        for (size_t j = 0; j < len; j++) {
            if (j == dot)
                num[k++] = '.';
            num[k++] = (char)('0' + rnd() % 10);
        }
        num[k] = '\0';
        if (rnd() & 1u)
            snprintf(num + k, sizeof num - k, "e%d", (int)(rnd() % 80) - 60);
        float want = strtof(num, NULL);
        snprintf(line, sizeof line, "w axis1.output_shaft.input_pos %s", num);
        if (!isfinite(want)) {
            ASSERT_ERROR(m, line, "value out of range");
            continue;
        }
        daran_value_t got = ASSERT_SET(m, line, DARAN_PROP_INPUT_POS);
        mock_check(memcmp(&got.f32, &want, sizeof want) == 0, m, __FILE__, __LINE__,
                   "\"%s\": expected %a, got %a", num, (double)want, (double)got.f32);
    }
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    for (size_t i = 0; i < sizeof floats_accepted / sizeof floats_accepted[0]; i++)
        mock_suite_add(&s, float_accepted_case, (void *)(uintptr_t)floats_accepted[i],
                       "test_float_\"%.40s\"_is_accepted_correctly_rounded", floats_accepted[i]);
    for (size_t i = 0; i < sizeof floats_invalid / sizeof floats_invalid[0]; i++)
        mock_suite_add(&s, float_invalid_case, (void *)(uintptr_t)floats_invalid[i],
                       "test_float_\"%s\"_is_an_invalid_value", floats_invalid[i]);
    for (size_t i = 0; i < sizeof floats_out_of_range / sizeof floats_out_of_range[0]; i++)
        mock_suite_add(&s, float_out_of_range_case, (void *)(uintptr_t)floats_out_of_range[i],
                       "test_float_\"%.40s\"_is_out_of_range", floats_out_of_range[i]);
    ADD(test_every_float_field_of_every_command_uses_the_grammar);
    ADD(test_a_long_decimal_is_rounded_correctly);
    ADD(test_random_decimals_reach_the_hal_correctly_rounded);
    ADD(test_midpoints_between_floats_round_to_nearest_even);
    ADD(test_long_random_decimals_are_correctly_rounded);
    for (size_t i = 0; i < sizeof id_cases / sizeof id_cases[0]; i++)
        mock_suite_add(&s, id_case_run, (void *)(uintptr_t)&id_cases[i],
                       "test_motor_id_\"%s\"_on_drive_%u_is_%s", id_cases[i].text,
                       (unsigned)id_cases[i].drive_id,
                       id_cases[i].expect == 1   ? "answered"
                       : id_cases[i].expect == 0 ? "silent"
                                                 : "an_invalid_motor");
    ADD(test_axis_path_ids_follow_the_motor_id_rule);
    for (size_t i = 0; i < sizeof mode_cases / sizeof mode_cases[0]; i++)
        mock_suite_add(&s, mode_case_run, (void *)(uintptr_t)&mode_cases[i],
                       "test_mode_line_\"%s\"_gives_%s", mode_cases[i].line,
                       mode_cases[i].error ? mode_cases[i].error : "a_move");
    ADD(test_start_mode_accepts_integral_floats);
    for (size_t i = 0; i < sizeof int_prop_cases / sizeof int_prop_cases[0]; i++)
        mock_suite_add(&s, int_prop_case_run, (void *)(uintptr_t)&int_prop_cases[i],
                       "test_integer_write_\"%s\"_gives_%s", int_prop_cases[i].line,
                       int_prop_cases[i].error ? int_prop_cases[i].error : "a_set");
    ADD(test_non_finite_values_are_never_accepted_for_properties);
    mock_suite_run(&s);
    return UNITY_END();
}

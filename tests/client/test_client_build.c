/* daran_client's request builder: the contract's worked examples byte for
 * byte (checksums included), every command, float edges, the `r`/`w`
 * addressing, refusals, and every built line accepted by a real core. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "daran_ascii.h"
#include "daran_client.h"
#include "minimal_hal.h"
#include "unity.h"

static char line[DARAN_CLIENT_LINE_MAX];
static size_t line_len;

void setUp(void)
{
    memset(line, 0, sizeof line);
    line_len = 0;
}

void tearDown(void)
{
}

static daran_client_request_t motion(daran_client_command_t command, uint8_t id, uint8_t count,
                                     float a, float b, float c, float d, float e)
{
    daran_client_request_t request = {command, id, count, {a, b, c, d, e}, NULL,
                                      DARAN_CLIENT_SCOPE_AUTO, {DARAN_CLIENT_VALUE_F32, 0, 0, 0}};
    return request;
}

static daran_client_request_t simple(daran_client_command_t command, uint8_t id)
{
    return motion(command, id, 0, 0, 0, 0, 0, 0);
}

static daran_client_request_t read_of(const char *path, uint8_t id)
{
    daran_client_request_t request = simple(DARAN_CLIENT_CMD_R, id);
    request.path = path;
    return request;
}

static daran_client_request_t write_of(const char *path, daran_client_value_t value, uint8_t id)
{
    daran_client_request_t request = simple(DARAN_CLIENT_CMD_W, id);
    request.path = path;
    request.value = value;
    return request;
}

static daran_client_value_t f32_value(float v)
{
    daran_client_value_t value = {DARAN_CLIENT_VALUE_F32, v, 0, 0};
    return value;
}

static daran_client_value_t uint_value(uint64_t v)
{
    daran_client_value_t value = {DARAN_CLIENT_VALUE_UINT, 0, v, 0};
    return value;
}

static daran_client_value_t int_value(int64_t v)
{
    daran_client_value_t value = {DARAN_CLIENT_VALUE_INT, 0, 0, v};
    return value;
}

/* Build and compare with the expected line (its "\n" included). */
static void expect_line(daran_client_request_t request, bool checksum, const char *expected)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_client_build(&request, checksum, line, sizeof line, &line_len));
    TEST_ASSERT_EQUAL_UINT64(strlen(expected), line_len);
    TEST_ASSERT_EQUAL_MEMORY(expected, line, line_len);
}

static void test_the_contracts_worked_examples_are_built_byte_for_byte(void)
{
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 3, 10, 0, 25, 0, 0), false, "t 1 10 0 25\n");
    expect_line(motion(DARAN_CLIENT_CMD_Q, 2, 3, 160, 30, 10, 0, 0), false, "q 2 160 30 10\n");
    expect_line(motion(DARAN_CLIENT_CMD_P, 0, 3, 10, 5, 3, 0, 0), false, "p 0 10 5 3\n");
    expect_line(motion(DARAN_CLIENT_CMD_V, 0, 3, 20, 3, 1, 0, 0), false, "v 0 20 3 1\n");
    expect_line(motion(DARAN_CLIENT_CMD_V, 2, 3, 15, 3, 2, 0, 0), false, "v 2 15 3 2\n");
    expect_line(motion(DARAN_CLIENT_CMD_C, 0, 3, 5, 0, 1, 0, 0), false, "c 0 5 0 1\n");
    expect_line(motion(DARAN_CLIENT_CMD_C, 2, 3, 5, 3, 6, 0, 0), false, "c 2 5 3 6\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 12.5f, 0, 0, 0, 0), false, "t 1 12.5\n");
    expect_line(motion(DARAN_CLIENT_CMD_V, 1, 3, 12.5f, 2.5f, 2, 0, 0), false, "v 1 12.5 2.5 2\n");
    expect_line(motion(DARAN_CLIENT_CMD_C, 1, 3, 0.1f, 0, 1, 0, 0), false, "c 1 0.1 0 1\n");
    expect_line(motion(DARAN_CLIENT_CMD_C, 1, 3, 0.1f, 0.02f, 6, 0, 0), false, "c 1 0.1 0.02 6\n");
    expect_line(motion(DARAN_CLIENT_CMD_MS, 1, 3, 120, 5, 10, 0, 0), false, "ms 1 120 5 10\n");
    expect_line(motion(DARAN_CLIENT_CMD_MS, 2, 3, -100, 5, 10, 0, 0), false, "ms 2 -100 5 10\n");
    expect_line(motion(DARAN_CLIENT_CMD_MQ, 0, 1, 1, 0, 0, 0, 0), false, "mq 0 1\n");
    expect_line(read_of("output_shaft.pos_setpoint", 1), false,
                "r axis1.output_shaft.pos_setpoint\n");
    expect_line(read_of("motor.current_control.Iq_measured", 5), false,
                "r axis5.motor.current_control.Iq_measured\n");
    expect_line(read_of("config.can_node_id", 0), false, "r axis0.config.can_node_id\n");
    expect_line(read_of("config.uart_baudrate", 1), false, "r config.uart_baudrate 1\n");
    expect_line(write_of("output_shaft.pos_setpoint", f32_value(150), 1), false,
                "w axis1.output_shaft.pos_setpoint 150\n");
    expect_line(write_of("config.can_node_id", uint_value(5), 0), false,
                "w axis0.config.can_node_id 5\n");
    expect_line(write_of("config.uart_baudrate", uint_value(9600), 1), false,
                "w config.uart_baudrate 9600 1\n");
    expect_line(write_of("config.uart_baudrate", uint_value(115200), 1), false,
                "w config.uart_baudrate 115200 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_F, 1), false, "f 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_G, 1), false, "g 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_SS, 1), false, "ss 1\n");
    expect_line(motion(DARAN_CLIENT_CMD_D, 1, 5, 10, 0, 0.5f, 0.1f, 0.01f), false,
                "d 1 10 0 0.5 0.1 0.01\n");
}

static void test_the_contracts_checksummed_examples_carry_their_sums(void)
{
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 3, 10, 0, 25, 0, 0), true, "t 1 10 0 25 *83\n");
    expect_line(simple(DARAN_CLIENT_CMD_F, 1), true, "f 1 *87\n");
    expect_line(write_of("config.can_node_id", uint_value(5), 0), true,
                "w axis0.config.can_node_id 5 *58\n");
}

static void test_examples_written_with_trailing_zeros_come_out_shortest(void)
{
    /* the contract's `q 1 50.0 7.5 2.5` and `v 1 12.5 0.0 1` mean these */
    expect_line(motion(DARAN_CLIENT_CMD_Q, 1, 3, 50.0f, 7.5f, 2.5f, 0, 0), false,
                "q 1 50 7.5 2.5\n");
    expect_line(motion(DARAN_CLIENT_CMD_V, 1, 3, 12.5f, 0.0f, 1, 0, 0), false, "v 1 12.5 0 1\n");
}

static void test_every_other_command_has_its_form(void)
{
    expect_line(motion(DARAN_CLIENT_CMD_MT, 3, 1, 0, 0, 0, 0, 0), false, "mt 3 0\n");
    expect_line(motion(DARAN_CLIENT_CMD_MP, 3, 1, 1, 0, 0, 0, 0), false, "mp 3 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_MV, 0), false, "mv 0\n");
    expect_line(simple(DARAN_CLIENT_CMD_MC, 63), false, "mc 63\n");
    expect_line(simple(DARAN_CLIENT_CMD_SE, 1), false, "se 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_SR, 1), false, "sr 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_SC, 1), false, "sc 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_SZ, 1), false, "sz 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_ST, 1), false, "st 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_U, 1), false, "u 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_I, 1), false, "i 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_E, 1), false, "e 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_H, 1), false, "h 1\n");
    expect_line(simple(DARAN_CLIENT_CMD_H_PROPERTIES, 1), false, "h 1 properties\n");
    daran_client_request_t prefixed = simple(DARAN_CLIENT_CMD_H_PROPERTIES, 2);
    prefixed.path = "axis0.telemetry";
    expect_line(prefixed, false, "h 2 properties axis0.telemetry\n");
    /* optional values left off */
    expect_line(motion(DARAN_CLIENT_CMD_Q, 1, 2, 90, 30, 0, 0, 0), false, "q 1 90 30\n");
    expect_line(motion(DARAN_CLIENT_CMD_P, 1, 1, -90, 0, 0, 0, 0), false, "p 1 -90\n");
}

static void test_floats_are_printed_shortest_round_trip(void)
{
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 1.5e-7f, 0, 0, 0, 0), false, "t 1 1.5e-07\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 1e-5f, 0, 0, 0, 0), false, "t 1 0.00001\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 1e9f, 0, 0, 0, 0), false, "t 1 1.0e+09\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, -0.0f, 0, 0, 0, 0), false, "t 1 -0\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, FLT_MAX, 0, 0, 0, 0), false,
                "t 1 3.4028235e+38\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 1.4e-45f, 0, 0, 0, 0), false, "t 1 1.0e-45\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 0.1f + 0.2f, 0, 0, 0, 0), false,
                "t 1 0.3\n");
    expect_line(motion(DARAN_CLIENT_CMD_T, 1, 1, 16777217.0f, 0, 0, 0, 0), false,
                "t 1 16777216\n");
}

static void test_write_values_keep_their_type(void)
{
    expect_line(write_of("serial_number", uint_value(UINT64_MAX), 1), false,
                "w serial_number 18446744073709551615 1\n");
    expect_line(write_of("motor.config.pole_pairs", int_value(-7), 2), false,
                "w axis2.motor.config.pole_pairs -7\n");
    expect_line(write_of("motor.config.pole_pairs", int_value(INT64_MIN), 2), false,
                "w axis2.motor.config.pole_pairs -9223372036854775808\n");
    expect_line(write_of("output_shaft.input_pos", f32_value(-12.25f), 3), false,
                "w axis3.output_shaft.input_pos -12.25\n");
}

static void test_paths_are_addressed_by_their_scope(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_SCOPE_SYSTEM,
                          daran_client_path_scope("vbus_voltage", strlen("vbus_voltage")));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_SCOPE_AXIS,
                          daran_client_path_scope("error", strlen("error")));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_SCOPE_AXIS, daran_client_path_scope("vbus", 4));
    /* a path given in discovery's form: its axis number is the request's id */
    expect_line(read_of("axis0.output_shaft.vel_limit", 7), false,
                "r axis7.output_shaft.vel_limit\n");
    expect_line(read_of("axis12.error", 3), false, "r axis3.error\n");
    /* the caller's scope for a path the client's table does not know */
    daran_client_request_t own = read_of("port.fan_speed", 4);
    own.scope = DARAN_CLIENT_SCOPE_SYSTEM;
    expect_line(own, false, "r port.fan_speed 4\n");
    own.scope = DARAN_CLIENT_SCOPE_AUTO;
    expect_line(own, false, "r axis4.port.fan_speed\n");
    /* "axis" without a number and a dot is a path of its own */
    expect_line(read_of("axisx.y", 1), false, "r axis1.axisx.y\n");
}

static void test_impossible_requests_are_refused_without_a_line(void)
{
    daran_client_request_t cases[] = {
        motion(DARAN_CLIENT_CMD_T, 64, 1, 1, 0, 0, 0, 0),   /* id past 63 */
        motion(DARAN_CLIENT_CMD_T, 1, 0, 0, 0, 0, 0, 0),    /* t without pos */
        motion(DARAN_CLIENT_CMD_T, 1, 4, 1, 1, 1, 1, 0),    /* t with four */
        motion(DARAN_CLIENT_CMD_D, 1, 4, 1, 1, 1, 1, 0),    /* d takes five */
        simple(DARAN_CLIENT_CMD_COUNT, 1),                  /* not a command */
        read_of(NULL, 1),                                   /* r without path */
        read_of("", 1),
        read_of("a b", 1),
        read_of("axis1.", 1),
        read_of("a*b", 1),
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        line_len = 99;
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_BAD_ARGUMENT,
                                      daran_client_build(&cases[i], false, line, sizeof line,
                                                         &line_len),
                                      "case");
        TEST_ASSERT_EQUAL_UINT64(0, line_len);
    }
    daran_client_request_t nan_value = motion(DARAN_CLIENT_CMD_T, 1, 1, NAN, 0, 0, 0, 0);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_build(&nan_value, false, line, sizeof line, &line_len));
    daran_client_request_t inf_write =
        write_of("output_shaft.input_pos", f32_value(INFINITY), 1);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE,
                          daran_client_build(&inf_write, false, line, sizeof line, &line_len));
    daran_client_request_t ok = simple(DARAN_CLIENT_CMD_F, 1);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_build(NULL, false, line, sizeof line, &line_len));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_build(&ok, false, NULL, sizeof line, &line_len));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_build(&ok, false, line, sizeof line, NULL));
}

static void test_a_buffer_one_byte_short_gets_no_line(void)
{
    daran_client_request_t request = motion(DARAN_CLIENT_CMD_D, 1, 5, 10, 0, 0.5f, 0.1f, 0.01f);
    for (int checksum = 0; checksum < 2; checksum++) {
        size_t need = 0;
        TEST_ASSERT_EQUAL_INT(DARAN_OK,
                              daran_client_build(&request, checksum != 0, line, sizeof line, &need));
        for (size_t size = 0; size < need; size++) {
            char small[DARAN_CLIENT_LINE_MAX];
            memset(small, '#', sizeof small);
            size_t len = 99;
            TEST_ASSERT_EQUAL_INT(DARAN_ERR_LINE_TOO_LONG,
                                  daran_client_build(&request, checksum != 0, small, size, &len));
            TEST_ASSERT_EQUAL_UINT64(0, len);
            /* nothing written past the size given */
            for (size_t k = size; k < sizeof small; k++) {
                TEST_ASSERT_EQUAL_INT('#', small[k]);
            }
        }
    }
}

static void test_a_raw_line_is_sealed_with_its_checksum(void)
{
    char raw[32] = "v motor 100.5 2.3";
    size_t len = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_seal(raw, sizeof raw, strlen(raw), true, &len));
    /* the contract's own example of section 2 */
    TEST_ASSERT_EQUAL_STRING_LEN("v motor 100.5 2.3 *24\n", raw, len);
    TEST_ASSERT_EQUAL_UINT64(strlen("v motor 100.5 2.3 *24\n"), len);
    char plain[8] = "f 1";
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_seal(plain, sizeof plain, 3, false, &len));
    TEST_ASSERT_EQUAL_STRING_LEN("f 1\n", plain, len);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_LINE_TOO_LONG, daran_client_seal(plain, 3, 3, false, &len));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_client_seal(plain, 3, 4, false, &len));
}

/* What the core answered: the lines a request got. */
static char answered[512];
static size_t answered_len;

static void collect(void *ctx, const char *text, size_t len)
{
    (void)ctx;
    TEST_ASSERT_TRUE(answered_len + len < sizeof answered);
    memcpy(answered + answered_len, text, len);
    answered_len += len;
}

static const daran_hal_t collect_port = {MINIMAL_HAL_FUNCTIONS, .write = collect};

static void test_every_built_request_is_accepted_by_a_real_core(void)
{
    static minimal_drive_t hal;
    static daran_drive_t drive;
    minimal_drive_init(&hal);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive, &collect_port, &hal));
    daran_client_request_t requests[] = {
        motion(DARAN_CLIENT_CMD_T, 1, 3, 10, 0, 25, 0, 0),
        motion(DARAN_CLIENT_CMD_Q, 1, 3, 160, 30, 10, 0, 0),
        motion(DARAN_CLIENT_CMD_P, 1, 3, 10, 5, 3, 0, 0),
        motion(DARAN_CLIENT_CMD_V, 1, 3, 15, 3, 2, 0, 0),
        motion(DARAN_CLIENT_CMD_C, 1, 3, 0.1f, 0.02f, 6, 0, 0),
        motion(DARAN_CLIENT_CMD_D, 1, 5, 10, 0, 0.5f, 0.1f, 0.01f),
#if DARAN_ENABLE_MULTI_MOTOR
        motion(DARAN_CLIENT_CMD_MS, 1, 3, 120, 5, 10, 0, 0),
        motion(DARAN_CLIENT_CMD_MT, 1, 1, 0, 0, 0, 0, 0),
        motion(DARAN_CLIENT_CMD_MS, 1, 3, 10, 0, 0, 0, 0),
        motion(DARAN_CLIENT_CMD_MP, 1, 1, 1, 0, 0, 0, 0),
        motion(DARAN_CLIENT_CMD_MS, 1, 3, 10, 0, 1, 0, 0),
        simple(DARAN_CLIENT_CMD_MV, 1),
        motion(DARAN_CLIENT_CMD_MS, 1, 3, 1, 0, 1, 0, 0),
        simple(DARAN_CLIENT_CMD_MC, 1),
#endif
        write_of("output_shaft.input_pos", f32_value(1.5e-7f), 1),
        write_of("config.uart_baudrate", uint_value(9600), 1),
        write_of("config.extra_setting.stored_turns_counts", int_value(-7), 1),
        simple(DARAN_CLIENT_CMD_U, 1),
        simple(DARAN_CLIENT_CMD_SZ, 1),
        simple(DARAN_CLIENT_CMD_SS, 1),
    };
    /* a start consumes its preset: each pass sends the whole sequence */
    for (int checksum = 0; checksum < 2; checksum++) {
        for (size_t i = 0; i < sizeof requests / sizeof requests[0]; i++) {
            answered_len = 0;
            TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_build(&requests[i], checksum != 0, line,
                                                               sizeof line, &line_len));
            TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK,
                                          daran_process_line(&drive, line, line_len - 1u), line);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(0, answered_len, line); /* silent: accepted */
        }
    }
    /* and the queries are answered with values, not errors */
    daran_client_request_t queries[] = {
        read_of("output_shaft.input_pos", 1), read_of("config.uart_baudrate", 1),
        read_of("config.extra_setting.stored_turns_counts", 1), simple(DARAN_CLIENT_CMD_F, 1),
        simple(DARAN_CLIENT_CMD_I, 1),
    };
    for (size_t i = 0; i < sizeof queries / sizeof queries[0]; i++) {
        answered_len = 0;
        TEST_ASSERT_EQUAL_INT(DARAN_OK,
                              daran_client_build(&queries[i], true, line, sizeof line, &line_len));
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, daran_process_line(&drive, line, line_len - 1u),
                                      line);
        TEST_ASSERT_TRUE(answered_len > 0u);
        TEST_ASSERT_TRUE(answered[0] != 'e');
    }
}

/* The client's view of every row of the protocol table (daran_protocol.h):
 * its word, value counts, reply shape, class and retry rule, and a request
 * of it built with its fewest values is a line a core takes apart the same
 * way. The drive's view is held to the same rows in tests/unit/test_protocol.c. */
typedef struct protocol_row {
    const char *name;
    char word[3];
    int min_values;
    int max_values;
    daran_client_reply_shape_t reply;
    int moves; /* MOTION or START: the client's class is MOTION */
    int may_retry;
} protocol_row_t;
#define MOVES_MOTION 1
#define MOVES_START 1
#define MOVES_PRESET 0
#define MOVES_QUERY 0
#define MOVES_READ 0
#define MOVES_WRITE 0
#define MOVES_SYSTEM 0
#define MOVES_UPDATE 0
#define RETRIES_RETRY 1
#define RETRIES_ONCE 0
#define PROTOCOL_ROW(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, \
                     f4, f5, f6)                                                                    \
    {#name, {c0, c1, 0}, DARAN_PROTOCOL_MIN_VALUES(f1, f2, f3, f4, f5, f6),                         \
     DARAN_PROTOCOL_MAX_VALUES(f1, f2, f3, f4, f5, f6), DARAN_CLIENT_REPLY_##reply, MOVES_##cls,     \
     RETRIES_##retry},
static const protocol_row_t protocol_rows[] = {DARAN_PROTOCOL_COMMANDS(PROTOCOL_ROW)};
#undef PROTOCOL_ROW

static void test_every_row_of_the_protocol_table_is_a_command_of_the_client(void)
{
    TEST_ASSERT_EQUAL_UINT64(DARAN_CLIENT_CMD_COUNT, sizeof protocol_rows / sizeof protocol_rows[0]);
    for (int c = 0; c < (int)DARAN_CLIENT_CMD_COUNT; c++) {
        const protocol_row_t *row = &protocol_rows[c];
        daran_client_command_t command = (daran_client_command_t)c;
        TEST_ASSERT_EQUAL_STRING_MESSAGE(row->word, daran_client_command_word(command), row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->reply, daran_client_reply_shape(command), row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->may_retry, daran_client_may_retry(command), row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(row->moves,
                                      daran_client_command_class(command) == DARAN_CLIENT_CLASS_MOTION,
                                      row->name);
        /* the fewest and the most values build; one more does not */
        daran_client_request_t request = {.command = command, .id = 1, .path = "vel_limit",
                                          .value = {.kind = DARAN_CLIENT_VALUE_F32, .f32 = 1.0f}};
        for (unsigned k = 0; k < DARAN_CLIENT_VALUES_MAX; k++) {
            request.values[k] = 1.0f;
        }
        request.value_count = (uint8_t)row->min_values;
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, daran_client_build(&request, false, line, sizeof line,
                                                                   &line_len), row->name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, strncmp(line, row->word, strlen(row->word)), row->name);
        request.value_count = (uint8_t)row->max_values;
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, daran_client_build(&request, false, line, sizeof line,
                                                                   &line_len), row->name);
        if (row->max_values < (int)DARAN_CLIENT_VALUES_MAX) {
            request.value_count = (uint8_t)(row->max_values + 1);
            TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_ERR_BAD_ARGUMENT,
                                          daran_client_build(&request, false, line, sizeof line,
                                                             &line_len),
                                          row->name);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_row_of_the_protocol_table_is_a_command_of_the_client);
    RUN_TEST(test_the_contracts_worked_examples_are_built_byte_for_byte);
    RUN_TEST(test_the_contracts_checksummed_examples_carry_their_sums);
    RUN_TEST(test_examples_written_with_trailing_zeros_come_out_shortest);
    RUN_TEST(test_every_other_command_has_its_form);
    RUN_TEST(test_floats_are_printed_shortest_round_trip);
    RUN_TEST(test_write_values_keep_their_type);
    RUN_TEST(test_paths_are_addressed_by_their_scope);
    RUN_TEST(test_impossible_requests_are_refused_without_a_line);
    RUN_TEST(test_a_buffer_one_byte_short_gets_no_line);
    RUN_TEST(test_a_raw_line_is_sealed_with_its_checksum);
    RUN_TEST(test_every_built_request_is_accepted_by_a_real_core);
    return UNITY_END();
}

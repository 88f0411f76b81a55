/* The bridge (docs/can.md, "The bridge"): drive 1 is a gateway on an
 * in-memory CAN bus with drives 2 and 3 (port/minimal's HAL each). Lines go
 * into drive 1's ring, frames travel when the test moves them, so each test
 * sees the frames of contract section 5.2 byte for byte, the answers, the
 * timeouts and the failures. */
#include <stdio.h>
#include <string.h>

#include "daran_ascii.h"
#include "daran_properties.h"
#include "minimal_hal.h"
#include "unity.h"

#if DARAN_ENABLE_CAN_BRIDGE

#define DRIVES 3
#define LOG_FRAMES 64
#define OUT_MAX 2048

typedef struct node {
    minimal_drive_t hal;
    daran_drive_t drive;
    daran_can_t can;
    bool unplugged; /* receives nothing, sends nothing */
} node_t;

static node_t nodes[DRIVES];
static daran_can_bridge_t bridge;
static uint32_t clock_ms;
static bool bus_off;                 /* every send refused */
static daran_can_frame_t log_frames[LOG_FRAMES];
static size_t logged;
static char out[OUT_MAX];            /* what drive 1 answered on its ASCII link */
static size_t out_len;

static uint32_t now_ms(void *ctx)
{
    (void)ctx;
    return clock_ms;
}

/* The bus: a frame reaches every other node at once (no loopback). */
static bool bus_send(void *ctx, const daran_can_frame_t *frame)
{
    node_t *from = ctx;
    if (bus_off || from->unplugged) {
        return false;
    }
    if (logged < LOG_FRAMES) {
        log_frames[logged++] = *frame;
    }
    for (size_t i = 0; i < DRIVES; i++) {
        if (&nodes[i] != from && !nodes[i].unplugged) {
            (void)daran_can_receive(&nodes[i].can, frame);
        }
    }
    return true;
}

static void gateway_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    TEST_ASSERT_TRUE(out_len + len < OUT_MAX);
    memcpy(out + out_len, line, len);
    out_len += len;
    out[out_len] = '\0';
}

static void remote_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
    TEST_FAIL_MESSAGE("a remote drive answered on its ASCII link");
}

/* A node is its ports' context: its first member is the drive minimal's
 * functions take. */
static const daran_hal_t gateway_port = {MINIMAL_HAL_FUNCTIONS, .write = gateway_write,
                                         .now_ms = now_ms, .can_send = bus_send};
static const daran_hal_t remote_port = {MINIMAL_HAL_FUNCTIONS, .write = remote_write,
                                        .now_ms = now_ms, .can_send = bus_send};

/* Forget what drive 1 answered so far. */
static void clear_out(void)
{
    out_len = 0;
    out[0] = '\0';
}

void setUp(void)
{
    memset(nodes, 0, sizeof nodes);
    clock_ms = 1000;
    bus_off = false;
    logged = 0;
    clear_out();
    out[0] = '\0';
    for (size_t i = 0; i < DRIVES; i++) {
        node_t *n = &nodes[i];
        minimal_drive_init(&n->hal);
        n->hal.props[DARAN_PROP_CAN_NODE_ID].u32 = (uint32_t)(i + 1u);
        TEST_ASSERT_EQUAL_INT(DARAN_OK,
                              daran_init(&n->drive, i == 0 ? &gateway_port : &remote_port, n));
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&n->can, &n->drive));
    }
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_bridge_init(&bridge, &nodes[0].can));
}

void tearDown(void)
{
}

/* Let every node take its frames, a few rounds, the clock standing still. */
static void settle(void)
{
    for (int round = 0; round < 8; round++) {
        (void)daran_poll(&nodes[0].drive);
        for (size_t i = 0; i < DRIVES; i++) {
            (void)daran_can_poll(&nodes[i].can);
        }
    }
}

static void line(const char *text)
{
    TEST_ASSERT_EQUAL_UINT64(strlen(text), daran_rx_write(&nodes[0].drive, text, strlen(text)));
    TEST_ASSERT_TRUE(daran_rx_byte(&nodes[0].drive, '\n'));
    settle();
}

/* Frame k of the log as "iii bb bb bb bb bb bb bb bb". */
static const char *frame_text(size_t k)
{
    static char text[40];
    TEST_ASSERT_TRUE_MESSAGE(k < logged, "fewer frames on the bus than expected");
    const daran_can_frame_t *f = &log_frames[k];
    int n = snprintf(text, sizeof text, "%03x", (unsigned)f->id);
    for (size_t i = 0; i < 8; i++) {
        n += snprintf(text + n, sizeof text - (size_t)n, " %02x", f->data[i]);
    }
    return text;
}

static void expect_frames(const char *const *frames, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        TEST_ASSERT_EQUAL_STRING(frames[i], frame_text(i));
    }
    TEST_ASSERT_EQUAL_UINT64(count, logged);
}

static void test_motions_go_out_as_the_contracts_frames(void)
{
    struct {
        const char *line;
        const char *frame;
    } cases[] = {
        {"t 2 90 0 10", "059 00 00 b4 42 00 00 e8 03"},
        {"t 2 12.5", "059 00 00 48 41 00 00 00 00"},
        {"q 2 -150 10 5", "05a 00 00 16 c3 e8 03 f4 01"},
        {"q 2 160 30 0", "05a 00 00 20 43 b8 0b 00 00"},
        {"p 2 30 5 0.3", "05b 00 00 f0 41 f4 01 1e 00"},
        {"v 3 20 1.5 1", "07c 00 00 a0 41 96 00 01 00"},
        {"v 3 20 5 2", "07c 00 00 a0 41 f4 01 02 00"},
        {"v 3 20", "07c 00 00 a0 41 00 00 01 00"},      /* an omitted mode is 1 */
        {"v 3 20 1.5", "07c 00 00 a0 41 96 00 01 00"},
        {"c 3 1.5", "07d 00 00 c0 3f 00 00 01 00"},
        {"c 3 -0.8 0.5 2", "07d cd cc 4c bf 32 00 06 00"},
        {"v 2 400 1 1", "05c 00 00 c8 43 64 00 01 00"},
        {"ms 2 120 5 10", "04c 00 00 f0 42 f4 01 e8 03"},
        {"mq 2 1", "048 11 00 00 00 01 00 00 00"},
        {"ms 3 20 5 2", "06c 00 00 a0 41 f4 01 c8 00"},
        {"mv 3", "068 13 00 00 00 00 00 00 00"},
        {"w axis2.output_shaft.vel_limit 60", "05f 7c 94 00 00 00 00 70 42"},
        {"w config.uart_baudrate 9600 3", "07f 11 27 03 00 80 25 00 00"},
        {"w axis2.config.extra_setting.enable_reply_state 1", "05f ee 79 03 00 01 00 00 00"},
        {"ss 2", "048 01 00 00 00 00 00 00 00"},
        {"sz 3", "068 05 00 00 00 00 00 00 00"},
        {"u 2", "048 20 00 00 00 00 00 00 00"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        setUp();
        line(cases[i].line);
        TEST_ASSERT_EQUAL_STRING_MESSAGE("", out, cases[i].line);
        TEST_ASSERT_EQUAL_STRING_MESSAGE(cases[i].frame, frame_text(0), cases[i].line);
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(1, logged, cases[i].line);
    }
}

static void test_impedance_is_a_preset_and_its_start_at_the_same_node(void)
{
    line("d 2 10 0 0.5 0.1 0.01");
    static const char *const frames[] = {"04c 00 00 20 41 00 00 32 00",
                                         "048 15 00 00 00 0a 00 01 00"};
    expect_frames(frames, 2);
    daran_move_t move;
    TEST_ASSERT_TRUE(minimal_drive_take_move(&nodes[1].hal, &move));
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_IMPEDANCE, move.kind);
    TEST_ASSERT_TRUE(move.pos_deg == 10.0f && move.torque_nm == 0.5f);
    TEST_ASSERT_TRUE(move.kp == 0.1f && move.kd == 0.01f);
}

static void test_the_remote_drive_runs_what_the_gateway_sent(void)
{
    line("t 2 90 0 10");
    daran_move_t move;
    TEST_ASSERT_TRUE(minimal_drive_take_move(&nodes[1].hal, &move));
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_FILTERED_POSITION, move.kind);
    TEST_ASSERT_TRUE(move.pos_deg == 90.0f && move.rate == 10.0f);
    TEST_ASSERT_FALSE(minimal_drive_take_move(&nodes[0].hal, &move));
    TEST_ASSERT_FALSE(minimal_drive_take_move(&nodes[2].hal, &move));
}

static void test_queries_answer_the_remotes_values_as_it_prints_them(void)
{
    nodes[1].hal.props[DARAN_PROP_POS_ESTIMATE].f32 = -45.25f;
    nodes[1].hal.props[DARAN_PROP_VEL_ESTIMATE].f32 = 12.5f;
    line("f 2");
    TEST_ASSERT_EQUAL_STRING("-45.25 12.5\r\n", out);
    static const char *const frames[] = {"05e 77 94 00 00 00 00 00 00",
                                         "05e 77 94 00 00 00 00 35 c2",
                                         "05e 78 94 00 00 00 00 00 00",
                                         "05e 78 94 00 00 00 00 48 41"};
    expect_frames(frames, 4);
}

static void test_serial_number_and_identity(void)
{
    nodes[2].hal.props[DARAN_PROP_SERIAL_NUMBER_L].u32 = 0x12345679u;
    nodes[2].hal.props[DARAN_PROP_SERIAL_NUMBER_H].u32 = 42u;
    nodes[2].hal.props[DARAN_PROP_FW_VERSION].u32 = 12u;
    nodes[2].hal.props[DARAN_PROP_HW_VERSION].u32 = 2u;
    line("r serial_number 3");
    TEST_ASSERT_EQUAL_STRING("180694046329\r\n", out);
    clear_out();
    line("i 3");
    TEST_ASSERT_EQUAL_STRING("12 2 180694046329\r\n", out);
}

static void test_signed_and_integer_properties(void)
{
    nodes[2].hal.props[DARAN_PROP_MOTOR_DIRECTION].s32 = -1;
    line("r axis3.motor.config.direction");
    TEST_ASSERT_EQUAL_STRING("-1\r\n", out);
    TEST_ASSERT_EQUAL_STRING("07e 54 81 04 00 00 00 00 00", frame_text(0));
    clear_out();
    line("r config.uart_baudrate 3");
    TEST_ASSERT_EQUAL_STRING("115200\r\n", out);
}

static void test_e_prints_seven_lines(void)
{
    nodes[1].hal.props[DARAN_PROP_AXIS_ERROR].u32 = 16384u;
    line("e 2");
    TEST_ASSERT_EQUAL_STRING("axis: 16384\r\nmotor: 0\r\nencoder: 0\r\ncontroller: 0\r\n"
                             "fet_thermistor: 0\r\nmotor_thermistor: 0\r\ncan: 0\r\n",
                             out);
    TEST_ASSERT_EQUAL_UINT64(14, logged);
}

static void test_checksummed_query_gets_checksummed_answer(void)
{
    nodes[1].hal.props[DARAN_PROP_POS_ESTIMATE].f32 = 1.0f;
    nodes[1].hal.props[DARAN_PROP_VEL_ESTIMATE].f32 = 2.0f;
    line("f 2 *84"); /* 'f' ^ ' ' ^ '2' ^ ' ' = 84 */
    /* the answer's checksum: the XOR of "1 2 " */
    char want[32];
    snprintf(want, sizeof want, "1 2 *%u\r\n", (unsigned)('1' ^ ' ' ^ '2' ^ ' '));
    TEST_ASSERT_EQUAL_STRING(want, out);
}

static void test_q_with_omitted_values_reads_the_remotes_limits_first(void)
{
    nodes[1].hal.props[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = 30.0f;
    nodes[1].hal.props[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = 10.0f;
    line("q 2 50");
    static const char *const frames[] = {"05e 7e 94 00 00 00 00 00 00",
                                         "05e 7e 94 00 00 00 00 f0 41",
                                         "05e 7f 94 00 00 00 00 00 00",
                                         "05e 7f 94 00 00 00 00 20 41",
                                         "05a 00 00 48 42 b8 0b e8 03"};
    expect_frames(frames, 5);
    TEST_ASSERT_EQUAL_STRING("", out);
}

static void test_values_beyond_the_scaled_range_are_refused_before_anything_is_sent(void)
{
    line("v 2 20 400 2");
    TEST_ASSERT_EQUAL_STRING("error: value out of range\r\n", out);
    TEST_ASSERT_EQUAL_UINT64(0, logged);
    clear_out();
    line("t 2 10 500 0"); /* t's velocity is ignored by every drive: saturated (C3) */
    TEST_ASSERT_EQUAL_STRING("", out);
    TEST_ASSERT_EQUAL_STRING("059 00 00 20 41 ff 7f 00 00", frame_text(0));
}

/* A scaled field (value x 100 in an s16) takes exactly -327.68..327.67 on
 * the bridge: the ends go out, a hair past them and far past are refused,
 * and any value inside goes out (the writer's answer, not only its bytes). */
static void test_a_scaled_field_takes_its_whole_range_and_nothing_past_it(void)
{
    static const struct {
        const char *line;
        const char *frame; /* NULL: refused */
    } cases[] = {
        {"p 2 10 327.67 0", "05b 00 00 20 41 ff 7f 00 00"},
        {"p 2 10 -327.68 0", "05b 00 00 20 41 00 80 00 00"},
        {"p 2 10 1 -1", "05b 00 00 20 41 64 00 9c ff"},
        {"p 2 10 327.675 0", "05b 00 00 20 41 ff 7f 00 00"}, /* a float just below 327.675 */
        {"p 2 10 327.68 0", NULL},
        {"p 2 10 -327.69 0", NULL},
        {"p 2 10 0 1e30", NULL},
        {"p 2 10 0 -8388608", NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        clear_out();
        logged = 0;
        line(cases[i].line);
        if (cases[i].frame == NULL) {
            TEST_ASSERT_EQUAL_STRING_MESSAGE("error: value out of range\r\n", out, cases[i].line);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(0, logged, cases[i].line);
        } else {
            TEST_ASSERT_EQUAL_STRING_MESSAGE("", out, cases[i].line);
            TEST_ASSERT_EQUAL_STRING_MESSAGE(cases[i].frame, frame_text(0), cases[i].line);
        }
    }
}

/* Every property with a CAN address is read through the bridge at that
 * address (the property list's eighth column, can_index.h's runs). */
#define BRIDGE_AXIS_AXIS true
#define BRIDGE_AXIS_SYSTEM false
#define BRIDGE_ROW_(id, path, scope, type, access, range, unit, can) {path, BRIDGE_AXIS_##scope, can},
static const struct {
    const char *path;
    bool axis;
    unsigned address;
} bridge_rows[] = {DARAN_PROPERTY_LIST(BRIDGE_ROW_)};
#undef BRIDGE_ROW_
#undef BRIDGE_AXIS_AXIS
#undef BRIDGE_AXIS_SYSTEM

static void test_every_property_is_read_at_its_own_address(void)
{
    size_t read = 0;
    for (size_t i = 0; i < sizeof bridge_rows / sizeof bridge_rows[0]; i++) {
        if (bridge_rows[i].address == 0u) {
            continue; /* serial_number: its two halves (test_serial_number_and_identity) */
        }
        char text[128];
        (void)snprintf(text, sizeof text, bridge_rows[i].axis ? "r axis2.%s" : "r %s 2",
                       bridge_rows[i].path);
        char want[16];
        (void)snprintf(want, sizeof want, "05e %02x %02x", bridge_rows[i].address & 0xFFu,
                       bridge_rows[i].address >> 8);
        clear_out();
        logged = 0;
        line(text);
        TEST_ASSERT_TRUE_MESSAGE(logged >= 1u, text);
        TEST_ASSERT_EQUAL_STRING_LEN_MESSAGE(want, frame_text(0), strlen(want), text);
        read++;
    }
    TEST_ASSERT_GREATER_THAN_UINT64(150, read);
}

/* Lines at the edges of what the bridge decides by itself: a broadcast q
 * with every value goes out (only one missing a value needs the remote's
 * limits, C35), q with its velocity alone is checked before it reads the
 * remote's acceleration limit, and writes go out whether broadcast or of
 * another drive's node id (C34 keeps only a broadcast node-id write here). */
static void test_lines_at_the_edges_of_what_the_bridge_decides(void)
{
    static const struct {
        const char *line;
        const char *answer;
        const char *first_frame_id; /* NULL: nothing sent */
    } cases[] = {
        {"q 0 10 20 30", "", "01a"},
        {"q 2 10 400", "error: value out of range\r\n", NULL},
        {"q 2 10 20", "", "05e"},
        {"w axis0.output_shaft.vel_limit 100", "", "01f"},
        {"w axis2.config.can_node_id 5", "", "05f"},
        {"w axis0.config.can_node_id 5", "", NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        clear_out();
        logged = 0;
        line(cases[i].line);
        TEST_ASSERT_EQUAL_STRING_MESSAGE(cases[i].answer, out, cases[i].line);
        if (cases[i].first_frame_id == NULL) {
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(0, logged, cases[i].line);
        } else {
            TEST_ASSERT_EQUAL_STRING_LEN_MESSAGE(cases[i].first_frame_id, frame_text(0), 3,
                                                 cases[i].line);
        }
    }
}

static void test_checks_of_a_local_line_apply(void)
{
    static const struct {
        const char *line;
        const char *answer;
    } cases[] = {
        {"t 2", "error: invalid command format\r\n"},
        {"t 2 abc", "error: invalid value\r\n"},
        {"q 2 10 -1 1", "error: value out of range\r\n"},
        {"v 2 10 1 3", "error: invalid mode\r\n"},
        {"r axis2.no.such", "error: invalid property\r\n"},
        {"w axis2.output_shaft.pos_estimate 1", "error: read only property\r\n"},
        {"w axis2.config.can_node_id 0", "error: value out of range\r\n"},
        {"w serial_number 5 2", "error: read only property\r\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        setUp();
        line(cases[i].line);
        TEST_ASSERT_EQUAL_STRING_MESSAGE(cases[i].answer, out, cases[i].line);
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(0, logged, cases[i].line);
    }
}

static void test_a_drive_that_does_not_answer_is_no_reply_after_the_timeout(void)
{
    line("f 9");
    TEST_ASSERT_EQUAL_STRING("", out);
    TEST_ASSERT_TRUE(daran_can_bridge_busy(&bridge));
    clock_ms += DARAN_CAN_BRIDGE_TIMEOUT_MS - 1u;
    settle();
    TEST_ASSERT_EQUAL_STRING("", out);
    clock_ms += 1u;
    settle();
    TEST_ASSERT_EQUAL_STRING("error: no reply\r\n", out);
    TEST_ASSERT_FALSE(daran_can_bridge_busy(&bridge));
}

static void test_lines_wait_while_a_query_waits(void)
{
    nodes[1].unplugged = true;
    line("f 2");
    line("t 3 1");
    /* the second line waits in the ring: nothing went to drive 3 yet */
    TEST_ASSERT_EQUAL_UINT64(1, logged);
    clock_ms += DARAN_CAN_BRIDGE_TIMEOUT_MS;
    settle();
    TEST_ASSERT_EQUAL_STRING("error: no reply\r\n", out);
    TEST_ASSERT_EQUAL_STRING("079 00 00 80 3f 00 00 00 00", frame_text(1));
}

static void test_a_late_reply_is_discarded(void)
{
    nodes[1].hal.props[DARAN_PROP_POS_ESTIMATE].f32 = 7.0f;
    line("f 2");
    clear_out();
    /* a stray read reply from drive 2 arrives when nothing waits */
    daran_can_frame_t stray = {0x05E, 8, 0, {0x77, 0x94, 0, 0, 0, 0, 0x35, 0xc2}};
    (void)daran_can_receive(&nodes[0].can, &stray);
    settle();
    TEST_ASSERT_EQUAL_STRING("", out);
}

static void test_a_send_the_port_refuses_is_bus_error(void)
{
    bus_off = true;
    line("t 2 1");
    TEST_ASSERT_EQUAL_STRING("error: bus error\r\n", out);
    clear_out();
    line("f 2");
    TEST_ASSERT_EQUAL_STRING("error: bus error\r\n", out);
    TEST_ASSERT_FALSE(daran_can_bridge_busy(&bridge));
}

static void test_broadcast_goes_out_then_runs_here(void)
{
    line("ms 1 10 0 0");
    line("ms 2 20 0 0");
    logged = 0;
    line("mt 0 0");
    TEST_ASSERT_EQUAL_STRING("008 10 00 00 00 00 00 00 00", frame_text(0));
    daran_move_t move;
    TEST_ASSERT_TRUE(minimal_drive_take_move(&nodes[0].hal, &move));
    TEST_ASSERT_TRUE(move.pos_deg == 10.0f);
    TEST_ASSERT_TRUE(minimal_drive_take_move(&nodes[1].hal, &move));
    TEST_ASSERT_TRUE(move.pos_deg == 20.0f);
    TEST_ASSERT_EQUAL_STRING("", out);
}

static void test_broadcast_estop_that_cannot_be_sent_does_nothing_here(void)
{
    bus_off = true;
    line("st 0");
    TEST_ASSERT_EQUAL_STRING("error: bus error\r\n", out);
    TEST_ASSERT_EQUAL_UINT32(0, nodes[0].hal.props[DARAN_PROP_AXIS_ERROR].u32);
}

static void test_broadcast_node_id_write_stays_here(void)
{
    line("w axis0.config.can_node_id 6");
    TEST_ASSERT_EQUAL_UINT64(0, logged);
    TEST_ASSERT_EQUAL_UINT32(6, nodes[0].hal.props[DARAN_PROP_CAN_NODE_ID].u32);
    TEST_ASSERT_EQUAL_UINT32(2, nodes[1].hal.props[DARAN_PROP_CAN_NODE_ID].u32);
}

static void test_lines_without_a_can_form(void)
{
    line("q 0 10");
    TEST_ASSERT_EQUAL_STRING("error: not bridged\r\n", out);
    TEST_ASSERT_EQUAL_UINT64(0, logged);
    clear_out();
    line("r serial_number 0"); /* a broadcast read stays local */
    TEST_ASSERT_EQUAL_UINT64(0, logged);
}

static void test_h_for_another_id_is_the_gateways_without_traffic(void)
{
    line("h 2");
    TEST_ASSERT_NOT_NULL(strstr(out, "t id pos [vel] [bw]\r\n"));
    TEST_ASSERT_EQUAL_UINT64(0, logged);
    clear_out();
    line("h 2 properties axis0.output_shaft.pos_e");
    TEST_ASSERT_EQUAL_STRING("axis0.output_shaft.pos_estimate f32 ro deg\r\nend\r\n", out);
    clear_out();
    line("h 2 properties serial_number");
    TEST_ASSERT_EQUAL_STRING("serial_number_h u32 ro -\r\nserial_number_l u32 ro -\r\nend\r\n", out);
}

static void test_without_can_protocol_lines_for_others_stay_silent(void)
{
    nodes[0].hal.props[DARAN_PROP_CAN_PROTOCOL].u32 = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&nodes[0].can, &nodes[0].drive));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_bridge_init(&bridge, &nodes[0].can));
    line("t 2 10");
    line("f 2");
    TEST_ASSERT_EQUAL_STRING("", out);
    TEST_ASSERT_EQUAL_UINT64(0, logged);
}

static void test_bridge_init_arguments(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_bridge_init(NULL, &nodes[0].can));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_bridge_init(&bridge, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_motions_go_out_as_the_contracts_frames);
    RUN_TEST(test_impedance_is_a_preset_and_its_start_at_the_same_node);
    RUN_TEST(test_the_remote_drive_runs_what_the_gateway_sent);
    RUN_TEST(test_queries_answer_the_remotes_values_as_it_prints_them);
    RUN_TEST(test_serial_number_and_identity);
    RUN_TEST(test_signed_and_integer_properties);
    RUN_TEST(test_e_prints_seven_lines);
    RUN_TEST(test_checksummed_query_gets_checksummed_answer);
    RUN_TEST(test_q_with_omitted_values_reads_the_remotes_limits_first);
    RUN_TEST(test_values_beyond_the_scaled_range_are_refused_before_anything_is_sent);
    RUN_TEST(test_a_scaled_field_takes_its_whole_range_and_nothing_past_it);
    RUN_TEST(test_every_property_is_read_at_its_own_address);
    RUN_TEST(test_lines_at_the_edges_of_what_the_bridge_decides);
    RUN_TEST(test_checks_of_a_local_line_apply);
    RUN_TEST(test_a_drive_that_does_not_answer_is_no_reply_after_the_timeout);
    RUN_TEST(test_lines_wait_while_a_query_waits);
    RUN_TEST(test_a_late_reply_is_discarded);
    RUN_TEST(test_a_send_the_port_refuses_is_bus_error);
    RUN_TEST(test_broadcast_goes_out_then_runs_here);
    RUN_TEST(test_broadcast_estop_that_cannot_be_sent_does_nothing_here);
    RUN_TEST(test_broadcast_node_id_write_stays_here);
    RUN_TEST(test_lines_without_a_can_form);
    RUN_TEST(test_h_for_another_id_is_the_gateways_without_traffic);
    RUN_TEST(test_without_can_protocol_lines_for_others_stay_silent);
    RUN_TEST(test_bridge_init_arguments);
    return UNITY_END();
}

#else /* a core without the bridge: nothing to test */

void setUp(void)
{
}

void tearDown(void)
{
}

int main(void)
{
    return 77;
}

#endif

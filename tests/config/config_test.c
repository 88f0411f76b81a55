/* Behaviour of one build configuration of daran_config.h. The same program
 * is built for every configuration tools/ci.d/50-package.sh tries; it reads
 * the options from the headers it was compiled with, and the arguments
 * (line_max=64 crlf=1 ...) say what the build was asked for, so an option
 * that silently failed to reach the build is caught too. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_ascii.h"
#include "stub_hal.h"

#if DARAN_REPLY_CRLF
#define LE "\r\n"
#else
#define LE "\n"
#endif

#define OWN_ID 1u

/* Every reply of one request, concatenated. */
static char replies[4096];
static size_t replies_len;
static unsigned reply_count;
static daran_stub_t stub;
#define error_flags (stub.values[DARAN_PROP_AXIS_ERROR].u32)

static void on_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (replies_len + len < sizeof replies) {
        memcpy(replies + replies_len, line, len);
        replies_len += len;
        replies[replies_len] = '\0';
    }
    reply_count++;
}

static const daran_hal_t on_reply_port = {DARAN_STUB_HAL_FUNCTIONS, .write = on_reply};

static daran_drive_t drive;
static unsigned passed;
static unsigned failed;

static void check(int ok, const char *test, const char *detail)
{
    if (ok) {
        passed++;
    } else {
        failed++;
        printf("FAIL %s: %s\n", test, detail);
    }
}

static void reset(void)
{
    daran_stub_init(&stub, OWN_ID);
    if (daran_init(&drive, &on_reply_port, &stub) != DARAN_OK) {
        printf("daran_init failed\n");
        exit(1);
    }
}

static void clear_replies(void)
{
    replies[0] = '\0';
    replies_len = 0;
    reply_count = 0;
}

/* The byte path, one byte at a time, polled after each so that a ring
 * smaller than the line never overflows. */
static void send_bytes(const char *bytes, size_t len)
{
    clear_replies();
    for (size_t i = 0; i < len; i++) {
        (void)daran_rx_byte(&drive, (uint8_t)bytes[i]);
        (void)daran_poll(&drive);
    }
}

static void send(const char *line)
{
    char buf[512];
    size_t len = strlen(line);
    if (len + 1u > sizeof buf) {
        len = sizeof buf - 1u; /* the tests send short lines; never past buf */
    }
    memcpy(buf, line, len);
    buf[len] = '\n';
    send_bytes(buf, len + 1u);
}

static void expect_reply(const char *test, const char *line, const char *want)
{
    char detail[512];
    send(line);
    snprintf(detail, sizeof detail, "'%.100s' answered '%.200s', want '%.150s'", line, replies, want);
    check(strcmp(replies, want) == 0, test, detail);
}

/* "e 1" padded with blanks to @p len bytes before the '\n'. */
static char *padded_query(size_t len)
{
    static char line[DARAN_LINE_MAX + 2];
    memset(line, ' ', len);
    memcpy(line, "r axis1.error", 13);
    line[len] = '\n';
    return line;
}

/* Does this build leave property @p prop out (its options header's
 * DARAN_OMIT_PROPERTIES)? */
static int omitted(daran_prop_t prop)
{
#ifdef DARAN_OMIT_PROPERTIES
#define OMITTED_IS(id) || prop == DARAN_PROP_##id
    return 0 DARAN_OMIT_PROPERTIES(OMITTED_IS);
#undef OMITTED_IS
#else
    (void)prop;
    return 0;
#endif
}

/* The properties this build knows: the vendor's less the omitted ones (the
 * configurations here add no rows of their own). */
static unsigned kept_rows(void)
{
    unsigned rows = 0;
    for (unsigned p = 0; p < (unsigned)DARAN_PROP_COUNT; p++) {
        rows += omitted((daran_prop_t)p) ? 0u : 1u;
    }
    return rows;
}

static void test_config_matches_what_the_build_asked_for(int argc, char **argv)
{
    const struct {
        const char *name;
        long value;
    } options[] = {
        {"line_max", DARAN_LINE_MAX},         {"ring", DARAN_RX_RING_SIZE},
        {"reply_max", DARAN_REPLY_MAX},       {"crlf", DARAN_REPLY_CRLF},
        {"motor_id_max", DARAN_MOTOR_ID_MAX}, {"help", DARAN_ENABLE_HELP},
        {"multi", DARAN_ENABLE_MULTI_MOTOR},  {"discovery", DARAN_ENABLE_DISCOVERY},
        {"telemetry", DARAN_ENABLE_TELEMETRY}, {"port_commands", DARAN_ENABLE_PORT_COMMANDS},
        {"s_curve", DARAN_ENABLE_S_CURVE},    {"prop_rows", (long)kept_rows()},
    };
    for (int a = 1; a < argc; a++) {
        const char *eq = strchr(argv[a], '=');
        int known = 0;
        for (size_t i = 0; eq != NULL && i < sizeof options / sizeof options[0]; i++) {
            if (strlen(options[i].name) == (size_t)(eq - argv[a]) &&
                strncmp(argv[a], options[i].name, (size_t)(eq - argv[a])) == 0) {
                char detail[128];
                long want = strtol(eq + 1, NULL, 10);
                snprintf(detail, sizeof detail, "%s is %ld, the build asked for %ld",
                         options[i].name, options[i].value, want);
                check(options[i].value == want, "config_matches_what_the_build_asked_for",
                      detail);
                known = 1;
            }
        }
        check(known, "config_matches_what_the_build_asked_for", argv[a]);
    }
}

static void test_line_of_exactly_line_max_bytes_is_executed(void)
{
    reset();
    send_bytes(padded_query(DARAN_LINE_MAX), DARAN_LINE_MAX + 1u);
    check(strcmp(replies, "0" LE) == 0, "line_of_exactly_line_max_bytes_is_executed", replies);
    clear_replies();
    (void)daran_process_line(&drive, padded_query(DARAN_LINE_MAX), DARAN_LINE_MAX);
    check(strcmp(replies, "0" LE) == 0, "line_of_exactly_line_max_bytes_is_executed (process_line)",
          replies);
}

static void test_line_one_byte_over_line_max_is_too_long(void)
{
    reset();
    send_bytes(padded_query(DARAN_LINE_MAX + 1u), DARAN_LINE_MAX + 2u);
    check(strcmp(replies, "error: line too long" LE) == 0 && reply_count == 1u,
          "line_one_byte_over_line_max_is_too_long", replies);
    clear_replies();
    check(daran_process_line(&drive, padded_query(DARAN_LINE_MAX + 1u), DARAN_LINE_MAX + 1u) ==
                  DARAN_ERR_LINE_TOO_LONG &&
              strcmp(replies, "error: line too long" LE) == 0,
          "line_one_byte_over_line_max_is_too_long (process_line)", replies);
}

static void test_replies_end_with_the_configured_line_end(void)
{
    char line[32];
    char want[32];
    unsigned sum = 0;
    reset();
    expect_reply("replies_end_with_the_configured_line_end", "r axis1.error", "0" LE);
    expect_reply("errors_end_with_the_configured_line_end", "x 1", "error: unknown command" LE);
    /* The checksum goes before the line end: "0 *N" where N is the XOR of "0 ". */
    for (const char *c = "r axis1.error"; *c != '\0'; c++) {
        sum ^= (unsigned char)*c;
    }
    snprintf(line, sizeof line, "r axis1.error*%u", sum);
    snprintf(want, sizeof want, "0 *%u" LE, (unsigned)('0' ^ ' '));
    expect_reply("checksummed_reply_ends_with_the_configured_line_end", line, want);
}

static void test_help_follows_enable_help(void)
{
    reset();
    send("h 1");
#if DARAN_ENABLE_HELP
    check(strncmp(replies, "t id pos", 8) == 0 && reply_count > 10u, "help_lists_the_commands",
          replies);
#else
    check(strcmp(replies, "error: unknown command" LE) == 0, "h_is_unknown_without_help",
          replies);
#endif
}

static void test_discovery_follows_enable_discovery(void)
{
    reset();
    send("h 1");
#if DARAN_ENABLE_DISCOVERY
    check(strstr(replies, LE "h id [properties [prefix]]" LE) != NULL,
          "help_offers_discovery_with_discovery", replies);
    expect_reply("discovery_lists_a_property", "h 1 properties vbus",
                 "vbus_voltage f32 ro V" LE "end" LE);
#elif DARAN_ENABLE_HELP
    check(strstr(replies, LE "h id" LE) != NULL && strstr(replies, "properties") == NULL,
          "help_offers_no_discovery_without_discovery", replies);
    expect_reply("h_takes_no_argument_without_discovery", "h 1 properties",
                 "error: invalid command format" LE);
    expect_reply("h_takes_no_prefix_without_discovery", "h 1 properties vbus",
                 "error: invalid command format" LE);
#else
    expect_reply("h_properties_is_unknown_without_help", "h 1 properties",
                 "error: unknown command" LE);
#endif
}

static void test_telemetry_follows_enable_telemetry(void)
{
    reset();
    stub.values[DARAN_PROP_TELEMETRY_PERIOD].f32 = 0.01f;
    stub.values[DARAN_PROP_TELEMETRY_FIELDS].u32 = 1u << 7; /* axis0.error */
    stub.values[DARAN_PROP_AXIS_ERROR].u32 = 0x40u;
    clear_replies();
    daran_result_t result = daran_telemetry_tick(&drive, 0u, 1000u);
#if DARAN_ENABLE_TELEMETRY
    check(result == DARAN_OK && strncmp(replies, "@1 0 64 *", 9) == 0 && reply_count == 1u,
          "telemetry_tick_reports_with_telemetry", replies);
#else
    check(result == DARAN_OK && reply_count == 0u, "telemetry_tick_does_nothing_without_telemetry",
          replies);
#endif
    if (!omitted(DARAN_PROP_TELEMETRY_FIELDS)) {
        /* the widest field set fits the default reply either way */
        expect_reply("telemetry_fields_are_a_setting", "w axis1.telemetry.fields 511", "");
    } else {
        expect_reply("omitted_telemetry_fields_are_invalid", "w axis1.telemetry.fields 511",
                     "error: invalid property" LE);
    }
}

#if DARAN_ENABLE_PORT_COMMANDS
static daran_result_t port_ping(daran_drive_t *d, const daran_args_t *args, void *ctx)
{
    (void)args;
    (void)ctx;
    daran_reply(d, "pong", 4);
    return DARAN_OK;
}
#endif

static void test_port_commands_follow_enable_port_commands(void)
{
#if DARAN_ENABLE_PORT_COMMANDS
    static const daran_port_command_t table[] = {{"ping", 0, 0, DARAN_PORT_COMMAND_QUERY, port_ping, ""}};
#else
    /* a table the library would take, were it built with port commands */
    static const daran_port_command_t table[] = {{"ping", 0, 0, DARAN_PORT_COMMAND_QUERY, NULL, ""}};
#endif
    reset();
    check(daran_set_port_commands(&drive, table, 0) == DARAN_OK,
          "an_empty_port_command_table_is_always_taken", "refused");
    daran_result_t result = daran_set_port_commands(&drive, table, 1);
#if DARAN_ENABLE_PORT_COMMANDS
    check(result == DARAN_OK, "port_command_table_is_taken_with_port_commands", "refused");
    expect_reply("port_command_runs_with_port_commands", "ping 1", "pong" LE);
#else
    check(result == DARAN_ERR_BAD_ARGUMENT,
          "port_command_table_is_refused_without_port_commands", "taken");
    expect_reply("port_word_is_unknown_without_port_commands", "ping 1",
                 "error: unknown command" LE);
#endif
}

#if DARAN_ENABLE_MULTI_MOTOR
/* The stub HAL, with the last move and the reads of traj_mode recorded. */
static daran_move_t last_move;
static unsigned traj_mode_reads;

static daran_result_t recording_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    traj_mode_reads += prop == DARAN_PROP_TRAJ_MODE ? 1u : 0u;
    return daran_stub_hal.get(ctx, prop, out);
}

static daran_result_t recording_move(void *ctx, const daran_move_t *move)
{
    last_move = *move;
    return daran_stub_hal.move(ctx, move);
}

#endif

static void test_mq_plans_s_curves_with_enable_s_curve(void)
{
#if DARAN_ENABLE_MULTI_MOTOR
    static daran_hal_t hal;
    hal = daran_stub_hal;
    hal.get = recording_get;
    hal.move = recording_move;
    hal.write = on_reply;
    daran_stub_init(&stub, OWN_ID);
    if (daran_init(&drive, &hal, &stub) != DARAN_OK) {
        check(0, "mq_plans_s_curves_with_enable_s_curve", "daran_init failed");
        return;
    }
    /* 120 degrees in 5 s at 10 (r/min)/s: an S-curve cruises at exactly
     * 5 r/min (v = 2ad / (at + sqrt((at)^2 - 8ad)) = 14400 / 480 deg/s), a
     * trapezoid at 4.38 (sqrt((at)^2 - 4ad) = sqrt(61200)) */
    stub.values[DARAN_PROP_TRAJ_MODE].u32 = 2u;
    stub.values[DARAN_PROP_TRAJECTORY_DONE].u32 = 1u;
    traj_mode_reads = 0;
    expect_reply("ms_before_mq", "ms 1 120 5 10", "");
    expect_reply("mq_runs", "mq 1 0", "");
    char detail[96];
    snprintf(detail, sizeof detail, "cruise %.4f r/min, traj_mode read %u times",
             (double)last_move.vel_rpm, traj_mode_reads);
#if DARAN_ENABLE_S_CURVE
    check(stub.moves == 1u && last_move.vel_rpm == 5.0f && traj_mode_reads == 1u,
          "mq_plans_an_s_curve_when_traj_mode_is_2", detail);
#else
    check(stub.moves == 1u && last_move.vel_rpm > 4.38f && last_move.vel_rpm < 4.39f &&
              traj_mode_reads == 0u,
          "mq_plans_a_trapezoid_without_s_curve_and_never_reads_traj_mode", detail);
#endif
#endif
}

static void test_multi_motor_commands_follow_enable_multi_motor(void)
{
    static const char *const lines[] = {"ms 1 1 2 3", "mt 1 0", "mq 1 0", "mp 1 0", "mv 1", "mc 1"};
    reset();
#if DARAN_ENABLE_MULTI_MOTOR
    expect_reply("ms_stores_a_preset_silently", lines[0], "");
    expect_reply("mt_starts_the_preset_silently", "mt 1 0", "");
#else
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        expect_reply("multi_motor_commands_are_unknown_without_multi_motor", lines[i],
                     "error: unknown command" LE);
    }
#endif
}

static void test_motor_ids_stop_at_motor_id_max(void)
{
    char line[32];
    reset();
    if (DARAN_MOTOR_ID_MAX != OWN_ID) {
        snprintf(line, sizeof line, "e %d", DARAN_MOTOR_ID_MAX);
        expect_reply("highest_motor_id_is_another_drive", line, "");
    }
    snprintf(line, sizeof line, "e %d", DARAN_MOTOR_ID_MAX + 1);
    expect_reply("motor_id_above_the_maximum_is_invalid", line, "error: invalid motor" LE);
}

static void test_rx_ring_holds_exactly_its_size(void)
{
    unsigned refused = 0;
    reset();
    clear_replies();
    for (unsigned i = 0; i < DARAN_RX_RING_SIZE + 1u; i++) {
        if (!daran_rx_byte(&drive, (uint8_t)' ')) {
            refused++;
        }
    }
    check(refused == 1u && daran_rx_dropped(&drive) == 1u, "rx_ring_holds_exactly_its_size",
          "the byte after DARAN_RX_RING_SIZE was not the only one refused");
    (void)daran_poll(&drive);
    (void)daran_rx_byte(&drive, (uint8_t)'\n');
    (void)daran_poll(&drive);
    check(strcmp(replies, "error: line too long" LE) == 0, "overrun_line_is_answered_too_long",
          replies);
}

static void test_longest_replies_fit_reply_max(void)
{
    /* `e` with every register at all ones, each line with its checksum */
    static const char *const names[] = {"axis", "motor", "encoder", "controller",
                                        "fet_thermistor", "motor_thermistor", "can"};
    static const daran_prop_t registers[] = {
        DARAN_PROP_AXIS_ERROR,       DARAN_PROP_MOTOR_ERROR,          DARAN_PROP_ENCODER_ERROR,
        DARAN_PROP_CONTROLLER_ERROR, DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CAN_ERROR};
    char want[512];
    size_t n = 0;
    reset();
    for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
        char payload[64];
        unsigned sum = 0;
        stub.values[registers[i]].u32 = 0xFFFFFFFFu;
        snprintf(payload, sizeof payload, "%s: 4294967295 ", names[i]);
        for (const char *c = payload; *c != '\0'; c++) {
            sum ^= (unsigned char)*c;
        }
        n += (size_t)snprintf(want + n, sizeof want - n, "%s*%u" LE, payload, sum);
    }
    unsigned line_sum = 0;
    char line[16];
    for (const char *c = "e 1"; *c != '\0'; c++) {
        line_sum ^= (unsigned char)*c;
    }
    snprintf(line, sizeof line, "e 1*%u", line_sum);
    expect_reply("longest_e_reply_fits_reply_max", line, want);
#if DARAN_ENABLE_DISCOVERY && DARAN_LINE_MAX >= 80
    /* the longest discovery line */
    reset();
    send("h 1 properties axis0.config.extra_setting.enable_circular_setpoint_limit");
    check(strcmp(replies, "axis0.config.extra_setting.enable_circular_setpoint_limit bool rw - 0|1" LE
                          "end" LE) == 0,
          "longest_discovery_line_fits_reply_max", replies);
#endif
}

static void test_instance_holds_its_buffers(void)
{
    check(sizeof(daran_drive_t) >= DARAN_LINE_MAX + DARAN_REPLY_MAX + DARAN_RX_RING_SIZE,
          "instance_holds_its_buffers", "sizeof(daran_drive_t) too small");
}

int main(int argc, char **argv)
{
    test_config_matches_what_the_build_asked_for(argc, argv);
    test_line_of_exactly_line_max_bytes_is_executed();
    test_line_one_byte_over_line_max_is_too_long();
    test_replies_end_with_the_configured_line_end();
    test_help_follows_enable_help();
    test_discovery_follows_enable_discovery();
    test_telemetry_follows_enable_telemetry();
    test_port_commands_follow_enable_port_commands();
    test_mq_plans_s_curves_with_enable_s_curve();
    test_multi_motor_commands_follow_enable_multi_motor();
    test_motor_ids_stop_at_motor_id_max();
    test_rx_ring_holds_exactly_its_size();
    test_longest_replies_fit_reply_max();
    test_instance_holds_its_buffers();
    printf("config_test (LINE_MAX %d, RX_RING %d, REPLY_MAX %d, CRLF %d, ID_MAX %d, HELP %d, "
           "MULTI %d, DISCOVERY %d, TELEMETRY %d, PORT_COMMANDS %d, S_CURVE %d, %u properties, "
           "sizeof(daran_drive_t) %u): %u passed, %u failed\n",
           DARAN_LINE_MAX, DARAN_RX_RING_SIZE, DARAN_REPLY_MAX, DARAN_REPLY_CRLF,
           DARAN_MOTOR_ID_MAX, DARAN_ENABLE_HELP, DARAN_ENABLE_MULTI_MOTOR,
           DARAN_ENABLE_DISCOVERY, DARAN_ENABLE_TELEMETRY, DARAN_ENABLE_PORT_COMMANDS,
           DARAN_ENABLE_S_CURVE, kept_rows(), (unsigned)sizeof(daran_drive_t), passed, failed);
    return failed == 0u ? 0 : 1;
}

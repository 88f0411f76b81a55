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
    if (daran_init(&drive, &daran_stub_hal, &stub, on_reply, NULL) != DARAN_OK) {
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

static void test_config_matches_what_the_build_asked_for(int argc, char **argv)
{
    static const struct {
        const char *name;
        long value;
    } options[] = {
        {"line_max", DARAN_LINE_MAX},         {"ring", DARAN_RX_RING_SIZE},
        {"reply_max", DARAN_REPLY_MAX},       {"crlf", DARAN_REPLY_CRLF},
        {"motor_id_max", DARAN_MOTOR_ID_MAX}, {"help", DARAN_ENABLE_HELP},
        {"multi", DARAN_ENABLE_MULTI_MOTOR},
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
#if DARAN_ENABLE_HELP && DARAN_LINE_MAX >= 80
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
    test_multi_motor_commands_follow_enable_multi_motor();
    test_motor_ids_stop_at_motor_id_max();
    test_rx_ring_holds_exactly_its_size();
    test_longest_replies_fit_reply_max();
    test_instance_holds_its_buffers();
    printf("config_test (LINE_MAX %d, RX_RING %d, REPLY_MAX %d, CRLF %d, ID_MAX %d, HELP %d, "
           "MULTI %d, sizeof(daran_drive_t) %u): %u passed, %u failed\n",
           DARAN_LINE_MAX, DARAN_RX_RING_SIZE, DARAN_REPLY_MAX, DARAN_REPLY_CRLF,
           DARAN_MOTOR_ID_MAX, DARAN_ENABLE_HELP, DARAN_ENABLE_MULTI_MOTOR,
           (unsigned)sizeof(daran_drive_t), passed, failed);
    return failed == 0u ? 0 : 1;
}

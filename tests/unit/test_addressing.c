/* Unit tests of addressing (spec section 3, D10): own id, common id 0,
 * silence for other ids, the forward hook, reads with id 0, a node-id change,
 * and several drive instances in one process. */
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

/* One line per command word, written for a given id. */
static const char *const per_word[] = {
    "t %d 10 0 25", "q %d 160 30 10", "p %d 10 5 3", "v %d 20 3 1", "c %d 5 0 1",
    "d %d 10 0 0.5 0.1 0.01", "ms %d 1 2 3", "mt %d 0", "mq %d 1", "mp %d 0", "mv %d", "mc %d",
    "r config.uart_baudrate %d", "w config.uart_baudrate 9600 %d", "ss %d", "se %d", "sr %d",
    "sc %d", "sz %d", "st %d",
#if DARAN_ENABLE_HELP
    "h %d",
#endif
    "f %d", "g %d", "i %d", "e %d", "u %d",
    "r axis%d.output_shaft.input_pos", "w axis%d.output_shaft.input_pos 5",
};
#define N_WORDS (sizeof per_word / sizeof per_word[0])

static bool is_read(const char *fmt)
{
    return strchr("rfghie", fmt[0]) != NULL && fmt[1] == ' ';
}

static void other_id_case(const void *row_arg)
{
    const char *fmt = row_arg;
    SKIP_LINE_IF_NO_MULTI(fmt);
    mock_t *m = mock_new();
#if DARAN_ENABLE_MULTI_MOTOR
    ASSERT_SILENT(m, "ms 1 10 1 5"); /* a preset must not make a start for others act */
#endif
    char line[80];
    static const int others[] = {2, 63, 10};
    for (size_t i = 0; i < 3; i++) {
        snprintf(line, sizeof line, fmt, others[i]);
        ASSERT_SILENT(m, line);
        TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    }
    /* with a forward hook the same line is forwarded as received */
    mock_enable_forward(m);
    snprintf(line, sizeof line, fmt, 7);
    ASSERT_SILENT(m, line);
    TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
    TEST_ASSERT_EQUAL_INT64(7, m->fwd[0].id);
    TEST_ASSERT_EQUAL_STRING(line, m->fwd[0].line);
    /* and with a trailing space and a checksum field, still as received */
    char raw[96], cks[96];
    snprintf(raw, sizeof raw, fmt, 7);
    strcat(raw, " ");
    mock_with_checksum(cks, sizeof cks, raw);
    ASSERT_SILENT(m, cks);
    TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
    TEST_ASSERT_EQUAL_STRING(cks, m->fwd[0].line);
}

static void own_and_common_id_case(const void *row_arg)
{
    const char *fmt = row_arg;
    SKIP_LINE_IF_NO_MULTI(fmt);
    char line[80];
    for (int id = 1; id >= 0; id--) {
        mock_t *m = mock_new();
        mock_enable_forward(m);
        bool start = fmt[0] == 'm' && fmt[1] != 's';
        if (start) {
            /* mv/mc read the third value as a mode: give them ramp mode 2 */
            mock_send_line(m, fmt[1] == 'v' || fmt[1] == 'c' ? "ms 1 10 2 2" : "ms 1 10 2 10");
            ASSERT_REPLY(m, "");
        }
        snprintf(line, sizeof line, fmt, id);
        mock_send_line(m, line);
        mock_check(strstr(m->out, "error") == NULL, m, __FILE__, __LINE__,
                   "own or common id must be executed here");
        bool read = is_read(fmt);
        if (read) {
            mock_check(m->n_writes >= 1, m, __FILE__, __LINE__, "a read is answered");
            mock_check(m->n_calls == 0, m, __FILE__, __LINE__, "a read has no effect");
        } else {
            mock_check(m->out_len == 0, m, __FILE__, __LINE__, "silent on success");
            if (strncmp(fmt, "ms", 2) != 0) /* a preset makes no HAL call */
                mock_check(m->n_calls >= 1, m, __FILE__, __LINE__, "executed here");
        }
        /* own id is never forwarded; a broadcast is, unless it is a read (D10) */
        size_t want_fwd = (id == 0 && !read) ? 1 : 0;
        mock_check(m->n_fwd == want_fwd, m, __FILE__, __LINE__, "expected %zu forwards, got %zu",
                   want_fwd, m->n_fwd);
        if (want_fwd) {
            TEST_ASSERT_EQUAL_INT64(0, m->fwd[0].id);
            TEST_ASSERT_EQUAL_STRING(line, m->fwd[0].line);
        }
    }
}

static void test_broadcast_is_forwarded_even_when_refused_here(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    mock_enable_forward(m);
    ASSERT_ACTION(m, "st 1", DARAN_ACTION_ESTOP);
    ASSERT_ERROR(m, "t 0 10", "estop active");
    TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
    TEST_ASSERT_EQUAL_STRING("t 0 10", m->fwd[0].line);
    /* a broadcast start without a preset here: silent, still forwarded */
    m = mock_new();
    mock_enable_forward(m);
    ASSERT_SILENT(m, "mq 0 1");
    TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
    TEST_ASSERT_EQUAL_INT64(0, m->fwd[0].id);
    TEST_ASSERT_EQUAL_STRING("mq 0 1", m->fwd[0].line);
}

static void test_lines_refused_before_the_id_are_not_forwarded(void)
{
    mock_t *m = mock_new();
    mock_enable_forward(m);
    mock_send_line(m, "t 2 10 *1");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "t 2 10 *x", "invalid checksum");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "x 2", "unknown command");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "t 2 1\x01", "invalid character");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "t 99 10", "invalid motor");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
    ASSERT_ERROR(m, "x 0", "unknown command");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
}

static void test_forward_hook_can_be_removed(void)
{
    mock_t *m = mock_new();
    mock_enable_forward(m);
    ASSERT_SILENT(m, "t 2 10");
    TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
    m->hal.forward = NULL;
    ASSERT_SILENT(m, "t 2 10");
    TEST_ASSERT_EQUAL_INT64(0, m->n_fwd);
}

static void test_lines_for_another_drive_are_forwarded_unchecked(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    mock_enable_forward(m);
    static const char *const lines[] = {"t 2 abc", "t 2 1 2 3 4 5 6", "r axis2.nope",
                                        "w axis2.output_shaft.input_pos 1 2", "mq 2 7",
                                        "r nope 2"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        ASSERT_SILENT(m, lines[i]);
        TEST_ASSERT_EQUAL_INT64(1, m->n_fwd);
        TEST_ASSERT_EQUAL_INT64(2, m->fwd[0].id);
        TEST_ASSERT_EQUAL_STRING(lines[i], m->fwd[0].line);
    }
}

static void test_reads_with_id_0_are_answered(void)
{
    mock_t *m = mock_new_id(9);
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 3.5f;
    TEST_ASSERT_EQUAL_STRING("3.5 0\n", ASSERT_QUERY(m, "f 0"));
    TEST_ASSERT_EQUAL_STRING("24 0\n", ASSERT_QUERY(m, "g 0"));
    mock_send_line(m, "e 0");
    ASSERT_REPLY(m, "axis: 0\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 0\n");
    ASSERT_NO_EFFECT(m);
    TEST_ASSERT_EQUAL_STRING("10203 7 1234567890123\n", ASSERT_QUERY(m, "i 0"));
    TEST_ASSERT_EQUAL_STRING("9\n", ASSERT_QUERY(m, "r axis0.config.can_node_id"));
    TEST_ASSERT_EQUAL_STRING("24\n", ASSERT_QUERY(m, "r vbus_voltage 0"));
    TEST_ASSERT_EQUAL_STRING("24\n", ASSERT_QUERY(m, "r vbus_voltage"));
}

static void test_node_id_change_moves_the_drive_to_the_new_id(void)
{
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis0.config.can_node_id 5", DARAN_PROP_CAN_NODE_ID);
    TEST_ASSERT_EQUAL_INT64(5, v.u32);
    ASSERT_SILENT(m, "t 1 10");
    ASSERT_MOVE(m, "t 5 10");
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 5"));
    ASSERT_MOVE(m, "t 0 10");
}

static void test_every_id_from_1_to_63_addresses_a_drive_with_that_id(void)
{
    for (uint32_t id = 1; id <= DARAN_MOTOR_ID_MAX; id++) {
        mock_t *m = mock_new_id(id);
        char line[32];
        snprintf(line, sizeof line, "t %u 10", (unsigned)id);
        ASSERT_MOVE(m, line);
        snprintf(line, sizeof line, "t %u 10", (unsigned)(id % DARAN_MOTOR_ID_MAX + 1));
        ASSERT_SILENT(m, line);
    }
}

/* ---- several instances ---- */

static void test_two_drives_on_one_link_answer_only_their_own_lines(void)
{
    mock_t *a = mock_new_slot(0, 1), *b = mock_new_slot(1, 2);
    a->props[DARAN_PROP_POS_ESTIMATE].f32 = 11.0f;
    b->props[DARAN_PROP_POS_ESTIMATE].f32 = 22.0f;
    mock_clear(a);
    mock_clear(b);
    const char *stream = "f 1\nf 2\nt 2 7\nt 1 3\ne 0\nx 3\n";
    /* the same bytes reach both, one at a time, each polled in turn */
    for (const char *c = stream; *c; c++) {
        TEST_ASSERT_TRUE(daran_rx_byte(&a->drive, (uint8_t)*c));
        (void)daran_poll(&a->drive);
        TEST_ASSERT_TRUE(daran_rx_byte(&b->drive, (uint8_t)*c));
        (void)daran_poll(&b->drive);
    }
    ASSERT_REPLY(a, "11 0\naxis: 0\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 0\nerror: unknown command\n");
    ASSERT_REPLY(b, "22 0\naxis: 0\nmotor: 0\nencoder: 0\ncontroller: 0\nfet_thermistor: 0\n"
                    "motor_thermistor: 0\ncan: 0\nerror: unknown command\n");
    TEST_ASSERT_EQUAL_INT64(1, mock_count(a, MOCK_CALL_MOVE));
    TEST_ASSERT_TRUE(a->calls[0].move.pos_deg == 3.0f);
    TEST_ASSERT_EQUAL_INT64(1, mock_count(b, MOCK_CALL_MOVE));
    TEST_ASSERT_TRUE(b->calls[0].move.pos_deg == 7.0f);
}

static void test_interleaved_bytes_of_different_streams_do_not_mix(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *a = mock_new_slot(0, 1), *b = mock_new_slot(1, 2), *c = mock_new_slot(2, 3);
    a->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 12.0f;
    b->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 48.0f;
    mock_clear(a);
    mock_clear(b);
    mock_clear(c);
    const char *sa = "g 1\nms 1 10 0 5\nmt 1 0\n";
    const char *sb = "g 2\nt 2 1 \n";
    const char *sc = "st 3\nt 3 1\n";
    size_t la = strlen(sa), lb = strlen(sb), lc = strlen(sc);
    for (size_t i = 0; i < la || i < lb || i < lc; i++) {
        if (i < la)
            (void)daran_rx_byte(&a->drive, (uint8_t)sa[i]);
        if (i < lb)
            (void)daran_rx_byte(&b->drive, (uint8_t)sb[i]);
        if (i < lc)
            (void)daran_rx_byte(&c->drive, (uint8_t)sc[i]);
        if (i % 3 == 0)
            (void)daran_poll(&b->drive);
        if (i % 2 == 0)
            (void)daran_poll(&a->drive);
    }
    (void)daran_poll(&a->drive);
    (void)daran_poll(&b->drive);
    (void)daran_poll(&c->drive);
    ASSERT_REPLY(a, "12 0\n");
    ASSERT_REPLY(b, "48 0\n");
    ASSERT_REPLY(c, "error: estop active\n");
    TEST_ASSERT_EQUAL_INT64(1, mock_count(a, MOCK_CALL_MOVE));
    TEST_ASSERT_TRUE(a->calls[0].move.pos_deg == 10.0f);
    TEST_ASSERT_EQUAL_INT64(1, mock_count(b, MOCK_CALL_MOVE));
    TEST_ASSERT_EQUAL_INT64(0, mock_count(c, MOCK_CALL_MOVE));
    /* the estop of drive 3 did not reach the others */
    ASSERT_MOVE(a, "t 1 2");
    ASSERT_MOVE(b, "t 2 2");
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    for (size_t i = 0; i < N_WORDS; i++)
        mock_suite_add(&s, other_id_case, (void *)(uintptr_t)per_word[i],
                       "test_\"%s\"_for_another_id_is_silent_and_forwarded", per_word[i]);
    for (size_t i = 0; i < N_WORDS; i++)
        mock_suite_add(&s, own_and_common_id_case, (void *)(uintptr_t)per_word[i],
                       "test_\"%s\"_for_own_and_common_id_is_executed", per_word[i]);
    ADD(test_broadcast_is_forwarded_even_when_refused_here);
    ADD(test_lines_refused_before_the_id_are_not_forwarded);
    ADD(test_forward_hook_can_be_removed);
    ADD(test_lines_for_another_drive_are_forwarded_unchecked);
    ADD(test_reads_with_id_0_are_answered);
    ADD(test_node_id_change_moves_the_drive_to_the_new_id);
    ADD(test_every_id_from_1_to_63_addresses_a_drive_with_that_id);
    ADD(test_two_drives_on_one_link_answer_only_their_own_lines);
    ADD(test_interleaved_bytes_of_different_streams_do_not_mix);
    mock_suite_run(&s);
    return UNITY_END();
}

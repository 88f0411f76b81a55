/* Unit tests of line framing and the receive ring: line ends, blank lines,
 * the 128-byte limit (D1, D2), invalid bytes, arbitrary chunking of the
 * byte input, ring overrun (D3) and daran_process_line(). */
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

static void make_padded(char *buf, const char *head, size_t total, const char *tail)
{
    size_t h = strlen(head), t = strlen(tail);
    TEST_ASSERT_TRUE(h + t <= total);
    memcpy(buf, head, h);
    memset(buf + h, ' ', total - h - t);
    memcpy(buf + total - t, tail, t);
    buf[total] = '\0';
}

static void test_lf_ends_a_line(void)
{
    mock_t *m = mock_new();
    mock_send_raw(m, "f 1\n");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_crlf_ends_a_line(void)
{
    mock_t *m = mock_new();
    mock_send_raw(m, "f 1\r\n");
    ASSERT_REPLY(m, "0 0\n");
    mock_send_raw(m, "t 1 10 0 25\r\n");
    ASSERT_REPLY(m, "");
    TEST_ASSERT_EQUAL_INT64(1, mock_count(m, MOCK_CALL_MOVE));
}

static void test_cr_anywhere_is_whitespace(void)
{
    mock_t *m = mock_new();
    mock_send_raw(m, "f\r1\n");
    ASSERT_REPLY(m, "0 0\n");
    mock_send_raw(m, "\rf 1\r\r\n");
    ASSERT_REPLY(m, "0 0\n");
    const daran_move_t *mv = ASSERT_MOVE(m, "t\r1\r10\r0\r25\r");
    ASSERT_MOVE_EQUALS(m, mv, {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 10, 0, 0, 25, 0, 0});
}

static void test_blank_lines_get_no_reply(void)
{
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "");
    ASSERT_SILENT(m, "   ");
    ASSERT_SILENT(m, "\t \t");
    ASSERT_SILENT(m, "\r");
    ASSERT_SILENT(m, " \r \t\r");
}

static void test_poll_counts_blank_lines_too(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT64(8, daran_rx_write(&m->drive, "\n \nf 1\nf", 8));
    TEST_ASSERT_EQUAL_INT64(3, daran_poll(&m->drive));
    ASSERT_REPLY(m, "0 0\n");
    TEST_ASSERT_EQUAL_INT64(0, daran_poll(&m->drive));
    TEST_ASSERT_EQUAL_INT64(3, daran_rx_write(&m->drive, " 1\n", 3));
    TEST_ASSERT_EQUAL_INT64(1, daran_poll(&m->drive));
    ASSERT_REPLY(m, "0 0\n");
}

static void test_line_of_exactly_128_bytes_is_accepted(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX + 1];
    make_padded(buf, "f 1", DARAN_LINE_MAX, "");
    mock_send_line(m, buf);
    ASSERT_REPLY(m, "0 0\n");
    /* the \r counts toward the limit (D1) */
    make_padded(buf, "f 1", DARAN_LINE_MAX, "\r");
    mock_send_line(m, buf);
    ASSERT_REPLY(m, "0 0\n");
}

/* Its line end comes after the room is full, where the framer skips the
 * overlong bytes before it ends the last field: a ninth field there still
 * only counts as one too many, and the command word keeps its length. */
static void test_a_full_length_line_whose_last_byte_ends_a_ninth_field_has_too_many(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX + 1];
    make_padded(buf, "d 1 1 2 3 4 5 6", DARAN_LINE_MAX, "7");
    ASSERT_ERROR(m, buf, "invalid command format");
    make_padded(buf, "f 1 1 2 3 4 5 6", DARAN_LINE_MAX, "7");
    ASSERT_ERROR(m, buf, "invalid command format");
}

static void test_line_of_128_bytes_with_checksum_is_accepted(void)
{
    mock_t *m = mock_new();
    char payload[DARAN_LINE_MAX + 1], line[DARAN_LINE_MAX + 16];
    /* payload + "*NNN" (three digits, leading zeros allowed by D4) = 128 bytes */
    make_padded(payload, "t 1 10", DARAN_LINE_MAX - 4, "");
    snprintf(line, sizeof line, "%s*%03u", payload, mock_xor(payload));
    TEST_ASSERT_EQUAL_INT64(DARAN_LINE_MAX, strlen(line));
    const daran_move_t *mv = ASSERT_MOVE(m, line);
    TEST_ASSERT_TRUE(mv->pos_deg == 10.0f);
}

static void test_line_of_129_bytes_is_too_long_once_and_the_next_line_works(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX + 2];
    make_padded(buf, "t 1 10", DARAN_LINE_MAX + 1, "");
    ASSERT_ERROR(m, buf, "line too long");
    make_padded(buf, "f 1", DARAN_LINE_MAX, "\r");
    strcat(buf, " ");
    ASSERT_ERROR(m, buf, "line too long");
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_very_long_line_is_answered_once(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX * 4 + 1];
    make_padded(buf, "t 1 10", DARAN_LINE_MAX * 4, "0");
    ASSERT_ERROR(m, buf, "line too long");
    TEST_ASSERT_EQUAL_INT64(1, m->n_writes);
    ASSERT_MOVE(m, "t 1 10");
}

static void test_overlong_line_with_invalid_byte_is_too_long(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX * 2 + 1];
    /* invalid byte early, length found later (D2) */
    make_padded(buf, "t 1 \x01", DARAN_LINE_MAX * 2, "");
    ASSERT_ERROR(m, buf, "line too long");
    /* invalid byte after the 128th byte */
    make_padded(buf, "t 1 10", DARAN_LINE_MAX * 2, "\x80");
    ASSERT_ERROR(m, buf, "line too long");
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_overlong_line_for_another_drive_is_still_answered(void)
{
    mock_t *m = mock_new();
    char buf[DARAN_LINE_MAX + 11];
    make_padded(buf, "t 7 10", DARAN_LINE_MAX + 10, "");
    ASSERT_ERROR(m, buf, "line too long");
}

/* ---- every invalid byte class, one case per byte ---- */

static void invalid_byte_case(const void *row_arg)
{
    uint8_t b = (uint8_t)(uintptr_t)row_arg;
    mock_t *m = mock_new();
    const char *places[] = {"@f 1", "f@1", "f 1@", "t 1 1@0 0 25", "t 9 10@"};
    for (size_t i = 0; i < sizeof places / sizeof places[0]; i++) {
        char line[32];
        strcpy(line, places[i]);
        *strchr(line, '@') = (char)b;
        size_t len = strlen(places[i]);
        line[len] = '\n';
        mock_clear(m);
        mock_send_bytes(m, line, len + 1, 0);
        ASSERT_REPLY(m, "error: invalid character\n");
        ASSERT_NO_EFFECT(m);
        /* recovery: the next line works */
        mock_send_line(m, "f 1");
        ASSERT_REPLY(m, "0 0\n");
    }
}

static void test_several_invalid_bytes_answer_once(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    static const char bad[] = "t\x01 1\x02 10\x7f\xff\n";
    mock_send_bytes(m, bad, sizeof bad - 1, 0);
    ASSERT_REPLY(m, "error: invalid character\n");
    ASSERT_NO_EFFECT(m);
}

/* The bytes given to daran_rx_write() and no more: these have no NUL
 * after them, so a read past them is an overflow under ASan. */
static const char exact_line[4] = {'f', ' ', '1', '\n'};

static void test_the_receive_ring_reads_only_the_bytes_it_is_given(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    TEST_ASSERT_EQUAL_UINT64(sizeof exact_line, daran_rx_write(&m->drive, exact_line, sizeof exact_line));
    TEST_ASSERT_EQUAL_UINT64(1, daran_poll(&m->drive));
    ASSERT_REPLY(m, "0 0\n");
}

static void test_tab_and_printable_ascii_are_allowed(void)
{
    mock_t *m = mock_new();
    /* every printable byte is accepted by the framer: the line is judged later */
    char line[200];
    size_t k = 0;
    line[k++] = 'x';
    line[k++] = ' ';
    for (int c = 0x21; c <= 0x7e; c++)
        if (c != '*')
            line[k++] = (char)c;
    line[k] = '\0';
    ASSERT_ERROR(m, line, "unknown command");
    mock_send_line(m, "f\t1\t");
    ASSERT_REPLY(m, "0 0\n");
}

/* ---- chunked byte input ---- */

static const char *const script[] = {
    "t 1 10 0 25\n",
    "f 1\n",
    "x 1\n",
    "q 1 50.0 7.5 2.5\r\n",
    "\n",
    " \t \n",
    "w axis1.output_shaft.pos_setpoint 150\n",
    "r axis1.output_shaft.pos_setpoint\n",
    "f 1 *87\n",
    "f 1 *88\n",
    "e 1\n",
    "ms 1 10 0 5\n",
    "mt 0 0\n",
    "t 1 \x01\n",
    "t 2 10\n",
    "v 1 12.5 2.5 2 \n",
    "r config.uart_baudrate 1\n",
    "u 1\n",
    "d 1 10 0 0.5 0.1 0.01\n",
};

typedef struct run_result {
    char out[4096];
    mock_call_t calls[64];
    size_t n_calls;
} run_result_t;

static run_result_t whole_run, chunk_run;

static void run_script(run_result_t *r, size_t chunk, unsigned seed)
{
    mock_t *m = mock_new();
    mock_clear(m);
    static char all[4096];
    size_t n = 0;
    for (size_t i = 0; i < sizeof script / sizeof script[0]; i++) {
        size_t l = strlen(script[i]);
        if (chunk == 0) {
            mock_send_bytes(m, script[i], l, l);
        } else {
            memcpy(all + n, script[i], l);
            n += l;
        }
    }
    /* a long line, longer than the ring, at the end of every run */
    char lng[DARAN_LINE_MAX * 2 + 2];
    make_padded(lng, "t 1 5", DARAN_LINE_MAX * 2, "\n");
    if (chunk == 0) {
        mock_send_bytes(m, lng, strlen(lng), 16);
        mock_send_bytes(m, "f 1\n", 4, 4);
    } else {
        memcpy(all + n, lng, strlen(lng));
        n += strlen(lng);
        memcpy(all + n, "f 1\n", 4);
        n += 4;
        size_t pos = 0;
        while (pos < n) {
            size_t c = chunk;
            if (chunk == (size_t)-1) {
                seed = seed * 1103515245u + 12345u;
                c = 1 + (seed >> 16) % 23;
            }
            if (c > DARAN_RX_RING_SIZE / 2)
                c = DARAN_RX_RING_SIZE / 2;
            if (c > n - pos)
                c = n - pos;
            TEST_ASSERT_EQUAL_INT64(c, daran_rx_write(&m->drive, all + pos, c));
            (void)daran_poll(&m->drive);
            pos += c;
        }
    }
    TEST_ASSERT_TRUE(m->out_len < sizeof r->out);
    memcpy(r->out, m->out, m->out_len + 1);
    TEST_ASSERT_TRUE(m->n_calls <= 64);
    memcpy(r->calls, m->calls, m->n_calls * sizeof m->calls[0]);
    r->n_calls = m->n_calls;
}

static void assert_same_run(const run_result_t *a, const run_result_t *b)
{
    TEST_ASSERT_EQUAL_STRING(b->out, a->out);
    TEST_ASSERT_EQUAL_INT64(b->n_calls, a->n_calls);
    for (size_t i = 0; i < a->n_calls; i++) {
        const mock_call_t *x = &a->calls[i], *y = &b->calls[i];
        TEST_ASSERT_EQUAL_INT64(y->kind, x->kind);
        if (x->kind == MOCK_CALL_SET) {
            TEST_ASSERT_EQUAL_INT64(y->prop, x->prop);
            TEST_ASSERT_EQUAL_MEMORY(&y->value, &x->value, sizeof x->value);
        } else if (x->kind == MOCK_CALL_ACTION) {
            TEST_ASSERT_EQUAL_INT64(y->action, x->action);
        } else {
            TEST_ASSERT_EQUAL_INT64(y->move.kind, x->move.kind);
            TEST_ASSERT_EQUAL_INT64(y->move.given, x->move.given);
            TEST_ASSERT_TRUE(x->move.pos_deg == y->move.pos_deg);
            TEST_ASSERT_TRUE(x->move.vel_rpm == y->move.vel_rpm);
            TEST_ASSERT_TRUE(x->move.torque_nm == y->move.torque_nm);
            TEST_ASSERT_TRUE(x->move.rate == y->move.rate);
            TEST_ASSERT_TRUE(x->move.kp == y->move.kp);
            TEST_ASSERT_TRUE(x->move.kd == y->move.kd);
        }
    }
}

static void chunk_case(const void *row_arg)
{
    size_t chunk = (size_t)(uintptr_t)row_arg;
    run_script(&whole_run, 0, 0);
    /* sanity: the reference run did what the script says */
    TEST_ASSERT_NOT_NULL(strstr(whole_run.out, "error: unknown command\n"));
    TEST_ASSERT_NOT_NULL(strstr(whole_run.out, "error: invalid character\n"));
    TEST_ASSERT_NOT_NULL(strstr(whole_run.out, "error: line too long\n"));
    TEST_ASSERT_TRUE(whole_run.n_calls >= 10);
    if (chunk == (size_t)-1) {
        for (unsigned seed = 1; seed <= 20; seed++) {
            run_script(&chunk_run, chunk, seed);
            assert_same_run(&whole_run, &chunk_run);
        }
    } else {
        run_script(&chunk_run, chunk, 0);
        assert_same_run(&whole_run, &chunk_run);
    }
}

/* ---- ring overrun (D3) ---- */

/* Queue text without the harness's no-loss check, then poll; returns the
 * bytes queued. */
static size_t raw_write_poll(mock_t *m, const char *text)
{
    size_t n = daran_rx_write(&m->drive, text, strlen(text));
    (void)daran_poll(&m->drive);
    return n;
}

static void test_ring_overrun_discards_the_damaged_line_as_too_long(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    /* 5-byte lines, never polled: the ring overflows inside a line */
    char flood[(DARAN_RX_RING_SIZE / 5 + 15) * 5];
    for (size_t i = 0; i < sizeof flood / 5; i++)
        memcpy(flood + 5 * i, "f 1 \n", 5);
    size_t queued = daran_rx_write(&m->drive, flood, sizeof flood);
    TEST_ASSERT_TRUE(queued < sizeof flood);
    TEST_ASSERT_TRUE(queued >= DARAN_RX_RING_SIZE - 1 && queued <= DARAN_RX_RING_SIZE);
    TEST_ASSERT_EQUAL_INT64(sizeof flood - queued, daran_rx_dropped(&m->drive));
    (void)daran_poll(&m->drive);
    /* every whole line that fitted executes once */
    static char want[DARAN_RX_RING_SIZE + 16];
    want[0] = '\0';
    for (size_t i = 0; i < queued / 5; i++)
        strcat(want, "0 0\n");
    ASSERT_REPLY(m, want);
    /* the line that lost bytes meets its end now: discarded, never executed
     * (the producer may drop the rest of the damaged line itself) */
    size_t q2 = raw_write_poll(m, "t 1 10\n");
    ASSERT_REPLY(m, "error: line too long\n");
    ASSERT_NO_EFFECT(m);
    /* later lines execute exactly once */
    size_t q3 = raw_write_poll(m, "t 1 10\nf 1\n");
    TEST_ASSERT_EQUAL_INT64(11, q3);
    ASSERT_REPLY(m, "0 0\n");
    TEST_ASSERT_EQUAL_INT64(1, mock_count(m, MOCK_CALL_MOVE));
    TEST_ASSERT_EQUAL_INT64(sizeof flood - queued + 7 - q2, daran_rx_dropped(&m->drive));
}

static void test_ring_overrun_never_executes_a_spliced_motion_line(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    /* whole lines, then a motion line whose digits are lost to the overrun */
    enum { WHOLE = (DARAN_RX_RING_SIZE - 4) / 4 };
    char fill[WHOLE * 4 + 8];
    for (int i = 0; i < WHOLE; i++)
        memcpy(fill + 4 * i, "u 1\n", 4);
    memcpy(fill + WHOLE * 4, "t 1 9999", 8);
    size_t queued = daran_rx_write(&m->drive, fill, sizeof fill);
    TEST_ASSERT_TRUE(queued < sizeof fill);
    TEST_ASSERT_FALSE(daran_rx_byte(&m->drive, '9'));
    TEST_ASSERT_EQUAL_INT64(sizeof fill - queued + 1, daran_rx_dropped(&m->drive));
    (void)daran_poll(&m->drive);
    ASSERT_REPLY(m, "");
    TEST_ASSERT_EQUAL_INT64(WHOLE, mock_count_action(m, DARAN_ACTION_FEED_WATCHDOG));
    mock_clear(m);
    /* what is left ("t 1 " or "t 1") + "0" would read as a valid line */
    (void)raw_write_poll(m, "0\n");
    ASSERT_REPLY(m, "error: line too long\n");
    ASSERT_NO_EFFECT(m);
    ASSERT_MOVE(m, "t 1 20");
}

static void test_rx_byte_accepts_until_the_ring_is_full(void)
{
    mock_t *m = mock_new();
    size_t ok = 0;
    for (int i = 0; i < DARAN_RX_RING_SIZE + 8; i++)
        ok += daran_rx_byte(&m->drive, ' ');
    TEST_ASSERT_TRUE(ok >= DARAN_RX_RING_SIZE - 1 && ok <= DARAN_RX_RING_SIZE);
    TEST_ASSERT_EQUAL_INT64(DARAN_RX_RING_SIZE + 8 - ok, daran_rx_dropped(&m->drive));
    (void)daran_poll(&m->drive);
    mock_clear(m);
    mock_send_raw(m, "\n");
    ASSERT_REPLY(m, "error: line too long\n");
    mock_send_raw(m, "f 1\n");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_rx_dropped_starts_at_zero(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT64(0, daran_rx_dropped(&m->drive));
    mock_send_raw(m, "f 1\n");
    TEST_ASSERT_EQUAL_INT64(0, daran_rx_dropped(&m->drive));
}

/* ---- daran_process_line ---- */

static void test_process_line_runs_a_framed_line(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1", 3));
    ASSERT_REPLY(m, "0 0\n");
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1\r", 4));
    ASSERT_REPLY(m, "0 0\n");
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "t 1 10", 6));
    TEST_ASSERT_EQUAL_INT64(1, mock_count(m, MOCK_CALL_MOVE));
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "", 0));
    /* an empty text may come as NULL: nothing is read or offset from it */
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, NULL, 0));
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 2", 3));
    ASSERT_REPLY(m, "");
    /* a checksum field works the same on this path */
    char want[32];
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1 *87", 7));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "0 0", true));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_CHECKSUM_MISMATCH, daran_process_line(&m->drive, "f 1 *86", 7));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "error: checksum mismatch", true));
    /* the same 128-byte limit as the byte path */
    char buf[DARAN_LINE_MAX + 1];
    make_padded(buf, "f 1", DARAN_LINE_MAX, "");
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, buf, DARAN_LINE_MAX));
    ASSERT_REPLY(m, "0 0\n");
}

static void test_process_line_between_the_bytes_of_a_line_never_runs_its_rest(void)
{
    /* D38: the byte path has framed "t 1 1" when a pre-framed line comes */
    mock_t *m = mock_new();
    mock_clear(m);
    (void)daran_rx_write(&m->drive, "t 1 1", 5);
    (void)daran_poll(&m->drive);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1", 3));
    ASSERT_REPLY(m, "0 0\n");
    (void)daran_rx_write(&m->drive, "0\n", 2); /* "0" alone must not become a line */
    (void)daran_poll(&m->drive);
    ASSERT_REPLY(m, "error: line too long\n");
    ASSERT_NO_EFFECT(m);
    /* the next line is whole again */
    mock_send_line(m, "t 1 10");
    TEST_ASSERT_EQUAL_UINT(2, m->n_calls); /* move and watchdog feed */
    /* without a pending line, nothing is marked */
    mock_clear(m);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1", 3));
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_process_line_before_a_pending_line_s_bare_line_end_answers_it(void)
{
    /* D38 with nothing left of the pending line but its '\n': the line buffer
     * is empty again, yet that '\n' ends a damaged line, not an empty one */
    mock_t *m = mock_new();
    mock_clear(m);
    (void)daran_rx_write(&m->drive, "t 1 10", 6);
    (void)daran_poll(&m->drive);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1", 3));
    ASSERT_REPLY(m, "0 0\n");
    (void)daran_rx_write(&m->drive, "\n", 1);
    (void)daran_poll(&m->drive);
    ASSERT_REPLY(m, "error: line too long\n");
    ASSERT_NO_EFFECT(m);
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_process_line_after_a_pending_line_that_ends_in_a_blank_never_runs_its_rest(void)
{
    /* D38 again, the pending line "f " ending between fields (it has bytes,
     * no flag): its rest "1" must not become the line "1" nor join "f " */
    mock_t *m = mock_new();
    mock_clear(m);
    (void)daran_rx_write(&m->drive, "f ", 2);
    (void)daran_poll(&m->drive);
    ASSERT_REPLY(m, "");
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_process_line(&m->drive, "f 1", 3));
    ASSERT_REPLY(m, "0 0\n");
    (void)daran_rx_write(&m->drive, "f 1\n", 4);
    (void)daran_poll(&m->drive);
    ASSERT_REPLY(m, "error: line too long\n");
    mock_send_line(m, "f 1");
    ASSERT_REPLY(m, "0 0\n");
}

static void test_process_line_returns_the_error_it_answered(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_UNKNOWN_COMMAND, daran_process_line(&m->drive, "x 1", 3));
    ASSERT_REPLY(m, "error: unknown command\n");
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_INVALID_CHARACTER, daran_process_line(&m->drive, "f\0001", 3));
    ASSERT_REPLY(m, "error: invalid character\n");
    /* the text comes without its line end: a '\n' is a character, even last */
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_INVALID_CHARACTER, daran_process_line(&m->drive, "t 1 10\n", 7));
    ASSERT_REPLY(m, "error: invalid character\n");
    ASSERT_NO_EFFECT(m);
    char buf[DARAN_LINE_MAX + 2];
    make_padded(buf, "f 1", DARAN_LINE_MAX + 1, "");
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_LINE_TOO_LONG, daran_process_line(&m->drive, buf, DARAN_LINE_MAX + 1));
    ASSERT_REPLY(m, "error: line too long\n");
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE, daran_process_line(&m->drive, "t 1 10 0 -1", 11));
    ASSERT_REPLY(m, "error: value out of range\n");
    ASSERT_NO_EFFECT(m);
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    ADD(test_lf_ends_a_line);
    ADD(test_crlf_ends_a_line);
    ADD(test_cr_anywhere_is_whitespace);
    ADD(test_blank_lines_get_no_reply);
    ADD(test_poll_counts_blank_lines_too);
    ADD(test_line_of_exactly_128_bytes_is_accepted);
    ADD(test_line_of_128_bytes_with_checksum_is_accepted);
    ADD(test_a_full_length_line_whose_last_byte_ends_a_ninth_field_has_too_many);
    ADD(test_line_of_129_bytes_is_too_long_once_and_the_next_line_works);
    ADD(test_very_long_line_is_answered_once);
    ADD(test_overlong_line_with_invalid_byte_is_too_long);
    ADD(test_overlong_line_for_another_drive_is_still_answered);
    ADD(test_several_invalid_bytes_answer_once);
    ADD(test_the_receive_ring_reads_only_the_bytes_it_is_given);
    ADD(test_tab_and_printable_ascii_are_allowed);
    for (unsigned b = 0; b <= 0xff; b++) {
        bool bad = b < 0x20 || b >= 0x7f;
        if (b == '\t' || b == '\r' || b == '\n')
            bad = false;
        bool listed = b <= 0x1f || b == 0x7f || b == 0x80 || b == 0xff;
        if (bad && listed)
            mock_suite_add(&s, invalid_byte_case, (void *)(uintptr_t)b,
                           "test_byte_0x%02X_is_an_invalid_character_and_the_next_line_works", b);
    }
    for (unsigned b = 0x81; b < 0xff; b += 0x1f)
        mock_suite_add(&s, invalid_byte_case, (void *)(uintptr_t)b,
                       "test_byte_0x%02X_is_an_invalid_character_and_the_next_line_works", b);
    /* the ring's own mark of a damaged line end: received, it is a byte */
    mock_suite_add(&s, invalid_byte_case, (void *)(uintptr_t)0x8Au,
                   "test_byte_0x%02X_is_an_invalid_character_and_the_next_line_works", 0x8Au);
    static const size_t chunks[] = {1, 2, 3, 7, 13};
    for (size_t i = 0; i < sizeof chunks / sizeof chunks[0]; i++)
        mock_suite_add(&s, chunk_case, (void *)(uintptr_t)chunks[i],
                       "test_input_in_chunks_of_%zu_bytes_acts_like_whole_lines", chunks[i]);
    mock_suite_add(&s, chunk_case, (void *)(uintptr_t)(size_t)-1,
                   "test_input_in_random_chunks_acts_like_whole_lines");
    ADD(test_ring_overrun_discards_the_damaged_line_as_too_long);
    ADD(test_ring_overrun_never_executes_a_spliced_motion_line);
    ADD(test_rx_byte_accepts_until_the_ring_is_full);
    ADD(test_rx_dropped_starts_at_zero);
    ADD(test_process_line_runs_a_framed_line);
    ADD(test_process_line_before_a_pending_line_s_bare_line_end_answers_it);
    ADD(test_process_line_after_a_pending_line_that_ends_in_a_blank_never_runs_its_rest);
    ADD(test_process_line_returns_the_error_it_answered);
    ADD(test_process_line_between_the_bytes_of_a_line_never_runs_its_rest);
    mock_suite_run(&s);
    return UNITY_END();
}

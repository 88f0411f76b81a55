/* The bad-input classes of docs/security.md, applied to every command
 * family's valid line: each answers its error phrase and makes no HAL set,
 * move or action (C22-C32); a line for another id is silent (C33); a right
 * checksum changes nothing but the replies' tails (C24). A family's setup
 * line (a preset) goes first, so a start that wrongly ran would move. */
#include <stdio.h>
#include <string.h>

#include "conformance.h"

static const char *own_id(void)
{
    static char text[8];
    (void)snprintf(text, sizeof text, "%u", CONF_ID);
    return text;
}

static void send_setup(const char *setup)
{
    if (setup != NULL) {
        char line[256];
        conf_fill(setup, own_id(), line, sizeof line);
        conf_send(line);
    }
}

/* Begin a check of @p req on family @p f; the subject is its valid line. */
static bool begin(conf_req_t req, const conf_family_t *f, const char *what)
{
    char line[256];
    char subject[320];
    conf_fill(f->valid, own_id(), line, sizeof line);
    (void)snprintf(subject, sizeof subject, "%s%s%s", line, what[0] != '\0' ? ": " : "", what);
    return conf_begin(req, subject);
}

/* Send setup, then @p bytes, expecting `error: <phrase>` and no effect. */
static void refused(conf_req_t req, const conf_family_t *f, const char *setup, const char *bytes,
                    size_t len, const char *phrase, bool checksum, const char *what)
{
    if (begin(req, f, what)) {
        send_setup(setup);
        conf_send_n(bytes, len);
        (void)conf_expect_error(phrase, checksum);
    }
    conf_end();
}

static size_t valid_line(const conf_family_t *f, char *buf, size_t size)
{
    conf_fill(f->valid, own_id(), buf, size);
    return strlen(buf);
}

/* ---- the checksum (C22-C24) ---- */

static void check_checksums(const conf_family_t *f, size_t index)
{
    static const char *const malformed[] = {" *256", " *", " *12x", " *1234", " * 5", " *8*7"};
    char line[512];
    size_t len = valid_line(f, line, sizeof line);
    const char *tail = malformed[index % (sizeof malformed / sizeof malformed[0])];
    (void)snprintf(line + len, sizeof line - len, "%s", tail);
    refused(REQ_BAD_CHECKSUM, f, f->setup, line, strlen(line), "invalid checksum", false, tail + 1);

    /* the XOR covers every byte before the '*', the blank included */
    len = valid_line(f, line, sizeof line);
    line[len] = ' ';
    unsigned right = conf_xor(line, len + 1u);
    (void)snprintf(line + len, sizeof line - len, " *%u", right ^ 0x21u);
    refused(REQ_CHECKSUM_MISMATCH, f, f->setup, line, strlen(line), "checksum mismatch", true,
            "wrong *N");

    if (!begin(REQ_CHECKSUM_OK, f, "right *N")) {
        conf_end();
        return;
    }
    /* the plain line first: its HAL effects and replies */
    char effects[2][1024];
    char replies[2][4096];
    for (int run = 0; run < 2; run++) {
        if (run == 1 && !conf_restart()) {
            break;
        }
        send_setup(f->setup);
        len = valid_line(f, line, sizeof line);
        if (run == 1) {
            (void)snprintf(line + len, sizeof line - len, " *%u", right);
        }
        conf_send(line);
        size_t used = 0;
        effects[run][0] = '\0';
        const daran_recorder_t *rec = conf_rec();
        for (size_t i = 0; i < rec->n_calls; i++) {
            if (rec->calls[i].kind != DARAN_CALL_GET && used + 200u < sizeof effects[run]) {
                used += daran_call_describe(&rec->calls[i], effects[run] + used,
                                            sizeof effects[run] - used);
                effects[run][used++] = ';';
                effects[run][used] = '\0';
            }
        }
        (void)snprintf(replies[run], sizeof replies[run], "%s", conf_reply());
    }
    if (!conf_failed()) {
        if (strcmp(effects[0], effects[1]) != 0) {
            conf_fail("the same HAL calls as without the checksum: %s",
                      effects[0][0] != '\0' ? effects[0] : "none");
        }
        /* each reply line of the plain run, with " *N" of "<line> " */
        char want[4096 + 512];
        size_t w = 0;
        const char *end = DARAN_REPLY_CRLF ? "\r\n" : "\n";
        size_t end_len = strlen(end);
        for (const char *p = replies[0]; *p != '\0' && w + 16u < sizeof want;) {
            const char *eol = strstr(p, end);
            if (eol == NULL) {
                break;
            }
            size_t n = (size_t)(eol - p);
            unsigned sum = conf_xor(p, n) ^ (unsigned)' ';
            int k = snprintf(want + w, sizeof want - w, "%.*s *%u%s", (int)n, p, sum, end);
            w += k > 0 ? (size_t)k : 0u;
            p = eol + end_len;
        }
        want[w < sizeof want ? w : sizeof want - 1u] = '\0';
        if (strcmp(want, replies[1]) != 0) {
            conf_fail("the same replies as without the checksum, each with its own ` *N` (D6)");
        }
    }
    conf_end();
}

/* ---- the whole line (C25, C26) ---- */

static void check_characters(const conf_family_t *f, size_t index)
{
    static const unsigned char bad[] = {0x01, 0x7F, 0x80, 0xFF, 0x00, 0x1B, 0x0B};
    char line[512];
    size_t len = valid_line(f, line, sizeof line);
    /* the bad byte right after the command word */
    size_t word = strcspn(line, " ");
    memmove(line + word + 1, line + word, len - word + 1u);
    line[word] = (char)bad[index % sizeof bad];
    char what[32];
    (void)snprintf(what, sizeof what, "byte 0x%02X", bad[index % sizeof bad]);
    refused(REQ_INVALID_CHARACTER, f, f->setup, line, len + 1u, "invalid character", false, what);
}

static void check_length(const conf_family_t *f)
{
    char line[DARAN_LINE_MAX + 128];
    if (!begin(REQ_LINE_TOO_LONG, f, "padded past DARAN_LINE_MAX")) {
        conf_end();
        return;
    }
    /* blanks that would not change the line, then digits that would */
    size_t len = valid_line(f, line, sizeof line);
    if (len < DARAN_LINE_MAX + 1u) {
        memset(line + len, ' ', DARAN_LINE_MAX + 1u - len);
        send_setup(f->setup);
        conf_send_n(line, DARAN_LINE_MAX + 1u);
        (void)conf_expect_error("line too long", false);
    }
    len = valid_line(f, line, sizeof line);
    if (len < DARAN_LINE_MAX + 60u) {
        memset(line + len, '0', DARAN_LINE_MAX + 60u - len);
        send_setup(f->setup);
        conf_send_n(line, DARAN_LINE_MAX + 60u);
        (void)conf_expect_error("line too long", false);
    }
    conf_end();
}

/* ---- the fields (C27-C32) ---- */

static bool port_has_word(const char *word)
{
    const daran_test_port_t *port = conf_port();
    for (size_t i = 0; i < port->command_count && port->commands != NULL; i++) {
        if (strcmp(port->commands[i].word, word) == 0) {
            return true;
        }
    }
    return false;
}

static void check_unknown_word(const conf_family_t *f)
{
    char line[512];
    char word[16];
    size_t len = valid_line(f, line, sizeof line);
    size_t word_len = strcspn(line, " ");
    /* the word with a letter more: a word no vendor table has (at most two letters) */
    const char *extra = "zxyqk";
    for (const char *e = extra; *e != '\0'; e++) {
        (void)snprintf(word, sizeof word, "%.*s%c", (int)word_len, line, *e);
        if (!port_has_word(word)) {
            break;
        }
    }
    char bad[520];
    (void)snprintf(bad, sizeof bad, "%s%s", word, line + word_len);
    (void)len;
    refused(REQ_UNKNOWN_COMMAND, f, f->setup, bad, strlen(bad), "unknown command", false, word);
}

static void refused_template(conf_req_t req, const char *setup, const char *line_template,
                             const char *phrase)
{
    if (line_template == NULL) {
        return;
    }
    char line[512];
    conf_fill(line_template, own_id(), line, sizeof line);
    if (conf_begin(req, line)) {
        send_setup(setup);
        conf_send(line);
        (void)conf_expect_error(phrase, false);
    }
    conf_end();
}

static void check_fields(const conf_family_t *f)
{
    refused_template(REQ_FIELD_COUNT, f->setup, f->too_few, "invalid command format");
    refused_template(REQ_FIELD_COUNT, f->setup, f->too_many, "invalid command format");
    refused_template(REQ_INVALID_VALUE, f->setup, f->malformed, "invalid value");
    refused_template(REQ_OUT_OF_RANGE,
                     f->out_of_range_setup != NULL ? f->out_of_range_setup : f->setup,
                     f->out_of_range, "value out of range");
    refused_template(REQ_INVALID_MODE, f->bad_mode_setup != NULL ? f->bad_mode_setup : f->setup,
                     f->bad_mode, "invalid mode");
}

static void check_ids(const conf_family_t *f)
{
    char too_large[8];
    (void)snprintf(too_large, sizeof too_large, "%d", DARAN_MOTOR_ID_MAX + 1);
    const char *ids[] = {too_large, "x", "1.5", "-1", "256"};
    if (begin(REQ_INVALID_MOTOR, f, "ids 64, x, 1.5, -1, 256")) {
        for (size_t i = 0; i < sizeof ids / sizeof ids[0]; i++) {
            if (strstr(f->valid, "axis{id}.") != NULL && strchr(ids[i], '.') != NULL) {
                continue; /* "axis1.5.x" is id 1 and the path "5.x" (D8) */
            }
            send_setup(f->setup);
            char line[512];
            conf_fill(f->valid, ids[i], line, sizeof line);
            conf_send(line);
            (void)conf_expect_error("invalid motor", false);
        }
    }
    conf_end();

    if (DARAN_MOTOR_ID_MAX < CONF_OTHER_ID) {
        conf_skip(REQ_OTHER_ID, f->word, "DARAN_MOTOR_ID_MAX leaves no other id");
        return;
    }
    char other[8];
    (void)snprintf(other, sizeof other, "%u", CONF_OTHER_ID);
    if (begin(REQ_OTHER_ID, f, "for id 2")) {
        send_setup(f->setup);
        char line[512];
        conf_fill(f->valid, other, line, sizeof line);
        conf_send(line);
        (void)conf_expect_silent();
        (void)conf_expect_no_effect();
        const daran_recorder_t *rec = conf_rec();
        for (size_t i = 0; i < rec->n_calls; i++) {
            if (rec->calls[i].kind == DARAN_CALL_GET && rec->calls[i].prop != DARAN_PROP_CAN_NODE_ID) {
                conf_fail("no HAL get but axis0.config.can_node_id (docs/security.md, invariant 3)");
                break;
            }
        }
    }
    conf_end();
}

void conf_check_bad_input(void)
{
    const conf_family_t *list;
    size_t count = conf_families(&list);
    for (size_t i = 0; i < count; i++) {
        const conf_family_t *f = &list[i];
        if (CONF_CHECKSUMS) {
            check_checksums(f, i);
        }
        check_characters(f, i);
        check_length(f);
        check_unknown_word(f);
        check_fields(f);
        check_ids(f);
    }
    if (!CONF_CHECKSUMS) {
        conf_skip(REQ_BAD_CHECKSUM, "*N", "the core's checksums are compiled out");
        conf_skip(REQ_CHECKSUM_MISMATCH, "*N", "the core's checksums are compiled out");
        conf_skip(REQ_CHECKSUM_OK, "*N", "the core's checksums are compiled out");
    }
}

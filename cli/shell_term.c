/* daran shell: the terminal side (shell.h). Input is read a byte at a time
 * from a poll() on standard input and the port together, so telemetry
 * reports are read and shown while nobody types; with libedit this is its
 * read function (EL_GETCFN). A report printed while the prompt is shown
 * clears the prompt's row, takes it, and has libedit draw the prompt and
 * the line being typed again below. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <wchar.h>

#include "shell.h"

#define HISTORY_SIZE 1000

/* ------------------------------------------------------------ signals */

static volatile sig_atomic_t interrupt_pending;
static volatile sig_atomic_t terminate_pending;

static void on_signal(int signo)
{
    if (signo == SIGINT) {
        interrupt_pending = 1;
    } else {
        terminate_pending = 1;
    }
}

void shell_catch_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: poll() returns at once */
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
}

bool shell_take_interrupt(void)
{
    bool was = interrupt_pending != 0;
    interrupt_pending = 0;
    return was;
}

bool shell_terminated(void)
{
    return terminate_pending != 0;
}

/* ------------------------------------------------------------ output apart from replies */

/* One line that is not a reply (a report, a stray line), on a row of its own. */
static void print_apart(shell_t *sh, const char *text)
{
    if (sh->editing && sh->at_prompt) {
        /* the cursor is on the prompt's row: clear it, print, redraw below */
        printf("\r\033[K%s\n", text);
        fflush(stdout);
        el_set(sh->el, EL_REFRESH);
    } else {
        printf("%s\n", text);
    }
}

/* The shortest text that reads back as f (the drive prints floats so). */
static void format_float(float f, char *buf, size_t size)
{
    if (isnan(f)) {
        (void)snprintf(buf, size, "nan");
        return;
    }
    if (isinf(f)) {
        (void)snprintf(buf, size, f < 0 ? "-inf" : "inf");
        return;
    }
    float magnitude = f < 0 ? -f : f;
    bool fixed = magnitude == 0.0f || (magnitude >= 1e-4f && magnitude < 1e9f);
    for (int digits = fixed ? 0 : 1; digits <= 12; digits++) {
        (void)snprintf(buf, size, fixed ? "%.*f" : "%.*g", digits, (double)f);
        if (strtof(buf, NULL) == f) {
            return;
        }
    }
}

static void format_number(const daran_client_number_t *n, char *buf, size_t size)
{
    if (n->is_integer) {
        (void)snprintf(buf, size, "%s%llu", n->negative && n->magnitude != 0 ? "-" : "",
                       (unsigned long long)n->magnitude);
    } else {
        format_float(n->f32, buf, size);
    }
}

/* The values of a report by the bit of axis0.telemetry.fields that asks
 * for them (protocol.md 11.2). */
static const char *const field_names[DARAN_CLIENT_REPORT_MAX] = {
    "pos", "vel", "torque", "iq", "vbus", "fet_temp", "motor_temp", "error", "traj_done"};

static size_t bits_set(uint32_t mask)
{
    size_t count = 0;
    for (; mask != 0; mask &= mask - 1) {
        count++;
    }
    return count;
}

void shell_print_report(void *ctx, const daran_client_report_t *report)
{
    shell_t *sh = ctx;
    uint8_t id = report->id <= DARAN_CLIENT_ID_MAX ? report->id : 0;
    if (sh->fields_state[id] == SHELL_FIELDS_UNKNOWN) {
        sh->fields_state[id] = SHELL_FIELDS_WANTED;
    }
    /* name the values only when the fields known are the ones that came */
    uint32_t mask = sh->fields_mask[id];
    bool named = sh->fields_state[id] == SHELL_FIELDS_KNOWN && bits_set(mask) == report->count;
    char text[DARAN_CLIENT_LINE_MAX * 2];
    char number[48];
    format_float(report->time_s, number, sizeof number);
    size_t len = (size_t)snprintf(text, sizeof text, "@%u t=%s", report->id, number);
    size_t bit = 0;
    for (size_t i = 0; i < report->count && len < sizeof text; i++) {
        while (named && (mask & (1u << bit)) == 0) {
            bit++;
        }
        format_number(&report->values[i], number, sizeof number);
        int n = named ? snprintf(text + len, sizeof text - len, " %s=%s", field_names[bit], number)
                      : snprintf(text + len, sizeof text - len, " %s", number);
        len += n > 0 ? (size_t)n : 0;
        bit++;
    }
    print_apart(sh, text);
}

void shell_print_stray(void *ctx, const daran_client_line_t *line)
{
    char text[DARAN_CLIENT_LINE_MAX + 16];
    (void)snprintf(text, sizeof text, "(unasked) %.*s", (int)line->len, line->payload);
    print_apart(ctx, text);
}

void shell_forget_fields(shell_t *sh)
{
    for (size_t id = 0; id <= DARAN_CLIENT_ID_MAX; id++) {
        sh->fields_state[id] = SHELL_FIELDS_UNKNOWN;
    }
}

void shell_resolve_fields(shell_t *sh)
{
    for (uint8_t id = 1; id <= DARAN_CLIENT_ID_MAX; id++) {
        if (sh->fields_state[id] != SHELL_FIELDS_WANTED) {
            continue;
        }
        sh->fields_state[id] = SHELL_FIELDS_UNREADABLE; /* unless the drive tells */
        daran_client_request_t request = {.command = DARAN_CLIENT_CMD_R,
                                          .id = id,
                                          .path = "telemetry.fields",
                                          .scope = DARAN_CLIENT_SCOPE_AXIS};
        daran_client_number_t n;
        uint32_t mask;
        if (cli_transact(sh->s, &request, NULL, NULL, true, NULL) == CLI_OK &&
            daran_client_parse_number(sh->s->link.last, sh->s->link.last_len, &n) == DARAN_OK &&
            daran_client_number_u32(&n, &mask) == DARAN_OK) {
            sh->fields_mask[id] = mask;
            sh->fields_state[id] = SHELL_FIELDS_KNOWN;
        }
    }
}

/* ------------------------------------------------------------ input */

/* The next byte of standard input: 1, 0 at its end (or when the shell must
 * end: a SIGTERM, the port gone), -1 with errno (EINTR: a SIGINT). The
 * port is serviced meanwhile. */
static int next_byte(shell_t *sh, char *byte)
{
    cli_session_t *s = sh->s;
    for (;;) {
        if (shell_terminated() || s->port_failed) {
            return 0;
        }
        if (interrupt_pending) {
            errno = EINTR;
            return -1;
        }
        shell_resolve_fields(sh);
        struct pollfd fds[2] = {{.fd = STDIN_FILENO, .events = POLLIN},
                                {.fd = s->fd, .events = POLLIN}};
        if (poll(fds, 2, -1) < 0) {
            if (errno == EINTR) {
                continue;
            }
            return -1;
        }
        if (fds[1].revents != 0) {
            daran_client_link_service(&s->link);
        }
        if (fds[0].revents != 0) {
            ssize_t n = read(STDIN_FILENO, byte, 1);
            if (n == 1) {
                return 1;
            }
            if (n == 0) {
                return 0;
            }
            if (errno != EINTR && errno != EAGAIN) {
                return -1;
            }
        }
    }
}

/* libedit's read function: one character, decoded from the bytes of the
 * locale's encoding. */
static int shell_getc(EditLine *el, wchar_t *out)
{
    shell_t *sh = NULL;
    if (el_get(el, EL_CLIENTDATA, &sh) != 0 || sh == NULL) {
        return -1;
    }
    char bytes[MB_LEN_MAX];
    size_t count = 0;
    for (;;) {
        int got = next_byte(sh, &bytes[count]);
        if (got <= 0) {
            *out = L'\0';
            return got;
        }
        count++;
        mbstate_t state;
        memset(&state, 0, sizeof state);
        wchar_t wc;
        size_t used = mbrtowc(&wc, bytes, count, &state);
        if (used == (size_t)-2 && count < sizeof bytes) {
            continue; /* the rest of a multibyte character */
        }
        if (used == (size_t)-1 || used == (size_t)-2) {
            wc = (wchar_t)(unsigned char)bytes[count - 1]; /* not one: the byte as it is */
        }
        *out = wc;
        return 1;
    }
}

static char *prompt_text(EditLine *el)
{
    (void)el;
    static char prompt[] = "daran> ";
    return prompt;
}

static void history_file(shell_t *sh)
{
    const char *path = getenv("DARAN_HISTORY");
    const char *home = getenv("HOME");
    sh->history_path[0] = '\0';
    if (path != NULL && path[0] != '\0') {
        (void)snprintf(sh->history_path, sizeof sh->history_path, "%s", path);
    } else if (home != NULL && home[0] != '\0') {
        (void)snprintf(sh->history_path, sizeof sh->history_path, "%s/.daran_history", home);
    }
}

bool shell_editing_open(shell_t *sh)
{
    HistEvent event;
    sh->history = history_init();
    sh->el = el_init("daran", stdin, stdout, stderr);
    if (sh->history == NULL || sh->el == NULL) {
        shell_editing_close(sh);
        return false;
    }
    history(sh->history, &event, H_SETSIZE, HISTORY_SIZE);
    history(sh->history, &event, H_SETUNIQUE, 1);
    history_file(sh);
    if (sh->history_path[0] != '\0') {
        /* a missing file is a first session */
        (void)history(sh->history, &event, H_LOAD, sh->history_path);
    }
    el_set(sh->el, EL_CLIENTDATA, sh);
    el_set(sh->el, EL_EDITOR, "emacs");
    el_set(sh->el, EL_SIGNAL, 1);
    el_set(sh->el, EL_PROMPT, prompt_text);
    el_set(sh->el, EL_HIST, history, sh->history);
    el_set(sh->el, EL_GETCFN, shell_getc);
    /* the wide call keeps these strings as they are (the narrow one copies
     * them, and libedit never frees the copies) */
    el_wset(sh->el, EL_ADDFN, L"daran-complete", L"complete a command word or property path",
            shell_complete);
    el_set(sh->el, EL_BIND, "^I", "daran-complete", NULL);
    (void)el_source(sh->el, NULL); /* the user's ~/.editrc, when there is one */
    return true;
}

void shell_editing_close(shell_t *sh)
{
    if (sh->history != NULL) {
        HistEvent event;
        if (sh->history_path[0] != '\0' &&
            history(sh->history, &event, H_SAVE, sh->history_path) < 0) {
            cli_fail(CLI_OK, "cannot save the history in %s: %s", sh->history_path,
                     strerror(errno));
        }
        history_end(sh->history);
        sh->history = NULL;
    }
    if (sh->el != NULL) {
        el_end(sh->el);
        sh->el = NULL;
    }
}

void shell_history_add(shell_t *sh, const char *line)
{
    HistEvent event;
    if (sh->history != NULL) {
        history(sh->history, &event, H_ENTER, line);
    }
}

static void report_too_long(size_t len, size_t size)
{
    cli_fail(CLI_USAGE, "a line of %zu characters is longer than the shell takes (%zu): skipped",
             len, size - 1);
}

/* Copy a line without its line end; false (reported) when it is too long. */
static bool take_line(const char *text, size_t len, char *line, size_t size)
{
    while (len > 0 && (text[len - 1] == '\n' || text[len - 1] == '\r')) {
        len--;
    }
    if (len >= size) {
        report_too_long(len, size);
        line[0] = '\0';
        return false;
    }
    memcpy(line, text, len);
    line[len] = '\0';
    return true;
}

static bool read_edited_line(shell_t *sh, char *line, size_t size)
{
    int count = 0;
    sh->at_prompt = true;
    const char *text = el_gets(sh->el, &count);
    sh->at_prompt = false;
    line[0] = '\0';
    if (text == NULL) {
        if (shell_take_interrupt() && !shell_terminated() && !sh->s->port_failed) {
            fputs("^C\n", stdout); /* the line typed so far is dropped */
            return true;
        }
        fputc('\n', stdout); /* Ctrl-D: leave the user's shell a clean row */
        return false;
    }
    (void)take_line(text, (size_t)count, line, size);
    return true;
}

/* Without a terminal: bytes up to a line end, no prompt, no editing. */
static bool read_plain_line(shell_t *sh, char *line, size_t size)
{
    char text[SHELL_LINE_MAX];
    size_t len = 0;
    size_t total = 0; /* with what did not fit */
    line[0] = '\0';
    for (;;) {
        char byte;
        int got = next_byte(sh, &byte);
        if (got < 0) {
            if (shell_take_interrupt()) {
                return !shell_terminated();
            }
            return false;
        }
        if (got == 0) {
            if (len == 0 || sh->s->port_failed || shell_terminated()) {
                return false;
            }
            break; /* a last line without its line end */
        }
        if (byte == '\n') {
            break;
        }
        if (len < sizeof text) {
            text[len++] = byte;
        }
        total++;
    }
    if (total > len) {
        report_too_long(total, size);
        return true;
    }
    (void)take_line(text, len, line, size);
    return true;
}

bool shell_read_line(shell_t *sh, char *line, size_t size)
{
    fflush(stdout);
    return sh->editing ? read_edited_line(sh, line, size) : read_plain_line(sh, line, size);
}

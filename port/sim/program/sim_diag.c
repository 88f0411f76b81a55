/* daran-sim's diagnostics (sim_diag.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_diag.h"

#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sim_app.h"

/* Diagnostics on stderr: at most this many a second, the rest counted. */
#define DIAG_PER_SECOND 20u

/* stderr may be a pipe nobody reads: a blocking write there would stop the
 * drives. Messages go out through a non-blocking description of stderr of
 * our own (O_NONBLOCK set on fd 2 itself would change it for every process
 * sharing it), at most DIAG_PER_SECOND a second; the others, and any that
 * find stderr full, are counted and the count is written when it can be. */

static struct {
    int fd;                   /* where messages go */
    bool socket;              /* fd 2 is a socket: send(MSG_DONTWAIT) */
    bool own;                 /* fd is our own non-blocking description */
    double window_s;          /* start of the current second */
    unsigned shown;           /* messages written in it */
    unsigned long suppressed; /* not written, not yet told */
} diag = {STDERR_FILENO, false, false, 0.0, 0u, 0ul};

void diag_init(void)
{
    struct stat st;
    int fd;
    if (fstat(STDERR_FILENO, &st) != 0 || S_ISREG(st.st_mode) || S_ISBLK(st.st_mode)) {
        return; /* a file never keeps us waiting */
    }
    if (S_ISSOCK(st.st_mode)) {
        diag.socket = true;
        return;
    }
    fd = open("/proc/self/fd/2", O_WRONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
        diag.fd = fd;
        diag.own = true;
    }
}

/* One whole message, or nothing (false) when stderr cannot take it now. */
static bool diag_emit(const char *text, size_t len)
{
    ssize_t n;
    if (diag.socket) {
        n = send(diag.fd, text, len, MSG_DONTWAIT | MSG_NOSIGNAL);
    } else if (diag.own || diag.fd != STDERR_FILENO) {
        n = write(diag.fd, text, len);
    } else {
        /* no non-blocking description: write only when stderr says it can
         * take bytes (a message is shorter than PIPE_BUF) */
        struct pollfd p = {STDERR_FILENO, POLLOUT, 0};
        struct stat st;
        bool file = fstat(STDERR_FILENO, &st) == 0 && (S_ISREG(st.st_mode) || S_ISBLK(st.st_mode));
        if (!file && (poll(&p, 1, 0) != 1 || (p.revents & POLLOUT) == 0)) {
            return false;
        }
        n = write(STDERR_FILENO, text, len);
    }
    return n == (ssize_t)len;
}

bool diag_summary(void)
{
    char text[160];
    int n;
    if (diag.suppressed == 0ul) {
        return true;
    }
    n = snprintf(text, sizeof text,
                 "daran-sim: %lu messages suppressed (at most %u a second on stderr)\n",
                 diag.suppressed, DIAG_PER_SECOND);
    if (n > 0 && diag_emit(text, (size_t)n)) {
        diag.suppressed = 0ul;
        return true;
    }
    return false;
}

/* A new second: room for messages again, and the count of the suppressed
 * ones goes first. */
void diag_tick(void)
{
    double t = now_s();
    if (t - diag.window_s >= 1.0) {
        diag.window_s = t;
        diag.shown = 0u;
        if (diag.suppressed > 0ul && diag_summary()) {
            diag.shown++;
        }
    }
}

/* "daran-sim: " + the message + "\n"; @p urgent ones (a failure at exit)
 * are not rate-limited, only never blocking. */
static void diag_v(bool urgent, const char *fmt, va_list ap)
{
    char text[512];
    int n = snprintf(text, sizeof text, "daran-sim: ");
    int m;
    diag_tick();
    if (!urgent && diag.shown >= DIAG_PER_SECOND) {
        diag.suppressed++;
        return;
    }
    m = vsnprintf(text + n, sizeof text - (size_t)n - 1u, fmt, ap);
    if (m < 0) {
        m = 0;
    }
    n += m;
    if ((size_t)n > sizeof text - 2u) {
        n = (int)sizeof text - 5;
        memcpy(text + n, "...", 3u);
        n += 3;
    }
    text[n++] = '\n';
    if (diag_emit(text, (size_t)n)) {
        diag.shown++;
    } else {
        diag.suppressed++;
    }
}

void diag_msg(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_v(false, fmt, ap);
    va_end(ap);
}

void diag_urgent(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_v(true, fmt, ap);
    va_end(ap);
}

void complain(const char *fmt, ...)
{
    char text[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    diag_msg("line %lu: %s", app.line_no, text);
    app.status = 1;
}

void quote_line(char *out, size_t size, const char *bytes, size_t len)
{
    size_t o = 0u;
    size_t i;
    for (i = 0; i < len && o + 8u < size; i++) {
        unsigned char c = (unsigned char)bytes[i];
        if (o >= 80u) {
            memcpy(out + o, "...", 3u);
            o += 3u;
            break;
        }
        if (c >= 0x20u && c < 0x7Fu && c != '\\') {
            out[o++] = (char)c;
        } else {
            o += (size_t)snprintf(out + o, size - o, "\\x%02X", c);
        }
    }
    out[o] = '\0';
}

/* daran-sim: simulated Daran drives on a multi-drop line, driven from stdin
 * in lock-step (time moves only with `!advance`) or from a pseudo-terminal in
 * real time (--pty); with --can the drives also share a simulated CAN bus,
 * reached from stdin (`!can`) and from host adapters on pseudo-terminals
 * (--slcan, --usbcan); with --bridge the ASCII link reaches drive 1 alone,
 * a gateway whose lines for other ids cross the CAN bus. The interface is
 * described in docs/simulator.md and by --help; tests and users script it,
 * so it changes only compatibly. */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <inttypes.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "daran_sim.h"
#include "sim_can_pty.h"
#include "sim_can_text.h"
#include "sim_file_storage.h"
#include "sim_gateway.h"
#include "sim_pty.h"

#define MAX_ADVANCE_S 86400.0
#define MAX_TICK_HZ 100000u
#define DARAN_SIM_STR_(x) #x
#define DARAN_SIM_STR(x) DARAN_SIM_STR_(x)

/* A protocol line is kept (recorded, sent to the drives) up to one byte past
 * the drive's line buffer: a longer line is answered `line too long` by the
 * drives whatever its remaining bytes, so the rest need not be stored. */
#define PROTOCOL_KEEP ((size_t)DARAN_LINE_MAX + 1u)
/* Longest directive line (a longer `!#` comment is still just ignored). */
#define DIRECTIVE_MAX 1024u
/* Words of a directive, its name included (`!can` takes 10). */
#define DIRECTIVE_WORDS 16
/* Host adapters on pseudo-terminals: --slcan, --usbcan. */
#define CAN_PTYS 2u
/* Diagnostics on stderr: at most this many a second, the rest counted. */
#define DIAG_PER_SECOND 20u
/* --pty output waiting for the client: the pty is not read while this much
 * is pending; the queue holds that plus the replies of one line on every
 * drive (DARAN_SIM_OUT_MAX each) and telemetry. */
#define OUTQ_HIGH (1024u * 1024u)
#define OUTQ_CAP (OUTQ_HIGH + DARAN_SIM_MAX_DRIVES * DARAN_SIM_OUT_MAX + 256u * 1024u)

static const char usage_text[] =
    "Usage: daran-sim [OPTIONS] < session.txt\n"
    "Simulated Daran servo drives sharing one multi-drop serial line.\n"
    "\n"
    "Protocol lines read on stdin reach every drive; stdout carries exactly the\n"
    "bytes the drives send back: line by line in the order the requests came,\n"
    "the answers to one line in id order. Simulated time stands still unless\n"
    "a directive moves it, so every run is reproducible. stdout is flushed after\n"
    "every input line.\n"
    "\n"
    "Options:\n"
    "  --drives N         N drives on the line, ids 1..N (default 1, at most 16)\n"
    "  --nvm DIR          keep each drive's non-volatile memory in DIR/drive-K.nvm\n"
    "                     (K = 1..N), so a saved config survives a restart; the\n"
    "                     shaft angles are kept in DIR/drive-K.shaft (replaced\n"
    "                     whole at exit; a failed write is an error, exit 1). A\n"
    "                     stored config holding a value `w` would refuse boots\n"
    "                     on defaults with axis0.config_warnings bit 0\n"
    "  --tick-hz HZ       control tick rate, 1..100000 (default 1000)\n"
    "  --trace FILE.csv   write time_s and, per drive K, pos_deg_K, vel_rpm_K,\n"
    "                     torque_nm_K (torque setpoint) and state_K at every tick\n"
    "  --trace-every N    write the trace every N ticks only (default 1)\n"
    "  --pty              create a pseudo-terminal, print its path as the first\n"
    "                     line of stdout and run in real time: any serial program\n"
    "                     can open that path as the drives' port. stdin still takes\n"
    "                     directives and protocol lines (replies on stdout). Replies\n"
    "                     leave whole lines, in request order; while 1 MiB of them\n"
    "                     waits for a client that does not read, the port is not\n"
    "                     read (back-pressure, nothing dropped)\n"
    "  --record FILE      write every protocol line the drives receive (not the\n"
    "                     directives) to FILE as `SECONDS<TAB>line bytes` (the\n"
    "                     bytes before the newline, trailing spaces kept), after\n"
    "                     `#` header lines; SECONDS is the simulated time (moved\n"
    "                     by !advance), with --pty the real time since start.\n"
    "                     A line longer than the drives' " DARAN_SIM_STR(DARAN_LINE_MAX) " bytes is recorded as\n"
    "                     its first " DARAN_SIM_STR(DARAN_LINE_MAX) "+1 after a `# overlong line` comment.\n"
    "                     tools/replay plays such a file back\n"
    "  --echo             also print each request as \"> line\", each reply line as\n"
    "                     \"< line\" and each directive (for demos; stdout is then\n"
    "                     no longer the drives' bytes)\n"
    "  --can              the drives share a simulated CAN bus too (1 Mbit/s, the\n"
    "                     vendor's CAN protocol): stdin sends frames with !can and\n"
    "                     stdout shows each frame the console's node receives as\n"
    "                     \"can SECONDS ID [DLC] BYTES\" (hex)\n"
    "  --slcan            (implies --can) a pseudo-terminal speaking the Lawicel\n"
    "                     serial-line CAN protocol (slcand, python-can's slcan) as\n"
    "                     one more node on the bus; its path is printed on stdout\n"
    "                     (after --pty's) and the drives run in real time\n"
    "  --usbcan           (implies --can) the same for the vendor USB-CAN adapter's\n"
    "                     16-byte packets (DrEmpower_can.py); its path is printed\n"
    "                     after --slcan's\n"
    "  --bridge           (implies --can) the ASCII link (stdin or --pty) reaches\n"
    "                     drive 1 alone; its lines for other ids cross the CAN\n"
    "                     bus through drive 1's bridge. A query for another id\n"
    "                     holds the link's next line until its answer (or\n"
    "                     `error: no reply` after 10 ms a reply): in lock-step\n"
    "                     simulated time runs meanwhile\n"
    "  --help             show this text and exit\n";

/* (two strings: C99 compilers need take no longer literal than 4095 bytes) */
static const char usage_more[] =
    "\n"
    "Directives (lines starting with '!', never sent to the drives):\n"
    "  !advance SECONDS   run the control loop for SECONDS (rounded to ticks)\n"
    "  !power-cycle [ID]  power the drive off and on (fresh protocol instance,\n"
    "                     config from its non-volatile memory); default 0\n"
    "  !fault ID KIND     inject a fault; KIND is one of\n"
    "                     overtemp: temperatures jump 5 degC above their upper\n"
    "                       limits; enabled thermistors trip at the next tick\n"
    "                       (idle, axis0.error 0x40000, thermistor error 1)\n"
    "                     undervoltage: the bus sags for 0.1 s to 2 V below\n"
    "                       config.dc_bus_undervoltage_trip_level (8 V: to 6 V);\n"
    "                       trips at the next tick (idle, axis0.error 0x2)\n"
    "                     stall: the stall limiter trips at the next tick (idle,\n"
    "                       motor.error 0x10000, axis0.error 0x40), whether or\n"
    "                       not config.extra_setting.enable_stall_limit is on\n"
    "                     overspeed: the shaft is thrown to 1.5 x vel_limit x\n"
    "                       vel_limit_tolerance; with controller.config.\n"
    "                       enable_overspeed_error 1 (default 0) the next tick\n"
    "                       in closed loop trips (idle, controller.error 0x1,\n"
    "                       axis0.error 0x200); otherwise nothing trips: the\n"
    "                       controller brakes the shaft back under its limits\n"
    "                       (in idle it coasts down)\n"
    "                     nvm-corrupt: the stored config is damaged, found at\n"
    "                       the next boot: defaults, and axis0.config_warnings\n"
    "                       bit 0 (a warning: motion is not blocked)\n"
    "  !load ID NM        apply an external load torque of NM (-1000..1000) to the\n"
    "                     shaft; 0 removes it\n"
    "  !fault ID KIND     with --can, bus faults; KIND is one of\n"
    "                     can-lose [N]: the next N frames (default 1) the drive\n"
    "                       sends are lost (ID 0: the next N anyone sends)\n"
    "                     can-mute: the drive receives but sends nothing\n"
    "                     can-unplug: the drive is off the bus (its frames wait)\n"
    "                     can-bus-off: its sends fail, it receives nothing\n"
    "                     can-recover: its bus faults end\n"
    "                     ID 0: every node, the host adapters included (bus-off:\n"
    "                     the whole bus is down)\n"
    "  !can ID [BYTES]    with --can, the console's node sends a frame: ID hex\n"
    "                     (3 digits, or 8 for an extended id), BYTES hex, 0..8\n"
    "                     of them (R or Rn alone: a remote frame of DLC n)\n"
    "  !# TEXT            a comment, ignored\n"
    "  ID is a drive's current can_node_id; 0 means every drive.\n"
    "\n"
    "Messages from directives and bus collisions (two or more drives answering\n"
    "one line) go to stderr, at most 20 a second (then a count of the ones\n"
    "suppressed), never waiting for a stderr nobody reads. A bad directive is\n"
    "reported and skipped; the run goes on and ends with exit status 1. Bad\n"
    "options: exit status 2.\n"
    "\n"
    "SIGINT, SIGTERM and SIGHUP stop every mode within a tick or a line: the\n"
    "--record and --trace files keep every whole line written so far, the shaft\n"
    "files are written as at a normal exit (the NVM is written only by `ss`,\n"
    "never cut by a signal), and daran-sim then dies of the same signal (exit\n"
    "status 128+N in a shell).\n";

typedef struct sim_app {
    daran_sim_bus_t bus;
    daran_sim_file_storage_t files[DARAN_SIM_MAX_DRIVES];
    uint32_t lost_reported[DARAN_SIM_MAX_DRIVES]; /* out_lost already told */
    FILE *trace;
    FILE *record;
    double record_start_s;
    uint32_t trace_every;
    bool echo;
    bool pty;       /* --pty: the ASCII link on a pseudo-terminal */
    bool realtime;  /* a pseudo-terminal is open (--pty, --slcan, --usbcan): time is real */
    int pty_fd;
    unsigned long line_no;
    int status;
    /* --can: the drives' CAN bus, the console's node on it (`!can`, the
     * `can ...` lines on stdout) and the host adapters on pseudo-terminals */
    bool can_on;
    daran_sim_can_t can;
    uint32_t console_node;
    sim_can_pty_t can_pty[CAN_PTYS];
    uint32_t can_ptys;
    bool stdout_pending;                          /* console lines not yet flushed */
    uint32_t can_dropped_told[DARAN_SIM_MAX_DRIVES]; /* daran_can_dropped() already told */
    uint32_t can_unsent_told[DARAN_SIM_MAX_DRIVES];  /* daran_can_unsent() already told */
    unsigned long pty_dropped_told[CAN_PTYS];
    unsigned long pty_refused_told[CAN_PTYS];
    /* --bridge: drive 1 a gateway, and where the answer to the query it
     * waits for goes (the sink of the line that asked) */
    sim_gateway_t gateway;
    daran_sim_sink_fn asker;
} sim_app_t;

static sim_app_t app;
/* The signal that asked us to stop (SIGINT, SIGTERM, SIGHUP), else 0. */
static volatile sig_atomic_t stop_signal;

static void on_signal(int sig)
{
    stop_signal = sig;
}

static void on_alarm(int sig)
{
    (void)sig; /* only to interrupt a blocked write (EINTR) */
}

/* SIGALRM after @p ms (0: none). */
static void set_timer_ms(long ms)
{
    struct itimerval it;
    memset(&it, 0, sizeof it);
    it.it_value.tv_sec = ms / 1000;
    it.it_value.tv_usec = (ms % 1000) * 1000;
    (void)setitimer(ITIMER_REAL, &it, NULL);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- diagnostics: rate-limited, never blocking ----
 *
 * stderr may be a pipe nobody reads: a blocking write there would stop the
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

static void diag_init(void)
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

static bool diag_summary(void)
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
static void diag_tick(void)
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

static void diag_msg(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_v(false, fmt, ap);
    va_end(ap);
}

static void diag_urgent(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_v(true, fmt, ap);
    va_end(ap);
}

static void complain(const char *fmt, ...)
{
    char text[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    diag_msg("line %lu: %s", app.line_no, text);
    app.status = 1;
}

/* A line's bytes for a message: printable ASCII as is, others as \xNN, at
 * most about 80 characters. */
static void quote_line(char *out, size_t size, const char *bytes, size_t len)
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

static bool parse_uint(const char *text, unsigned long max, unsigned long *out)
{
    char *end;
    unsigned long v;
    if (text == NULL || *text < '0' || *text > '9') {
        return false;
    }
    errno = 0;
    v = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || v > max) {
        return false;
    }
    *out = v;
    return true;
}

/* ---- trace ---- */

static void trace_header(void)
{
    uint32_t i;
    fputs("time_s", app.trace);
    for (i = 1; i <= app.bus.count; i++) {
        fprintf(app.trace, ",pos_deg_%u,vel_rpm_%u,torque_nm_%u,state_%u", i, i, i, i);
    }
    fputc('\n', app.trace);
}

static void trace_row(void)
{
    uint32_t i;
    if (app.trace == NULL || app.bus.ticks % app.trace_every != 0u) {
        return;
    }
    fprintf(app.trace, "%.6f", (double)app.bus.ticks / (double)app.bus.tick_hz);
    for (i = 0; i < app.bus.count; i++) {
        const daran_sim_model_t *m = &app.bus.node[i].sim.model;
        fprintf(app.trace, ",%.6g,%.6g,%.6g,%u", (double)daran_sim_model_pos_deg(m),
                (double)m->vel_rpm, (double)m->torque_cmd, m->state);
    }
    fputc('\n', app.trace);
}

/* ---- replies ---- */

/* Reply bytes a drive could not hold (its output buffer full): never
 * silent. */
static void report_lost(void)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        uint32_t lost = app.bus.node[i].out_lost;
        if (lost != app.lost_reported[i]) {
            diag_msg("drive %u: %u reply bytes lost (its output buffer of %u bytes was full)",
                     daran_sim_drive_id(&app.bus.node[i].sim), lost - app.lost_reported[i],
                     DARAN_SIM_OUT_MAX);
            app.lost_reported[i] = lost;
        }
    }
}

/* A count that a power cycle may have restarted: what is new since @p told. */
static uint32_t news(uint32_t now, uint32_t *told)
{
    uint32_t fresh;
    if (now < *told) {
        *told = 0u;
    }
    fresh = now - *told;
    *told = now;
    return fresh;
}

/* CAN frames a drive lost (its receive ring full) or could not send, and
 * frames an adapter dropped or had refused: never silent. */
static void report_can(void)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        uint32_t id = daran_sim_drive_id(&app.bus.node[i].sim);
        uint32_t lost = news(daran_can_dropped(&app.can.front[i]), &app.can_dropped_told[i]);
        uint32_t unsent = news(daran_can_unsent(&app.can.front[i]), &app.can_unsent_told[i]);
        if (lost > 0u) {
            diag_msg("drive %u: %u CAN frames lost (its receive ring of %u frames was full)", id,
                     lost, (unsigned)DARAN_CAN_RX_FRAMES);
        }
        if (unsent > 0u) {
            diag_msg("drive %u: %u CAN frames not sent (bus-off, or its transmit queue full)", id,
                     unsent);
        }
    }
    for (i = 0; i < app.can_ptys; i++) {
        const sim_can_pty_t *p = &app.can_pty[i];
        if (p->dropped != app.pty_dropped_told[i]) {
            diag_msg("%s: %lu frames for the client dropped (it has not read %u KiB)",
                     sim_can_pty_option(p), p->dropped - app.pty_dropped_told[i],
                     (unsigned)(SIM_CAN_PTY_OUT_MAX / 1024u));
            app.pty_dropped_told[i] = p->dropped;
        }
        if (p->refused != app.pty_refused_told[i]) {
            diag_msg("%s: %lu of the client's frames refused (bus-off)", sim_can_pty_option(p),
                     p->refused - app.pty_refused_told[i]);
            app.pty_refused_told[i] = p->refused;
        }
    }
}

/* The console's node received a frame: a `can ...` line on stdout. */
static void console_receive(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    char line[SIM_CAN_TEXT_LINE_MAX];
    size_t n = sim_can_text_format(frame, end_ns, line);
    (void)ctx;
    fwrite(line, 1, n, stdout);
    app.stdout_pending = true;
}

static void sink_stdout(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
    app.stdout_pending = true; /* a tick's output is flushed in real time */
    if (!app.echo) {
        fwrite(bytes, 1, len, stdout);
        return;
    }
    while (len > 0u) {
        const char *nl = memchr(bytes, '\n', len);
        size_t n = nl != NULL ? (size_t)(nl - bytes) + 1u : len;
        fputs("< ", stdout);
        fwrite(bytes, 1, n, stdout);
        bytes += n;
        len -= n;
    }
}

/* --pty output: a bounded queue, written without blocking when the pty can
 * take bytes (POLLOUT). While OUTQ_HIGH bytes wait, the pty is not read, so
 * a client that does not read is slowed down instead of losing replies. */
static struct {
    char buf[OUTQ_CAP];
    size_t start;
    size_t len;
    unsigned long dropped_lines; /* whole lines that found the queue full, not yet told */
} outq;

static bool outq_put(const char *bytes, size_t len)
{
    if (len > OUTQ_CAP - outq.len) {
        return false;
    }
    if (outq.start + outq.len + len > OUTQ_CAP) {
        memmove(outq.buf, outq.buf + outq.start, outq.len);
        outq.start = 0u;
    }
    memcpy(outq.buf + outq.start + outq.len, bytes, len);
    outq.len += len;
    return true;
}

static void sink_pty(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
    if (outq_put(bytes, len)) {
        return;
    }
    /* Only telemetry can find the queue full (replies are made only below
     * OUTQ_HIGH): keep the whole lines that fit, count the others. */
    while (len > 0u) {
        const char *nl = memchr(bytes, '\n', len);
        size_t n = nl != NULL ? (size_t)(nl - bytes) + 1u : len;
        if (!outq_put(bytes, n)) {
            outq.dropped_lines++;
        }
        bytes += n;
        len -= n;
    }
}

static void outq_flush(void)
{
    while (outq.len > 0u) {
        ssize_t n = write(app.pty_fd, outq.buf + outq.start, outq.len);
        if (n > 0) {
            outq.start += (size_t)n;
            outq.len -= (size_t)n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            break; /* the client is not reading: wait for POLLOUT */
        } else {
            diag_msg("--pty: write failed (%s): %zu bytes of replies dropped",
                     n < 0 ? strerror(errno) : "nothing written", outq.len);
            outq.len = 0u;
        }
    }
    if (outq.len == 0u) {
        outq.start = 0u;
    }
}

/* Lines dropped are told at most once a second (and at the end), with
 * their count. */
static void outq_report(bool final)
{
    static double last_s = -1.0;
    double t = now_s();
    if (outq.dropped_lines > 0ul && (final || last_s < 0.0 || t - last_s >= 1.0)) {
        diag_urgent("--pty: %lu telemetry lines dropped: the client has not read the last "
                    "%u KiB of output",
                    outq.dropped_lines, (unsigned)(outq.len / 1024u));
        outq.dropped_lines = 0ul;
        last_s = t;
    }
}

typedef struct collect_ctx {
    daran_sim_sink_fn sink;
    uint32_t ids[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
} collect_ctx_t;

static void sink_recording(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    collect_ctx_t *c = ctx;
    if (c->n < DARAN_SIM_MAX_DRIVES) {
        c->ids[c->n++] = id;
    }
    c->sink(NULL, id, bytes, len);
}

/* After one line: hand its replies out (drives in id order); report a
 * collision on stderr when two or more drives answered that line. */
static void collect(daran_sim_sink_fn sink, const char *what, size_t what_len)
{
    collect_ctx_t c;
    char ids[DARAN_SIM_MAX_DRIVES * 4u + 1u];
    char quoted[100];
    size_t o = 0u;
    uint32_t i;
    c.sink = sink;
    c.n = 0u;
    if (daran_sim_bus_collect(&app.bus, sink_recording, &c) >= 2u) {
        for (i = 0; i < c.n; i++) {
            o += (size_t)snprintf(ids + o, sizeof ids - o, " %u", c.ids[i]);
        }
        quote_line(quoted, sizeof quoted, what, what_len);
        diag_msg("collision: %u drives answered `%s` (ids%s)", c.n, quoted, ids);
    }
    report_lost();
}

/* What the drives wrote while a tick (or the bus) ran goes out. Telemetry
 * reports leave after the tick that made them, so they interleave with
 * replies in time order; they are no collision (protocol.md 11.2:
 * streaming is for point-to-point links). So does the gateway's answer to a
 * bridged query, to the input that asked (it waited for it: @p answering). */
static void hand_out(bool answering)
{
    if (daran_sim_bus_collect(&app.bus, answering ? app.asker : app.pty ? sink_pty : sink_stdout,
                              NULL) > 0u) {
        report_lost();
    }
}

/* @p n control ticks; a signal stops the run between two ticks. */
static void run_ticks(uint64_t n)
{
    uint64_t k;
    for (k = 0; k < n && stop_signal == 0; k++) {
        bool answering = sim_gateway_busy(&app.gateway);
        if (app.can_on) {
            daran_sim_can_tick(&app.can); /* the bus, the line's tick, the front ends */
            sim_gateway_after_run(&app.gateway, &app.bus);
            report_can();
        } else {
            daran_sim_bus_tick(&app.bus);
        }
        trace_row();
        hand_out(answering);
    }
}

/* The simulated time of the next control tick, in nanoseconds. */
static uint64_t next_tick_ns(void)
{
    return daran_sim_can_tick_ns(&app.bus, app.bus.ticks + 1u);
}

/* --can: the bus alone runs on to @p sim_ns, inside the current tick (the
 * drives answer the frames that end by then); what that made goes out as
 * a tick's output does. */
static void run_bus(uint64_t sim_ns)
{
    bool answering = sim_gateway_busy(&app.gateway);
    if (app.can_on && daran_sim_can_bus_run(&app.can.wire, sim_ns) > 0u) {
        sim_gateway_after_run(&app.gateway, &app.bus);
        report_can();
        hand_out(answering);
    }
}

/* Lock-step --bridge: the line just sent left a query waiting; simulated
 * time runs, frame by frame inside a tick and tick by tick, until its
 * answer (or `error: no reply`) has come, so answers keep the order of the
 * lines and come in the bus's time, which the `can` lines show. */
static void wait_for_gateway(void)
{
    uint64_t limit = sim_gateway_wait_limit(app.bus.tick_hz);
    uint64_t ticks = 0u;
    while (sim_gateway_busy(&app.gateway) && ticks < limit && stop_signal == 0) {
        uint64_t frame_end = daran_sim_can_bus_next_ns(&app.can.wire);
        if (frame_end < next_tick_ns()) {
            run_bus(frame_end);
        } else {
            run_ticks(1u);
            ticks++;
        }
    }
    if (sim_gateway_busy(&app.gateway) && stop_signal == 0) {
        complain("drive 1's bridge still waits after %" PRIu64 " ticks (more than its timeouts)",
                 ticks);
    }
}

/* ---- --record ---- */

/* The header says how the session ran, so tools/replay can run it the same
 * way without being told. */
static void record_header(void)
{
    fputs("# Protocol lines received by daran-sim (--record): seconds since start, a tab,\n"
          "# then the exact bytes of the line before its \\n. Directives are not recorded.\n",
          app.record);
    fprintf(app.record, "# daran-sim --drives %u --tick-hz %u%s%s\n", app.bus.count,
            app.bus.tick_hz, app.gateway.on ? " --bridge" : "",
            app.pty ? " --pty (real time)" : app.realtime ? " (real time)" : "");
}

/* Simulated time in as many decimals as make it exact (4 at 1 kHz, 6 at
 * 8 kHz, at most 9), from the tick count in integers: replaying it gives back
 * the same tick for every line. */
static void record_sim_time(void)
{
    uint64_t hz = app.bus.tick_hz;
    uint64_t scale = 10000u;
    int digits = 4;
    uint64_t whole;
    uint64_t frac;
    while (digits < 9 && scale % hz != 0u) {
        scale *= 10u;
        digits++;
    }
    whole = app.bus.ticks / hz;
    frac = ((app.bus.ticks % hz) * scale + hz / 2u) / hz;
    if (frac >= scale) {
        whole++;
        frac -= scale;
    }
    fprintf(app.record, "%" PRIu64 ".%0*" PRIu64, whole, digits, frac);
}

/* One received line, without its '\n': @p kept of its @p total bytes (a
 * line longer than PROTOCOL_KEEP keeps only those, which the drives answer
 * as they would the whole line: `line too long`). */
static void record_line(const char *bytes, size_t kept, uint64_t total)
{
    if (app.record == NULL) {
        return;
    }
    if (total > kept) {
        fprintf(app.record,
                "# overlong line: %" PRIu64 " bytes before its \\n, the first %zu recorded "
                "(more than DARAN_LINE_MAX %u: the drives answer both `line too long`)\n",
                total, kept, (unsigned)DARAN_LINE_MAX);
    }
    if (app.realtime) {
        fprintf(app.record, "%.6f", now_s() - app.record_start_s);
    } else {
        record_sim_time();
    }
    fputc('\t', app.record);
    fwrite(bytes, 1, kept, app.record);
    fputc('\n', app.record);
    fflush(app.record); /* a killed session keeps what it received */
}

/* ---- directives ---- */

/* Indexes of the drives a directive's ID names; 0 when none. */
static uint32_t select_drives(const char *text, uint32_t out[DARAN_SIM_MAX_DRIVES])
{
    unsigned long id;
    uint32_t n = 0u;
    uint32_t i;
    if (!parse_uint(text, 255ul, &id)) {
        complain("bad drive id '%s' (a can_node_id, or 0 for every drive)", text);
        return 0u;
    }
    for (i = 0; i < app.bus.count; i++) {
        if (id == 0ul || daran_sim_drive_id(&app.bus.node[i].sim) == id) {
            out[n++] = i;
        }
    }
    if (n == 0u) {
        complain("no drive has id %lu", id);
    }
    return n;
}

/* `!fault ID can-...` (argv as directive() splits it). ID 0 is the bus
 * itself: every node, the host adapters included. */
static void can_fault(int argc, char **argv, daran_sim_can_fault_t fault)
{
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    unsigned long count = 1ul;
    unsigned long id;
    uint32_t n;
    uint32_t i;
    if (!app.can_on) {
        complain("!fault %s needs --can", argv[2]);
        return;
    }
    if (argc > (fault == DARAN_SIM_CAN_FAULT_LOSE ? 4 : 3)) {
        complain("usage: !fault ID %s", fault == DARAN_SIM_CAN_FAULT_LOSE ? "can-lose [N]" : argv[2]);
        return;
    }
    if (argc == 4 && (!parse_uint(argv[3], 1000000ul, &count) || count < 1ul)) {
        complain("bad count '%s' for can-lose (frames, 1..1000000)", argv[3]);
        return;
    }
    if (parse_uint(argv[1], 255ul, &id) && id == 0ul) {
        sel[0] = DARAN_SIM_CAN_ANY_NODE;
        n = 1u;
    } else {
        n = select_drives(argv[1], sel); /* drive i is node i of the bus */
    }
    for (i = 0; i < n; i++) {
        if (daran_sim_can_bus_fault(&app.can.wire, sel[i], fault, (uint32_t)count) != DARAN_OK) {
            complain("!fault %s: the bus refused it", argv[2]); /* a node it does not have */
        }
    }
}

/* `!can ID [BYTES...]`: the console's node sends a frame, at the current
 * simulated time. */
static void can_directive(int argc, char **argv)
{
    daran_can_frame_t frame;
    const char *why = NULL;
    if (!app.can_on) {
        complain("!can needs --can");
        return;
    }
    if (!sim_can_text_parse(argc - 1, argv + 1, &frame, &why)) {
        complain("!can: %s", why);
        return;
    }
    if (app.can.wire.bus_off || app.can.wire.node[app.console_node].bus_off) {
        diag_msg("line %lu: !can: the bus is off: frame %s not sent", app.line_no, argv[1]);
        return;
    }
    if (!daran_sim_can_bus_send(&app.can.wire, app.console_node, &frame)) {
        complain("!can: %u frames already wait to be sent (let time run with !advance)",
                 (unsigned)DARAN_SIM_CAN_TX_FRAMES);
    }
}

static void directive(char *line)
{
    char *argv[DIRECTIVE_WORDS];
    int argc = 0;
    char *save = NULL;
    char *tok;
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
    uint32_t i;

    if (line[1] == '#') {
        return;
    }
    for (tok = strtok_r(line + 1, " \t\r\n", &save); tok != NULL && argc < DIRECTIVE_WORDS;
         tok = strtok_r(NULL, " \t\r\n", &save)) {
        argv[argc++] = tok;
    }
    if (argc == 0) {
        complain("empty directive");
        return;
    }
    if (strcmp(argv[0], "advance") == 0) {
        char *end;
        double s;
        if (argc != 2) {
            complain("usage: !advance SECONDS");
            return;
        }
        errno = 0;
        s = strtod(argv[1], &end);
        if (errno != 0 || *end != '\0' || end == argv[1] || !(s >= 0.0) || s > MAX_ADVANCE_S) {
            complain("bad time '%s' for !advance (seconds, 0..%g)", argv[1], MAX_ADVANCE_S);
            return;
        }
        if (app.realtime) {
            complain("!advance has no meaning in real time (--pty, --slcan, --usbcan)");
            return;
        }
        run_ticks((uint64_t)llround(s * (double)app.bus.tick_hz));
    } else if (strcmp(argv[0], "power-cycle") == 0) {
        if (argc > 2) {
            complain("usage: !power-cycle [ID]");
            return;
        }
        n = select_drives(argc == 2 ? argv[1] : "0", sel);
        for (i = 0; i < n; i++) {
            daran_sim_bus_power_cycle(&app.bus, sel[i]);
        }
    } else if (strcmp(argv[0], "fault") == 0) {
        /* the library's fault injection, as a test would call it */
        daran_sim_fault_t fault;
        daran_sim_can_fault_t bus_fault;
        if (argc >= 3 && daran_sim_can_fault_from_name(argv[2], &bus_fault)) {
            can_fault(argc, argv, bus_fault);
            return;
        }
        if (argc != 3) {
            complain("usage: !fault ID %s", DARAN_SIM_FAULT_NAMES);
            return;
        }
        if (!daran_sim_fault_from_name(argv[2], &fault)) {
            complain("unknown fault '%s' (%s; with --can %s)", argv[2], DARAN_SIM_FAULT_NAMES,
                     DARAN_SIM_CAN_FAULT_NAMES);
            return;
        }
        n = select_drives(argv[1], sel);
        for (i = 0; i < n; i++) {
            daran_sim_drive_t *d = &app.bus.node[sel[i]].sim;
            if (daran_sim_drive_inject_fault(d, fault) != DARAN_OK) {
                complain("drive %u: its storage failed", daran_sim_drive_id(d));
            }
        }
    } else if (strcmp(argv[0], "load") == 0) {
        char *end;
        float nm;
        if (argc != 3) {
            complain("usage: !load ID NM");
            return;
        }
        errno = 0;
        nm = strtof(argv[2], &end);
        if (errno != 0 || *end != '\0' || end == argv[2] || !(fabsf(nm) <= 1000.0f)) {
            complain("bad torque '%s' for !load (Nm, -1000..1000)", argv[2]);
            return;
        }
        n = select_drives(argv[1], sel);
        for (i = 0; i < n; i++) {
            app.bus.node[sel[i]].sim.model.ext_torque_nm = nm;
        }
    } else if (strcmp(argv[0], "can") == 0) {
        can_directive(argc, argv);
    } else {
        complain("unknown directive '!%s' (see --help)", argv[0]);
    }
}

/* ---- input: whole lines, one at a time ----
 *
 * Each input (stdin, the pty) assembles its lines in a bounded buffer and
 * hands each to the drives whole, when its '\n' arrives, then collects the
 * replies of that line alone: replies leave in the order the requests came,
 * as on a real multi-drop line, a collision is a property of one line, and
 * lines from stdin and the pty never interleave inside the drives. A
 * protocol line keeps PROTOCOL_KEEP bytes (the drives answer a longer one
 * `line too long` whatever follows), a directive DIRECTIVE_MAX: memory does
 * not grow with a line that never ends. */

typedef struct line_source {
    bool directives;        /* lines starting with '!' are directives (stdin) */
    daran_sim_sink_fn sink; /* where the replies to its lines go */
    bool directive;         /* the current line is one */
    size_t kept;            /* bytes of the current line in line[] */
    uint64_t total;         /* bytes of the current line so far, before its '\n' */
    char line[DIRECTIVE_MAX + 2u];
} line_source_t;

static void source_init(line_source_t *s, bool directives, daran_sim_sink_fn sink)
{
    memset(s, 0, sizeof *s);
    s->directives = directives;
    s->sink = sink;
}

/* Bytes up to the end of the current line (its '\n' included, *ended set)
 * or all of them; returns how many were taken. */
static size_t source_take(line_source_t *s, const char *bytes, size_t len, bool *ended)
{
    const char *nl = memchr(bytes, '\n', len);
    size_t n = nl != NULL ? (size_t)(nl - bytes) : len;
    size_t room;
    if (s->total == 0u && n > 0u) {
        s->directive = s->directives && bytes[0] == '!';
    }
    room = (s->directive ? DIRECTIVE_MAX : PROTOCOL_KEEP) - s->kept;
    if (room > n) {
        room = n;
    }
    memcpy(s->line + s->kept, bytes, room);
    s->kept += room;
    s->total += n;
    *ended = nl != NULL;
    return nl != NULL ? n + 1u : n;
}

static void protocol_line(line_source_t *s)
{
    if (app.echo && s->sink == sink_stdout) { /* a pty client's lines are not echoed */
        fputs("> ", stdout);
        fwrite(s->line, 1, s->kept, stdout);
        fputc('\n', stdout);
    }
    record_line(s->line, s->kept, s->total);
    s->line[s->kept] = '\n';
    if (app.gateway.on) {
        daran_sim_bus_send_to(&app.bus, SIM_GATEWAY_INDEX, s->line, s->kept + 1u);
    } else {
        daran_sim_bus_send(&app.bus, s->line, s->kept + 1u);
    }
    collect(s->sink, s->line, s->kept);
    if (sim_gateway_busy(&app.gateway)) {
        app.asker = s->sink;
        if (!app.realtime) {
            wait_for_gateway();
        }
    }
}

static void directive_line(line_source_t *s)
{
    if (app.echo) {
        fwrite(s->line, 1, s->kept, stdout);
        fputc('\n', stdout);
    }
    if (s->total > s->kept) {
        if (s->line[1] != '#') {
            complain("directive longer than %u bytes: skipped", DIRECTIVE_MAX);
        }
        return;
    }
    s->line[s->kept] = '\0';
    directive(s->line);
}

/* The current line has ended (its '\n' arrived, or the input did). */
static void source_end_line(line_source_t *s)
{
    if (s->directives) {
        app.line_no++;
    }
    if (s->directive) {
        directive_line(s);
    } else {
        protocol_line(s);
    }
    if (s->sink == sink_stdout) {
        fflush(stdout);
    }
    s->kept = 0u;
    s->total = 0u;
    s->directive = false;
}

/* Every line of @p bytes, until a signal asks to stop. */
static void source_feed(line_source_t *s, const char *bytes, size_t len)
{
    while (len > 0u && stop_signal == 0) {
        bool ended;
        size_t n = source_take(s, bytes, len, &ended);
        if (ended) {
            source_end_line(s);
        }
        bytes += n;
        len -= n;
    }
}

/* A last line without its '\n' is taken as if it had one. */
static void source_eof(line_source_t *s)
{
    if (s->total > 0u && stop_signal == 0) {
        source_end_line(s);
    }
}

/* ---- lock-step mode ---- */

static line_source_t stdin_source;

/* stdin is polled (a signal's EINTR, or at worst the 250 ms timeout, ends
 * the wait) and read in chunks; lines are taken one at a time. */
static void run_lockstep(void)
{
    char buf[4096];
    source_init(&stdin_source, true, sink_stdout);
    while (stop_signal == 0) {
        struct pollfd p = {STDIN_FILENO, POLLIN, 0};
        ssize_t n;
        int r = poll(&p, 1, 250);
        if (r < 0 && errno != EINTR) {
            diag_urgent("stdin: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (r <= 0) {
            continue;
        }
        n = read(STDIN_FILENO, buf, sizeof buf);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) {
            continue;
        }
        if (n < 0) {
            diag_urgent("stdin: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (n == 0) {
            break;
        }
        source_feed(&stdin_source, buf, (size_t)n);
        diag_tick();
    }
    source_eof(&stdin_source);
}

/* ---- real time: --pty, --slcan, --usbcan ---- */

static line_source_t pty_source;

/* The pseudo-terminals' paths on stdout: the ASCII link's first, then the
 * adapters' in the order --slcan, --usbcan. */
static int open_links(int *slave_keep)
{
    char path[256];
    uint32_t k;
    if (app.pty) {
        app.pty_fd = sim_pty_open(path, sizeof path, slave_keep);
        if (app.pty_fd < 0) {
            fprintf(stderr, "daran-sim: cannot create a pseudo-terminal: %s\n", strerror(errno));
            return 1;
        }
        printf("%s\n", path);
    }
    for (k = 0; k < app.can_ptys; k++) {
        printf("%s\n", app.can_pty[k].path);
    }
    fflush(stdout);
    return 0;
}

/* After ticks: what the adapters and the console's node received goes out. */
static void flush_can_outputs(void)
{
    uint32_t k;
    for (k = 0; k < app.can_ptys; k++) {
        sim_can_pty_flush(&app.can_pty[k]);
    }
    if (app.stdout_pending) {
        fflush(stdout);
        app.stdout_pending = false;
    }
}

/* Bytes read from an input (the pty, stdin) wait here until their lines
 * may run; the input is not read again before they all have. */
typedef struct held_input {
    char buf[4096];
    size_t pos;
    size_t len;
} held_input_t;

/* Whether the next line of @p s may run now: not while drive 1's bridge
 * waits for an answer (--bridge: the line would wait in its ring), and for
 * the pty not while its replies pile up (back-pressure). */
static bool may_take_line(const line_source_t *s)
{
    return stop_signal == 0 && !sim_gateway_busy(&app.gateway) &&
           (s->sink != sink_pty || outq.len < OUTQ_HIGH);
}

/* One line at a time, its replies queued behind the earlier ones, while
 * lines may run. */
static void take_held(line_source_t *s, held_input_t *in)
{
    while (in->pos < in->len && may_take_line(s)) {
        bool ended;
        in->pos += source_take(s, in->buf + in->pos, in->len - in->pos, &ended);
        if (ended) {
            source_end_line(s);
        }
    }
}

/* Whether to read more of @p s: when what it held has run and a line could
 * run now. */
static bool wants_input(const line_source_t *s, const held_input_t *in)
{
    return in->pos == in->len && may_take_line(s);
}

static uint64_t mono_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* poll() with a timeout in nanoseconds (UINT64_MAX: none): pselect(), the
 * POSIX wait with a timespec, so the loop wakes for a tick or a frame's
 * end to the microsecond, not rounded up to poll()'s milliseconds. Only
 * POLLIN and POLLOUT are asked for and reported (a hang-up reads as
 * readable). -1 with EBADF for a descriptor an fd_set cannot hold (the
 * program's few are far below FD_SETSIZE). */
static int poll_ns(struct pollfd *pfd, size_t n, uint64_t timeout_ns)
{
    fd_set rd;
    fd_set wr;
    struct timespec ts;
    int top = -1;
    int r;
    size_t k;
    FD_ZERO(&rd);
    FD_ZERO(&wr);
    for (k = 0; k < n; k++) {
        if (pfd[k].fd >= FD_SETSIZE) {
            errno = EBADF;
            return -1;
        }
    }
    for (k = 0; k < n; k++) {
        if (pfd[k].fd >= 0 && (pfd[k].events & POLLIN) != 0) {
            FD_SET(pfd[k].fd, &rd);
        }
        if (pfd[k].fd >= 0 && (pfd[k].events & POLLOUT) != 0) {
            FD_SET(pfd[k].fd, &wr);
        }
        if (pfd[k].fd > top && (pfd[k].events & (POLLIN | POLLOUT)) != 0) {
            top = pfd[k].fd;
        }
    }
    ts.tv_sec = (time_t)(timeout_ns / 1000000000u);
    ts.tv_nsec = (long)(timeout_ns % 1000000000u);
    r = pselect(top + 1, &rd, &wr, NULL, timeout_ns == UINT64_MAX ? NULL : &ts, NULL);
    for (k = 0; k < n; k++) {
        pfd[k].revents = 0;
        if (r > 0 && pfd[k].fd >= 0 && FD_ISSET(pfd[k].fd, &rd)) {
            pfd[k].revents |= POLLIN;
        }
        if (r > 0 && pfd[k].fd >= 0 && FD_ISSET(pfd[k].fd, &wr)) {
            pfd[k].revents |= POLLOUT;
        }
    }
    return r;
}

/* Real time: simulated time t runs at the clock's pace from origin_ns
 * (the clock's reading at simulated time 0). */
static uint64_t origin_ns;

/* Simulated time catches up with the clock: the ticks that are due, then
 * the CAN bus to the present (the drives answer every frame that has
 * ended, whatever the tick rate); never past the next tick, which runs
 * first. After a suspension of more than a second the ticks missed are
 * skipped, not raced through. */
static void catch_up(void)
{
    uint64_t now = mono_ns();
    if (now - origin_ns > next_tick_ns() + 1000000000u) {
        origin_ns = now - next_tick_ns();
    }
    while (origin_ns + next_tick_ns() <= now && stop_signal == 0) {
        run_ticks(1u);
    }
    if (stop_signal == 0 && now - origin_ns > app.can.wire.now_ns) {
        run_bus(now - origin_ns);
    }
}

/* A frame's end closer than this is waited for by polling without a
 * timeout rather than in the kernel: a timed wake-up comes tens of
 * microseconds late on a busy machine, and a request and its answer are
 * two of them in a round trip of about 0.26 ms. Only while a frame is on
 * the bus, so an idle simulator does not spin. */
#define SPIN_BEFORE_FRAME_END_NS 150000u

/* How long the loop may sleep: until the next tick, or the next frame's
 * end on the bus, whichever comes first; not at all when that end is near. */
static uint64_t sleep_ns(void)
{
    uint64_t wake = origin_ns + next_tick_ns();
    uint64_t now = mono_ns();
    bool frame_first = false;
    if (app.can_on) {
        uint64_t frame_end = daran_sim_can_bus_next_ns(&app.can.wire);
        if (frame_end != UINT64_MAX && origin_ns + frame_end < wake) {
            wake = origin_ns + frame_end;
            frame_first = true;
        }
    }
    if (wake <= now || (frame_first && wake - now <= SPIN_BEFORE_FRAME_END_NS)) {
        return 0u;
    }
    return wake - now;
}

static int run_realtime(void)
{
    /* the ASCII pty, stdin, then the CAN adapters */
    struct pollfd pfd[2u + CAN_PTYS];
    int slave_keep = -1;
    static held_input_t pty_in;
    static held_input_t stdin_in;
    bool stdin_open = true;
    uint32_t k;

    app.pty_fd = -1;
    if (open_links(&slave_keep) != 0) {
        return 1;
    }
#ifdef __linux__
    /* wake-ups on time to the microsecond: the default slack is 50 us */
    (void)prctl(PR_SET_TIMERSLACK, 1ul, 0ul, 0ul, 0ul);
#endif
    source_init(&pty_source, false, sink_pty);
    source_init(&stdin_source, true, sink_stdout);
    origin_ns = mono_ns() - daran_sim_can_tick_ns(&app.bus, app.bus.ticks);
    while (stop_signal == 0) {
        bool want_pty = wants_input(&pty_source, &pty_in);
        bool want_stdin = stdin_open && wants_input(&stdin_source, &stdin_in);
        pfd[0].fd = app.pty_fd; /* a negative descriptor is skipped */
        pfd[0].events = (short)((want_pty ? POLLIN : 0) | (outq.len > 0u ? POLLOUT : 0));
        pfd[1].fd = want_stdin ? STDIN_FILENO : -1;
        pfd[1].events = POLLIN;
        for (k = 0; k < app.can_ptys; k++) {
            pfd[2u + k].fd = app.can_pty[k].fd;
            pfd[2u + k].events = sim_can_pty_events(&app.can_pty[k]);
        }
        if (poll_ns(pfd, 2u + app.can_ptys, sleep_ns()) < 0 && errno != EINTR) {
            diag_urgent("pselect: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (stop_signal != 0) {
            break;
        }
        /* time first: what the inputs bring comes at the present */
        catch_up();
        if (outq.len > 0u) {
            outq_flush();
        }
        if (want_pty && (pfd[0].revents & POLLIN) != 0) {
            ssize_t n = read(app.pty_fd, pty_in.buf, sizeof pty_in.buf);
            if (n > 0) {
                pty_in.pos = 0u;
                pty_in.len = (size_t)n;
            }
        }
        take_held(&pty_source, &pty_in);
        if (outq.len > 0u) {
            outq_flush();
        }
        if (want_stdin && (pfd[1].revents & POLLIN) != 0) {
            ssize_t n = read(STDIN_FILENO, stdin_in.buf, sizeof stdin_in.buf);
            if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) {
                source_eof(&stdin_source); /* nothing held, no query waiting */
                stdin_open = false;        /* keep serving the ptys */
            } else if (n > 0) {
                stdin_in.pos = 0u;
                stdin_in.len = (size_t)n;
            }
        }
        take_held(&stdin_source, &stdin_in);
        /* the adapters' frames join the bus now */
        for (k = 0; k < app.can_ptys; k++) {
            sim_can_pty_serve(&app.can_pty[k], pfd[2u + k].revents);
        }
        if (outq.len > 0u) {
            outq_flush();
        }
        flush_can_outputs();
        outq_report(false);
        diag_tick();
    }
    outq_report(true);
    if (slave_keep >= 0) {
        close(slave_keep);
    }
    if (app.pty_fd >= 0) {
        close(app.pty_fd);
    }
    return 0;
}

/* ---- setup ---- */

/* With --nvm the shaft angles persist too (DIR/drive-K.shaft): the shaft
 * does not turn while the program is not running, so a zero set with `sz`
 * and saved still reads 0 after a restart. */
static void shaft_file(char *path, size_t size, const char *dir, uint32_t index)
{
    snprintf(path, size, "%s/drive-%u.shaft", dir, index + 1u);
}

static void load_shafts(const char *dir)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        FILE *f;
        float angle;
        shaft_file(path, sizeof path, dir, i);
        f = fopen(path, "r");
        if (f == NULL) {
            if (errno != ENOENT) {
                diag_msg("--nvm: cannot read %s (%s): the shaft starts at 0 deg", path,
                         strerror(errno));
            }
            continue;
        }
        if (fscanf(f, "%f", &angle) == 1 && isfinite(angle)) {
            app.bus.node[i].sim.model.raw_pos_deg = angle;
            daran_sim_bus_power_cycle(&app.bus, i);
        } else {
            diag_msg("--nvm: %s holds no shaft angle: the shaft starts at 0 deg", path);
        }
        fclose(f);
    }
}

/* Each file is replaced whole: written beside it, then renamed over it, so
 * whenever the program stops (a signal, a kill) a shaft file holds the old
 * angle or the new one, never a part. False (and said on stderr) when one
 * could not be written. */
static bool save_shafts(const char *dir)
{
    bool ok = true;
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        char tmp[4200];
        FILE *f;
        int err = 0;
        shaft_file(path, sizeof path, dir, i);
        snprintf(tmp, sizeof tmp, "%s.tmp", path);
        f = fopen(tmp, "w");
        if (f == NULL) {
            err = errno;
        } else {
            if (fprintf(f, "%.9g\n", (double)app.bus.node[i].sim.model.raw_pos_deg) < 0 ||
                fflush(f) != 0) {
                err = errno != 0 ? errno : EIO;
            }
            if (fclose(f) != 0 && err == 0) {
                err = errno;
            }
            if (err == 0 && rename(tmp, path) != 0) {
                err = errno;
            }
            if (err != 0) {
                (void)unlink(tmp);
            }
        }
        if (err != 0) {
            diag_urgent("--nvm: cannot write %s: %s", path, strerror(err));
            ok = false;
        }
    }
    return ok;
}

static int open_nvm(const char *dir)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        daran_sim_storage_t st;
        int n = snprintf(path, sizeof path, "%s/drive-%u.nvm", dir, i + 1u);
        if (n < 0 || (size_t)n >= sizeof path) {
            fprintf(stderr, "daran-sim: --nvm path too long\n");
            return 2;
        }
        if (!daran_sim_file_storage_open(&app.files[i], path, &st)) {
            fprintf(stderr, "daran-sim: --nvm: cannot open %s: %s\n", path, strerror(errno));
            return 2;
        }
        daran_sim_bus_set_storage(&app.bus, i, &st);
        if (app.bus.node[i].sim.nvm_status == DARAN_SIM_NVM_DAMAGED) {
            diag_msg("--nvm: %s is damaged or holds a value out of range: drive %u boots on "
                     "defaults (axis0.config_warnings bit 0)",
                     path, i + 1u);
        }
    }
    return 0;
}

/* A closed stdin, stdout or stderr becomes /dev/null, so that no file this
 * program opens (an NVM file) takes its number and receives messages. */
static void keep_std_fds(void)
{
    int fd;
    for (fd = 0; fd <= 2; fd++) {
        if (fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
            int null = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
            if (null >= 0 && null != fd) {
                (void)dup2(null, fd);
                (void)close(null);
            }
        }
    }
}

/* --can: the drives' front ends on the bus, the console's node, drive 1's
 * bridge with --bridge, and the adapters asked for (which, as --bridge,
 * imply --can). Exit status 2 when one cannot be set up. */
static int start_can(bool slcan, bool usbcan)
{
    static const sim_can_pty_kind_t kinds[CAN_PTYS] = {SIM_CAN_PTY_SLCAN, SIM_CAN_PTY_USBCAN};
    bool wanted[CAN_PTYS];
    uint32_t k;
    wanted[0] = slcan;
    wanted[1] = usbcan;
    app.can_on = true;
    if (daran_sim_can_attach(&app.can, &app.bus) != DARAN_OK) {
        fprintf(stderr, "daran-sim: --can: the drives' CAN front ends refused their port\n");
        return 2;
    }
    app.console_node = daran_sim_can_bus_add_node(&app.can.wire, console_receive, NULL);
    if (app.gateway.on) {
        sim_gateway_start(&app.gateway, &app.can);
        if (app.gateway.refused > 0u) {
            fprintf(stderr, "daran-sim: --bridge: drive 1's bridge refused its front end\n");
            return 2;
        }
    }
    for (k = 0; k < CAN_PTYS; k++) {
        sim_can_pty_t *p = &app.can_pty[app.can_ptys];
        if (!wanted[k]) {
            continue;
        }
        if (!sim_can_pty_open(p, kinds[k], &app.can.wire)) {
            fprintf(stderr, "daran-sim: %s: cannot create a pseudo-terminal: %s\n",
                    kinds[k] == SIM_CAN_PTY_SLCAN ? "--slcan" : "--usbcan", strerror(errno));
            return 2;
        }
        app.can_ptys++;
    }
    return 0;
}

static int bad_option(const char *fmt, const char *arg)
{
    fputs("daran-sim: ", stderr);
    fprintf(stderr, fmt, arg);
    fputs("\nTry 'daran-sim --help'.\n", stderr);
    return 2;
}

static void on_signals(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction sa;
    size_t k;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: a blocked read or write returns EINTR */
    for (k = 0; k < sizeof sigs / sizeof sigs[0]; k++) {
        (void)sigaction(sigs[k], &sa, NULL);
    }
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"drives", required_argument, NULL, 'd'},
        {"nvm", required_argument, NULL, 'n'},
        {"tick-hz", required_argument, NULL, 't'},
        {"trace", required_argument, NULL, 'r'},
        {"trace-every", required_argument, NULL, 'e'},
        {"pty", no_argument, NULL, 'p'},
        {"echo", no_argument, NULL, 'E'},
        {"record", required_argument, NULL, 'R'},
        {"can", no_argument, NULL, 'c'},
        {"slcan", no_argument, NULL, 's'},
        {"usbcan", no_argument, NULL, 'u'},
        {"bridge", no_argument, NULL, 'b'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    unsigned long drives = 1ul;
    unsigned long tick_hz = 1000ul;
    unsigned long every = 1ul;
    const char *nvm_dir = NULL;
    const char *trace_path = NULL;
    const char *record_path = NULL;
    bool slcan = false;
    bool usbcan = false;
    int c;
    int rc;
    uint32_t i;

    /* a closed stdout or pty is an error return, not a death (--help | grep -q
     * included) */
    signal(SIGPIPE, SIG_IGN);
    keep_std_fds();
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        switch (c) {
        case 'd':
            if (!parse_uint(optarg, DARAN_SIM_MAX_DRIVES, &drives) || drives < 1ul) {
                return bad_option("--drives takes a number of drives 1..16, not '%s'", optarg);
            }
            break;
        case 'n':
            nvm_dir = optarg;
            break;
        case 't':
            if (!parse_uint(optarg, MAX_TICK_HZ, &tick_hz) || tick_hz < 1ul) {
                return bad_option("--tick-hz takes a rate 1..100000 Hz, not '%s'", optarg);
            }
            break;
        case 'r':
            trace_path = optarg;
            break;
        case 'e':
            if (!parse_uint(optarg, 1000000000ul, &every) || every < 1ul) {
                return bad_option("--trace-every takes a number of ticks >= 1, not '%s'", optarg);
            }
            break;
        case 'p':
            app.pty = true;
            break;
        case 'E':
            app.echo = true;
            break;
        case 'R':
            record_path = optarg;
            break;
        case 'c':
            app.can_on = true;
            break;
        case 's':
            slcan = true;
            break;
        case 'u':
            usbcan = true;
            break;
        case 'b':
            app.gateway.on = true;
            break;
        case 'h':
            fputs(usage_text, stdout);
            fputs(usage_more, stdout);
            return 0;
        default:
            if (optopt != 0) {
                size_t k;
                for (k = 0; opts[k].name != NULL; k++) {
                    if (opts[k].val == optopt) {
                        return bad_option("option '--%s' needs a value", opts[k].name);
                    }
                }
            }
            return bad_option("unknown option or missing value: '%s'", argv[optind - 1]);
        }
    }
    if (optind < argc) {
        return bad_option("unexpected argument '%s'", argv[optind]);
    }

    on_signals();
    diag_init();

    if (daran_sim_bus_init(&app.bus, (uint32_t)drives, (uint32_t)tick_hz) != DARAN_OK) {
        return bad_option("cannot set up %s drives", "the");
    }
    for (i = 0; i < DARAN_SIM_MAX_DRIVES; i++) {
        app.files[i].fd = -1;
    }
    if (nvm_dir != NULL) {
        if ((rc = open_nvm(nvm_dir)) != 0) {
            return rc;
        }
        load_shafts(nvm_dir);
    }
    app.trace_every = (uint32_t)every;
    if (trace_path != NULL) {
        app.trace = fopen(trace_path, "w");
        if (app.trace == NULL) {
            fprintf(stderr, "daran-sim: --trace: cannot write %s: %s\n", trace_path,
                    strerror(errno));
            return 2;
        }
        trace_header();
        trace_row();
    }
    if (app.can_on || slcan || usbcan || app.gateway.on) {
        if ((rc = start_can(slcan, usbcan)) != 0) {
            return rc;
        }
    }
    app.realtime = app.pty || app.can_ptys > 0u;
    if (record_path != NULL) {
        app.record = fopen(record_path, "w");
        if (app.record == NULL) {
            fprintf(stderr, "daran-sim: --record: cannot write %s: %s\n", record_path,
                    strerror(errno));
            return 2;
        }
        record_header();
        app.record_start_s = now_s();
    }

    if (app.realtime) {
        rc = run_realtime();
        if (rc != 0) {
            app.status = rc;
        }
    } else {
        run_lockstep();
    }

    /* The same ending for a signal as for the end of input: the files are
     * closed whole, the shaft angles written. After a signal, a stdout
     * nobody reads may hold the last replies back for at most 0.25 s. */
    if (stop_signal != 0) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_alarm;
        sigemptyset(&sa.sa_mask);
        (void)sigaction(SIGALRM, &sa, NULL);
        set_timer_ms(250);
    }
    (void)fflush(stdout);
    set_timer_ms(0);
    if (app.trace != NULL && fclose(app.trace) != 0) {
        diag_urgent("--trace: write failed");
        app.status = 1;
    }
    if (app.record != NULL) {
        bool failed = ferror(app.record) != 0;
        if (fclose(app.record) != 0 || failed) {
            diag_urgent("--record: write failed");
            app.status = 1;
        }
    }
    if (nvm_dir != NULL && !save_shafts(nvm_dir)) {
        app.status = 1;
    }
    for (i = 0; i < DARAN_SIM_MAX_DRIVES; i++) {
        daran_sim_file_storage_close(&app.files[i]);
    }
    for (i = 0; i < app.can_ptys; i++) {
        sim_can_pty_close(&app.can_pty[i]);
    }
    (void)diag_summary();
    if (stop_signal != 0) {
        /* die of the signal, as a program that did not catch it would: the
         * shell sees 128 + N, a parent WIFSIGNALED */
        int sig = (int)stop_signal;
        signal(sig, SIG_DFL);
        raise(sig);
        return 128 + sig;
    }
    return app.status;
}

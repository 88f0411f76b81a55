/* daran-sim: simulated Daran drives on a multi-drop line, driven from stdin
 * in lock-step (time moves only with `!advance`) or from a pseudo-terminal in
 * real time (--pty). The interface is described in docs/simulator.md and by
 * --help; tests and users script it, so it changes only compatibly. */
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
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "sim_bus.h"
#include "sim_file_storage.h"

#define MAX_ADVANCE_S 86400.0
#define MAX_TICK_HZ 100000u

static const char usage_text[] =
    "Usage: daran-sim [OPTIONS] < session.txt\n"
    "Simulated Daran servo drives sharing one multi-drop serial line.\n"
    "\n"
    "Protocol lines read on stdin reach every drive; stdout carries exactly the\n"
    "bytes the drives send back, in id order. Simulated time stands still unless\n"
    "a directive moves it, so every run is reproducible. stdout is flushed after\n"
    "every input line.\n"
    "\n"
    "Options:\n"
    "  --drives N         N drives on the line, ids 1..N (default 1, at most 16)\n"
    "  --nvm DIR          keep each drive's non-volatile memory in DIR/drive-K.nvm\n"
    "                     (K = 1..N), so a saved config survives a restart; the\n"
    "                     shaft angles are kept in DIR/drive-K.shaft\n"
    "  --tick-hz HZ       control tick rate, 1..100000 (default 1000)\n"
    "  --trace FILE.csv   write time_s and, per drive K, pos_deg_K, vel_rpm_K,\n"
    "                     torque_nm_K (torque setpoint) and state_K at every tick\n"
    "  --trace-every N    write the trace every N ticks only (default 1)\n"
    "  --pty              create a pseudo-terminal, print its path as the first\n"
    "                     line of stdout and run in real time: any serial program\n"
    "                     can open that path as the drives' port. stdin still takes\n"
    "                     directives and protocol lines (replies on stdout); ends\n"
    "                     on SIGINT or SIGTERM\n"
    "  --record FILE      write every protocol line the drives receive (not the\n"
    "                     directives) to FILE as `SECONDS<TAB>line bytes` (the\n"
    "                     bytes before the newline, trailing spaces kept), after\n"
    "                     `#` header lines; SECONDS is the simulated time (moved\n"
    "                     by !advance), with --pty the real time since start.\n"
    "                     tools/replay plays such a file back\n"
    "  --echo             also print each request as \"> line\", each reply line as\n"
    "                     \"< line\" and each directive (for demos; stdout is then\n"
    "                     no longer the drives' bytes)\n"
    "  --help             show this text and exit\n"
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
    "  !# TEXT            a comment, ignored\n"
    "  ID is a drive's current can_node_id; 0 means every drive.\n"
    "\n"
    "Messages from directives and bus collisions (two or more drives answering\n"
    "one line) go to stderr. A bad directive is reported on stderr and skipped;\n"
    "the run goes on and ends with exit status 1. Bad options: exit status 2.\n";

typedef struct sim_app {
    daran_sim_bus_t bus;
    daran_sim_file_storage_t files[DARAN_SIM_MAX_DRIVES];
    FILE *trace;
    FILE *record;
    double record_start_s;
    char *record_partial; /* --pty: bytes of a line not yet ended */
    size_t record_partial_len;
    size_t record_partial_cap;
    uint32_t trace_every;
    bool echo;
    bool pty;
    int pty_fd;
    unsigned long line_no;
    int status;
} sim_app_t;

static sim_app_t app;
static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

static void complain(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "daran-sim: line %lu: ", app.line_no);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    app.status = 1;
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

static void sink_stdout(void *ctx, uint32_t id, const char *bytes, size_t len);
static void sink_pty(void *ctx, uint32_t id, const char *bytes, size_t len);

/* Telemetry reports leave after the tick that made them, so they interleave
 * with replies in time order; they are no collision (protocol.md 11.2:
 * streaming is for point-to-point links). */
static void run_ticks(uint64_t n)
{
    uint64_t k;
    for (k = 0; k < n; k++) {
        daran_sim_bus_tick(&app.bus);
        trace_row();
        (void)daran_sim_bus_collect(&app.bus, app.pty ? sink_pty : sink_stdout, NULL);
    }
}

/* ---- --record ---- */

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The header says how the session ran, so tools/replay can run it the same
 * way without being told. */
static void record_header(void)
{
    fputs("# Protocol lines received by daran-sim (--record): seconds since start, a tab,\n"
          "# then the exact bytes of the line before its \\n. Directives are not recorded.\n",
          app.record);
    fprintf(app.record, "# daran-sim --drives %u --tick-hz %u%s\n", app.bus.count,
            app.bus.tick_hz, app.pty ? " --pty (real time)" : "");
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

/* One received line, without its '\n'. */
static void record_line(const char *bytes, size_t len)
{
    if (app.record == NULL) {
        return;
    }
    if (app.pty) {
        fprintf(app.record, "%.6f", now_s() - app.record_start_s);
    } else {
        record_sim_time();
    }
    fputc('\t', app.record);
    fwrite(bytes, 1, len, app.record);
    fputc('\n', app.record);
    fflush(app.record); /* a killed session keeps what it received */
}

/* Bytes from the pty arrive in any chunks: a line is recorded when its '\n'
 * arrives (a line never ended by the end of the run is not recorded). */
static void record_bytes(const char *bytes, size_t len)
{
    while (app.record != NULL && len > 0u) {
        const char *nl = memchr(bytes, '\n', len);
        size_t n = nl != NULL ? (size_t)(nl - bytes) : len;
        /* >=: the buffer exists even for an empty line (no NULL to memcpy) */
        if (app.record_partial_len + n >= app.record_partial_cap) {
            size_t cap = app.record_partial_len + n + 256u;
            char *grown = realloc(app.record_partial, cap);
            if (grown == NULL) {
                return;
            }
            app.record_partial = grown;
            app.record_partial_cap = cap;
        }
        memcpy(app.record_partial + app.record_partial_len, bytes, n);
        app.record_partial_len += n;
        if (nl == NULL) {
            return;
        }
        record_line(app.record_partial, app.record_partial_len);
        app.record_partial_len = 0u;
        bytes += n + 1u;
        len -= n + 1u;
    }
}

/* ---- replies ---- */

static void write_all(int fd, const char *bytes, size_t len)
{
    while (len > 0u) {
        ssize_t n = write(fd, bytes, len);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return; /* nobody reading (pty full or closed): the bytes are lost */
        }
        bytes += n;
        len -= (size_t)n;
    }
}

static void sink_stdout(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
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

static void sink_pty(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
    write_all(app.pty_fd, bytes, len);
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

/* Hand the replies out in id order; report a collision on stderr. */
static void collect(daran_sim_sink_fn sink, const char *what, size_t what_len)
{
    collect_ctx_t c;
    uint32_t i;
    c.sink = sink;
    c.n = 0u;
    if (daran_sim_bus_collect(&app.bus, sink_recording, &c) < 2u) {
        return;
    }
    fprintf(stderr, "daran-sim: collision: %u drives answered", c.n);
    if (what != NULL) {
        fprintf(stderr, " `%.*s`", (int)what_len, what);
    }
    fputs(" (ids", stderr);
    for (i = 0; i < c.n; i++) {
        fprintf(stderr, " %u", c.ids[i]);
    }
    fputs(")\n", stderr);
}

/* ---- directives ---- */

/* `!fault ID KIND`: the model's injections, and the NVM's. */
static const struct {
    const char *name;
    daran_sim_fault_t kind;
    bool nvm;
} faults[] = {
    {"overtemp", DARAN_SIM_FAULT_OVERTEMP, false},
    {"undervoltage", DARAN_SIM_FAULT_UNDERVOLTAGE, false},
    {"stall", DARAN_SIM_FAULT_STALL, false},
    {"overspeed", DARAN_SIM_FAULT_OVERSPEED, false},
    {"nvm-corrupt", DARAN_SIM_FAULT_OVERTEMP, true},
};
#define FAULT_NAMES "overtemp, undervoltage, stall, overspeed, nvm-corrupt"

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

static void directive(char *line)
{
    char *argv[8];
    int argc = 0;
    char *save = NULL;
    char *tok;
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
    uint32_t i;

    if (line[1] == '#') {
        return;
    }
    for (tok = strtok_r(line + 1, " \t\r\n", &save); tok != NULL && argc < 8;
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
        if (app.pty) {
            complain("!advance has no meaning in --pty mode (time is real)");
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
        size_t k;
        if (argc != 3) {
            complain("usage: !fault ID %s", FAULT_NAMES);
            return;
        }
        for (k = 0; k < sizeof faults / sizeof faults[0]; k++) {
            if (strcmp(argv[2], faults[k].name) == 0) {
                break;
            }
        }
        if (k == sizeof faults / sizeof faults[0]) {
            complain("unknown fault '%s' (%s)", argv[2], FAULT_NAMES);
            return;
        }
        n = select_drives(argv[1], sel);
        for (i = 0; i < n; i++) {
            daran_sim_drive_t *d = &app.bus.node[sel[i]].sim;
            if (!faults[k].nvm) {
                daran_sim_model_fault(&d->model, faults[k].kind);
            } else if (!daran_sim_drive_corrupt_nvm(d)) {
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
    } else {
        complain("unknown directive '!%s' (see --help)", argv[0]);
    }
}

/* One line from stdin: a directive, or bytes for the drives (with its '\n'). */
static void handle_input_line(char *line, size_t len)
{
    app.line_no++;
    if (len > 0u && line[0] == '!') {
        if (app.echo) {
            fwrite(line, 1, len, stdout);
        }
        line[len - (line[len - 1u] == '\n' ? 1u : 0u)] = '\0';
        directive(line);
    } else {
        if (app.echo) {
            fputs("> ", stdout);
            fwrite(line, 1, len, stdout);
        }
        record_line(line, len > 0u && line[len - 1u] == '\n' ? len - 1u : len);
        daran_sim_bus_send(&app.bus, line, len);
        collect(sink_stdout, line, len > 0u && line[len - 1u] == '\n' ? len - 1u : len);
    }
    fflush(stdout);
}

/* ---- lock-step mode ---- */

static void run_lockstep(void)
{
    char *line = NULL;
    size_t cap = 0u;
    ssize_t got;
    while ((got = getline(&line, &cap, stdin)) >= 0) {
        size_t len = (size_t)got;
        if (len == 0u || line[len - 1u] != '\n') {
            /* a last line without its '\n' is taken as if it had one */
            char *grown = realloc(line, len + 2u);
            if (grown == NULL) {
                break;
            }
            line = grown;
            line[len++] = '\n';
            line[len] = '\0';
        }
        handle_input_line(line, len);
    }
    free(line);
}

/* ---- real-time pty mode ---- */

static int open_pty(char *path, size_t path_size, int *slave_keep)
{
    struct termios tio;
    const char *name;
    int fd = posix_openpt(O_RDWR | O_NOCTTY);
    if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0 || (name = ptsname(fd)) == NULL) {
        return -1;
    }
    snprintf(path, path_size, "%s", name);
    /* Holding the slave open ourselves keeps the master readable (no
     * hang-up) while no client has the port open. */
    *slave_keep = open(path, O_RDWR | O_NOCTTY);
    if (*slave_keep >= 0 && tcgetattr(*slave_keep, &tio) == 0) {
        cfmakeraw(&tio);
        (void)tcsetattr(*slave_keep, TCSANOW, &tio);
    }
    (void)fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    return fd;
}

static int run_pty(void)
{
    char path[256];
    int slave_keep = -1;
    double period = 1.0 / (double)app.bus.tick_hz;
    double next;
    char *stdin_buf = NULL;
    size_t stdin_len = 0u;
    size_t stdin_cap = 0u;
    bool stdin_open = true;

    app.pty_fd = open_pty(path, sizeof path, &slave_keep);
    if (app.pty_fd < 0) {
        fprintf(stderr, "daran-sim: cannot create a pseudo-terminal: %s\n", strerror(errno));
        return 1;
    }
    printf("%s\n", path);
    fflush(stdout);
    next = now_s() + period;
    while (!stop_requested) {
        struct pollfd pfd[2];
        double wait = next - now_s();
        int timeout = wait <= 0.0 ? 0 : (int)ceil(wait * 1000.0);
        nfds_t nfds = 1;
        pfd[0].fd = app.pty_fd;
        pfd[0].events = POLLIN;
        pfd[1].fd = STDIN_FILENO;
        pfd[1].events = POLLIN;
        if (stdin_open) {
            nfds = 2;
        }
        if (poll(pfd, nfds, timeout) < 0 && errno != EINTR) {
            break;
        }
        if ((pfd[0].revents & POLLIN) != 0) {
            char buf[512];
            ssize_t n = read(app.pty_fd, buf, sizeof buf);
            if (n > 0) {
                record_bytes(buf, (size_t)n);
                daran_sim_bus_send(&app.bus, buf, (size_t)n);
                collect(sink_pty, NULL, 0u);
            }
        }
        if (stdin_open && (pfd[1].revents & (POLLIN | POLLHUP)) != 0) {
            char buf[512];
            ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
            if (n <= 0) {
                stdin_open = false; /* keep serving the pty */
            } else {
                char *nl;
                if (stdin_len + (size_t)n + 1u > stdin_cap) {
                    char *grown = realloc(stdin_buf, stdin_len + (size_t)n + 1u);
                    if (grown == NULL) {
                        break;
                    }
                    stdin_buf = grown;
                    stdin_cap = stdin_len + (size_t)n + 1u;
                }
                memcpy(stdin_buf + stdin_len, buf, (size_t)n);
                stdin_len += (size_t)n;
                while ((nl = memchr(stdin_buf, '\n', stdin_len)) != NULL) {
                    size_t len = (size_t)(nl - stdin_buf) + 1u;
                    char saved = stdin_buf[len];
                    stdin_buf[len] = '\0';
                    handle_input_line(stdin_buf, len);
                    stdin_buf[len] = saved;
                    memmove(stdin_buf, stdin_buf + len, stdin_len - len);
                    stdin_len -= len;
                }
            }
        }
        {
            double t = now_s();
            if (t - next > 1.0) {
                next = t; /* fell far behind (suspended): do not race to catch up */
            }
            while (next <= t) {
                run_ticks(1u);
                next += period;
            }
        }
    }
    free(stdin_buf);
    if (slave_keep >= 0) {
        close(slave_keep);
    }
    close(app.pty_fd);
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
            continue;
        }
        if (fscanf(f, "%f", &angle) == 1 && isfinite(angle)) {
            app.bus.node[i].sim.model.raw_pos_deg = angle;
            daran_sim_bus_power_cycle(&app.bus, i);
        }
        fclose(f);
    }
}

static void save_shafts(const char *dir)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        FILE *f;
        shaft_file(path, sizeof path, dir, i);
        f = fopen(path, "w");
        if (f != NULL) {
            fprintf(f, "%.9g\n", (double)app.bus.node[i].sim.model.raw_pos_deg);
            fclose(f);
        }
    }
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
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    unsigned long drives = 1ul;
    unsigned long tick_hz = 1000ul;
    unsigned long every = 1ul;
    const char *nvm_dir = NULL;
    const char *trace_path = NULL;
    const char *record_path = NULL;
    int c;
    int rc;
    uint32_t i;

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
        case 'h':
            fputs(usage_text, stdout);
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

    signal(SIGPIPE, SIG_IGN);
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);

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

    if (app.pty) {
        rc = run_pty();
        if (rc != 0) {
            app.status = rc;
        }
    } else {
        run_lockstep();
    }

    if (app.trace != NULL && fclose(app.trace) != 0) {
        fprintf(stderr, "daran-sim: --trace: write failed\n");
        app.status = 1;
    }
    if (app.record != NULL) {
        bool failed = ferror(app.record) != 0;
        if (fclose(app.record) != 0 || failed) {
            fprintf(stderr, "daran-sim: --record: write failed\n");
            app.status = 1;
        }
    }
    free(app.record_partial);
    if (nvm_dir != NULL) {
        save_shafts(nvm_dir);
    }
    for (i = 0; i < DARAN_SIM_MAX_DRIVES; i++) {
        daran_sim_file_storage_close(&app.files[i]);
    }
    return app.status;
}

/* daran-sim in real time (sim_realtime.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_realtime.h"

#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "sim_app.h"
#include "sim_diag.h"
#include "sim_lines.h"
#include "sim_outq.h"
#include "sim_pty.h"
#include "sim_replies.h"
#include "sim_time.h"
#include "sim_wait.h"

static line_source_t pty_source;
static line_source_t stdin_source;

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
           (s->sink != sink_pty || outq_has_room());
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

/* How long the loop may sleep: until the next tick, or the next frame's
 * end on the bus (sim_wait_ns()). */
static uint64_t sleep_ns(void)
{
    uint64_t frame_end = app.can_on ? daran_sim_can_bus_next_ns(&app.can.wire) : UINT64_MAX;
    return sim_wait_ns(mono_ns(), origin_ns + next_tick_ns(),
                       frame_end == UINT64_MAX ? UINT64_MAX : origin_ns + frame_end);
}

/* The pollfd set of one wait: the ASCII pty (@p pfd[0]), stdin ([1]), then
 * the CAN adapters. */
typedef struct watch {
    struct pollfd pfd[2u + CAN_PTYS];
    bool want_pty;
    bool want_stdin;
} watch_t;

static held_input_t pty_in;
static held_input_t stdin_in;
static bool stdin_open;

/* What to wait for: input from whichever may take a line, the pty's and the
 * adapters' output while some waits. */
static void watch_set(watch_t *w)
{
    uint32_t k;
    w->want_pty = wants_input(&pty_source, &pty_in);
    w->want_stdin = stdin_open && wants_input(&stdin_source, &stdin_in);
    w->pfd[0].fd = app.pty_fd; /* a negative descriptor is skipped */
    w->pfd[0].events = (short)((w->want_pty ? POLLIN : 0) | (outq_pending() > 0u ? POLLOUT : 0));
    w->pfd[1].fd = w->want_stdin ? STDIN_FILENO : -1;
    w->pfd[1].events = POLLIN;
    for (k = 0; k < app.can_ptys; k++) {
        w->pfd[2u + k].fd = app.can_pty[k].fd;
        w->pfd[2u + k].events = sim_can_pty_events(&app.can_pty[k]);
    }
}

/* stdin's bytes, if it has some; its end (or an error) closes it. */
static void read_stdin(void)
{
    ssize_t n = read(STDIN_FILENO, stdin_in.buf, sizeof stdin_in.buf);
    if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) {
        source_eof(&stdin_source); /* nothing held, no query waiting */
        stdin_open = false;        /* keep serving the ptys */
    } else if (n > 0) {
        stdin_in.pos = 0u;
        stdin_in.len = (size_t)n;
    }
}

/* After a wait: time first (what the inputs bring comes at the present),
 * then the inputs, then the outputs. */
static void serve(const watch_t *w)
{
    uint32_t k;
    catch_up();
    if (outq_pending() > 0u) {
        outq_flush();
    }
    if (w->want_pty && (w->pfd[0].revents & POLLIN) != 0) {
        ssize_t n = read(app.pty_fd, pty_in.buf, sizeof pty_in.buf);
        if (n > 0) {
            pty_in.pos = 0u;
            pty_in.len = (size_t)n;
        }
    }
    take_held(&pty_source, &pty_in);
    if (outq_pending() > 0u) {
        outq_flush();
    }
    if (w->want_stdin && (w->pfd[1].revents & POLLIN) != 0) {
        read_stdin();
    }
    take_held(&stdin_source, &stdin_in);
    /* the adapters' frames join the bus now */
    for (k = 0; k < app.can_ptys; k++) {
        sim_can_pty_serve(&app.can_pty[k], w->pfd[2u + k].revents);
    }
    if (outq_pending() > 0u) {
        outq_flush();
    }
    flush_can_outputs();
    outq_report(false);
    diag_tick();
}

int run_realtime(void)
{
    watch_t w;
    int slave_keep = -1;

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
    stdin_open = true;
    origin_ns = mono_ns() - daran_sim_can_tick_ns(&app.bus, app.bus.ticks);
    while (stop_signal == 0) {
        watch_set(&w);
        if (poll_ns(w.pfd, 2u + app.can_ptys, sleep_ns()) < 0 && errno != EINTR) {
            diag_urgent("pselect: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (stop_signal != 0) {
            break;
        }
        serve(&w);
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

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
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "sim_app.h"
#include "sim_diag.h"
#include "sim_lockstep.h"
#include "sim_nvm_dir.h"
#include "sim_options.h"
#include "sim_realtime.h"
#include "sim_record.h"
#include "sim_replies.h"

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

/* The drives, the files and the CAN bus the options ask for; -1, or the
 * exit status when one cannot be set up (said on stderr). */
static int setup(const sim_options_t *o)
{
    uint32_t i;
    int rc;
    app.pty = o->pty;
    app.echo = o->echo;
    app.can_on = o->can;
    app.gateway.on = o->bridge;
    if (daran_sim_bus_init(&app.bus, (uint32_t)o->drives, (uint32_t)o->tick_hz) != DARAN_OK) {
        fputs("daran-sim: cannot set up the drives\nTry 'daran-sim --help'.\n", stderr);
        return 2;
    }
    for (i = 0; i < DARAN_SIM_MAX_DRIVES; i++) {
        app.files[i].fd = -1;
    }
    if (o->nvm_dir != NULL) {
        if ((rc = open_nvm(o->nvm_dir)) != 0) {
            return rc;
        }
        load_shafts(o->nvm_dir);
    }
    app.trace_every = (uint32_t)o->every;
    if (o->trace_path != NULL) {
        app.trace = fopen(o->trace_path, "w");
        if (app.trace == NULL) {
            fprintf(stderr, "daran-sim: --trace: cannot write %s: %s\n", o->trace_path,
                    strerror(errno));
            return 2;
        }
        trace_header();
        trace_row();
    }
    if (app.can_on || o->slcan || o->usbcan || app.gateway.on) {
        if ((rc = start_can(o->slcan, o->usbcan)) != 0) {
            return rc;
        }
    }
    app.realtime = app.pty || app.can_ptys > 0u;
    if (o->record_path != NULL) {
        app.record = fopen(o->record_path, "w");
        if (app.record == NULL) {
            fprintf(stderr, "daran-sim: --record: cannot write %s: %s\n", o->record_path,
                    strerror(errno));
            return 2;
        }
        record_header();
        app.record_start_s = now_s();
    }
    return -1;
}

/* The same ending for a signal as for the end of input: the files are
 * closed whole, the shaft angles written; the exit status. */
static int finish(const sim_options_t *o)
{
    uint32_t i;
    /* After a signal, a stdout nobody reads may hold the last replies back
     * for at most 0.25 s. */
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
    if (o->nvm_dir != NULL && !save_shafts(o->nvm_dir)) {
        app.status = 1;
    }
    for (i = 0; i < DARAN_SIM_MAX_DRIVES; i++) {
        daran_sim_file_storage_close(&app.files[i]);
    }
    for (i = 0; i < app.can_ptys; i++) {
        sim_can_pty_close(&app.can_pty[i]);
    }
    (void)diag_summary();
    return app.status;
}

int main(int argc, char **argv)
{
    sim_options_t o;
    int rc;

    /* a closed stdout or pty is an error return, not a death (--help | grep -q
     * included) */
    signal(SIGPIPE, SIG_IGN);
    keep_std_fds();
    if ((rc = sim_options_parse(argc, argv, &o)) >= 0) {
        return rc;
    }
    on_signals();
    diag_init();
    if ((rc = setup(&o)) >= 0) {
        return rc;
    }
    if (app.realtime) {
        rc = run_realtime();
        if (rc != 0) {
            app.status = rc;
        }
    } else {
        run_lockstep();
    }
    rc = finish(&o);
    if (stop_signal != 0) {
        /* die of the signal, as a program that did not catch it would: the
         * shell sees 128 + N, a parent WIFSIGNALED */
        int sig = (int)stop_signal;
        signal(sig, SIG_DFL);
        raise(sig);
        return 128 + sig;
    }
    return rc;
}

/* daran-sim's command line (sim_options.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_options.h"

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_sim.h"

#define MAX_ADVANCE_S 86400.0
#define MAX_TICK_HZ 100000u
#define DARAN_SIM_STR_(x) #x
#define DARAN_SIM_STR(x) DARAN_SIM_STR_(x)

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

bool parse_uint(const char *text, unsigned long max, unsigned long *out)
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

static int bad_option(const char *fmt, const char *arg)
{
    fputs("daran-sim: ", stderr);
    fprintf(stderr, fmt, arg);
    fputs("\nTry 'daran-sim --help'.\n", stderr);
    return 2;
}

static const struct option options[] = {
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

/* An option that takes a number; -1, or 2 when @p arg is not one. */
static int number_option(int c, const char *arg, sim_options_t *o)
{
    switch (c) {
    case 'd':
        if (!parse_uint(arg, DARAN_SIM_MAX_DRIVES, &o->drives) || o->drives < 1ul) {
            return bad_option("--drives takes a number of drives 1..16, not '%s'", arg);
        }
        break;
    case 't':
        if (!parse_uint(arg, MAX_TICK_HZ, &o->tick_hz) || o->tick_hz < 1ul) {
            return bad_option("--tick-hz takes a rate 1..100000 Hz, not '%s'", arg);
        }
        break;
    default: /* 'e' */
        if (!parse_uint(arg, 1000000000ul, &o->every) || o->every < 1ul) {
            return bad_option("--trace-every takes a number of ticks >= 1, not '%s'", arg);
        }
        break;
    }
    return -1;
}

/* getopt_long()'s '?': an unknown option, or a known one without its value. */
static int unknown_option(char **argv)
{
    if (optopt != 0) {
        size_t k;
        for (k = 0; options[k].name != NULL; k++) {
            if (options[k].val == optopt) {
                return bad_option("option '--%s' needs a value", options[k].name);
            }
        }
    }
    return bad_option("unknown option or missing value: '%s'", argv[optind - 1]);
}

/* Option @p c (getopt_long()'s answer) with its @p arg; -1, or the exit
 * status. */
static int take_option(int c, const char *arg, char **argv, sim_options_t *o)
{
    switch (c) {
    case 'd':
    case 't':
    case 'e':
        return number_option(c, arg, o);
    case 'n': o->nvm_dir = arg; break;
    case 'r': o->trace_path = arg; break;
    case 'R': o->record_path = arg; break;
    case 'p': o->pty = true; break;
    case 'E': o->echo = true; break;
    case 'c': o->can = true; break;
    case 's': o->slcan = true; break;
    case 'u': o->usbcan = true; break;
    case 'b': o->bridge = true; break;
    case 'h':
        fputs(usage_text, stdout);
        fputs(usage_more, stdout);
        return 0;
    default:
        return unknown_option(argv);
    }
    return -1;
}

int sim_options_parse(int argc, char **argv, sim_options_t *o)
{
    int c;
    memset(o, 0, sizeof *o);
    o->drives = 1ul;
    o->tick_hz = 1000ul;
    o->every = 1ul;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", options, NULL)) != -1) {
        int status = take_option(c, optarg, argv, o);
        if (status >= 0) {
            return status;
        }
    }
    if (optind < argc) {
        return bad_option("unexpected argument '%s'", argv[optind]);
    }
    return -1;
}

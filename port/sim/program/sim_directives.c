/* daran-sim's directives (sim_directives.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_directives.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim_app.h"
#include "sim_can_text.h"
#include "sim_diag.h"
#include "sim_options.h"
#include "sim_time.h"

#define MAX_ADVANCE_S 86400.0
/* Words of a directive, its name included (`!can` takes 10). */
#define DIRECTIVE_WORDS 16

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

/* `!advance SECONDS`: lock-step only. */
static void advance_directive(int argc, char **argv)
{
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
}

/* `!power-cycle [ID]` */
static void power_cycle_directive(int argc, char **argv)
{
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
    uint32_t i;
    if (argc > 2) {
        complain("usage: !power-cycle [ID]");
        return;
    }
    n = select_drives(argc == 2 ? argv[1] : "0", sel);
    for (i = 0; i < n; i++) {
        daran_sim_bus_power_cycle(&app.bus, sel[i]);
    }
}

/* `!fault ID KIND`: the library's fault injection, as a test would call it,
 * or with --can a bus fault. */
static void fault_directive(int argc, char **argv)
{
    daran_sim_fault_t fault;
    daran_sim_can_fault_t bus_fault;
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
    uint32_t i;
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
}

/* `!load ID NM` */
static void load_directive(int argc, char **argv)
{
    uint32_t sel[DARAN_SIM_MAX_DRIVES];
    uint32_t n;
    uint32_t i;
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
}

static const struct {
    const char *name;
    void (*run)(int argc, char **argv);
} directives[] = {
    {"advance", advance_directive},
    {"power-cycle", power_cycle_directive},
    {"fault", fault_directive},
    {"load", load_directive},
    {"can", can_directive},
};

void directive(char *line)
{
    char *argv[DIRECTIVE_WORDS];
    int argc = 0;
    char *save = NULL;
    char *tok;
    size_t k;

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
    for (k = 0; k < sizeof directives / sizeof directives[0]; k++) {
        if (strcmp(argv[0], directives[k].name) == 0) {
            directives[k].run(argc, argv);
            return;
        }
    }
    complain("unknown directive '!%s' (see --help)", argv[0]);
}

/* What both fuzz targets (lines and frames) share: the build's property
 * table as they read it (from the public lists compiled with the adopter's
 * options header), what daran_hal.h promises the HAL about each call, and
 * the test port's start and a violation's report. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "daran_fuzz.h"
#include "daran_recorder.h"
#include "daran_test_port.h"

typedef struct prop_row {
    bool writable;
    daran_prop_type_t type;
    uint32_t can_address; /* 0: none */
} prop_row_t;

#define DARAN_FUZZ_WRITABLE_RW true
#define DARAN_FUZZ_WRITABLE_RO false
#define DARAN_FUZZ_ROW(id, path, scope, type, access, range, unit, can) \
    [DARAN_PROP_##id] = {DARAN_FUZZ_WRITABLE_##access, DARAN_TYPE_##type, can},
static const prop_row_t rows[DARAN_PROP_COUNT] = {
    DARAN_PROPERTY_LIST(DARAN_FUZZ_ROW)
#ifdef DARAN_PORT_PROPERTY_LIST
    DARAN_PORT_PROPERTY_LIST(DARAN_FUZZ_ROW)
#endif
};

#ifdef DARAN_OMIT_PROPERTIES
#define DARAN_FUZZ_OMITTED(id) [DARAN_PROP_##id] = true,
static const bool omitted[DARAN_PROP_COUNT] = {DARAN_OMIT_PROPERTIES(DARAN_FUZZ_OMITTED)};
#else
static const bool omitted[DARAN_PROP_COUNT] = {false};
#endif

bool daran_fuzz_prop_omitted(daran_prop_t prop)
{
    return (unsigned)prop < (unsigned)DARAN_PROP_COUNT && omitted[prop];
}

bool daran_fuzz_can_row(uint32_t address, daran_prop_t *prop)
{
    for (size_t i = 0; address != 0u && i < DARAN_PROP_COUNT; i++) {
        if (rows[i].can_address == address && !omitted[i]) {
            *prop = (daran_prop_t)i;
            return true;
        }
    }
    return false;
}

unsigned daran_fuzz_can_type_code(daran_prop_t prop)
{
    switch (rows[prop].type) {
    case DARAN_TYPE_F32:
        return 0u;
    case DARAN_TYPE_S32:
        return 4u;
    default:
        return 3u; /* u32 and bool */
    }
}

static bool finite_move(const daran_move_t *m)
{
    return isfinite(m->pos_deg) && isfinite(m->vel_rpm) && isfinite(m->torque_nm) &&
           isfinite(m->rate) && isfinite(m->kp) && isfinite(m->kd);
}

const char *daran_fuzz_call_problem(const daran_call_t *c, bool state_known, bool may_move)
{
    static char text[160];
    switch (c->kind) {
    case DARAN_CALL_GET:
    case DARAN_CALL_SET:
        if ((unsigned)c->prop >= (unsigned)DARAN_PROP_COUNT) {
            (void)snprintf(text, sizeof text, "a HAL call for property id %d, outside the build's table",
                           (int)c->prop);
            return text;
        }
        if (omitted[c->prop]) {
            (void)snprintf(text, sizeof text,
                           "a HAL call for property id %d, which the options header leaves out",
                           (int)c->prop);
            return text;
        }
        if (c->kind == DARAN_CALL_GET) {
            return NULL;
        }
        if (!rows[c->prop].writable) {
            (void)snprintf(text, sizeof text, "a set() of read-only property id %d", (int)c->prop);
            return text;
        }
        if (rows[c->prop].type == DARAN_TYPE_F32 && !isfinite(c->value.f32)) {
            (void)snprintf(text, sizeof text, "a set() of property id %d to a value that is not finite",
                           (int)c->prop);
            return text;
        }
        if (rows[c->prop].type == DARAN_TYPE_BOOL && c->value.u32 > 1u) {
            (void)snprintf(text, sizeof text, "a set() of bool property id %d to %u", (int)c->prop,
                           (unsigned)c->value.u32);
            return text;
        }
        return NULL;
    case DARAN_CALL_MOVE:
        if ((unsigned)c->move.kind > (unsigned)DARAN_MOVE_IMPEDANCE) {
            (void)snprintf(text, sizeof text, "a move() of kind %d", (int)c->move.kind);
            return text;
        }
        if (!finite_move(&c->move)) {
            return "a move() with a value that is not finite";
        }
        if (state_known && !may_move) {
            return "a move() while the drive was idle or had a blocking flag (the port's getters "
                   "said so before the request)";
        }
        return NULL;
    case DARAN_CALL_ACTION:
        if ((unsigned)c->action > (unsigned)DARAN_ACTION_NODE_GUARD) {
            (void)snprintf(text, sizeof text, "an action() %d", (int)c->action);
            return text;
        }
        return NULL;
    }
    (void)snprintf(text, sizeof text, "a logged call of kind %d", (int)c->kind);
    return text;
}

/* ---- the test port's start, a violation's report ---- */

static const char *input_name;

void daran_fuzz_set_input_name(const char *name)
{
    input_name = name;
}

const char *daran_fuzz_port_problem(const daran_test_port_t *port)
{
    if (port == NULL || port->hal == NULL || port->reset == NULL || port->hal->get == NULL ||
        port->hal->set == NULL || port->hal->move == NULL || port->hal->action == NULL) {
        return "daran_test_port() gave no port, or one without its HAL (all four functions) "
               "and reset()";
    }
    return NULL;
}

const char *daran_fuzz_start_drive(const daran_test_port_t *port, daran_recorder_t *rec,
                                   daran_drive_t *drive, const daran_hal_t *shim)
{
    if (!port->reset(port->ctx)) {
        return "the test port's reset() failed";
    }
    daran_recorder_init(rec, port->hal, port->ctx);
    rec->log_gets = true;
    if (daran_init(drive, shim, rec) != DARAN_OK) {
        return "daran_init() refused the drive: is the harness built against the core's "
               "options header?";
    }
    return NULL;
}

void daran_fuzz_report_violation(const char *front_end, const daran_test_port_t *port,
                                 const char *fmt, va_list ap)
{
    fprintf(stderr, "\nDARAN FUZZ INVARIANT VIOLATED (%sport \"%s\"%s%s): ", front_end,
            port != NULL && port->name != NULL ? port->name : "?",
            input_name != NULL ? ", input " : "", input_name != NULL ? input_name : "");
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void daran_fuzz_report_calls(const daran_recorder_t *rec, const char *label)
{
    static char text[4096];
    (void)daran_recorder_describe(rec, text, sizeof text);
    fputs(label, stderr);
    for (const char *c = text; *c != '\0'; c++) {
        if (*c == '\n') {
            fprintf(stderr, "\n%*s", (int)strlen(label), ""); /* one call a line, aligned */
        } else {
            fputc(*c, stderr);
        }
    }
    fputc('\n', stderr);
}

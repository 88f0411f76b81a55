/* Per command family: valid motion lines reach the HAL as the right move
 * (C10) and leave their targets readable (C11); actions (C12); queries
 * (C13); the drive-state contract of st, sc, error registers, sz, node id
 * and requested_state (C14-C19); motion refused while e-stopped or idle
 * (C34); starts without a preset (C35). Also the table of families the
 * bad-input checks vary. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conformance.h"

/* ---- the families ---- */

static const conf_family_t fixed_families[] = {
    /* word, setup, valid, motion, multi, help, query,
     * too few, too many, malformed, out of range (and its setup), bad mode (and its setup) */
    {"t", NULL, "t {id} 10 0 25", true, false, false, false, "t {id}", "t {id} 10 0 25 1",
     "t {id} 1x0", "t {id} 10 0 -1", NULL, NULL, NULL},
    {"q", NULL, "q {id} 90 120 60", true, false, false, false, "q {id}", "q {id} 90 120 60 1",
     "q {id} 90 abc", "q {id} 90 0 10", NULL, NULL, NULL},
    {"p", NULL, "p {id} 45 10 0.5", true, false, false, false, "p {id}", "p {id} 45 10 0.5 1",
     "p {id} 45 10 0.5.1", "p {id} 1e39", NULL, NULL, NULL},
    {"v", NULL, "v {id} 30 5 2", true, false, false, false, "v {id}", "v {id} 30 5 2 1",
     "v {id} 3o", "v {id} 30 -1 2", NULL, "v {id} 30 0 7", NULL},
    {"c", NULL, "c {id} 0.5 2 6", true, false, false, false, "c {id}", "c {id} 0.5 2 6 1",
     "c {id} 0.5 2 x", "c {id} 0.5 -2 6", NULL, "c {id} 0.5 1 3", NULL},
    {"d", NULL, "d {id} 10 0 0.5 0.1 0.01", true, false, false, false, "d {id} 10 0 0.5 0.1",
     "d {id} 10 0 0.5 0.1 0.01 1", "d {id} 10 0 0.5 0.1 0.0.1", "d {id} 10 0 0.5 -0.1 0.01",
     NULL, NULL, NULL},
#if DARAN_ENABLE_MULTI_MOTOR
    {"ms", NULL, "ms {id} 120 5 10", false, true, false, false, "ms {id} 120 5",
     "ms {id} 120 5 10 1", "ms {id} 120 5 1O", "ms {id} 1e39 5 10", NULL, NULL, NULL},
    {"mt", "ms {id} 120 5 10", "mt {id} 0", true, true, false, false, "mt {id}", "mt {id} 0 1",
     "mt {id} 0.5", "mt {id} 0", "ms {id} 120 5 -10", "mt {id} 2", "ms {id} 120 5 10"},
    {"mq", "ms {id} 90 5 10", "mq {id} 1", true, true, false, false, "mq {id}", "mq {id} 1 1",
     "mq {id} x", "mq {id} 1", "ms {id} 90 -5 10", "mq {id} 3", "ms {id} 90 5 10"},
    {"mp", "ms {id} 45 10 0.5", "mp {id} 0", true, true, false, false, "mp {id}", "mp {id} 0 0",
     "mp {id} 1.5", NULL, NULL, "mp {id} 7", "ms {id} 45 10 0.5"},
    {"mv", "ms {id} 30 5 2", "mv {id}", true, true, false, false, "mv", "mv {id} 1", NULL,
     "mv {id}", "ms {id} 30 -5 2", "mv {id}", "ms {id} 30 5 7"},
    {"mc", "ms {id} 0.5 2 6", "mc {id}", true, true, false, false, "mc", "mc {id} 1", NULL,
     "mc {id}", "ms {id} 0.5 -2 6", "mc {id}", "ms {id} 0.5 2 5"},
#endif
    {"ss", NULL, "ss {id}", false, false, false, false, "ss", "ss {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"se", NULL, "se {id}", false, false, false, false, "se", "se {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"sr", NULL, "sr {id}", false, false, false, false, "sr", "sr {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"sc", NULL, "sc {id}", false, false, false, false, "sc", "sc {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"sz", NULL, "sz {id}", false, false, false, false, "sz", "sz {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"st", NULL, "st {id}", false, false, false, false, "st", "st {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"u", NULL, "u {id}", false, false, false, false, "u", "u {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"f", NULL, "f {id}", false, false, false, true, "f", "f {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"g", NULL, "g {id}", false, false, false, true, "g", "g {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"i", NULL, "i {id}", false, false, false, true, "i", "i {id} 1", NULL, NULL, NULL, NULL, NULL},
    {"e", NULL, "e {id}", false, false, false, true, "e", "e {id} 1", NULL, NULL, NULL, NULL, NULL},
#if DARAN_ENABLE_DISCOVERY
    {"h", NULL, "h {id}", false, false, true, true, "h", "h {id} properties x y", "h {id} props",
     NULL, NULL, NULL, NULL},
#elif DARAN_ENABLE_HELP
    /* without discovery `h` takes nothing after the id */
    {"h", NULL, "h {id}", false, false, true, true, "h", "h {id} properties", NULL, NULL, NULL,
     NULL, NULL},
#endif
};

#define FIXED_COUNT (sizeof fixed_families / sizeof fixed_families[0])
#define FAMILIES_MAX (FIXED_COUNT + 4u)

static conf_family_t families[FAMILIES_MAX];
static size_t family_count;
/* the r and w lines, made from the build's properties */
static char rw_lines[4][7][200];

static daran_prop_t pick(bool axis, bool writable, const daran_prop_t *preferred, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        const conf_prop_t *p = &conf_props[preferred[i]];
        if (conf_in_build(preferred[i]) && p->axis == axis && !p->read_refused &&
            (!writable || p->write_ok)) {
            return preferred[i];
        }
    }
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        const conf_prop_t *p = &conf_props[i];
        if (conf_in_build((daran_prop_t)i) && p->axis == axis && !p->read_refused &&
            (!writable || (p->write_ok && p->rw && i != DARAN_PROP_CAN_NODE_ID &&
                           i != DARAN_PROP_REQUESTED_STATE))) {
            return (daran_prop_t)i;
        }
    }
    return DARAN_PROP_COUNT;
}

/* Add the r or w family of one property (axis path or trailing id). */
static void add_property_family(size_t slot, bool write, daran_prop_t prop)
{
    if (prop == DARAN_PROP_COUNT) {
        return;
    }
    const conf_prop_t *p = &conf_props[prop];
    char (*l)[200] = rw_lines[slot];
    conf_family_t *f = &families[family_count++];
    memset(f, 0, sizeof *f);
    f->word = write ? "w" : "r";
    /* the id text goes where a motor id goes: axis{id}. or the last field */
    char path[128];
    if (p->axis) {
        (void)snprintf(path, sizeof path, "axis{id}.%s", p->path);
    } else {
        (void)snprintf(path, sizeof path, "%s", p->path);
    }
    const char *tail = p->axis ? "" : " {id}";
    if (!write) {
        (void)snprintf(l[0], sizeof l[0], "r %s%s", path, tail);
        f->valid = l[0];
        /* r takes no values: one field too many is the only wrong count
         * (a system path without its id is id 0, which is valid) */
        (void)snprintf(l[1], sizeof l[1], p->axis ? "r %s 1" : "r %s {id} 1", path);
        f->too_many = l[1];
        f->too_few = "r";
        f->query = true;
        return;
    }
    char valid[8][40];
    char invalid[12][40];
    if (conf_valid_values(prop, p->factory_known ? &p->factory : NULL, valid, 8) == 0u) {
        family_count--;
        return;
    }
    size_t refused = conf_invalid_values(prop, invalid, 12);
    (void)snprintf(l[0], sizeof l[0], "w %s %s%s", path, valid[0], tail);
    (void)snprintf(l[1], sizeof l[1], "w %s%s", path, p->axis ? "" : "");
    (void)snprintf(l[2], sizeof l[2], p->axis ? "w %s %s 1" : "w %s %s {id} 1", path, valid[0]);
    (void)snprintf(l[3], sizeof l[3], "w %s x%s", path, tail);
    f->valid = l[0];
    f->too_few = p->axis ? l[1] : "w";
    f->too_many = l[2];
    f->malformed = l[3];
    if (refused > 0u) {
        (void)snprintf(l[4], sizeof l[4], "w %s %s%s", path, invalid[0], tail);
        f->out_of_range = l[4];
    }
}

size_t conf_families(const conf_family_t **out)
{
    if (family_count == 0u) {
        memcpy(families, fixed_families, sizeof fixed_families);
        family_count = FIXED_COUNT;
        static const daran_prop_t axis_reads[] = {DARAN_PROP_CURRENT_STATE, DARAN_PROP_POS_GAIN};
        static const daran_prop_t system_reads[] = {DARAN_PROP_VBUS_VOLTAGE, DARAN_PROP_FW_VERSION};
        static const daran_prop_t axis_writes[] = {DARAN_PROP_POS_GAIN, DARAN_PROP_VEL_GAIN};
        static const daran_prop_t system_writes[] = {DARAN_PROP_CAN_HEARTBEAT_MS,
                                                     DARAN_PROP_BRAKE_RESISTANCE};
        add_property_family(0, false, pick(true, false, axis_reads, 2));
        add_property_family(1, false, pick(false, false, system_reads, 2));
        add_property_family(2, true, pick(true, true, axis_writes, 2));
        add_property_family(3, true, pick(false, true, system_writes, 2));
    }
    *out = families;
    return family_count;
}

void conf_fill(const char *template_text, const char *id, char *buf, size_t size)
{
    size_t k = 0;
    size_t id_len = strlen(id);
    for (const char *t = template_text; *t != '\0' && k + 1u < size;) {
        if (strncmp(t, "{id}", 4) == 0) {
            size_t n = id_len < size - 1u - k ? id_len : size - 1u - k;
            memcpy(buf + k, id, n);
            k += n;
            t += 4;
        } else {
            buf[k++] = *t++;
        }
    }
    buf[k] = '\0';
}

void conf_send_family_line(const conf_family_t *family, const char *line_template,
                           const char *setup_template, const char *id)
{
    char line[512];
    char own[8];
    (void)snprintf(own, sizeof own, "%u", CONF_ID);
    (void)family;
    if (setup_template != NULL) {
        conf_fill(setup_template, own, line, sizeof line);
        conf_send(line);
    }
    conf_fill(line_template, id, line, sizeof line);
    conf_send(line);
}

/* ---- helpers over the last exchange ---- */

static const char *own_id(void)
{
    static char text[8];
    (void)snprintf(text, sizeof text, "%u", CONF_ID);
    return text;
}

static void send_own(const char *template_text)
{
    char line[256];
    conf_fill(template_text, own_id(), line, sizeof line);
    conf_send(line);
}

static const daran_call_t *logged_get(daran_prop_t prop)
{
    const daran_recorder_t *rec = conf_rec();
    const daran_call_t *found = NULL;
    for (size_t i = 0; i < rec->n_calls; i++) {
        if (rec->calls[i].kind == DARAN_CALL_GET && rec->calls[i].prop == prop &&
            rec->calls[i].result == DARAN_OK) {
            found = &rec->calls[i];
        }
    }
    return found;
}

/* The exchange was one action of @p action, accepted, and no reply. */
static bool expect_action(daran_action_t action)
{
    const daran_call_t *call = daran_recorder_first(conf_rec(), DARAN_CALL_ACTION);
    bool ok = daran_recorder_mutations(conf_rec()) == 1u && call != NULL && call->action == action &&
              call->result == DARAN_OK;
    if (!ok) {
        conf_fail("one HAL action %s, accepted, nothing else", daran_recorder_action_name(action));
    }
    return conf_expect_silent() && ok;
}

/* The exchange was an accepted move (then its watchdog feed), no reply. */
static const daran_move_t *expect_accepted_move(void)
{
    const daran_recorder_t *rec = conf_rec();
    const daran_call_t *move = daran_recorder_first(rec, DARAN_CALL_MOVE);
    bool ok = move != NULL && move->result == DARAN_OK && rec->n_calls > 0u &&
              daran_recorder_count(rec, DARAN_CALL_MOVE, -1) == 1u &&
              daran_recorder_count(rec, DARAN_CALL_ACTION, DARAN_ACTION_FEED_WATCHDOG) == 1u &&
              daran_recorder_mutations(rec) == 2u &&
              rec->calls[rec->n_calls - 1u].kind == DARAN_CALL_ACTION;
    if (!ok) {
        conf_fail("one HAL move, accepted, then one FEED_WATCHDOG action (D22), nothing else");
    }
    if (!conf_expect_silent() || !ok) {
        return NULL;
    }
    return &move->move;
}

static bool read_u32(daran_prop_t prop, uint32_t *out)
{
    if (!conf_in_build(prop)) {
        return false;
    }
    daran_value_t value;
    if (!conf_read_value(prop, CONF_ID, &value, false)) {
        return false;
    }
    *out = value.u32;
    return true;
}

static void expect_state(uint32_t state, const char *when)
{
    uint32_t now;
    if (read_u32(DARAN_PROP_CURRENT_STATE, &now) && now != state) {
        conf_fail("current_state %lu %s, not %lu", (unsigned long)state, when, (unsigned long)now);
    }
}

/* ---- C10, C11: motion ---- */

enum member { M_POS, M_VEL, M_TORQUE, M_RATE, M_NONE };

typedef struct conf_motion {
    const char *setup;
    const char *line;
    bool multi;
    bool timed; /* mq: position relative to the setpoint, cruise from the duration */
    daran_move_kind_t kind;
    uint8_t given;
    float pos, vel, torque, rate, kp, kd;
    struct {
        daran_prop_t prop;
        enum member from;
    } back[4];
} conf_motion_t;

#define BOTH_GIVEN (DARAN_GIVEN_VEL | DARAN_GIVEN_RATE)
#define NO_BACK {DARAN_PROP_COUNT, M_NONE}

static const conf_motion_t motions[] = {
    {NULL, "t {id} 10", false, false, DARAN_MOVE_FILTERED_POSITION, 0, 10.0f, 0, 0, 0, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, NO_BACK, NO_BACK, NO_BACK}},
    {NULL, "t {id} -22.5 0 25", false, false, DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE,
     -22.5f, 0, 0, 25.0f, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_INPUT_FILTER_BANDWIDTH, M_RATE}, NO_BACK, NO_BACK}},
    {NULL, "q {id} 90 120 60", false, false, DARAN_MOVE_TRAPEZOID, BOTH_GIVEN, 90.0f, 120.0f, 0,
     60.0f, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, M_VEL},
      {DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, M_RATE}, {DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, M_RATE}}},
    {NULL, "q {id} 45", false, false, DARAN_MOVE_TRAPEZOID, 0, 45.0f, 0, 0, 0, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, NO_BACK, NO_BACK, NO_BACK}},
    {NULL, "p {id} 45 10 0.5", false, false, DARAN_MOVE_PASSTHROUGH, 0, 45.0f, 10.0f, 0.5f, 0, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_INPUT_TORQUE, M_TORQUE},
      NO_BACK}},
    {NULL, "v {id} 30 0.25", false, false, DARAN_MOVE_VELOCITY, 0, 0, 30.0f, 0.25f, 0, 0, 0,
     {{DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_INPUT_TORQUE, M_TORQUE}, NO_BACK, NO_BACK}},
    {NULL, "v {id} 30 5 2", false, false, DARAN_MOVE_VELOCITY_RAMP, 0, 0, 30.0f, 0, 5.0f, 0, 0,
     {{DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_VEL_RAMP_RATE, M_RATE}, NO_BACK, NO_BACK}},
    {NULL, "c {id} 0.5", false, false, DARAN_MOVE_TORQUE, 0, 0, 0, 0.5f, 0, 0, 0,
     {{DARAN_PROP_INPUT_TORQUE, M_TORQUE}, NO_BACK, NO_BACK, NO_BACK}},
    {NULL, "c {id} 0.5 2 6", false, false, DARAN_MOVE_TORQUE_RAMP, 0, 0, 0, 0.5f, 2.0f, 0, 0,
     {{DARAN_PROP_INPUT_TORQUE, M_TORQUE}, {DARAN_PROP_TORQUE_RAMP_RATE, M_RATE}, NO_BACK, NO_BACK}},
    {NULL, "d {id} 10 0 0.5 0.1 0.01", false, false, DARAN_MOVE_IMPEDANCE, 0, 10.0f, 0, 0.5f, 0,
     0.1f, 0.01f,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_INPUT_TORQUE, M_TORQUE},
      NO_BACK}},
    {"ms {id} 120 5 10", "mt {id} 0", true, false, DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE,
     120.0f, 0, 0, 10.0f, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_INPUT_FILTER_BANDWIDTH, M_RATE}, NO_BACK, NO_BACK}},
    {"ms {id} 90 5 10", "mq {id} 1", true, true, DARAN_MOVE_TRAPEZOID, BOTH_GIVEN, 90.0f, 0, 0,
     10.0f, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, M_VEL},
      {DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, M_RATE}, {DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, M_RATE}}},
    {"ms {id} 45 10 0.5", "mp {id} 0", true, false, DARAN_MOVE_PASSTHROUGH, 0, 45.0f, 10.0f, 0.5f,
     0, 0, 0,
     {{DARAN_PROP_INPUT_POS, M_POS}, {DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_INPUT_TORQUE, M_TORQUE},
      NO_BACK}},
    {"ms {id} 30 5 2", "mv {id}", true, false, DARAN_MOVE_VELOCITY_RAMP, 0, 0, 30.0f, 0, 5.0f, 0, 0,
     {{DARAN_PROP_INPUT_VEL, M_VEL}, {DARAN_PROP_VEL_RAMP_RATE, M_RATE}, NO_BACK, NO_BACK}},
    {"ms {id} 0.5 2 6", "mc {id}", true, false, DARAN_MOVE_TORQUE_RAMP, 0, 0, 0, 0.5f, 2.0f, 0, 0,
     {{DARAN_PROP_INPUT_TORQUE, M_TORQUE}, {DARAN_PROP_TORQUE_RAMP_RATE, M_RATE}, NO_BACK, NO_BACK}},
};

static bool same_float(float a, float b)
{
    return a == b || (a != a && b != b);
}

/* The timed start's cruise meets the duration (D31): trapezoid
 * T = D/V + V/A, S-curve T = D/V + 2V/A, in deg/s and deg/s^2. */
static bool meets_duration(float distance, float duration, const daran_move_t *move)
{
    double v = (double)move->vel_rpm * 6.0;
    double a = (double)move->rate * 6.0;
    if (!(v > 0.0) || !(a > 0.0)) {
        return false;
    }
    double trapezoid = (double)distance / v + v / a;
    double s_curve = (double)distance / v + 2.0 * v / a;
    return fabs(trapezoid - (double)duration) <= 1e-3 * (double)duration ||
           fabs(s_curve - (double)duration) <= 1e-3 * (double)duration;
}

/* Send the row's lines; the accepted move, checked against the row, or NULL. */
static const daran_move_t *run_motion(const conf_motion_t *m, bool check_values)
{
    if (m->setup != NULL) {
        send_own(m->setup);
    }
    send_own(m->line);
    const daran_move_t *move = expect_accepted_move();
    if (move == NULL || !check_values) {
        return move;
    }
    if (move->kind != m->kind) {
        conf_fail("a move %s, not %s", daran_recorder_move_name(m->kind),
                  daran_recorder_move_name(move->kind));
        return move;
    }
    bool given_matters = m->kind == DARAN_MOVE_FILTERED_POSITION || m->kind == DARAN_MOVE_TRAPEZOID;
    if (given_matters && move->given != m->given) {
        conf_fail("given bits %u, not %u", m->given, move->given);
    }
    if (m->timed) {
        const daran_call_t *setpoint = logged_get(DARAN_PROP_POS_SETPOINT);
        float origin = setpoint != NULL ? setpoint->value.f32 : 0.0f;
        if (!same_float(move->pos_deg, origin + m->pos) || !same_float(move->rate, m->rate) ||
            !meets_duration(m->pos, 5.0f, move)) {
            conf_fail("a trapezoid to %.9g (the setpoint %.9g + %.9g), acceleration %.9g, and a "
                      "cruise that arrives after the preset's 5 s (D31)",
                      (double)(origin + m->pos), (double)origin, (double)m->pos, (double)m->rate);
        }
        return move;
    }
    if (!same_float(move->pos_deg, m->pos) || !same_float(move->vel_rpm, m->vel) ||
        !same_float(move->torque_nm, m->torque) || !same_float(move->rate, m->rate) ||
        !same_float(move->kp, m->kp) || !same_float(move->kd, m->kd)) {
        conf_fail("pos %.9g vel %.9g torque %.9g rate %.9g kp %.9g kd %.9g (unused members 0)",
                  (double)m->pos, (double)m->vel, (double)m->torque, (double)m->rate, (double)m->kp,
                  (double)m->kd);
    }
    return move;
}

static float member_of(const daran_move_t *move, enum member from)
{
    switch (from) {
    case M_POS: return move->pos_deg;
    case M_VEL: return move->vel_rpm;
    case M_TORQUE: return move->torque_nm;
    default: return move->rate;
    }
}

/* The settings a filtered or trapezoid move carries only when its given bit
 * is set; without it the drive keeps its current one (porting.md section 3,
 * daran_hal.h). Each is first written with a marker value the drive is
 * unlikely to hold, so a HAL that overwrites it (with 0, or a default) is
 * seen. */
static const struct {
    daran_move_kind_t kind;
    daran_prop_t prop;
    uint8_t given;
    const char *marker;
} kept_settings[] = {
    {DARAN_MOVE_FILTERED_POSITION, DARAN_PROP_INPUT_FILTER_BANDWIDTH, DARAN_GIVEN_RATE, "37.25"},
    {DARAN_MOVE_TRAPEZOID, DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, DARAN_GIVEN_VEL, "37.25"},
    {DARAN_MOVE_TRAPEZOID, DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, DARAN_GIVEN_RATE, "13.5"},
    {DARAN_MOVE_TRAPEZOID, DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, DARAN_GIVEN_RATE, "13.5"},
};

/* Before the move: write the markers of the settings row @p m leaves to the
 * drive; true for each one written and read back (@p armed). */
static void arm_kept_settings(const conf_motion_t *m, bool armed[])
{
    for (size_t k = 0; k < sizeof kept_settings / sizeof kept_settings[0]; k++) {
        armed[k] = false;
        daran_prop_t prop = kept_settings[k].prop;
        if (m->multi || m->kind != kept_settings[k].kind || (m->given & kept_settings[k].given) != 0u ||
            !conf_in_build(prop) || conf_props[prop].read_refused) {
            continue;
        }
        char line[192];
        daran_value_t got;
        daran_value_t want;
        conf_write_line(prop, CONF_ID, kept_settings[k].marker, line, sizeof line);
        conf_send(line);
        armed[k] = conf_reply_len() == 0u && conf_value_of_text(DARAN_TYPE_F32, kept_settings[k].marker, &want) &&
                   conf_read_value(prop, CONF_ID, &got, true) &&
                   conf_same_value(DARAN_TYPE_F32, got, want);
    }
}

/* After the move: every armed marker still reads back. */
static void check_kept_settings(const bool armed[])
{
    for (size_t k = 0; k < sizeof kept_settings / sizeof kept_settings[0]; k++) {
        daran_value_t got;
        daran_value_t want;
        if (!armed[k] || !conf_value_of_text(DARAN_TYPE_F32, kept_settings[k].marker, &want) ||
            !conf_read_value(kept_settings[k].prop, CONF_ID, &got, false) ||
            conf_same_value(DARAN_TYPE_F32, got, want)) {
            continue;
        }
        char path[128];
        conf_wire_path(kept_settings[k].prop, CONF_ID, path, sizeof path);
        conf_fail("%s to keep %s: the line did not carry it, so the drive keeps its current "
                  "setting (docs/porting.md section 3, move: `given`), not %.9g",
                  path, kept_settings[k].marker, (double)got.f32);
    }
}

static void check_motion(void)
{
    for (size_t i = 0; i < sizeof motions / sizeof motions[0]; i++) {
        const conf_motion_t *m = &motions[i];
        char subject[96];
        conf_fill(m->line, own_id(), subject, sizeof subject);
        if (m->multi && !DARAN_ENABLE_MULTI_MOTOR) {
            conf_skip(REQ_MOVE, subject, "DARAN_ENABLE_MULTI_MOTOR is 0");
            conf_skip(REQ_MOVE_TARGETS, subject, "DARAN_ENABLE_MULTI_MOTOR is 0");
            continue;
        }
        bool moved = false;
        if (conf_begin(REQ_MOVE, subject)) {
            moved = run_motion(m, true) != NULL;
        }
        conf_end();
        if (!moved) {
            conf_skip(REQ_MOVE_TARGETS, subject, "the move itself failed C10");
            continue;
        }
        if (!conf_begin(REQ_MOVE_TARGETS, subject)) {
            conf_end();
            continue;
        }
        bool armed[sizeof kept_settings / sizeof kept_settings[0]];
        arm_kept_settings(m, armed);
        const daran_move_t *move = run_motion(m, false);
        daran_move_t kept;
        if (move != NULL) {
            kept = *move;
            for (size_t b = 0; b < 4u && m->back[b].from != M_NONE; b++) {
                daran_prop_t prop = m->back[b].prop;
                if (!conf_in_build(prop) || conf_props[prop].read_refused) {
                    continue;
                }
                daran_value_t got;
                daran_value_t want;
                want.u64 = 0;
                want.f32 = member_of(&kept, m->back[b].from);
                if (conf_read_value(prop, CONF_ID, &got, false) &&
                    !conf_same_value(DARAN_TYPE_F32, got, want)) {
                    char path[128];
                    conf_wire_path(prop, CONF_ID, path, sizeof path);
                    conf_fail("%s to read %.9g after the move (docs/porting.md section 3, move), "
                              "not %.9g", path, (double)want.f32, (double)got.f32);
                }
            }
            check_kept_settings(armed);
        }
        conf_end();
    }
}

/* ---- C12: actions ---- */

static void check_actions(void)
{
    static const struct {
        const char *line;
        daran_action_t action;
    } actions[] = {
        {"ss {id}", DARAN_ACTION_SAVE_CONFIG}, {"se {id}", DARAN_ACTION_ERASE_CONFIG},
        {"sr {id}", DARAN_ACTION_REBOOT},      {"sc {id}", DARAN_ACTION_CLEAR_ERRORS},
        {"sz {id}", DARAN_ACTION_SET_ZERO},    {"st {id}", DARAN_ACTION_ESTOP},
        {"u {id}", DARAN_ACTION_FEED_WATCHDOG}, {"SS {id}", DARAN_ACTION_SAVE_CONFIG},
    };
    for (size_t i = 0; i < sizeof actions / sizeof actions[0]; i++) {
        char subject[32];
        conf_fill(actions[i].line, own_id(), subject, sizeof subject);
        if (conf_begin(REQ_ACTION, subject)) {
            send_own(actions[i].line);
            (void)expect_action(actions[i].action);
        }
        conf_end();
    }
#if DARAN_ENABLE_MULTI_MOTOR
    if (conf_begin(REQ_ACTION, "ms 1 120 5 10")) {
        send_own("ms {id} 120 5 10");
        (void)conf_expect_silent();
        (void)conf_expect_no_effect();
    }
    conf_end();
#else
    conf_skip(REQ_ACTION, "ms", "DARAN_ENABLE_MULTI_MOTOR is 0");
#endif
}

/* ---- C13: queries ---- */

/* The reply's lines, their line ends cut: pointers into a copy. */
static size_t reply_lines(char *copy, size_t size, char *lines[], size_t max)
{
    size_t n = 0;
    const char *end = DARAN_REPLY_CRLF ? "\r\n" : "\n";
    (void)snprintf(copy, size, "%s", conf_reply());
    char *p = copy;
    while (*p != '\0' && n < max) {
        char *eol = strstr(p, end);
        if (eol == NULL) {
            break;
        }
        *eol = '\0';
        lines[n++] = p;
        p = eol + strlen(end);
    }
    return n;
}

/* @p line is values of @p types, one space apart. */
static bool values_of_types(const char *line, const daran_prop_type_t *types, size_t count)
{
    const char *p = line;
    for (size_t i = 0; i < count; i++) {
        const char *space = strchr(p, ' ');
        size_t len = space != NULL ? (size_t)(space - p) : strlen(p);
        daran_value_t value;
        if (!conf_parse_reply_value(types[i], p, len, &value)) {
            return false;
        }
        if (i + 1u < count) {
            if (space == NULL) {
                return false;
            }
            p = space + 1;
        } else if (space != NULL) {
            return false;
        }
    }
    return true;
}

static void check_value_query(const char *template_text, const daran_prop_type_t *types,
                              size_t count, const char *format)
{
    char subject[32];
    conf_fill(template_text, own_id(), subject, sizeof subject);
    if (conf_begin(REQ_QUERY, subject)) {
        send_own(template_text);
        (void)conf_expect_no_effect();
        char copy[512];
        char *lines[2];
        if (conf_expect_one_line() && reply_lines(copy, sizeof copy, lines, 2) == 1u &&
            !values_of_types(lines[0], types, count)) {
            conf_fail("one line `%s`", format);
        }
    }
    conf_end();
}

static void check_queries(void)
{
    static const daran_prop_type_t two_floats[] = {DARAN_TYPE_F32, DARAN_TYPE_F32};
    static const daran_prop_type_t versions[] = {DARAN_TYPE_U32, DARAN_TYPE_U32, DARAN_TYPE_U64};
    check_value_query("f {id}", two_floats, 2, "<pos> <vel>");
    check_value_query("g {id}", two_floats, 2, "<vbus> <iq>");
    check_value_query("i {id}", versions, 3, "<fw_version> <hw_version> <serial_number>");

    static const char *const registers[] = {"axis", "motor", "encoder", "controller",
                                            "fet_thermistor", "motor_thermistor", "can"};
    if (conf_begin(REQ_QUERY, "e 1")) {
        send_own("e {id}");
        (void)conf_expect_no_effect();
        char copy[1024];
        char *lines[8];
        size_t n = reply_lines(copy, sizeof copy, lines, 8);
        bool ok = n == 7u && conf_reply_lines() == 7u;
        for (size_t i = 0; ok && i < 7u; i++) {
            size_t name = strlen(registers[i]);
            daran_value_t value;
            ok = strncmp(lines[i], registers[i], name) == 0 && strncmp(lines[i] + name, ": ", 2) == 0 &&
                 conf_parse_reply_value(DARAN_TYPE_U32, lines[i] + name + 2, strlen(lines[i] + name + 2),
                                        &value);
        }
        if (!ok) {
            conf_fail("seven lines `axis: N`, `motor: N`, `encoder: N`, `controller: N`, "
                      "`fet_thermistor: N`, `motor_thermistor: N`, `can: N` (D24)");
        }
    }
    conf_end();
#if DARAN_ENABLE_HELP
    if (conf_begin(REQ_QUERY, "h 1")) {
        send_own("h {id}");
        (void)conf_expect_no_effect();
        char copy[4096];
        char *lines[64];
        size_t n = reply_lines(copy, sizeof copy, lines, 64);
        bool ok = n >= 1u && n == conf_reply_lines();
        for (size_t i = 0; ok && i < n; i++) {
            ok = lines[i][0] >= 'a' && lines[i][0] <= 'z';
        }
        if (!ok) {
            conf_fail("one line per command, each starting with its word (D25)");
        }
    }
    conf_end();
#if DARAN_ENABLE_DISCOVERY
    if (conf_begin(REQ_QUERY, "h 1 properties " CONF_NO_SUCH_PATH)) {
        send_own("h {id} properties " CONF_NO_SUCH_PATH);
        (void)conf_expect_no_effect();
        char want[8];
        (void)snprintf(want, sizeof want, "end%s", DARAN_REPLY_CRLF ? "\r\n" : "\n");
        if (strcmp(conf_reply(), want) != 0) {
            conf_fail("`end` alone: no path starts with the prefix (D37)");
        }
    }
    conf_end();
#endif
#else
    conf_skip(REQ_QUERY, "h", "DARAN_ENABLE_HELP is 0");
#endif
}

/* ---- C14-C19: the drive-state contract ---- */

static void check_estop(void)
{
    if (conf_begin(REQ_ESTOP, "st 1")) {
        send_own("st {id}");
        (void)expect_action(DARAN_ACTION_ESTOP);
        expect_state(DARAN_STATE_IDLE, "after st");
        uint32_t flags;
        if (read_u32(DARAN_PROP_AXIS_ERROR, &flags) && (flags & DARAN_FLAG_ESTOP) == 0u) {
            conf_fail("axis0.error with DARAN_FLAG_ESTOP (0x4000) after st, not 0x%lx",
                      (unsigned long)flags);
        }
    }
    conf_end();
}

static void check_clear_errors(void)
{
    if (conf_begin(REQ_CLEAR_ERRORS, "st 1, sc 1, w axis1.requested_state 8")) {
        send_own("st {id}");
        send_own("sc {id}");
        (void)expect_action(DARAN_ACTION_CLEAR_ERRORS);
        uint32_t flags;
        if (read_u32(DARAN_PROP_AXIS_ERROR, &flags) && flags != 0u) {
            conf_fail("axis0.error 0 after sc, not 0x%lx", (unsigned long)flags);
        }
        expect_state(DARAN_STATE_IDLE, "after sc (the drive stays idle)");
        send_own("w axis{id}.requested_state 8");
        if (conf_expect_silent()) {
            expect_state(DARAN_STATE_CLOSED_LOOP, "after w axis1.requested_state 8");
            send_own("t {id} 10");
            (void)expect_accepted_move();
        }
    }
    conf_end();
}

static void check_clear_registers(void)
{
    static const daran_prop_t registers[] = {
        DARAN_PROP_AXIS_ERROR,           DARAN_PROP_MOTOR_ERROR,
        DARAN_PROP_ENCODER_ERROR,        DARAN_PROP_CONTROLLER_ERROR,
        DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CAN_ERROR,            DARAN_PROP_CONFIG_WARNINGS,
    };
    for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
        daran_prop_t prop = registers[i];
        char path[128];
        conf_wire_path(prop, CONF_ID, path, sizeof path);
        if (!conf_in_build(prop) || conf_props[prop].read_refused || !conf_props[prop].rw) {
            conf_skip(REQ_CLEAR_REGISTER, path, "not in this build or not kept by the HAL");
            continue;
        }
        if (conf_begin(REQ_CLEAR_REGISTER, path)) {
            send_own("st {id}");
            char line[200];
            conf_write_line(prop, CONF_ID, "0", line, sizeof line);
            conf_send(line);
            const daran_call_t *set = daran_recorder_first(conf_rec(), DARAN_CALL_SET);
            if (!conf_expect_silent() || set == NULL || set->result != DARAN_OK) {
                conf_fail("`%s` accepted: one set, no reply", line);
            } else {
                daran_value_t value;
                if (conf_read_value(prop, CONF_ID, &value, false) && value.u32 != 0u) {
                    conf_fail("%s to read 0 after it was written 0, not %lu", path,
                              (unsigned long)value.u32);
                }
                expect_state(DARAN_STATE_IDLE, "after the register was cleared (the drive stays idle)");
            }
        }
        conf_end();
    }
}

static void check_set_zero(void)
{
    if (!conf_in_build(DARAN_PROP_POS_ESTIMATE) || conf_props[DARAN_PROP_POS_ESTIMATE].read_refused) {
        conf_skip(REQ_SET_ZERO, "sz 1", "output_shaft.pos_estimate is not readable");
        return;
    }
    if (conf_begin(REQ_SET_ZERO, "sz 1")) {
        /* move somewhere first, if the port lets time pass */
        send_own("t {id} 30");
        conf_advance(1000);
        daran_value_t estimate;
        daran_value_t input;
        bool have_input = conf_in_build(DARAN_PROP_INPUT_POS) &&
                          !conf_props[DARAN_PROP_INPUT_POS].read_refused &&
                          conf_read_value(DARAN_PROP_INPUT_POS, CONF_ID, &input, false);
        if (conf_read_value(DARAN_PROP_POS_ESTIMATE, CONF_ID, &estimate, false)) {
            send_own("sz {id}");
            (void)expect_action(DARAN_ACTION_SET_ZERO);
            daran_value_t after;
            if (conf_read_value(DARAN_PROP_POS_ESTIMATE, CONF_ID, &after, false) &&
                !(fabsf(after.f32) <= 1e-3f)) {
                conf_fail("output_shaft.pos_estimate 0 after sz, not %.9g", (double)after.f32);
            }
            daran_value_t shifted;
            daran_value_t want;
            want.u64 = 0;
            want.f32 = have_input ? input.f32 - estimate.f32 : 0.0f;
            if (have_input && conf_read_value(DARAN_PROP_INPUT_POS, CONF_ID, &shifted, false) &&
                !conf_same_value(DARAN_TYPE_F32, shifted, want) && fabsf(shifted.f32 - want.f32) > 1e-3f) {
                conf_fail("output_shaft.input_pos shifted with the position (%.9g), not %.9g",
                          (double)want.f32, (double)shifted.f32);
            }
        }
    }
    conf_end();
}

static void check_node_id(void)
{
    unsigned next = DARAN_MOTOR_ID_MAX >= 5 ? 5u : (unsigned)DARAN_MOTOR_ID_MAX;
    if (next == CONF_ID || !conf_in_build(DARAN_PROP_CAN_NODE_ID)) {
        conf_skip(REQ_NODE_ID, "can_node_id", "no second id in this build");
        return;
    }
    char subject[64];
    (void)snprintf(subject, sizeof subject, "w axis1.config.can_node_id %u", next);
    if (conf_begin(REQ_NODE_ID, subject)) {
        char line[96];
        (void)snprintf(line, sizeof line, "w axis%u.config.can_node_id %u", CONF_ID, next);
        conf_send(line);
        if (conf_expect_silent()) {
            (void)snprintf(line, sizeof line, "t %u 10", next);
            conf_send(line);
            if (expect_accepted_move() == NULL) {
                conf_fail("the drive to take `%s`: its id is %u now", line, next);
            }
            (void)snprintf(line, sizeof line, "t %u 10", CONF_ID);
            conf_send(line);
            if (!conf_expect_silent() || !conf_expect_no_effect()) {
                conf_fail("the drive to ignore `%s`: its id is %u now", line, next);
            }
            daran_value_t value;
            if (conf_read_value(DARAN_PROP_CAN_NODE_ID, next, &value, false) && value.u32 != next) {
                conf_fail("can_node_id to read %u", next);
            }
        }
    }
    conf_end();
}

static void check_requested_state(void)
{
    if (!conf_in_build(DARAN_PROP_REQUESTED_STATE)) {
        conf_skip(REQ_REQUESTED_STATE, "requested_state", "left out of this build");
        return;
    }
    if (conf_begin(REQ_REQUESTED_STATE, "w axis1.requested_state 1, then 8")) {
        send_own("w axis{id}.requested_state 1");
        if (conf_expect_silent()) {
            expect_state(DARAN_STATE_IDLE, "after w axis1.requested_state 1");
            send_own("t {id} 10");
            (void)conf_expect_error("motor idle", false);
            send_own("w axis{id}.requested_state 8");
            if (conf_expect_silent()) {
                expect_state(DARAN_STATE_CLOSED_LOOP, "after w axis1.requested_state 8");
                send_own("t {id} 10");
                (void)expect_accepted_move();
            }
        }
    }
    conf_end();
}

/* ---- C34, C35 ---- */

static void check_not_running(void)
{
    const conf_family_t *list;
    size_t count = conf_families(&list);
    for (size_t i = 0; i < count; i++) {
        const conf_family_t *f = &list[i];
        if (!f->motion) {
            continue;
        }
        char subject[96];
        conf_fill(f->valid, own_id(), subject, sizeof subject);
        if (conf_begin(REQ_NOT_RUNNING, subject)) {
            send_own("st {id}");
            conf_send_family_line(f, f->valid, f->setup, own_id());
            (void)conf_expect_error("estop active", false);
            if (!conf_restart()) {
                conf_end();
                continue;
            }
            send_own("st {id}");
            send_own("sc {id}");
            conf_send_family_line(f, f->valid, f->setup, own_id());
            (void)conf_expect_error("motor idle", false);
        }
        conf_end();
    }
}

static void check_no_preset(void)
{
#if DARAN_ENABLE_MULTI_MOTOR
    const conf_family_t *list;
    size_t count = conf_families(&list);
    for (size_t i = 0; i < count; i++) {
        const conf_family_t *f = &list[i];
        if (!f->multi || f->setup == NULL) {
            continue;
        }
        char subject[96];
        conf_fill(f->valid, own_id(), subject, sizeof subject);
        if (conf_begin(REQ_NO_PRESET, subject)) {
            conf_send_family_line(f, f->valid, NULL, own_id());
            (void)conf_expect_error("no preset", false);
            /* a start consumes its preset (D16) */
            conf_send_family_line(f, f->valid, f->setup, own_id());
            if (expect_accepted_move() != NULL) {
                conf_send_family_line(f, f->valid, NULL, own_id());
                (void)conf_expect_error("no preset", false);
            }
        }
        conf_end();
    }
#else
    conf_skip(REQ_NO_PRESET, "mt mq mp mv mc", "DARAN_ENABLE_MULTI_MOTOR is 0");
#endif
}

void conf_check_commands(void)
{
    check_motion();
    check_actions();
    check_queries();
    check_estop();
    check_clear_errors();
    check_clear_registers();
    check_set_zero();
    check_node_id();
    check_requested_state();
    check_not_running();
    check_no_preset();
}

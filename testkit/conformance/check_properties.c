/* Per property of the build: read (C2), discovery (C3), the properties the
 * protocol needs served (C4), valid writes read back (C5), read-only
 * refusals (C6), out-of-range (C7) and malformed (C8) values, and paths the
 * build lacks (C9). Also C1, the factory state the rest starts from. */
#include <stdio.h>
#include <string.h>

#include "conformance.h"

/* The vendor's rows come first; a port's own rows follow (daran_properties.h). */
#define CONF_COUNT_ROW_(id, path, scope, type, access, range, unit, can) +1u
#define VENDOR_ROWS ((size_t)(0u DARAN_PROPERTY_LIST(CONF_COUNT_ROW_)))

static const char *line_end(void)
{
    return DARAN_REPLY_CRLF ? "\r\n" : "\n";
}

/* Is the last exchange's reply exactly "error: <phrase>"? */
static bool reply_is_error(const char *phrase)
{
    char want[128];
    (void)snprintf(want, sizeof want, "error: %s%s", phrase, line_end());
    return strcmp(conf_reply(), want) == 0;
}

/* The last logged get of @p prop in the exchange, or NULL. */
static const daran_call_t *last_get(daran_prop_t prop)
{
    const daran_recorder_t *rec = conf_rec();
    const daran_call_t *found = NULL;
    for (size_t i = 0; i < rec->n_calls; i++) {
        if (rec->calls[i].kind == DARAN_CALL_GET && rec->calls[i].prop == prop) {
            found = &rec->calls[i];
        }
    }
    return found;
}

static bool is_error_register(daran_prop_t prop)
{
    switch (prop) {
    case DARAN_PROP_AXIS_ERROR:
    case DARAN_PROP_MOTOR_ERROR:
    case DARAN_PROP_ENCODER_ERROR:
    case DARAN_PROP_CONTROLLER_ERROR:
    case DARAN_PROP_FET_THERMISTOR_ERROR:
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR:
    case DARAN_PROP_CAN_ERROR:
        return true;
    default:
        return false;
    }
}

/* ---- C1 ---- */

bool conf_check_factory_state(void)
{
    if (!conf_begin(REQ_FACTORY_STATE, "reset()")) {
        conf_end();
        return false;
    }
    /* through id 0, which every drive answers: a wrong id shows as a value */
    daran_value_t value;
    if (conf_read_value(DARAN_PROP_CAN_NODE_ID, 0, &value, false) && value.u32 != CONF_ID) {
        conf_fail("node id %u after reset() (daran_test_port.h), not %lu", CONF_ID,
                  (unsigned long)value.u32);
    }
    if (conf_read_value(DARAN_PROP_CURRENT_STATE, CONF_ID, &value, false) &&
        value.u32 != DARAN_STATE_CLOSED_LOOP) {
        conf_fail("current_state %u (closed loop) after reset(), not %lu", DARAN_STATE_CLOSED_LOOP,
                  (unsigned long)value.u32);
    }
    if (conf_read_value(DARAN_PROP_AXIS_ERROR, CONF_ID, &value, false) && value.u32 != 0u) {
        conf_fail("axis0.error 0 after reset(), not %lu", (unsigned long)value.u32);
    }
    bool ok = !conf_failed();
    conf_end();
    return ok;
}

/* ---- C2: r ---- */

static void check_read(daran_prop_t prop)
{
    conf_prop_t *p = &conf_props[prop];
    char path[128];
    char line[160];
    conf_wire_path(prop, CONF_ID, path, sizeof path);
    if (!conf_begin(REQ_READ, path)) {
        conf_end();
        return;
    }
    conf_read_line(prop, CONF_ID, line, sizeof line);
    conf_send(line);
    const daran_call_t *get = last_get(prop);
    if (get == NULL && reply_is_error("invalid property")) {
        /* the core answered alone: the row is not in this build */
        p->presence = PRESENT_LEFT_OUT;
        conf_abandon();
        conf_skip(REQ_READ, path, "left out of this build");
        return;
    }
    p->presence = PRESENT_IN_BUILD;
    if (p->header_omits) {
        conf_fail("invalid property with no HAL call: DARAN_OMIT_PROPERTIES leaves this row out");
    }
    (void)conf_expect_no_effect();
    if (get == NULL) {
        conf_fail("a HAL get of %s", path);
        conf_end();
        return;
    }
    if (get->result != DARAN_OK) {
        if (reply_is_error("motor fault")) {
            /* porting.md section 3: hardware the drive lacks */
            p->read_refused = true;
            conf_note("%s: the HAL refuses to read it (motor fault)", path);
        } else if (get->result == DARAN_ERR_INVALID_PROPERTY && is_error_register(prop)) {
            /* D24: a register the HAL does not keep reads 0 in `e` */
            p->read_refused = true;
            conf_note("%s: the HAL does not keep this error register (invalid property; e reads it 0)",
                      path);
        } else if (get->result == DARAN_ERR_INVALID_PROPERTY && (size_t)prop >= VENDOR_ROWS) {
            conf_fail("a value: the build lists %s, one of the port's own rows, but the HAL's "
                      "get answers invalid property (serve it, or take it out of "
                      "DARAN_PORT_PROPERTY_LIST)", path);
        } else if (get->result == DARAN_ERR_INVALID_PROPERTY) {
            conf_fail("a value: the build lists %s, but the HAL's get answers invalid property "
                      "(leave the row out of the build instead: DARAN_OMIT_PROPERTIES or "
                      "DARAN_PROPERTY_OMIT)", path);
        } else {
            conf_fail("a value, or the HAL's documented refusal `error: motor fault`; the HAL's "
                      "get answered %s", daran_result_phrase(get->result));
        }
        conf_end();
        return;
    }
    daran_value_t shown;
    size_t end = strlen(line_end());
    const char *reply = conf_reply();
    size_t len = conf_reply_len();
    if (!conf_expect_one_line() || len <= end ||
        !conf_parse_reply_value(p->type, reply, len - end, &shown)) {
        static const char *const type_names[] = {"f32", "u32", "s32", "u64", "bool"};
        conf_fail("one value of type %s", type_names[p->type]);
    } else if (!(p->type == DARAN_TYPE_F32
                     ? (shown.f32 == get->value.f32 || (shown.f32 != shown.f32 && get->value.f32 != get->value.f32))
                     : conf_same_value(p->type, shown, get->value))) {
        conf_fail("the value the HAL's get returned");
    } else {
        p->factory = get->value;
        p->factory_known = true;
    }
    conf_end();
}

/* ---- C3: discovery ---- */

#if DARAN_ENABLE_DISCOVERY
static daran_prop_t prop_of_path(const char *path, size_t len)
{
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        char wire[128];
        if (conf_props[i].path == NULL) {
            continue;
        }
        conf_wire_path((daran_prop_t)i, 0, wire, sizeof wire);
        if (strlen(wire) == len && memcmp(wire, path, len) == 0) {
            return (daran_prop_t)i;
        }
    }
    return DARAN_PROP_COUNT;
}

/* The next space-separated word of [*p, end), moving *p past it. */
static size_t next_word(const char **p, const char *end, const char **word)
{
    while (*p < end && **p == ' ') {
        (*p)++;
    }
    *word = *p;
    while (*p < end && **p != ' ') {
        (*p)++;
    }
    return (size_t)(*p - *word);
}

static bool word_is(const char *word, size_t len, const char *text)
{
    return strlen(text) == len && memcmp(word, text, len) == 0;
}

static const char *const type_names[] = {"f32", "u32", "s32", "u64", "bool"};

/* One discovery line's type, access, unit and range (after its path, at
 * *p) against the row of @p prop. A range discovery prints that differs from
 * the list's is taken for the range checks of `w`, and noted. */
static void check_discovery_row(daran_prop_t prop, const char *word, size_t len, const char *p,
                                const char *eol)
{
    conf_prop_t *row = &conf_props[prop];
    const char *type;
    size_t type_len = next_word(&p, eol, &type);
    const char *access;
    size_t access_len = next_word(&p, eol, &access);
    const char *unit;
    size_t unit_len = next_word(&p, eol, &unit);
    const char *range;
    size_t range_len = next_word(&p, eol, &range);
    if (!word_is(type, type_len, type_names[row->type]) ||
        !word_is(access, access_len, row->rw ? "rw" : "ro") ||
        !word_is(unit, unit_len, row->unit[0] != '\0' ? row->unit : "-")) {
        conf_fail("%s %s %s %s for %.*s, as its row says", row->path, type_names[row->type],
                  row->rw ? "rw" : "ro", row->unit[0] != '\0' ? row->unit : "-", (int)len, word);
    }
    const char *want_range = row->rw ? row->range_text : "";
    if (word_is(range, range_len, want_range)) {
        return;
    }
    static char taken[DARAN_PROP_COUNT][64];
    if (row->rw && range_len > 0u && range_len < sizeof taken[0]) {
        memcpy(taken[prop], range, range_len);
        taken[prop][range_len] = '\0';
        conf_note("%.*s: discovery's range %s differs from the list's \"%s\"; checked with %s",
                  (int)len, word, taken[prop], want_range, taken[prop]);
        row->range_text = taken[prop];
        conf_parse_range(row->range_text, &row->range);
    } else {
        conf_fail("the range \"%s\" for %.*s", want_range, (int)len, word);
    }
}

/* The lines of `h id properties`: whole, each a path of the build's lists
 * once with its row's attributes, then `end` and nothing after it. Marks
 * each path listed. */
static void check_discovery_lines(const char *text, const char *stop, bool *listed)
{
    size_t end_len = strlen(line_end());
    bool ended = false;
    while (text < stop) {
        const char *eol = strstr(text, line_end());
        if (eol == NULL) {
            conf_fail("whole lines");
            break;
        }
        if (ended) {
            conf_fail("nothing after `end`");
            break;
        }
        const char *p = text;
        const char *word;
        size_t len = next_word(&p, eol, &word);
        text = eol + end_len;
        if (word_is(word, len, "end") && p == eol) {
            ended = true;
            continue;
        }
        daran_prop_t prop = prop_of_path(word, len);
        if (prop == DARAN_PROP_COUNT) {
            conf_fail("only paths of the build's property lists; `%.*s` is none (is the program "
                      "built with the core's options header?)", (int)len, word);
            continue;
        }
        if (conf_props[prop].presence != PRESENT_IN_BUILD || listed[prop]) {
            conf_fail("%.*s listed once, and only if `r` serves it", (int)len, word);
        }
        listed[prop] = true;
        check_discovery_row(prop, word, len, p, eol);
    }
    if (!ended) {
        conf_fail("a last line `end`");
    }
}

static void check_discovery(void)
{
    static bool listed[DARAN_PROP_COUNT];
    char line[32];
    memset(listed, 0, sizeof listed);
    (void)snprintf(line, sizeof line, "h %u properties", CONF_ID);
    if (!conf_begin(REQ_DISCOVERY, line)) {
        conf_end();
        return;
    }
    conf_send(line);
    (void)conf_expect_no_effect();
    check_discovery_lines(conf_reply(), conf_reply() + conf_reply_len(), listed);
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        if (conf_props[i].presence == PRESENT_IN_BUILD && !listed[i]) {
            char path[128];
            conf_wire_path((daran_prop_t)i, 0, path, sizeof path);
            conf_fail("%s listed: `r` serves it", path);
        }
    }
    conf_end();
}
#endif

/* ---- C4: what the protocol reads itself ---- */

static void check_served(void)
{
    /* addressing, the state rules, f g i e, relative starts, and the
     * targets every motion command leaves in input_* */
    static const daran_prop_t needed[] = {
        DARAN_PROP_CAN_NODE_ID,   DARAN_PROP_REQUESTED_STATE, DARAN_PROP_CURRENT_STATE,
        DARAN_PROP_AXIS_ERROR,    DARAN_PROP_POS_SETPOINT,    DARAN_PROP_POS_ESTIMATE,
        DARAN_PROP_VEL_ESTIMATE,  DARAN_PROP_VBUS_VOLTAGE,    DARAN_PROP_IQ_MEASURED,
        DARAN_PROP_FW_VERSION,    DARAN_PROP_HW_VERSION,      DARAN_PROP_SERIAL_NUMBER,
        DARAN_PROP_INPUT_POS,     DARAN_PROP_INPUT_VEL,       DARAN_PROP_INPUT_TORQUE,
    };
    for (size_t i = 0; i < sizeof needed / sizeof needed[0]; i++) {
        char path[128];
        conf_wire_path(needed[i], CONF_ID, path, sizeof path);
        if (!conf_in_build(needed[i])) {
            conf_skip(REQ_SERVED, path, "left out of this build");
            continue;
        }
        if (!conf_begin(REQ_SERVED, path)) {
            conf_end();
            continue;
        }
        daran_value_t value;
        (void)conf_read_value(needed[i], CONF_ID, &value, false);
        conf_end();
    }
}

/* ---- C5: valid writes ---- */

static bool exact_value(daran_prop_type_t type, daran_value_t a, daran_value_t b)
{
    if (type == DARAN_TYPE_F32) {
        return a.f32 == b.f32 || (a.f32 != a.f32 && b.f32 != b.f32);
    }
    return conf_same_value(type, a, b);
}

static void check_write(daran_prop_t prop)
{
    conf_prop_t *p = &conf_props[prop];
    char path[128];
    conf_wire_path(prop, CONF_ID, path, sizeof path);
    char values[8][40];
    size_t count = conf_valid_values(prop, p->factory_known ? &p->factory : NULL, values, 8);
    if (count == 0u) {
        conf_skip(REQ_WRITE, path, "no valid value known for its range");
        conf_note("%s: range \"%s\" not understood: its writes were not checked", path, p->range_text);
        return;
    }
    if (!conf_begin(REQ_WRITE, path)) {
        conf_end();
        return;
    }
    unsigned id = CONF_ID;
    bool all_ok = true;
    for (size_t i = 0; i < count && !conf_failed(); i++) {
        daran_value_t want;
        daran_value_t before;
        bool before_known = !p->read_refused && conf_read_value(prop, id, &before, true);
        (void)conf_value_of_text(p->type, values[i], &want);
        char line[200];
        conf_write_line(prop, id, values[i], line, sizeof line);
        conf_send(line);
        const daran_call_t *set = daran_recorder_first(conf_rec(), DARAN_CALL_SET);
        bool one_set = daran_recorder_mutations(conf_rec()) == 1u && set != NULL && set->prop == prop &&
                       exact_value(p->type, set->value, want);
        if (!one_set) {
            conf_fail("one HAL set of %s with %s, nothing else", path, values[i]);
            break;
        }
        if (set->result != DARAN_OK) {
            if (reply_is_error("motor fault")) {
                p->write_refused = true;
                all_ok = false;
                conf_note("%s: the HAL refuses writes (motor fault)", path);
                daran_value_t after;
                if (before_known && conf_read_value(prop, id, &after, false) &&
                    !conf_same_value(p->type, after, before)) {
                    conf_fail("a refused write leaves the value as it was");
                }
            } else {
                conf_fail("the set accepted, or refused with the documented `motor fault`; it "
                          "answered %s", daran_result_phrase(set->result));
            }
            break;
        }
        if (!conf_expect_silent()) {
            break;
        }
        if (prop == DARAN_PROP_CAN_NODE_ID) {
            id = want.u32; /* the drive answers to its new id from now on */
        }
        if (p->read_refused) {
            continue;
        }
        daran_value_t got;
        if (conf_read_value(prop, id, &got, false) && !conf_same_value(p->type, got, want)) {
            char text[40];
            conf_format_value(p->type, got, text, sizeof text);
            conf_fail("`r` to read back %s (within the type's rounding), not %s", values[i], text);
        }
    }
    p->write_ok = all_ok && !conf_failed();
    conf_end();
}

/* ---- C6, C7, C8: refused writes ---- */

static void check_read_only(daran_prop_t prop)
{
    char path[128];
    char line[200];
    conf_wire_path(prop, CONF_ID, path, sizeof path);
    if (!conf_begin(REQ_READ_ONLY, path)) {
        conf_end();
        return;
    }
    conf_write_line(prop, CONF_ID, "1", line, sizeof line);
    conf_send(line);
    (void)conf_expect_error("read only property", false);
    conf_end();
}

static void check_refused_values(conf_req_t req, daran_prop_t prop, char values[][40], size_t count,
                                 const char *phrase)
{
    char path[128];
    conf_wire_path(prop, CONF_ID, path, sizeof path);
    if (!conf_begin(req, path)) {
        conf_end();
        return;
    }
    for (size_t i = 0; i < count; i++) {
        char line[200];
        conf_write_line(prop, CONF_ID, values[i], line, sizeof line);
        conf_send(line);
        (void)conf_expect_error(phrase, false);
    }
    conf_end();
}

static void check_out_of_range(daran_prop_t prop)
{
    char values[12][40];
    size_t count = conf_invalid_values(prop, values, 12);
    check_refused_values(REQ_WRITE_OUT_OF_RANGE, prop, values, count, "value out of range");
}

static void check_malformed(daran_prop_t prop)
{
    static const char *const any_type[] = {"x", "1.2.3", "0x10", "nan", "1e", "--1", "1,5"};
    static const char *const integers[] = {"1.5", "0.5e0", "inf"};
    char values[12][40];
    size_t count = 0;
    for (size_t i = 0; i < sizeof any_type / sizeof any_type[0]; i++) {
        (void)snprintf(values[count++], sizeof values[0], "%s", any_type[i]);
    }
    if (conf_props[prop].type != DARAN_TYPE_F32) {
        for (size_t i = 0; i < sizeof integers / sizeof integers[0]; i++) {
            (void)snprintf(values[count++], sizeof values[0], "%s", integers[i]);
        }
    }
    check_refused_values(REQ_WRITE_MALFORMED, prop, values, count, "invalid value");
}

/* ---- C9: paths the build lacks ---- */

static void check_unknown_paths(void)
{
    static const char *const lines[] = {
        "r axis1." CONF_NO_SUCH_PATH, "w axis1." CONF_NO_SUCH_PATH " 1",
        "r " CONF_NO_SUCH_PATH " 1",  "w " CONF_NO_SUCH_PATH " 1 1",
        "r axis1.config",             "r axis1.controller.config.pos_gai",
    };
    if (conf_begin(REQ_UNKNOWN_PATH, "paths no build has")) {
        for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
            conf_send(lines[i]);
            (void)conf_expect_error("invalid property", false);
        }
    }
    conf_end();
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        daran_prop_t prop = (daran_prop_t)i;
        if (conf_props[i].presence != PRESENT_LEFT_OUT) {
            continue;
        }
        char path[128];
        char line[200];
        conf_wire_path(prop, CONF_ID, path, sizeof path);
        if (!conf_begin(REQ_UNKNOWN_PATH, path)) {
            conf_end();
            continue;
        }
        conf_read_line(prop, CONF_ID, line, sizeof line);
        conf_send(line);
        (void)conf_expect_error("invalid property", false);
        if (last_get(prop) != NULL) {
            conf_fail("no HAL get of a row left out of the build");
        }
        conf_write_line(prop, CONF_ID, "0", line, sizeof line);
        conf_send(line);
        (void)conf_expect_error("invalid property", false);
        conf_end();
    }
}

void conf_check_properties(void)
{
    size_t in_build = 0;
    size_t left_out = 0;
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        if (conf_props[i].path != NULL) {
            check_read((daran_prop_t)i);
            if (conf_props[i].presence == PRESENT_IN_BUILD) {
                in_build++;
            } else {
                left_out++;
            }
        }
    }
    conf_note("properties: %lu in this build (the vendor's and the port's own rows), %lu left "
              "out of it (DARAN_OMIT_PROPERTIES, DARAN_PROPERTY_OMIT)",
              (unsigned long)in_build, (unsigned long)left_out);
#if DARAN_ENABLE_DISCOVERY
    check_discovery();
#else
    conf_skip(REQ_DISCOVERY, "h 1 properties", "DARAN_ENABLE_DISCOVERY is 0");
#endif
    check_served();
    for (int i = 0; i < (int)DARAN_PROP_COUNT; i++) {
        daran_prop_t prop = (daran_prop_t)i;
        if (!conf_in_build(prop)) {
            continue;
        }
        if (conf_props[i].rw) {
            check_write(prop);
            check_out_of_range(prop);
            check_malformed(prop);
        } else {
            check_read_only(prop);
        }
    }
    check_unknown_paths();
}

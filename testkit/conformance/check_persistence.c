/* Non-volatile memory through the protocol: a value saved with `ss`
 * survives `sr` and a later unsaved change does not (C20); `se` brings the
 * defaults back at the next boot (C21). Catches an `ss` that answers
 * success without writing anything, and an `sr` that reboots nothing. */
#include <stdio.h>
#include <string.h>

#include "conformance.h"

/* Drive time for a save or a reboot to complete, when the port keeps time. */
#define SETTLE_MS 500u

/* A configuration value to save: accepted by `w`, read back, with at least
 * two valid values besides its factory one. */
static daran_prop_t pick_setting(char values[][40])
{
    static const daran_prop_t preferred[] = {
        DARAN_PROP_POS_GAIN, DARAN_PROP_VEL_GAIN, DARAN_PROP_VEL_INTEGRATOR_GAIN,
        DARAN_PROP_CURRENT_LIM, DARAN_PROP_CONTROLLER_VEL_LIMIT,
    };
    for (size_t pass = 0; pass < 2u; pass++) {
        size_t count = pass == 0u ? sizeof preferred / sizeof preferred[0] : (size_t)DARAN_PROP_COUNT;
        for (size_t i = 0; i < count; i++) {
            daran_prop_t prop = pass == 0u ? preferred[i] : (daran_prop_t)i;
            const conf_prop_t *p = &conf_props[prop];
            if (!conf_in_build(prop) || !p->rw || !p->write_ok || !p->factory_known ||
                strstr(p->path, "config") == NULL || prop == DARAN_PROP_CAN_NODE_ID) {
                continue;
            }
            char all[8][40];
            size_t n = conf_valid_values(prop, &p->factory, all, 8);
            /* two values, each unlike the factory one */
            size_t kept = 0;
            for (size_t k = 0; k < n && kept < 2u; k++) {
                daran_value_t v;
                if (conf_value_of_text(p->type, all[k], &v) && !conf_same_value(p->type, v, p->factory)) {
                    memcpy(values[kept++], all[k], sizeof all[k]);
                }
            }
            if (kept == 2u) {
                return prop;
            }
        }
    }
    return DARAN_PROP_COUNT;
}

static void send_action(const char *word)
{
    char line[16];
    (void)snprintf(line, sizeof line, "%s %u", word, CONF_ID);
    conf_send(line);
    if (!conf_expect_silent()) {
        conf_fail("`%s` accepted", line);
    }
    conf_advance(SETTLE_MS);
}

static bool write_value(daran_prop_t prop, const char *value)
{
    char line[200];
    conf_write_line(prop, CONF_ID, value, line, sizeof line);
    conf_send(line);
    return conf_expect_silent();
}

static void expect_value(daran_prop_t prop, daran_value_t want, const char *why)
{
    daran_value_t got;
    const conf_prop_t *p = &conf_props[prop];
    if (conf_read_value(prop, CONF_ID, &got, false) && !conf_same_value(p->type, got, want)) {
        char want_text[40];
        char got_text[40];
        conf_format_value(p->type, want, want_text, sizeof want_text);
        conf_format_value(p->type, got, got_text, sizeof got_text);
        conf_fail("%s: `r` to read %s, not %s", why, want_text, got_text);
    }
}

void conf_check_persistence(void)
{
    char values[2][40];
    daran_prop_t prop = pick_setting(values);
    if (prop == DARAN_PROP_COUNT) {
        conf_skip(REQ_SAVE, "ss", "no writable configuration value that reads back");
        conf_skip(REQ_ERASE, "se", "no writable configuration value that reads back");
        conf_note("persistence not checked: no writable configuration value reads back");
        return;
    }
    const conf_prop_t *p = &conf_props[prop];
    char path[128];
    char subject[400];
    conf_wire_path(prop, CONF_ID, path, sizeof path);
    daran_value_t saved;
    (void)conf_value_of_text(p->type, values[0], &saved);

    (void)snprintf(subject, sizeof subject, "w %s %s, ss, w %s %s, sr", path, values[0], path, values[1]);
    if (conf_begin(REQ_SAVE, subject)) {
        if (write_value(prop, values[0])) {
            send_action("ss");
            if (write_value(prop, values[1])) {
                send_action("sr");
                expect_value(prop, saved,
                             "the value saved with ss after sr (a change made after ss is not saved)");
            }
        }
    }
    conf_end();

    (void)snprintf(subject, sizeof subject, "w %s %s, ss, se, sr", path, values[0]);
    if (conf_begin(REQ_ERASE, subject)) {
        if (write_value(prop, values[0])) {
            send_action("ss");
            send_action("se");
            send_action("sr");
            expect_value(prop, p->factory, "the factory value after se and sr");
        }
    }
    conf_end();
}

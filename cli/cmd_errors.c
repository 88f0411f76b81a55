/* errors and clear (docs/cli.md, "errors, clear"): `e` decoded into the
 * vendor's bit names; `sc`, then what is still set, and --enable. */
#include <string.h>

#include "commands.h"
#include "errors_bits.h"

#define REGISTERS DARAN_CLIENT_ERROR_REGISTERS
/* Room for the bit names of a register, or of every register that has
 * some (32 names of up to 30 characters each fit). */
#define NAMES_MAX 1024u
/* protocol.md 6: closed-loop control, the state motion needs. */
#define STATE_CLOSED_LOOP 8u
/* How long `clear --enable` gives the drive to reach it after the write
 * (the simulator is there at once; a real drive may take a control tick or
 * more), and how often it asks meanwhile. */
#define ENABLE_WAIT_MS 500u
#define ENABLE_POLL_MS 20u

/* ------------------------------------------------------------ reading */

typedef struct error_reply {
    daran_client_errors_t errors;
    size_t lines;
    bool unreadable;                 /* a line is not the register expected there */
    size_t bad_line;                 /* which (from 1) */
    char bad[DARAN_CLIENT_LINE_MAX]; /* the first such line */
} error_reply_t;

static void take_error_line(void *ctx, const daran_client_line_t *line)
{
    error_reply_t *r = ctx;
    if (!r->unreadable && (r->lines >= REGISTERS ||
                           daran_client_parse_error_line(line, r->lines, &r->errors) != DARAN_OK)) {
        r->unreadable = true;
        r->bad_line = r->lines + 1;
        (void)snprintf(r->bad, sizeof r->bad, "%.*s", (int)line->len, line->payload);
    }
    r->lines++;
}

/* `e id` into *out; a failure is reported here. */
static cli_status_t read_errors(cli_session_t *s, uint8_t id, daran_client_errors_t *out)
{
    error_reply_t reply;
    memset(&reply, 0, sizeof reply);
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_E, .id = id};
    cli_status_t status = cli_transact(s, &request, take_error_line, &reply, false, NULL);
    if (status != CLI_OK) {
        return status;
    }
    /* the link collected seven lines; they must be the registers, in order */
    if (reply.unreadable) {
        return cli_fail(CLI_NO_REPLY,
                        "drive %u's reply to \"e %u\" on %s is not its error registers "
                        "(line %zu: \"%s\")",
                        id, id, s->port_path, reply.bad_line, reply.bad);
    }
    if (reply.lines != REGISTERS) {
        return cli_fail(CLI_NO_REPLY, "drive %u's reply to \"e %u\" on %s has %zu lines, not %u",
                        id, id, s->port_path, reply.lines, REGISTERS);
    }
    *out = reply.errors;
    return CLI_OK;
}

/* `r path` of drive id as a u32; a failure is reported here. The value is
 * the link's last reply line (link.last): no copy of our own. */
static cli_status_t read_u32(cli_session_t *s, uint8_t id, const char *path, uint32_t *out)
{
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_R, .id = id, .path = path};
    cli_status_t status = cli_transact(s, &request, NULL, NULL, false, NULL);
    if (status != CLI_OK) {
        return status;
    }
    const char *text = s->link.last;
    size_t len = s->link.last_len;
    daran_client_number_t number;
    if (daran_client_parse_number(text, len, &number) != DARAN_OK ||
        daran_client_number_u32(&number, out) != DARAN_OK) {
        return cli_fail(CLI_NO_REPLY, "drive %u's %s on %s is not an unsigned integer: \"%.*s\"",
                        id, path, s->port_path, (int)len, text);
    }
    return CLI_OK;
}

/* ------------------------------------------------------------ printing */

static bool all_clear(const daran_client_errors_t *e)
{
    for (size_t r = 0; r < REGISTERS; r++) {
        if (e->reg[r] != 0) {
            return false;
        }
    }
    return true;
}

/* Append the names of the bits set in register r to buf (blank before
 * each; `bit N` for a bit the vendor does not name). Cut short, never
 * overrun, when buf is full. */
static void append_bit_names(char *buf, size_t size, size_t *len, size_t r, uint32_t value)
{
    for (unsigned bit = 0; bit < 32u && *len < size; bit++) {
        if ((value & (UINT32_C(1) << bit)) == 0) {
            continue;
        }
        const char *name = cli_error_bit_name(r, bit);
        int n = name != NULL ? snprintf(buf + *len, size - *len, " %s", name)
                             : snprintf(buf + *len, size - *len, " bit %u", bit);
        *len = n < 0 ? size : *len + (size_t)n;
    }
    if (*len >= size) {
        *len = size - 1;
    }
}

/* One line a register: `axis             0x00004000 ESTOP_REQUESTED`. */
static void print_registers_text(const daran_client_errors_t *e)
{
    for (size_t r = 0; r < REGISTERS; r++) {
        char names[NAMES_MAX] = "";
        size_t len = 0;
        append_bit_names(names, sizeof names, &len, r, e->reg[r]);
        printf("%-16s 0x%08lx%s\n", daran_client_error_register_name(r), (unsigned long)e->reg[r],
               names);
    }
}

/* `"registers":[{"name":"axis","value":16384,"bits":[{"bit":14,"name":"ESTOP_REQUESTED"}]},…]`
 * (an unnamed bit has "name":null) and `"clear":BOOL`. */
static void print_registers_json(const daran_client_errors_t *e)
{
    fputs("\"registers\":[", stdout);
    for (size_t r = 0; r < REGISTERS; r++) {
        const char *reg_name = daran_client_error_register_name(r);
        printf("%s{\"name\":", r > 0 ? "," : "");
        cli_json_string(stdout, reg_name, strlen(reg_name));
        printf(",\"value\":%lu,\"bits\":[", (unsigned long)e->reg[r]);
        size_t count = 0;
        for (unsigned bit = 0; bit < 32u; bit++) {
            if ((e->reg[r] & (UINT32_C(1) << bit)) == 0) {
                continue;
            }
            const char *name = cli_error_bit_name(r, bit);
            printf("%s{\"bit\":%u,\"name\":", count++ > 0 ? "," : "", bit);
            if (name != NULL) {
                cli_json_string(stdout, name, strlen(name));
            } else {
                fputs("null", stdout);
            }
            putchar('}');
        }
        fputs("]}", stdout);
    }
    printf("],\"clear\":%s", all_clear(e) ? "true" : "false");
}

/* What remains, for the one stderr line of `clear`: `axis OVER_TEMP, fet_thermistor OVER_TEMP`. */
static void describe_remaining(const daran_client_errors_t *e, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = '\0';
    for (size_t r = 0; r < REGISTERS && len + 1 < size; r++) {
        if (e->reg[r] == 0) {
            continue;
        }
        int n = snprintf(buf + len, size - len, "%s%s", len > 0 ? ", " : "",
                         daran_client_error_register_name(r));
        len = n < 0 ? size - 1 : len + (size_t)n;
        if (len >= size) {
            len = size - 1;
        }
        append_bit_names(buf, size, &len, r, e->reg[r]);
    }
}

/* ------------------------------------------------------------ errors */

static cli_status_t run_errors(cli_session_t *s, int argc, char **argv)
{
    uint8_t id;
    if (argc != 1) {
        return cli_usage(&cli_cmd_errors, "one motor id is needed");
    }
    if (!cli_parse_id(argv[0], false, &id)) {
        return cli_usage(&cli_cmd_errors, "\"%s\" is not a motor id (1..63)", argv[0]);
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    daran_client_errors_t errors;
    status = read_errors(s, id, &errors);
    if (status != CLI_OK) {
        return status;
    }
    if (s->options.json) {
        printf("{\"id\":%u,", id);
        print_registers_json(&errors);
        puts("}");
    } else {
        print_registers_text(&errors);
        if (all_clear(&errors)) {
            printf("drive %u: all clear, no error flag set\n", id);
        }
    }
    return CLI_OK; /* flags set are an answer, not a failure */
}

const cli_command_t cli_cmd_errors = {
    .name = "errors",
    .synopsis = "ID",
    .summary = "read the error registers and name their bits",
    .help = "Sends `e ID` and prints the seven error registers (axis, motor, encoder,\n"
            "controller, fet_thermistor, motor_thermistor, can), each in hex with the\n"
            "names the vendor's tools give its set bits (ODrive 0.5.1's AXIS_ERROR_*,\n"
            "MOTOR_ERROR_*, ... without the prefix; `bit N` for a bit without a name).\n"
            "Exit status 0 whenever the drive answered, flags set or not.\n",
    .run = run_errors,
};

/* ------------------------------------------------------------ clear */

typedef struct clear_result {
    daran_client_errors_t errors;
    bool errors_read; /* after sc: what the output reports */
    bool have_state;
    uint32_t state; /* current_state after sc (and after the write of --enable) */
    bool enable_tried;
    char kept[DARAN_CLIENT_LINE_MAX]; /* requested_state as read back */
    daran_result_t refused;           /* the drive's answer to the write */
} clear_result_t;

/* --enable: write requested_state 8, read it back, then wait for current_state. */
static cli_status_t enable(cli_session_t *s, uint8_t id, clear_result_t *c)
{
    daran_client_value_t closed_loop = {.kind = DARAN_CLIENT_VALUE_UINT, .uint = STATE_CLOSED_LOOP};
    c->enable_tried = true;
    cli_status_t status = cli_write_read_back(s, id, "requested_state", &closed_loop, c->kept,
                                              sizeof c->kept, &c->refused);
    if (status == CLI_DRIVE_ERROR) {
        return cli_fail(status, "drive %u refused requested_state %u: %s%s%s%s", id,
                        STATE_CLOSED_LOOP, daran_result_phrase(c->refused),
                        c->kept[0] != '\0' ? " (it keeps " : "", c->kept,
                        c->kept[0] != '\0' ? ")" : "");
    }
    if (status != CLI_OK) {
        return status;
    }
    uint32_t start = cli_now_ms();
    for (;;) {
        status = read_u32(s, id, "current_state", &c->state);
        if (status != CLI_OK) {
            return status;
        }
        c->have_state = true;
        if (c->state == STATE_CLOSED_LOOP || cli_now_ms() - start >= ENABLE_WAIT_MS ||
            cli_interrupted()) {
            break;
        }
        cli_session_pump(s, ENABLE_POLL_MS);
    }
    if (c->state != STATE_CLOSED_LOOP) {
        return cli_fail(CLI_DRIVE_ERROR,
                        "drive %u took requested_state %u but is in current_state %lu after %u ms",
                        id, STATE_CLOSED_LOOP, (unsigned long)c->state, ENABLE_WAIT_MS);
    }
    return CLI_OK;
}

static void print_clear_json(uint8_t id, const clear_result_t *c)
{
    printf("{\"id\":%u,", id);
    print_registers_json(&c->errors);
    if (c->have_state) {
        printf(",\"current_state\":%lu", (unsigned long)c->state);
    }
    if (c->enable_tried) {
        if (c->kept[0] != '\0') {
            fputs(",\"requested_state\":", stdout);
            cli_json_number(stdout, c->kept, strlen(c->kept));
        }
        if (c->refused != DARAN_OK) {
            cli_json_member(stdout, "error", daran_result_phrase(c->refused));
        }
    }
    printf(",\"enabled\":%s}\n", c->have_state && c->state == STATE_CLOSED_LOOP ? "true" : "false");
}

static cli_status_t clear_drive(cli_session_t *s, uint8_t id, bool want_enable, clear_result_t *c)
{
    daran_client_request_t sc = {.command = DARAN_CLIENT_CMD_SC, .id = id};
    cli_status_t status = cli_transact(s, &sc, NULL, NULL, false, NULL);
    if (status != CLI_OK) {
        return status;
    }
    status = read_errors(s, id, &c->errors);
    if (status != CLI_OK) {
        return status;
    }
    c->errors_read = true;
    if (!all_clear(&c->errors)) {
        /* sc cleared them, the fault set them again: the cause is still there */
        char remaining[NAMES_MAX];
        describe_remaining(&c->errors, remaining, sizeof remaining);
        return cli_fail(CLI_DRIVE_ERROR,
                        "drive %u: still set after \"sc %u\" (the fault is still present): %s%s",
                        id, id, remaining, want_enable ? "; not enabled" : "");
    }
    if (want_enable) {
        return enable(s, id, c);
    }
    status = read_u32(s, id, "current_state", &c->state);
    c->have_state = status == CLI_OK;
    return status;
}

static cli_status_t run_clear(cli_session_t *s, int argc, char **argv)
{
    uint8_t id = 0;
    bool have_id = false;
    bool want_enable = false;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--enable") == 0) {
            want_enable = true;
        } else if (argv[i][0] == '-' && argv[i][1] == '-') {
            return cli_usage(&cli_cmd_clear, "no option %s", argv[i]);
        } else if (have_id) {
            return cli_usage(&cli_cmd_clear, "one motor id is needed");
        } else if (!cli_parse_id(argv[i], false, &id)) {
            return cli_usage(&cli_cmd_clear, "\"%s\" is not a motor id (1..63)", argv[i]);
        } else {
            have_id = true;
        }
    }
    if (!have_id) {
        return cli_usage(&cli_cmd_clear, "one motor id is needed");
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    clear_result_t c;
    memset(&c, 0, sizeof c);
    status = clear_drive(s, id, want_enable, &c);
    if (!c.errors_read) {
        return status; /* sc refused, or no reply: reported, nothing to show */
    }
    if (s->options.json) {
        print_clear_json(id, &c);
        return status;
    }
    print_registers_text(&c.errors);
    if (status != CLI_OK) {
        return status;
    }
    if (c.state == STATE_CLOSED_LOOP) {
        printf("drive %u: cleared; %s closed-loop control (current_state %u)\n", id,
               want_enable ? "in" : "still in", STATE_CLOSED_LOOP);
    } else {
        printf("drive %u: cleared; it stays idle (current_state %lu) until `daran set %u "
               "requested_state %u` (or `daran clear %u --enable`)\n",
               id, (unsigned long)c.state, id, STATE_CLOSED_LOOP, id);
    }
    return CLI_OK;
}

const cli_command_t cli_cmd_clear = {
    .name = "clear",
    .synopsis = "ID [--enable]",
    .summary = "clear the error flags and report what remains",
    .help = "Sends `sc ID`, then `e ID`, and prints the registers as `errors` does: a\n"
            "flag still set means its fault is still present (exit status 1). A cleared\n"
            "drive stays idle until `daran set ID requested_state 8`; --enable writes\n"
            "that too, reads it back and waits up to 0.5 s for current_state 8 (exit\n"
            "status 1 when the drive refuses or does not get there).\n",
    .run = run_clear,
};

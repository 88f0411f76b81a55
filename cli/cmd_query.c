/* scan, get, set and send (docs/cli.md). */
#include <string.h>

#include "commands.h"

/* ------------------------------------------------------------------ scan */

/* Waiting for a drive that is not there is most of a scan: without
 * --timeout each id gets this long (a drive answers `i` within a few ms). */
#define SCAN_TIMEOUT_MS 50u

typedef struct version_line {
    char text[DARAN_CLIENT_LINE_MAX];
    size_t len;
    daran_client_number_t numbers[3];
    size_t count;
    bool readable;
} version_line_t;

static void take_version(void *ctx, const daran_client_line_t *line)
{
    version_line_t *v = ctx;
    memcpy(v->text, line->payload, line->len);
    v->len = line->len;
    v->readable = daran_client_parse_values(line, v->numbers, 3, 3, &v->count) == DARAN_OK;
}

static bool parse_range(const char *text, uint8_t *first, uint8_t *last)
{
    char buf[16];
    const char *dash = strchr(text, '-');
    if (dash == NULL) {
        return cli_parse_id(text, false, first) && (*last = *first, true);
    }
    size_t len = (size_t)(dash - text);
    if (len == 0 || len >= sizeof buf) {
        return false;
    }
    memcpy(buf, text, len);
    buf[len] = '\0';
    return cli_parse_id(buf, false, first) && cli_parse_id(dash + 1, false, last) &&
           *first <= *last;
}

static cli_status_t scan_ids(cli_session_t *s, uint8_t first, uint8_t last);

static cli_status_t run_scan(cli_session_t *s, int argc, char **argv)
{
    uint8_t first = 1;
    uint8_t last = DARAN_CLIENT_ID_MAX;
    if (argc > 1 || (argc == 1 && !parse_range(argv[0], &first, &last))) {
        return cli_usage(&cli_cmd_scan, "the ids to try are FIRST-LAST or one id, 1..63");
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    /* An id nobody has would cost every attempt and the quiet gap after it;
     * a late answer still goes to the stray handler, never to the next id. */
    uint32_t saved_timeout = s->options.timeout_ms;
    daran_client_link_config_t saved_config = s->link.config;
    if (!s->options.timeout_given) {
        s->options.timeout_ms = SCAN_TIMEOUT_MS;
    }
    s->link.config.retries = 0;
    s->link.config.quiet_ms = 5;
    status = scan_ids(s, first, last);
    s->options.timeout_ms = saved_timeout;
    s->link.config = saved_config;
    return status;
}

static cli_status_t scan_ids(cli_session_t *s, uint8_t first, uint8_t last)
{
    size_t found = 0;
    cli_status_t stopped = CLI_OK;
    if (s->options.json) {
        fputs("{\"drives\":[", stdout);
    }
    for (unsigned id = first; id <= last && !cli_interrupted(); id++) {
        version_line_t v = {.len = 0};
        daran_client_request_t request = {.command = DARAN_CLIENT_CMD_I, .id = (uint8_t)id};
        daran_result_t result;
        cli_status_t one = cli_transact(s, &request, take_version, &v, true, &result);
        if (one == CLI_PORT_ERROR || one == CLI_GATEWAY_BUS_ERROR) {
            /* the port, or the gateway's bus, is down: the next ids would fail alike */
            char why[CLI_FAILURE_MAX];
            stopped = cli_failure_text(s, &request, one, result, why, sizeof why);
            stopped = cli_fail(stopped, "%s; scan stopped at id %u", why, id);
            break;
        }
        if (one == CLI_NO_REPLY && result == DARAN_ERR_NO_REPLY) {
            continue; /* nobody there */
        }
        found++;
        cli_field_t f[3];
        bool whole = one == CLI_OK && v.readable && cli_split_fields(v.text, v.len, f, 3) == 3;
        if (s->options.json) {
            printf("%s{\"id\":%u", found > 1 ? "," : "", id);
            if (whole) {
                static const char *const names[3] = {"firmware", "hardware", "serial_number"};
                for (size_t k = 0; k < 3; k++) {
                    printf(",\"%s\":", names[k]);
                    cli_json_number(stdout, f[k].text, f[k].len);
                }
            } else {
                cli_json_member(stdout, "error", one == CLI_DRIVE_ERROR
                                                     ? daran_result_phrase(result)
                                                     : "unreadable reply");
            }
            putchar('}');
        } else if (whole) {
            printf("drive %u: firmware %.*s, hardware %.*s, serial number %.*s\n", id,
                   (int)f[0].len, f[0].text, (int)f[1].len, f[1].text, (int)f[2].len, f[2].text);
        } else {
            printf("drive %u: answers, but %s\n", id,
                   one == CLI_DRIVE_ERROR ? daran_result_phrase(result) : "its reply is unreadable");
        }
    }
    if (s->options.json) {
        printf("],\"port\":");
        cli_json_string(stdout, s->port_path, strlen(s->port_path));
        puts("}");
    } else if (found == 0 && stopped == CLI_OK) {
        printf("no drive answered on %s (ids %u..%u)\n", s->port_path, first, last);
    }
    if (stopped != CLI_OK) {
        return stopped;
    }
    if (cli_interrupted()) {
        return cli_fail(CLI_NO_REPLY, "scan interrupted");
    }
    return found > 0 ? CLI_OK : CLI_NO_REPLY;
}

const cli_command_t cli_cmd_scan = {
    .name = "scan",
    .synopsis = "[FIRST-LAST]",
    .summary = "list the drives that answer, with version and serial number",
    .help = "Sends `i ID` to each id (default 1-63) and lists the drives that answer:\n"
            "their firmware version, hardware version and serial number. Each id waits\n"
            "50 ms unless --timeout says otherwise. Exit status 3 when none answers.\n",
    .run = run_scan,
};

/* ------------------------------------------------------------------ get */

/* A path's `axisN.` names a drive too: N must be the command's id (or 0,
 * as discovery writes it), else another drive's value would be shown under
 * this one's name. */
static bool path_names_other_drive(const char *path, uint8_t id)
{
    if (strncmp(path, "axis", 4) != 0) {
        return false;
    }
    unsigned n = 0;
    const char *p = path + 4;
    while (*p >= '0' && *p <= '9' && n < 100u) {
        n = n * 10u + (unsigned)(*p++ - '0');
    }
    return p != path + 4 && *p == '.' && n != 0u && n != id;
}

static void json_path_head(size_t index, const char *path)
{
    printf("%s{\"path\":", index > 0 ? "," : "");
    cli_json_string(stdout, path, strlen(path));
}

static cli_status_t run_get(cli_session_t *s, int argc, char **argv)
{
    uint8_t id;
    if (argc < 2) {
        return cli_usage(&cli_cmd_get, "an id and at least one path are needed");
    }
    if (!cli_parse_id(argv[0], false, &id)) {
        return cli_usage(&cli_cmd_get, "\"%s\" is not a motor id (1..63)", argv[0]);
    }
    for (int i = 1; i < argc; i++) {
        if (path_names_other_drive(argv[i], id)) {
            return cli_usage(&cli_cmd_get, "%s is not a path of drive %u", argv[i], id);
        }
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    if (s->options.json) {
        printf("{\"id\":%u,\"properties\":[", id);
    }
    cli_status_t worst = CLI_OK;
    for (int i = 1; i < argc; i++) {
        cli_text_line_t value = {.len = 0};
        daran_client_request_t request = {.command = DARAN_CLIENT_CMD_R, .id = id, .path = argv[i]};
        daran_result_t result;
        status = cli_transact(s, &request, cli_take_line, &value, false, &result);
        if (status != CLI_OK && status != CLI_DRIVE_ERROR) {
            worst = status; /* the drive or the port is gone: the rest would fail alike */
            break;
        }
        if (s->options.json) {
            json_path_head((size_t)(i - 1), argv[i]);
            if (status == CLI_OK) {
                fputs(",\"value\":", stdout);
                cli_json_number(stdout, value.text, value.len);
            } else {
                cli_json_member(stdout, "error", daran_result_phrase(result));
            }
            putchar('}');
        } else if (status == CLI_OK) {
            printf("%s %.*s\n", argv[i], (int)value.len, value.text);
        }
        if (status != CLI_OK && worst == CLI_OK) {
            worst = status;
        }
    }
    if (s->options.json) {
        puts("]}");
    }
    return worst;
}

const cli_command_t cli_cmd_get = {
    .name = "get",
    .synopsis = "ID PATH...",
    .summary = "read properties",
    .help = "Reads each property (`r`) and prints `PATH VALUE`, the value as the drive\n"
            "printed it. PATH is written as the vendor's tools write it, with or without\n"
            "`axisN.` (`output_shaft.vel_limit`, `axis1.output_shaft.vel_limit`, `vbus_voltage`);\n"
            "the id goes where the protocol wants it. A path the drive refuses is reported\n"
            "and the others are still read (exit status 1).\n",
    .run = run_get,
};

/* ------------------------------------------------------------------ set */

static cli_status_t run_set(cli_session_t *s, int argc, char **argv)
{
    uint8_t id;
    if (argc < 3 || argc % 2 == 0) {
        return cli_usage(&cli_cmd_set, "an id and PATH VALUE pairs are needed");
    }
    if (!cli_parse_id(argv[0], false, &id)) {
        return cli_usage(&cli_cmd_set, "\"%s\" is not a motor id (1..63)", argv[0]);
    }
    daran_client_value_t values[32];
    if (argc / 2 > 32) {
        return cli_usage(&cli_cmd_set, "at most 32 properties at a time");
    }
    for (int i = 1; i < argc; i += 2) {
        if (path_names_other_drive(argv[i], id)) {
            return cli_usage(&cli_cmd_set, "%s is not a path of drive %u", argv[i], id);
        }
        if (!cli_parse_value(argv[i + 1], &values[i / 2])) {
            return cli_usage(&cli_cmd_set, "\"%s\" is not a number (for %s)", argv[i + 1],
                             argv[i]);
        }
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    if (s->options.json) {
        printf("{\"id\":%u,\"properties\":[", id);
    }
    cli_status_t worst = CLI_OK;
    for (int i = 1; i < argc; i += 2) {
        char kept[DARAN_CLIENT_LINE_MAX];
        daran_result_t refused;
        status = cli_write_read_back(s, id, argv[i], &values[i / 2], kept, sizeof kept, &refused);
        if (status != CLI_OK && status != CLI_DRIVE_ERROR) {
            worst = status;
            break;
        }
        if (status == CLI_DRIVE_ERROR) {
            cli_fail(status, "drive %u refused %s = %s: %s%s%s%s", id, argv[i], argv[i + 1],
                     daran_result_phrase(refused), kept[0] != '\0' ? " (it keeps " : "", kept,
                     kept[0] != '\0' ? ")" : "");
            if (worst == CLI_OK) {
                worst = status;
            }
        }
        if (s->options.json) {
            json_path_head((size_t)(i / 2), argv[i]);
            fputs(",\"asked\":", stdout); /* the user's text, which JSON may not take as a number */
            cli_json_string(stdout, argv[i + 1], strlen(argv[i + 1]));
            if (kept[0] != '\0') {
                fputs(",\"kept\":", stdout);
                cli_json_number(stdout, kept, strlen(kept));
            }
            if (status == CLI_DRIVE_ERROR) {
                cli_json_member(stdout, "error", daran_result_phrase(refused));
            }
            putchar('}');
        } else if (status == CLI_OK) {
            if (cli_same_number(argv[i + 1], kept)) {
                printf("%s %s\n", argv[i], kept);
            } else {
                printf("%s %s (asked %s)\n", argv[i], kept, argv[i + 1]);
            }
        }
    }
    if (s->options.json) {
        puts("]}");
    }
    return worst;
}

const cli_command_t cli_cmd_set = {
    .name = "set",
    .synopsis = "ID PATH VALUE [PATH VALUE...]",
    .summary = "write properties and read back what the drive kept",
    .help = "Writes each property (`w`) and reads it back (`r`) in the same round trip,\n"
            "then prints `PATH KEPT` with `(asked VALUE)` when the drive keeps something\n"
            "else. An integer VALUE is sent as an integer, anything else as a float. A\n"
            "refused value is reported with the phrase the drive gave and the value it\n"
            "still has (exit status 1); the other pairs are still written. Nothing is\n"
            "saved: `daran send \"ss ID\"` keeps the values over a power cycle.\n",
    .run = run_set,
};

/* ------------------------------------------------------------------ send */

typedef struct send_ctx {
    bool json;
    size_t lines;
} send_ctx_t;

static void print_reply_line(void *ctx, const daran_client_line_t *line)
{
    send_ctx_t *c = ctx;
    if (c->json) {
        if (c->lines > 0) {
            putchar(',');
        }
        cli_json_string(stdout, line->payload, line->len);
    } else {
        printf("%.*s\n", (int)line->len, line->payload);
    }
    c->lines++;
}

static cli_status_t send_one(cli_session_t *s, const char *text, size_t len, size_t index)
{
    while (len > 0 && (text[len - 1] == '\n' || text[len - 1] == '\r')) {
        len--;
    }
    bool known;
    daran_client_reply_shape_t shape = daran_client_line_shape(text, len, &known);
    if (!known) {
        shape = DARAN_CLIENT_REPLY_UNTIL_QUIET; /* a port's own command: lines or none */
    }
    send_ctx_t ctx = {.json = s->options.json, .lines = 0};
    if (s->options.json) {
        printf("%s{\"line\":", index > 0 ? "," : "");
        cli_json_string(stdout, text, len);
        fputs(",\"reply\":[", stdout);
    }
    daran_client_outcome_t outcome;
    daran_result_t result = daran_client_transact_line(&s->link, text, len, shape,
                                                       s->options.timeout_ms, print_reply_line,
                                                       &ctx, &outcome);
    if (!known && result == DARAN_ERR_NO_REPLY && !outcome.drive_error) {
        result = DARAN_OK; /* silence is an answer from a command we do not know */
    }
    cli_status_t status = s->port_failed ? CLI_PORT_ERROR : cli_status_of(result, outcome.drive_error);
    if (s->options.json) {
        putchar(']');
        if (status != CLI_OK) {
            const char *what = outcome.drive_error || result == DARAN_ERR_NO_REPLY
                                   ? daran_result_phrase(result)
                                   : "damaged reply";
            cli_json_member(stdout, "error", what);
        }
        putchar('}');
    } else if (outcome.drive_error) {
        printf("error: %s\n", daran_result_phrase(result)); /* the line as it came */
    }
    switch (status) {
    case CLI_OK:
        return CLI_OK;
    case CLI_DRIVE_ERROR:
        return cli_fail(status, "\"%.*s\": the drive answered error: %s", (int)len, text,
                        daran_result_phrase(result));
    case CLI_PORT_ERROR:
        return s->port_failed ? cli_port_status(s) : cli_fail(status, "%s: cannot write", s->port_path);
    case CLI_GATEWAY_BUS_ERROR:
        return cli_fail(status, "\"%.*s\": not sent: the gateway on %s answered \"error: %s\" "
                        "(it could not send it, or all of it, on its CAN bus)", (int)len, text,
                        s->port_path, daran_result_phrase(result));
    case CLI_NO_REPLY:
        if (result == DARAN_ERR_NO_REPLY && outcome.drive_error) {
            return cli_fail(status, "\"%.*s\": no reply: the gateway on %s answered \"error: no "
                            "reply\"", (int)len, text, s->port_path);
        }
        if (result == DARAN_ERR_NO_REPLY) {
            return cli_fail(status, "\"%.*s\": no reply within %u ms on %s", (int)len, text,
                            (unsigned)s->options.timeout_ms, s->port_path);
        }
        return cli_fail(status, "\"%.*s\": the reply on %s was damaged (%s)", (int)len, text,
                        s->port_path, daran_result_phrase(result));
    default:
        return cli_fail(status, "\"%.*s\": %s", (int)len, text,
                        result == DARAN_ERR_LINE_TOO_LONG ? "line too long"
                                                          : daran_result_phrase(result));
    }
}

static cli_status_t run_send(cli_session_t *s, int argc, char **argv)
{
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    if (s->options.json) {
        fputs("{\"lines\":[", stdout);
    }
    cli_status_t worst = CLI_OK;
    size_t index = 0;
    if (argc > 0) {
        for (int i = 0; i < argc && worst != CLI_PORT_ERROR; i++) {
            status = send_one(s, argv[i], strlen(argv[i]), index++);
            worst = worst != CLI_OK ? worst : status;
        }
    } else {
        char line[DARAN_CLIENT_LINE_MAX + 2];
        unsigned long number = 0;
        while (worst != CLI_PORT_ERROR && fgets(line, sizeof line, stdin) != NULL) {
            size_t len = strlen(line);
            number++;
            if (len == sizeof line - 1 && line[len - 1] != '\n') {
                /* longer than any line a drive takes: skipped whole, never sent in pieces */
                int c;
                while ((c = getchar()) != EOF && c != '\n') {
                }
                status = cli_fail(CLI_USAGE, "standard input line %lu: longer than %u bytes, "
                                             "not sent", number, (unsigned)DARAN_CLIENT_LINE_MAX);
            } else {
                status = send_one(s, line, len, index++);
            }
            worst = worst != CLI_OK ? worst : status;
        }
    }
    if (s->options.json) {
        puts("]}");
    }
    return worst;
}

const cli_command_t cli_cmd_send = {
    .name = "send",
    .synopsis = "[LINE...]",
    .summary = "send raw protocol lines and print the replies",
    .help = "Sends each LINE (or, with none, each line of standard input) as it is and\n"
            "prints every reply line. With --checksum the tool ends each line with\n"
            "` *N` (do not type it) and checks the sum of each reply line. The reply of\n"
            "a command the tool knows is collected by its shape (one line for `r f g i`,\n"
            "seven for `e`, up to `end` for `h ID properties`, errors only for the\n"
            "others, which wait --timeout for one); a port's own command is read until\n"
            "the link is quiet. The status is the first failure's; the lines after it\n"
            "are still sent.\n",
    .run = run_send,
};

/* watch (docs/cli.md): live values of one drive, through its telemetry
 * stream when it has one (protocol.md 11.2), else by polling `f` and `g`.
 * A stream the tool switched on is switched back to what the drive had
 * however the run ends: its duration, Ctrl-C, SIGTERM or an error. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "daran_port.h"
#include "watch_output.h"

/* The fields, in telemetry bit order (protocol.md 11.2). */
static const watch_field_t watch_fields[WATCH_FIELDS_MAX] = {
    {"pos", "deg", 0, 'f', 0},
    {"vel", "r/min", 1, 'f', 1},
    {"torque", "Nm", 2, 0, 0},
    {"iq", "A", 3, 'g', 1},
    {"vbus", "V", 4, 'g', 0},
    {"fet_temp", "\xC2\xB0" "C", 5, 0, 0},
    {"motor_temp", "\xC2\xB0" "C", 6, 0, 0},
    {"error", "", 7, 0, 0},
    {"trajectory_done", "", 8, 0, 0},
};

#define WATCH_DEFAULT_PERIOD_MS 50u
/* A stream that sends nothing for this long (or four periods, if longer)
 * has stopped: the drive was reset or the link is gone. */
#define WATCH_STALL_MS 1000u
/* How long one wait for reports lasts, so the duration ends on time. */
#define WATCH_SLICE_MS 50u

typedef struct watch_args {
    uint8_t id;
    const watch_field_t *fields[WATCH_FIELDS_MAX];
    size_t field_count;
    uint32_t period_ms;
    uint32_t duration_ms; /* 0: until a signal */
    const char *csv;
    const char *plot;
    bool poll;
} watch_args_t;

static const watch_field_t *field_named(const char *name)
{
    for (size_t i = 0; i < WATCH_FIELDS_MAX; i++) {
        if (strcmp(watch_fields[i].name, name) == 0) {
            return &watch_fields[i];
        }
    }
    return NULL;
}

static bool pollable(const watch_args_t *a, const watch_field_t **missing)
{
    for (size_t i = 0; i < a->field_count; i++) {
        if (a->fields[i]->poll_command == 0) {
            *missing = a->fields[i];
            return false;
        }
    }
    return true;
}

/* The directory of `path` can take a new file (checked before the port is
 * opened, so a mistyped path costs no run). */
static bool directory_writable(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL) {
        return access(".", W_OK) == 0;
    }
    char dir[512];
    size_t len = slash == path ? 1 : (size_t)(slash - path);
    if (len >= sizeof dir) {
        return false;
    }
    memcpy(dir, path, len);
    dir[len] = '\0';
    return access(dir, W_OK) == 0;
}

static cli_status_t parse_args(int argc, char **argv, watch_args_t *a)
{
    const cli_command_t *me = &cli_cmd_watch;
    memset(a, 0, sizeof *a);
    a->period_ms = WATCH_DEFAULT_PERIOD_MS;
    bool have_id = false;
    for (int i = 0; i < argc; i++) {
        const char *arg = argv[i];
        if (strcmp(arg, "--poll") == 0) {
            a->poll = true;
            continue;
        }
        if (strcmp(arg, "--period") == 0 || strcmp(arg, "--duration") == 0 ||
            strcmp(arg, "--csv") == 0 || strcmp(arg, "--plot") == 0) {
            if (i + 1 >= argc) {
                return cli_usage(me, "%s needs a value", arg);
            }
            const char *value = argv[++i];
            if (strcmp(arg, "--csv") == 0) {
                a->csv = value;
            } else if (strcmp(arg, "--plot") == 0) {
                a->plot = value;
            } else {
                uint32_t *ms = arg[2] == 'p' ? &a->period_ms : &a->duration_ms;
                if (!cli_parse_seconds(value, ms) || *ms == 0) {
                    return cli_usage(me, "%s %s: not a time in seconds (0.001..3600)", arg, value);
                }
            }
            continue;
        }
        if (arg[0] == '-' && arg[1] == '-') {
            return cli_usage(me, "no option %s", arg);
        }
        if (!have_id) {
            if (!cli_parse_id(arg, false, &a->id)) {
                return cli_usage(me, "\"%s\" is not a motor id (1..63)", arg);
            }
            have_id = true;
            continue;
        }
        const watch_field_t *f = field_named(arg);
        if (f == NULL) {
            return cli_usage(me, "no field \"%s\" (pos vel torque iq vbus fet_temp motor_temp "
                                 "error trajectory_done)", arg);
        }
        for (size_t k = 0; k < a->field_count; k++) {
            if (a->fields[k] == f) {
                return cli_usage(me, "field %s named twice", arg);
            }
        }
        a->fields[a->field_count++] = f;
    }
    if (!have_id) {
        return cli_usage(me, "an id is needed");
    }
    if (a->field_count == 0) {
        a->fields[0] = field_named("pos");
        a->fields[1] = field_named("vel");
        a->field_count = 2;
    }
    const watch_field_t *missing;
    if (a->poll && !pollable(a, &missing)) {
        return cli_usage(me, "--poll reads pos vel (f) and vbus iq (g) only, not %s",
                         missing->name);
    }
    if (a->plot != NULL && !watch_gnuplot_found()) {
        return cli_usage(me, "--plot needs gnuplot, which is not on PATH "
                             "(Debian: apt-get install gnuplot-nox)");
    }
    const char *files[2] = {a->csv, a->plot};
    for (size_t k = 0; k < 2; k++) {
        if (files[k] != NULL && (files[k][0] == '\0' || !directory_writable(files[k]))) {
            return cli_usage(me, "cannot write %s (no such directory, or not writable)",
                             files[k]);
        }
    }
    return CLI_OK;
}

/* A number of a report as the drive printed it: the drive's printer is the
 * core's, and a correctly rounded read gives back the float it printed. */
static void number_text(const daran_client_number_t *n, char *buf)
{
    size_t len;
    if (n->is_integer) {
        size_t sign = n->negative ? 1 : 0;
        buf[0] = '-';
        len = sign + daran_format_uint(n->magnitude, buf + sign, WATCH_TEXT_MAX - 1 - sign);
    } else {
        len = daran_format_float(n->f32, buf, WATCH_TEXT_MAX - 1);
    }
    buf[len] = '\0';
}

/* ------------------------------------------------------------ telemetry */

typedef struct stream {
    watch_output_t *out;
    uint8_t id;
    size_t slot[WATCH_FIELDS_MAX]; /* each shown field's place in a report */
    size_t report_fields;          /* how many values a report of ours carries */
    uint32_t last_report_ms;
} stream_t;

static void take_report(void *ctx, const daran_client_report_t *report)
{
    stream_t *st = ctx;
    /* another drive's, or one sent before our fields were taken */
    if (report->id != st->id || report->count != st->report_fields) {
        return;
    }
    st->last_report_ms = cli_now_ms();
    watch_sample_t sample;
    size_t len = daran_format_float(report->time_s, sample.time, WATCH_TEXT_MAX - 1);
    sample.time[len] = '\0';
    for (size_t i = 0; i < st->out->field_count; i++) {
        number_text(&report->values[st->slot[i]], sample.values[i]);
    }
    watch_output_sample(st->out, &sample);
}

typedef struct saved_setting {
    const char *path;
    char value[DARAN_CLIENT_LINE_MAX];
} saved_setting_t;

/* A reply line into a char[DARAN_CLIENT_LINE_MAX], as a string. */
static void take_text(void *ctx, const daran_client_line_t *line)
{
    char *text = ctx;
    size_t len = line->len < DARAN_CLIENT_LINE_MAX - 1 ? line->len : DARAN_CLIENT_LINE_MAX - 1;
    memcpy(text, line->payload, len);
    text[len] = '\0';
}

static cli_status_t read_setting(cli_session_t *s, uint8_t id, saved_setting_t *setting)
{
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_R, .id = id,
                                      .path = setting->path, .scope = DARAN_CLIENT_SCOPE_AXIS};
    setting->value[0] = '\0';
    return cli_transact(s, &request, take_text, setting->value, false, NULL);
}

/* Write `text` to the drive's `path`; the drive's refusal is reported here. */
static cli_status_t write_setting(cli_session_t *s, uint8_t id, const char *path, const char *text,
                                  char *kept)
{
    daran_client_value_t value;
    if (!cli_parse_value(text, &value)) {
        return cli_fail(CLI_DRIVE_ERROR, "drive %u: axis%u.%s holds \"%s\", not a number", id, id,
                        path, text);
    }
    daran_result_t refused;
    cli_status_t status = cli_write_read_back(s, id, path, &value, kept, WATCH_TEXT_MAX, &refused);
    if (status == CLI_DRIVE_ERROR) {
        cli_fail(status, "drive %u refused axis%u.%s = %s: %s", id, id, path, text,
                 daran_result_phrase(refused));
    }
    return status;
}

/* Put the stream back as the drive had it: the period first (our reports
 * stop), then the fields. Both are tried whatever the first one does. */
static cli_status_t restore_stream(cli_session_t *s, uint8_t id, const saved_setting_t *period,
                                   const saved_setting_t *fields)
{
    char kept[WATCH_TEXT_MAX];
    cli_status_t first = write_setting(s, id, period->path, period->value, kept);
    if (first == CLI_PORT_ERROR) {
        return first;
    }
    cli_status_t second = write_setting(s, id, fields->path, fields->value, kept);
    return first != CLI_OK ? first : second;
}

static size_t bits_set(uint32_t bits)
{
    size_t count = 0;
    for (; bits != 0; bits &= bits - 1u) {
        count++;
    }
    return count;
}

/* The telemetry.fields bitmask of the shown fields; a report carries them
 * in bit order, so each one's place is the count of the bits below its own. */
static uint32_t plan_reports(const watch_args_t *a, stream_t *st)
{
    uint32_t mask = 0;
    for (size_t i = 0; i < a->field_count; i++) {
        mask |= 1u << a->fields[i]->bit;
    }
    for (size_t i = 0; i < a->field_count; i++) {
        st->slot[i] = bits_set(mask & ((1u << a->fields[i]->bit) - 1u));
    }
    st->report_fields = bits_set(mask);
    return mask;
}

/* Show the reports until the run ends. */
static cli_status_t follow_stream(cli_session_t *s, const watch_args_t *a, watch_output_t *out,
                                  stream_t *st, uint32_t stall_ms)
{
    s->on_report = take_report;
    s->report_ctx = st;
    uint32_t start = cli_now_ms();
    st->last_report_ms = start;
    bool stalled = false;
    while (!cli_interrupted() && !s->port_failed && watch_output_going(out)) {
        uint32_t now = cli_now_ms();
        if (a->duration_ms != 0 && now - start >= a->duration_ms) {
            break;
        }
        if (now - st->last_report_ms >= stall_ms) {
            stalled = true;
            break;
        }
        uint32_t slice = WATCH_SLICE_MS;
        if (a->duration_ms != 0 && a->duration_ms - (now - start) < slice) {
            slice = a->duration_ms - (now - start);
        }
        cli_session_pump(s, slice);
    }
    s->on_report = NULL;
    watch_output_end_line(out); /* a message below starts on a line of its own */
    if (s->port_failed) {
        return cli_port_status(s); /* nothing can be written back */
    }
    if (stalled) {
        return cli_fail(CLI_NO_REPLY, "drive %u sent no telemetry report for %u ms on %s", a->id,
                        (unsigned)stall_ms, s->port_path);
    }
    return out->failed;
}

static cli_status_t run_stream(cli_session_t *s, const watch_args_t *a, watch_output_t *out,
                               const char *old_period)
{
    saved_setting_t period = {.path = "telemetry.period"};
    saved_setting_t fields = {.path = "telemetry.fields"};
    memcpy(period.value, old_period, sizeof period.value);
    cli_status_t status = read_setting(s, a->id, &fields);
    if (status != CLI_OK) {
        return status;
    }

    stream_t st = {.out = out, .id = a->id};
    uint32_t mask = plan_reports(a, &st);

    /* From the first write on, whatever happens, the old settings go back. */
    char mask_text[WATCH_TEXT_MAX];
    char kept[WATCH_TEXT_MAX];
    char period_text[WATCH_TEXT_MAX];
    (void)snprintf(mask_text, sizeof mask_text, "%u", (unsigned)mask);
    (void)snprintf(period_text, sizeof period_text, "%u.%03u", (unsigned)(a->period_ms / 1000u),
                   (unsigned)(a->period_ms % 1000u));
    status = write_setting(s, a->id, fields.path, mask_text, kept);
    if (status == CLI_OK && strcmp(kept, mask_text) != 0) {
        status = cli_fail(CLI_DRIVE_ERROR, "drive %u keeps telemetry.fields %s, not %s", a->id,
                          kept, mask_text);
    }
    char period_kept[WATCH_TEXT_MAX] = "";
    if (status == CLI_OK) {
        status = write_setting(s, a->id, period.path, period_text, period_kept);
    }
    if (status == CLI_OK) {
        char banner[128];
        (void)snprintf(banner, sizeof banner, "drive %u: telemetry every %s s", a->id,
                       period_kept);
        watch_output_banner(out, banner);
        /* A drive that was streaming may first finish its old period. */
        uint32_t old_ms = 0;
        (void)cli_parse_seconds(period.value, &old_ms);
        uint32_t stall_ms = WATCH_STALL_MS;
        if (stall_ms < 4u * a->period_ms) {
            stall_ms = 4u * a->period_ms;
        }
        if (stall_ms < old_ms + a->period_ms) {
            stall_ms = old_ms + a->period_ms;
        }
        status = follow_stream(s, a, out, &st, stall_ms);
    }
    if (status == CLI_PORT_ERROR) {
        return status;
    }
    cli_status_t restored = restore_stream(s, a->id, &period, &fields);
    return status != CLI_OK ? status : restored;
}

/* ------------------------------------------------------------ polling */

/* Ask `f` or `g` and put its two values where the shown fields want them. */
static cli_status_t poll_once(cli_session_t *s, const watch_args_t *a, watch_output_t *out,
                              char command, watch_sample_t *sample)
{
    daran_client_request_t request = {
        .command = command == 'f' ? DARAN_CLIENT_CMD_F : DARAN_CLIENT_CMD_G, .id = a->id};
    char reply[DARAN_CLIENT_LINE_MAX] = "";
    daran_result_t result;
    cli_status_t status = cli_transact(s, &request, take_text, reply, true, &result);
    if (status != CLI_OK) {
        watch_output_end_line(out); /* the message starts on a line of its own */
        return cli_transact_failed(s, &request, status, result);
    }
    cli_field_t values[2];
    if (cli_split_fields(reply, strlen(reply), values, 2) != 2 || values[0].len >= WATCH_TEXT_MAX ||
        values[1].len >= WATCH_TEXT_MAX) {
        watch_output_end_line(out);
        return cli_fail(CLI_NO_REPLY, "drive %u's reply to \"%c %u\" is not two values: \"%s\"",
                        a->id, command, a->id, reply);
    }
    for (size_t i = 0; i < a->field_count; i++) {
        if (a->fields[i]->poll_command == command) {
            const cli_field_t *v = &values[a->fields[i]->poll_index];
            memcpy(sample->values[i], v->text, v->len);
            sample->values[i][v->len] = '\0';
        }
    }
    return CLI_OK;
}

static cli_status_t run_poll(cli_session_t *s, const watch_args_t *a, watch_output_t *out)
{
    bool need_f = false;
    bool need_g = false;
    for (size_t i = 0; i < a->field_count; i++) {
        need_f = need_f || a->fields[i]->poll_command == 'f';
        need_g = need_g || a->fields[i]->poll_command == 'g';
    }
    char banner[96];
    (void)snprintf(banner, sizeof banner, "drive %u: polling every %u.%03u s", a->id,
                   (unsigned)(a->period_ms / 1000u), (unsigned)(a->period_ms % 1000u));
    watch_output_banner(out, banner);
    uint32_t start = cli_now_ms();
    uint32_t next = start;
    while (!cli_interrupted() && watch_output_going(out)) {
        uint32_t now = cli_now_ms();
        if (a->duration_ms != 0 && now - start >= a->duration_ms) {
            break;
        }
        int32_t early = (int32_t)(next - now);
        if (early > 0) {
            uint32_t wait = (uint32_t)early;
            if (a->duration_ms != 0 && a->duration_ms - (now - start) < wait) {
                wait = a->duration_ms - (now - start);
            }
            cli_session_pump(s, wait);
            continue;
        }
        watch_sample_t sample;
        uint32_t elapsed = now - start;
        (void)snprintf(sample.time, sizeof sample.time, "%u.%03u", (unsigned)(elapsed / 1000u),
                       (unsigned)(elapsed % 1000u));
        cli_status_t status = CLI_OK;
        if (need_f) {
            status = poll_once(s, a, out, 'f', &sample);
        }
        if (status == CLI_OK && need_g) {
            status = poll_once(s, a, out, 'g', &sample);
        }
        if (status != CLI_OK) {
            return status;
        }
        watch_output_sample(out, &sample);
        /* keep the rhythm; a late sample does not make the next ones crowd */
        next += a->period_ms;
        if ((int32_t)(cli_now_ms() - next) > 0) {
            next = cli_now_ms() + a->period_ms;
        }
    }
    return out->failed;
}

/* ------------------------------------------------------------ the command */

static cli_status_t watch(cli_session_t *s, const watch_args_t *a, watch_output_t *out)
{
    if (!a->poll) {
        saved_setting_t period = {.path = "telemetry.period"};
        daran_client_request_t probe = {.command = DARAN_CLIENT_CMD_R, .id = a->id,
                                        .path = period.path, .scope = DARAN_CLIENT_SCOPE_AXIS};
        daran_result_t result;
        cli_status_t status = cli_transact(s, &probe, take_text, period.value, true, &result);
        if (status == CLI_OK) {
            out->time_label = "drive time (s)";
            return run_stream(s, a, out, period.value);
        }
        if (status != CLI_DRIVE_ERROR || result != DARAN_ERR_INVALID_PROPERTY) {
            return cli_transact_failed(s, &probe, status, result);
        }
        const watch_field_t *missing;
        if (!pollable(a, &missing)) {
            return cli_usage(&cli_cmd_watch, "drive %u has no telemetry, and polling reads pos "
                                             "vel (f) and vbus iq (g) only, not %s",
                             a->id, missing->name);
        }
    }
    out->time_label = "time since start (s)";
    return run_poll(s, a, out);
}

static cli_status_t run_watch(cli_session_t *s, int argc, char **argv)
{
    watch_args_t a;
    cli_status_t status = parse_args(argc, argv, &a);
    if (status != CLI_OK) {
        return status;
    }
    status = cli_session_connect(s);
    if (status != CLI_OK) {
        return status;
    }
    cli_catch_signals();
    void (*saved_pipe)(int) = signal(SIGPIPE, SIG_IGN); /* see watch_output_going() */
    watch_output_t out = {.field_count = a.field_count, .json = s->options.json,
                          .csv_path = a.csv, .plot_path = a.plot};
    memcpy(out.fields, a.fields, sizeof out.fields);
    watch_output_init(&out);
    /* the shell lends its session: its handlers come back afterwards */
    cli_report_fn saved_report = s->on_report;
    void *saved_report_ctx = s->report_ctx;
    s->on_report = NULL;
    status = watch(s, &a, &out);
    s->on_report = saved_report;
    s->report_ctx = saved_report_ctx;
    cli_status_t finished = watch_output_finish(&out, status == CLI_OK);
    if (!out.reader_gone) {
        signal(SIGPIPE, saved_pipe); /* else main's last flush would die of it */
    }
    if (status == CLI_OK && out.terminal) {
        printf("%lu samples%s%s%s%s\n", out.samples, a.csv != NULL ? "; CSV in " : "",
               a.csv != NULL ? a.csv : "", finished == CLI_OK && a.plot != NULL ? "; plot in " : "",
               finished == CLI_OK && a.plot != NULL ? a.plot : "");
    }
    return status != CLI_OK ? status : finished;
}

const cli_command_t cli_cmd_watch = {
    .name = "watch",
    .synopsis = "ID [FIELD...] [--period S] [--duration S] [--csv FILE] [--plot FILE.png] [--poll]",
    .summary = "live values, streamed or polled; CSV and a gnuplot picture",
    .help = "Shows FIELDs of drive ID live (default: pos vel), every --period seconds\n"
            "(default 0.05), until --duration seconds have passed or Ctrl-C/SIGTERM.\n"
            "FIELDs: pos (deg) vel (r/min) torque (Nm) iq (A) vbus (V) fet_temp (C)\n"
            "motor_temp (C) error trajectory_done.\n"
            "A drive with telemetry (protocol.md 11.2) streams them: the tool sets\n"
            "axisID.telemetry.fields and .period and writes the drive's own values back\n"
            "when it ends, however it ends. A drive without (or --poll) is polled with\n"
            "`f` (pos vel) and `g` (vbus iq); other fields need telemetry.\n"
            "On a terminal one status line is redrawn in place (at most 10 times a\n"
            "second); otherwise each sample is a line `TIME VALUE...`, with --json a JSON\n"
            "object per line. TIME is the drive's clock (telemetry) or seconds since the\n"
            "start (polling). --csv FILE: `time_s,FIELD...` and a row per sample, values\n"
            "as the drive printed them. --plot FILE.png: gnuplot draws each field against\n"
            "time when the run ends (needs gnuplot on PATH; without it: exit status 2).\n"
            "A file that cannot be written is exit status 2.\n",
    .run = run_watch,
};

/* `daran watch`: the live view, the CSV file and the gnuplot picture
 * (watch_output.h). */
#include "watch_output.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* A person reads a status line a few times a second; redrawing it at the
 * rate of a fast stream would only load the terminal. */
#define WATCH_REDRAW_MS 100u

bool watch_gnuplot_found(void)
{
    const char *path = getenv("PATH");
    if (path == NULL || path[0] == '\0') {
        path = "/usr/bin:/bin";
    }
    while (*path != '\0') {
        size_t len = strcspn(path, ":");
        char candidate[512];
        /* an empty PATH entry means the current directory */
        int n = snprintf(candidate, sizeof candidate, "%.*s%sgnuplot", (int)len, path,
                         len > 0 ? "/" : "");
        if (n > 0 && (size_t)n < sizeof candidate && access(candidate, X_OK) == 0) {
            return true;
        }
        path += len;
        if (*path == ':') {
            path++;
        }
    }
    return false;
}

void watch_output_init(watch_output_t *out)
{
    out->terminal = !out->json && isatty(STDOUT_FILENO);
    out->opened = false;
    out->csv = NULL;
    out->plot_data = NULL;
    out->plot_data_path[0] = '\0';
    out->failed = CLI_OK;
    out->reader_gone = false;
    out->draw_pending = false;
    out->line_open = false;
    out->samples = 0;
}

bool watch_output_going(const watch_output_t *out)
{
    return out->failed == CLI_OK && !out->reader_gone;
}

/* Each sample is flushed: a script reading the pipe sees it as it comes.
 * A reader that went away (SIGPIPE is ignored meanwhile) ends the run as
 * Ctrl-C would, so the drive's settings still go back. */
static void flush_stdout(watch_output_t *out)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        out->reader_gone = true;
    }
}

void watch_output_banner(watch_output_t *out, const char *what)
{
    if (out->terminal) {
        printf("%s (Ctrl-C ends)\n", what);
        fflush(stdout);
    }
}

static cli_status_t file_failed(watch_output_t *out, const char *path, int error)
{
    watch_output_end_line(out);
    out->failed = cli_fail(CLI_USAGE, "watch: cannot write %s: %s", path, strerror(error));
    return out->failed;
}

static cli_status_t open_files(watch_output_t *out)
{
    out->opened = true;
    if (out->csv_path != NULL) {
        out->csv = fopen(out->csv_path, "w");
        if (out->csv == NULL) {
            return file_failed(out, out->csv_path, errno);
        }
        fputs("time_s", out->csv);
        for (size_t i = 0; i < out->field_count; i++) {
            fprintf(out->csv, ",%s", out->fields[i]->name);
        }
        fputc('\n', out->csv);
    }
    if (out->plot_path != NULL) {
        const char *dir = getenv("TMPDIR");
        int n = snprintf(out->plot_data_path, sizeof out->plot_data_path, "%s/daran-watch-XXXXXX",
                         dir != NULL && dir[0] != '\0' ? dir : "/tmp");
        int fd = n > 0 && (size_t)n < sizeof out->plot_data_path ? mkstemp(out->plot_data_path)
                                                                  : -1;
        if (fd < 0) {
            int error = n > 0 && (size_t)n < sizeof out->plot_data_path ? errno : ENAMETOOLONG;
            out->plot_data_path[0] = '\0';
            return file_failed(out, "the plot's data (in TMPDIR)", error);
        }
        out->plot_data = fdopen(fd, "w");
        if (out->plot_data == NULL) {
            close(fd);
            return file_failed(out, out->plot_data_path, errno);
        }
    }
    return CLI_OK;
}

static void draw_status_line(watch_output_t *out)
{
    const watch_sample_t *sample = &out->newest;
    printf("\rt %s s", sample->time);
    for (size_t i = 0; i < out->field_count; i++) {
        const watch_field_t *f = out->fields[i];
        printf("   %s %s%s%s", f->name, sample->values[i], f->unit[0] != '\0' ? " " : "", f->unit);
    }
    fputs("\033[K", stdout); /* erase what a longer line left */
    flush_stdout(out);
    out->line_open = true;
    out->draw_pending = false;
    out->last_draw_ms = cli_now_ms();
}

static void print_sample(watch_output_t *out, const watch_sample_t *sample)
{
    if (out->json) {
        fputs("{\"time_s\":", stdout);
        cli_json_number(stdout, sample->time, strlen(sample->time));
        for (size_t i = 0; i < out->field_count; i++) {
            printf(",\"%s\":", out->fields[i]->name);
            cli_json_number(stdout, sample->values[i], strlen(sample->values[i]));
        }
        fputs("}\n", stdout);
    } else {
        fputs(sample->time, stdout);
        for (size_t i = 0; i < out->field_count; i++) {
            printf(" %s", sample->values[i]);
        }
        putchar('\n');
    }
    flush_stdout(out);
}

static void record(FILE *file, char separator, const watch_sample_t *sample, size_t count)
{
    fputs(sample->time, file);
    for (size_t i = 0; i < count; i++) {
        fprintf(file, "%c%s", separator, sample->values[i]);
    }
    fputc('\n', file);
}

void watch_output_sample(watch_output_t *out, const watch_sample_t *sample)
{
    if (!watch_output_going(out) || (!out->opened && open_files(out) != CLI_OK)) {
        return;
    }
    out->samples++;
    if (out->terminal) {
        out->newest = *sample;
        out->draw_pending = true;
        if (!out->line_open || cli_now_ms() - out->last_draw_ms >= WATCH_REDRAW_MS) {
            draw_status_line(out);
        }
    } else {
        print_sample(out, sample);
    }
    if (out->csv != NULL) {
        record(out->csv, ',', sample, out->field_count);
        if (ferror(out->csv)) {
            file_failed(out, out->csv_path, errno);
        }
    }
    if (out->plot_data != NULL) {
        record(out->plot_data, ' ', sample, out->field_count);
        if (ferror(out->plot_data)) {
            file_failed(out, out->plot_data_path, errno);
        }
    }
}

/* A gnuplot string: single quotes, an inner one doubled. */
static void gnuplot_string(FILE *script, const char *text)
{
    fputc('\'', script);
    for (; *text != '\0'; text++) {
        if (*text == '\'') {
            fputc('\'', script);
        }
        fputc(*text, script);
    }
    fputc('\'', script);
}

static void write_plot_script(FILE *script, const watch_output_t *out)
{
    size_t panels = out->field_count;
    fprintf(script, "set terminal png size 900,%zu\nset output ", 60 + 220 * panels);
    gnuplot_string(script, out->plot_path);
    /* a margin above and below: a value that settles would hide in the frame */
    fprintf(script, "\nset multiplot layout %zu,1\nset grid\nset offsets 0, 0, graph 0.05, "
                    "graph 0.05\nset xlabel ", panels);
    gnuplot_string(script, out->time_label);
    fputs(" noenhanced\n", script);
    for (size_t i = 0; i < panels; i++) {
        const watch_field_t *f = out->fields[i];
        char label[64];
        (void)snprintf(label, sizeof label, "%s%s%s%s", f->name, f->unit[0] != '\0' ? " (" : "",
                       f->unit, f->unit[0] != '\0' ? ")" : "");
        fputs("set ylabel ", script);
        gnuplot_string(script, label);
        fputs(" noenhanced\nplot ", script); /* trajectory_done: no subscript */
        gnuplot_string(script, out->plot_data_path);
        fprintf(script, " using 1:%zu with lines notitle\n", i + 2);
    }
    fputs("unset multiplot\nset output\n", script);
}

/* text into why[0..size), cut to fit (a message may lose its tail). */
static void copy_cut(char *why, size_t size, const char *text)
{
    size_t len = strlen(text);
    if (len >= size) {
        len = size - 1;
    }
    memcpy(why, text, len);
    why[len] = '\0';
}

/* gnuplot's complaint, from what it wrote on stderr, as one line: the text
 * after "line N:" (and the system error, when it gave one), else its last
 * line. */
static void gnuplot_complaint(FILE *errors, char *why, size_t size)
{
    char line[256];
    why[0] = '\0';
    rewind(errors);
    while (fgets(line, sizeof line, errors) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        const char *text = line;
        while (*text == ' ') {
            text++;
        }
        if (*text == '\0' || *text == '^' || strncmp(text, "gnuplot>", 8) == 0) {
            continue;
        }
        const char *colon = strchr(text, ':');
        if (strncmp(text, "line ", 5) == 0 && colon != NULL) {
            for (text = colon + 1; *text == ' '; text++) {
            }
            copy_cut(why, size, text);
        } else if (strncmp(text, "system error:", 13) == 0 && why[0] != '\0') {
            size_t used = strlen(why);
            (void)snprintf(why + used, size - used, " (%s)", text + 14);
        } else if (why[0] == '\0' || strncmp(why, "line", 4) != 0) {
            copy_cut(why, size, text);
        }
    }
}

/* Run gnuplot with the script on its stdin; its stdout (where it would put
 * the picture when it cannot open the file) goes nowhere, its stderr into
 * a temporary file for the message. */
static cli_status_t draw_plot(const watch_output_t *out)
{
    FILE *errors = tmpfile();
    int script_pipe[2];
    if (errors == NULL || pipe(script_pipe) != 0) {
        if (errors != NULL) {
            fclose(errors);
        }
        return cli_fail(CLI_USAGE, "watch: cannot run gnuplot: %s", strerror(errno));
    }
    fflush(stdout);
    fflush(stderr);
    pid_t child = fork();
    if (child == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(script_pipe[0], STDIN_FILENO);
        dup2(null >= 0 ? null : fileno(errors), STDOUT_FILENO);
        dup2(fileno(errors), STDERR_FILENO);
        close(script_pipe[0]);
        close(script_pipe[1]);
        execlp("gnuplot", "gnuplot", (char *)NULL);
        fprintf(stderr, "cannot run gnuplot: %s\n", strerror(errno));
        _exit(127);
    }
    close(script_pipe[0]);
    if (child < 0) {
        close(script_pipe[1]);
        fclose(errors);
        return cli_fail(CLI_USAGE, "watch: cannot run gnuplot: %s", strerror(errno));
    }
    /* gnuplot may die before it has read the script: a write error, not a signal */
    void (*saved_pipe)(int) = signal(SIGPIPE, SIG_IGN);
    FILE *script = fdopen(script_pipe[1], "w");
    if (script != NULL) {
        write_plot_script(script, out);
        fclose(script);
    } else {
        close(script_pipe[1]);
    }
    int wait_status = 0;
    while (waitpid(child, &wait_status, 0) < 0 && errno == EINTR) {
    }
    signal(SIGPIPE, saved_pipe);
    cli_status_t status = CLI_OK;
    if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
        char why[200];
        gnuplot_complaint(errors, why, sizeof why);
        status = cli_fail(CLI_USAGE, "watch: gnuplot could not draw %s: %s", out->plot_path,
                          why[0] != '\0' ? why : "it failed");
    }
    fclose(errors);
    return status;
}

void watch_output_end_line(watch_output_t *out)
{
    if (out->terminal && out->line_open) {
        if (out->draw_pending) {
            draw_status_line(out);
        }
        putchar('\n');
        fflush(stdout);
        out->line_open = false;
    }
}

cli_status_t watch_output_finish(watch_output_t *out, bool ok)
{
    watch_output_end_line(out);
    if (ok && !out->opened && out->failed == CLI_OK) {
        (void)open_files(out); /* a run without samples still leaves its CSV header */
    }
    cli_status_t status = out->failed;
    if (out->csv != NULL && fclose(out->csv) != 0 && status == CLI_OK) {
        status = file_failed(out, out->csv_path, errno);
    }
    out->csv = NULL;
    if (out->plot_data != NULL && fclose(out->plot_data) != 0 && status == CLI_OK) {
        status = file_failed(out, out->plot_data_path, errno);
    }
    out->plot_data = NULL;
    if (ok && status == CLI_OK && out->plot_path != NULL) {
        status = out->samples > 0 ? draw_plot(out)
                                  : cli_fail(CLI_NO_REPLY, "watch: no sample came, so no plot");
    }
    if (out->plot_data_path[0] != '\0') {
        (void)remove(out->plot_data_path);
        out->plot_data_path[0] = '\0';
    }
    return status;
}

/* The replay program of a fuzz target (<name>_replay): runs stored inputs
 * through LLVMFuzzerTestOneInput() without libFuzzer, so CTest checks the
 * corpus with any compiler, and writes a recording's seeds for libFuzzer.
 *
 *   <name>_replay [--timeout SECONDS] [--write-seeds DIR] ARG...
 *
 * ARG: a directory (each regular file in it is one input, libFuzzer's corpus
 * format), a file (one input), or `--recording FILE` (a recording, whose
 * request lines become seeds: daran_fuzz_recording_next()). Each input runs
 * under an alarm of --timeout seconds (default 10): a hang fails like a
 * crash. With --write-seeds, the recordings' seeds are written to DIR as
 * <recording name>-<n> instead of being run (libFuzzer's seed corpus).
 * Exit status 0 when every input ran and held every invariant (at least one
 * input), else 1; a violation or a sanitizer report aborts at once.
 *
 * Built for the CAN target (DARAN_FUZZ_CAN_TARGET), ARG may also be
 * `--seeds`: the target's built-in seeds (daran_fuzz_can_seed()), which
 * --write-seeds writes too; recordings (lines) do not apply to frames. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "daran_fuzz.h"

static unsigned timeout_seconds = 10;
static const char *seed_dir; /* --write-seeds */
static size_t inputs_run;
static size_t seeds_written;
static char input_name[4096];

/* A violated invariant has printed its report and aborts: leave with
 * status 1, as the sanitizers do, so a test can read the report (CTest
 * reads no output of a program a signal ended). */
static void on_abort(int signal_number)
{
    (void)signal_number;
    _exit(1);
}

static void on_alarm(int signal_number)
{
    (void)signal_number;
    static const char text[] = "\nDARAN FUZZ: an input ran past the timeout (a hang): ";
    (void)!write(2, text, sizeof text - 1u);
    (void)!write(2, input_name, strlen(input_name));
    (void)!write(2, "\n", 1);
    _exit(1);
}

/* The whole file in a fresh buffer (one byte more, for a seed's last
 * '\n'), or NULL. */
static char *read_whole(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "cannot open %s\n", path);
        return NULL;
    }
    size_t cap = 4096;
    size_t used = 0;
    char *buf = malloc(cap);
    while (buf != NULL) {
        used += fread(buf + used, 1, cap - used - 1u, f);
        if (used < cap - 1u) {
            break;
        }
        cap *= 2u;
        char *bigger = realloc(buf, cap);
        if (bigger == NULL) {
            free(buf);
        }
        buf = bigger;
    }
    bool failed = ferror(f) != 0;
    fclose(f);
    if (buf == NULL || failed) {
        fprintf(stderr, "cannot read %s\n", path);
        free(buf);
        return NULL;
    }
    *len = used;
    return buf;
}

static void run_input(const uint8_t *data, size_t len)
{
    daran_fuzz_set_input_name(input_name);
    alarm(timeout_seconds);
    (void)LLVMFuzzerTestOneInput(data, len);
    alarm(0);
    daran_fuzz_set_input_name(NULL);
    inputs_run++;
}

static int replay_file(const char *path)
{
    size_t len = 0;
    char *data = read_whole(path, &len);
    if (data == NULL) {
        return 1;
    }
    snprintf(input_name, sizeof input_name, "%s", path);
    run_input((const uint8_t *)data, len);
    free(data);
    return 0;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every regular file of @p dir, in name order (a stable order for logs). */
static int replay_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (d == NULL) {
        fprintf(stderr, "cannot open directory %s\n", dir);
        return 1;
    }
    char **names = NULL;
    size_t count = 0;
    size_t cap = 0;
    int failures = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') {
            continue;
        }
        if (count == cap) {
            cap = cap == 0u ? 64u : cap * 2u;
            char **bigger = realloc(names, cap * sizeof *names);
            if (bigger == NULL) {
                failures++;
                break;
            }
            names = bigger;
        }
        names[count] = malloc(strlen(dir) + strlen(e->d_name) + 2u);
        if (names[count] == NULL) {
            failures++;
            break;
        }
        sprintf(names[count], "%s/%s", dir, e->d_name);
        count++;
    }
    closedir(d);
    if (count > 0u) {
        qsort(names, count, sizeof *names, compare_names);
    }
    for (size_t i = 0; i < count; i++) {
        struct stat st;
        if (failures == 0 && stat(names[i], &st) == 0 && S_ISREG(st.st_mode)) {
            failures += replay_file(names[i]);
        }
        free(names[i]);
    }
    free(names);
    return failures;
}

static int write_seed(const char *recording, unsigned n, const char *data, size_t len)
{
    const char *base = strrchr(recording, '/');
    base = base != NULL ? base + 1 : recording;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s-%03u", seed_dir, base, n);
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        return 1;
    }
    seeds_written++;
    return 0;
}

static int replay_recording(const char *path)
{
    size_t len = 0;
    char *text = read_whole(path, &len);
    if (text == NULL) {
        return 1;
    }
    char *seed = malloc(len + 1u);
    if (seed == NULL) {
        free(text);
        return 1;
    }
    daran_fuzz_recording_t rec;
    daran_fuzz_recording_open(&rec, text, len);
    int failures = 0;
    unsigned n = 0;
    for (;;) {
        size_t seed_len = 0;
        unsigned first = 0;
        unsigned last = 0;
        int got = daran_fuzz_recording_next(&rec, seed, len + 1u, &seed_len, &first, &last);
        if (got == 0) {
            break;
        }
        if (got < 0) {
            fprintf(stderr, "%s:%u: not a recording line (`# comment`, `SECONDS<TAB>request` "
                            "or `<SECONDS<TAB>reply`)\n",
                    path, first);
            failures++;
            break;
        }
        n++;
        if (seed_dir != NULL) {
            failures += write_seed(path, n, seed, seed_len);
        } else {
            snprintf(input_name, sizeof input_name, "%s, seed %u (request lines %u-%u)", path,
                     n, first, last);
            run_input((const uint8_t *)seed, seed_len);
        }
    }
    if (n == 0u && failures == 0) {
        fprintf(stderr, "%s: a recording without a request line\n", path);
        failures++;
    }
    free(seed);
    free(text);
    return failures;
}

#ifdef DARAN_FUZZ_CAN_TARGET
static int builtin_seeds(void)
{
    static uint8_t seed[4096];
    int failures = 0;
    size_t len;
    for (size_t n = 0; (len = daran_fuzz_can_seed(n, seed, sizeof seed)) > 0u; n++) {
        if (seed_dir != NULL) {
            failures += write_seed("can", (unsigned)n + 1u, (const char *)seed, len);
        } else {
            snprintf(input_name, sizeof input_name, "built-in seed %zu", n + 1u);
            run_input(seed, len);
        }
    }
    return failures;
}
#endif

static int usage(const char *program)
{
    fprintf(stderr,
            "usage: %s [--timeout SECONDS] [--write-seeds DIR] "
#ifdef DARAN_FUZZ_CAN_TARGET
            "(DIR | FILE | --seeds)...\n",
#else
            "(DIR | FILE | --recording FILE)...\n",
#endif
            program);
    return 2;
}

int main(int argc, char **argv)
{
    int failures = 0;
    int first = 1;
    for (; first < argc; first += 2) {
        if (strcmp(argv[first], "--timeout") == 0 && first + 1 < argc) {
            timeout_seconds = (unsigned)strtoul(argv[first + 1], NULL, 10);
        } else if (strcmp(argv[first], "--write-seeds") == 0 && first + 1 < argc) {
            seed_dir = argv[first + 1];
        } else {
            break;
        }
    }
    if (first >= argc) {
        return usage(argv[0]);
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_alarm;
    sigaction(SIGALRM, &sa, NULL);
    sa.sa_handler = on_abort;
    sigaction(SIGABRT, &sa, NULL);

    for (int i = first; i < argc; i++) {
#ifdef DARAN_FUZZ_CAN_TARGET
        if (strcmp(argv[i], "--seeds") == 0) {
            failures += builtin_seeds();
            continue;
        }
#endif
        if (strcmp(argv[i], "--recording") == 0) {
            if (i + 1 >= argc) {
                return usage(argv[0]);
            }
            failures += replay_recording(argv[++i]);
            continue;
        }
        if (seed_dir != NULL) {
            continue; /* only recordings become seeds */
        }
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "no such file or directory: %s\n", argv[i]);
            failures++;
        } else if (S_ISDIR(st.st_mode)) {
            failures += replay_dir(argv[i]);
        } else {
            failures += replay_file(argv[i]);
        }
    }
    if (seed_dir != NULL) {
        printf("%s: %zu seeds written to %s\n", argv[0], seeds_written, seed_dir);
        return failures == 0 ? 0 : 1;
    }
    if (failures != 0 || inputs_run == 0u) {
        fprintf(stderr, "%s: %zu inputs replayed; %s\n", argv[0], inputs_run,
                failures != 0 ? "some could not be read" : "no input");
        return 1;
    }
    const daran_fuzz_totals_t *t = daran_fuzz_totals();
#ifdef DARAN_FUZZ_CAN_TARGET
    printf("%s: %zu inputs replayed, every invariant held: %zu frames, %zu to ignore, %zu for "
           "another node, %zu with a setter, move or action call\n",
           argv[0], inputs_run, t->lines, t->answered_error, t->other_drive, t->mutating);
#else
    printf("%s: %zu inputs replayed, every invariant held: %zu request lines, %zu answered "
           "with an error, %zu for another drive, %zu with a setter, move or action call "
           "(%zu refused by the HAL)\n",
           argv[0], inputs_run, t->lines, t->answered_error, t->other_drive, t->mutating,
           t->refused);
#endif
    return 0;
}

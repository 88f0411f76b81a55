/* Standalone driver for a fuzz harness: replays the files and directories
 * named on the command line through LLVMFuzzerTestOneInput, so CTest can run
 * the corpus and every past crash under gcc without libFuzzer. A violated
 * invariant aborts (non-zero exit); a sanitizer report does the same. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz_hal.h"

static size_t replayed;

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "cannot open %s\n", path);
        return 1;
    }
    size_t cap = 4096, len = 0;
    uint8_t *buf = malloc(cap);
    for (;;) {
        if (buf == NULL) {
            fclose(f);
            fprintf(stderr, "out of memory reading %s\n", path);
            return 1;
        }
        len += fread(buf + len, 1, cap - len, f);
        if (len < cap) {
            break;
        }
        cap *= 2;
        buf = realloc(buf, cap);
    }
    fclose(f);
    /* Name the input first, so a crash report says which one. */
    fprintf(stderr, "replay %s (%zu bytes)\n", path, len);
    (void)LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    replayed++;
    return 0;
}

static int replay_path(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        fprintf(stderr, "no such file or directory: %s\n", path);
        return 1;
    }
    if (!S_ISDIR(st.st_mode)) {
        return replay_file(path);
    }
    DIR *d = opendir(path);
    if (d == NULL) {
        fprintf(stderr, "cannot open directory %s\n", path);
        return 1;
    }
    int failures = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') {
            continue;
        }
        size_t n = strlen(path) + strlen(e->d_name) + 2u;
        char *child = malloc(n);
        if (child == NULL) {
            closedir(d);
            return 1;
        }
        snprintf(child, n, "%s/%s", path, e->d_name);
        failures += replay_path(child);
        free(child);
    }
    closedir(d);
    return failures;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s FILE|DIR...\n", argv[0]);
        return 2;
    }
    int failures = 0;
    for (int i = 1; i < argc; i++) {
        failures += replay_path(argv[i]);
    }
    printf("%s: %zu inputs replayed, every invariant held\n", argv[0], replayed);
    return failures == 0 && replayed > 0 ? 0 : 1;
}

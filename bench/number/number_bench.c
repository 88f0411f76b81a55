/* Instruction-count benchmark of the number module against glibc, meant to run
 * under callgrind (bench/number/run_callgrind.sh): parse with daran_parse_f32
 * vs strtof, print with daran_format_float vs snprintf("%.9g"), over numbers a
 * real session sends: the tokens of the recorded client lines (file given on
 * the command line) plus generated telemetry (positions -360..360 with 2-4
 * decimals, velocities, small torques, %f-style values). Only the bench_*
 * functions are measured (callgrind --toggle-collect=bench_*). */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "number.h"

#define MAX_TOKENS 20000
#define TOKEN_LEN 48

static char g_text[MAX_TOKENS][TOKEN_LEN];
static size_t g_len[MAX_TOKENS];
static float g_value[MAX_TOKENS];
static size_t g_count;

static uint32_t g_rng = 12345u;

static uint32_t rnd(uint32_t n)
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return (g_rng >> 8) % n;
}

static void add_token(const char *t, size_t len)
{
    if (g_count < MAX_TOKENS && len > 0 && len < TOKEN_LEN) {
        memcpy(g_text[g_count], t, len);
        g_text[g_count][len] = '\0';
        g_len[g_count] = len;
        g_value[g_count] = strtof(g_text[g_count], NULL);
        g_count++;
    }
}

/* Numeric fields of the recorded lines: words made of digits, sign, '.', 'e'. */
static void load_recordings(const char *path)
{
    char line[256];
    FILE *f = fopen(path, "r");
    if (!f) {
        return;
    }
    while (fgets(line, sizeof line, f)) {
        char *tab = strchr(line, '\t'), *w;
        if (line[0] == '#' || !tab) {
            continue;
        }
        for (w = strtok(tab + 1, " \r\n"); w; w = strtok(NULL, " \r\n")) {
            float tmp;
            if (w[0] != '\0' && strspn(w, "0123456789+-.eE") == strlen(w) &&
                daran_parse_f32(w, strlen(w), &tmp) == DARAN_OK) {
                add_token(w, strlen(w));
            }
        }
    }
    fclose(f);
}

static void add_generated(size_t n)
{
    char buf[TOKEN_LEN];
    size_t i;
    for (i = 0; i < n; i++) {
        int len;
        switch (rnd(5)) {
        case 0: /* position, 2..4 decimals */
            len = snprintf(buf, sizeof buf, "%.*f", (int)(2 + rnd(3)), (double)rnd(7200001) / 10000.0 - 360.0);
            break;
        case 1: /* velocity */
            len = snprintf(buf, sizeof buf, "%.*f", (int)(1 + rnd(3)), (double)rnd(200001) / 1000.0 - 100.0);
            break;
        case 2: /* torque */
            len = snprintf(buf, sizeof buf, "%.3f", (double)rnd(10001) / 1000.0 - 5.0);
            break;
        case 3: /* C clients: printf("%f") */
            len = snprintf(buf, sizeof buf, "%f", (double)rnd(3600001) / 10000.0 - 180.0);
            break;
        default: /* small integers: ids, modes, counts */
            len = snprintf(buf, sizeof buf, "%u", rnd(100));
            break;
        }
        add_token(buf, (size_t)len);
    }
}

static volatile uint32_t g_sink;

__attribute__((noinline)) static void bench_parse_ours(void)
{
    size_t i;
    for (i = 0; i < g_count; i++) {
        float f;
        if (daran_parse_f32(g_text[i], g_len[i], &f) == DARAN_OK) {
            uint32_t b;
            memcpy(&b, &f, 4);
            g_sink ^= b;
        }
    }
}

__attribute__((noinline)) static void bench_parse_strtof(void)
{
    size_t i;
    for (i = 0; i < g_count; i++) {
        float f = strtof(g_text[i], NULL);
        uint32_t b;
        memcpy(&b, &f, 4);
        g_sink ^= b;
    }
}

__attribute__((noinline)) static void bench_print_ours(void)
{
    char buf[DARAN_F32_TEXT_MAX];
    size_t i;
    for (i = 0; i < g_count; i++) {
        g_sink ^= (uint32_t)daran_format_float(g_value[i], buf, sizeof buf);
    }
}

__attribute__((noinline)) static void bench_print_snprintf(void)
{
    char buf[32];
    size_t i;
    for (i = 0; i < g_count; i++) {
        g_sink ^= (uint32_t)snprintf(buf, sizeof buf, "%.9g", (double)g_value[i]);
    }
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "";
    int i;
    for (i = 2; i < argc; i++) {
        load_recordings(argv[i]);
    }
    add_generated(10000);
    if (!strcmp(mode, "parse_ours")) {
        bench_parse_ours();
    } else if (!strcmp(mode, "parse_strtof")) {
        bench_parse_strtof();
    } else if (!strcmp(mode, "print_ours")) {
        bench_print_ours();
    } else if (!strcmp(mode, "print_snprintf")) {
        bench_print_snprintf();
    } else {
        fprintf(stderr, "usage: number_bench parse_ours|parse_strtof|print_ours|print_snprintf [recordings...]\n");
        return 2;
    }
    printf("%zu values\n", g_count);
    return 0;
}

/* Replays a recorded request stream through daran-ascii or the baseline
 * yardstick, for callgrind to count (see run_all.sh) or to print every HAL
 * call and reply (--trace) so compare_traces.py can check both parsers do the
 * same thing.
 *
 *   bench_driver MODE [--trace] [--repeat N] (STREAM | --line TEXT)
 *   MODE: ours       daran_process_line() per line
 *         ours-poll  daran_rx_write() + daran_poll() per line (the byte path)
 *         baseline   baseline_process_line() per line (the sscanf/printf yardstick)
 *         handwritten handwritten_process_line() per line (the hand-written yardstick)
 *         handwritten-bytes handwritten_rx_write() of the line and its '\n'
 *         none       everything but the parser: reading, splitting, looping
 *         respell    no parsing: print the stream with every number the
 *                    hand-written yardstick rounds differently from a
 *                    correctly rounded strtof spelled as the float it gets
 *                    (%.9g, which reads back exactly), and the checksum of
 *                    such a line kept right (or kept wrong by as much);
 *                    compare_traces.py --yardstick handwritten runs the core
 *                    on it to tell rounding from other differences
 *
 * The stream is read and split before the first line is processed, so a
 * callgrind run limited to the parser's entry point counts the parser alone
 * (plus the trivial HAL and reply sink it calls). Only the public API is
 * used, so the core's insides can change without breaking this program: the
 * property lookup is counted by toggling callgrind on daran_find_property. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "baseline.h"
#include "handwritten.h"
#include "bench_hal.h"
#include "daran_drive.h"


static char *read_all(const char *path, size_t *size)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        perror(path);
        exit(2);
    }
    fseek(file, 0, SEEK_END);
    long length = ftell(file);
    fseek(file, 0, SEEK_SET);
    char *text = malloc((size_t)length + 1);
    if (text == NULL || fread(text, 1, (size_t)length, file) != (size_t)length) {
        fprintf(stderr, "%s: read failed\n", path);
        exit(2);
    }
    fclose(file);
    text[length] = '\0';
    *size = (size_t)length;
    return text;
}

typedef struct line {
    const char *text;
    size_t len;
} line_t;

/* Split at '\n' in place; each line becomes NUL-terminated too (the
 * baseline needs C strings; daran-ascii takes the length). */
static line_t *split_lines(char *text, size_t size, size_t *count)
{
    size_t n = 0;
    for (size_t i = 0; i < size; i++) {
        n += text[i] == '\n';
    }
    line_t *lines = malloc((n + 1) * sizeof *lines);
    size_t k = 0;
    char *start = text;
    for (size_t i = 0; i < size; i++) {
        if (text[i] == '\n') {
            text[i] = '\0';
            lines[k].text = start;
            lines[k].len = (size_t)(&text[i] - start);
            k++;
            start = &text[i + 1];
        }
    }
    *count = k;
    return lines;
}

/* Is the token a decimal of the protocol's grammar (no nan, inf, hex)? */
static int decimal_token(const char *text, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        char c = text[i];
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) {
            return 0;
        }
    }
    return len > 0;
}

static unsigned xor_of(const char *text, size_t len)
{
    unsigned x = 0;
    for (size_t i = 0; i < len; i++) {
        x ^= (unsigned char)text[i];
    }
    return x;
}

static void respell(const char *line, size_t len, FILE *out)
{
    char buf[1024];
    size_t n = 0;
    const char *star = memchr(line, '*', len);
    size_t payload = star != NULL ? (size_t)(star - line) : len;
    size_t i = 0;
    int field = 0;
    while (i < payload) {
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
            buf[n++] = line[i++];
            continue;
        }
        size_t start = i;
        while (i < payload && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
            i++;
        }
        size_t tlen = i - start;
        char token[256];
        float mine, right;
        int replaced = 0;
        if (field > 0 && tlen < sizeof token && decimal_token(line + start, tlen)) {
            memcpy(token, line + start, tlen);
            token[tlen] = '\0';
            char *end;
            right = strtof(token, &end);
            if (*end == '\0' && handwritten_parse_f32(token, tlen, &mine) == DARAN_OK &&
                memcmp(&mine, &right, sizeof mine) != 0) {
                n += (size_t)snprintf(buf + n, sizeof buf - n, "%.9g", (double)mine);
                replaced = 1;
            }
        }
        if (!replaced) {
            memcpy(buf + n, line + start, tlen);
            n += tlen;
        }
        field++;
    }
    if (star != NULL) {
        /* a well-formed checksum field: keep it right, or wrong by as much */
        const char *p = star + 1;
        unsigned value = 0, digits = 0;
        while (p < line + len && *p >= '0' && *p <= '9' && digits < 4) {
            value = value * 10 + (unsigned)(*p++ - '0');
            digits++;
        }
        if (digits >= 1 && digits <= 3 && value <= 255) {
            value ^= xor_of(line, payload) ^ xor_of(buf, n);
            n += (size_t)snprintf(buf + n, sizeof buf - n, "*%u", value);
            memcpy(buf + n, p, (size_t)(line + len - p));
            n += (size_t)(line + len - p);
        } else {
            memcpy(buf + n, star, len - payload);
            n += len - payload;
        }
    }
    fwrite(buf, 1, n, out);
    fputc('\n', out);
}

static int usage(void)
{
    fprintf(stderr, "usage: bench_driver ours|ours-poll|baseline|handwritten|handwritten-bytes|none|respell [--trace] [--repeat N] "
                    "(STREAM | --line TEXT)\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        return usage();
    }
    const char *mode = argv[1];
    const char *stream = NULL;
    const char *single = NULL;
    unsigned long repeat = 1;
    int trace = 0;
    for (int i = 2; i < argc; i++) {
        if (strcmp(argv[i], "--trace") == 0) {
            trace = 1;
        } else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
            repeat = strtoul(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--line") == 0 && i + 1 < argc) {
            single = argv[++i];
        } else {
            stream = argv[i];
        }
    }
    if ((stream == NULL) == (single == NULL)) {
        return usage();
    }
    size_t size;
    char *text;
    if (stream != NULL) {
        text = read_all(stream, &size);
    } else {
        size = strlen(single) + 1;
        text = malloc(size + 1);
        memcpy(text, single, size - 1);
        text[size - 1] = '\n';
        text[size] = '\0';
    }
    size_t count;
    line_t *lines = split_lines(text, size, &count);

    if (strcmp(mode, "respell") == 0) {
        for (size_t i = 0; i < count; i++) {
            respell(lines[i].text, lines[i].len, stdout);
        }
        return 0;
    }

    bench_hal_state_t hal_state;
    bench_hal_reset(&hal_state, trace ? stdout : NULL);
    static daran_drive_t drive;
    static baseline_t baseline;
    static handwritten_t handwritten;
    if (daran_init(&drive, &bench_hal, &hal_state) != DARAN_OK) {
        return 2;
    }
    baseline_init(&baseline, &bench_hal, &hal_state, bench_write, &hal_state);
    handwritten_init(&handwritten, &bench_hal, &hal_state, bench_write, &hal_state);

    unsigned long errors = 0;
    for (unsigned long r = 0; r < repeat; r++) {
        for (size_t i = 0; i < count; i++) {
            hal_state.line = (unsigned long)i + 1;
            if (strcmp(mode, "ours") == 0) {
                errors += daran_process_line(&drive, lines[i].text, lines[i].len) != DARAN_OK;
            } else if (strcmp(mode, "baseline") == 0) {
                errors += baseline_process_line(&baseline, lines[i].text) != DARAN_OK;
            } else if (strcmp(mode, "handwritten") == 0) {
                errors += handwritten_process_line(&handwritten, lines[i].text, lines[i].len) !=
                          DARAN_OK;
            } else if (strcmp(mode, "handwritten-bytes") == 0) {
                char *end = (char *)lines[i].text + lines[i].len;
                *end = '\n';
                handwritten_rx_write(&handwritten, lines[i].text, lines[i].len + 1);
                *end = '\0';
            } else if (strcmp(mode, "ours-poll") == 0) {
                /* The line and its '\n' through the ring, in pieces the ring can hold. */
                const char *p = lines[i].text;
                size_t left = lines[i].len + 1;
                char *end = (char *)lines[i].text + lines[i].len;
                *end = '\n';
                while (left > 0) {
                    size_t queued = daran_rx_write(&drive, p, left);
                    p += queued;
                    left -= queued;
                    (void)daran_poll(&drive);
                }
                *end = '\0';
            } else if (strcmp(mode, "none") != 0) {
                return usage();
            }
        }
    }
    if (!trace) {
        printf("%s: %lu lines x %lu, %lu answered with an error, %lu reply bytes\n", mode,
               (unsigned long)count, repeat, errors, hal_state.reply_bytes);
    }
    free(lines);
    free(text);
    return 0;
}

/* A program that uses daran-ascii the way a firmware project would, built
 * three ways by tools/ci.d/50-package.sh (installed CMake package,
 * add_subdirectory, pkg-config). It also proves that the headers it compiled
 * against agree with the library about the configuration: a line of exactly
 * DARAN_LINE_MAX bytes must be accepted and one byte more refused. */
#include <stdio.h>
#include <string.h>

#include "daran_ascii.h"
#include "stub_hal.h"

#if DARAN_REPLY_CRLF
#define LINE_END "\r\n"
#else
#define LINE_END "\n"
#endif

static char reply[DARAN_REPLY_MAX + 1];

static daran_stub_t stub;

static void write_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len > DARAN_REPLY_MAX) {
        len = DARAN_REPLY_MAX;
    }
    memcpy(reply, line, len);
    reply[len] = '\0';
}

static const daran_hal_t write_reply_port = {DARAN_STUB_HAL_FUNCTIONS, .write = write_reply};


static int failed;

static void expect(daran_drive_t *drive, const char *line, size_t len, const char *want)
{
    reply[0] = '\0';
    (void)daran_process_line(drive, line, len);
    if (strcmp(reply, want) != 0) {
        printf("FAIL: %.20s... (%u bytes) -> \"%s\", want \"%s\"\n", line, (unsigned)len, reply,
               want);
        failed++;
    }
}

int main(void)
{
    static daran_drive_t drive;
    static char padded[DARAN_LINE_MAX + 1];
    const char *read_vbus = "r vbus_voltage 1";

#ifdef CONSUMER_EXPECT_LINE_MAX
    /* the options header the project named must have reached both sides */
    if (DARAN_LINE_MAX != CONSUMER_EXPECT_LINE_MAX) {
        printf("FAIL: DARAN_LINE_MAX is %d, the project's options header says %d\n",
               (int)DARAN_LINE_MAX, (int)CONSUMER_EXPECT_LINE_MAX);
        return 1;
    }
#endif
    /* daran_init() also compares this file's build signature and
     * sizeof(daran_drive_t) with the
     * library's: built with other size options, it must refuse. */
    daran_stub_init(&stub, 1);
    stub.values[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.5f;
    daran_result_t init = daran_init(&drive, &write_reply_port, &stub);
    if (init != DARAN_OK) {
        printf("daran_init refused the instance: %s (sizeof(daran_drive_t) %u here)\n",
               daran_result_phrase(init), (unsigned)sizeof drive);
        return 1;
    }
    expect(&drive, read_vbus, strlen(read_vbus), "24.5" LINE_END);
    expect(&drive, "x 1", 3, "error: unknown command" LINE_END);
    /* Trailing blanks are whitespace, so the padded read is the same request. */
    memset(padded, ' ', sizeof padded);
    memcpy(padded, read_vbus, strlen(read_vbus));
    expect(&drive, padded, DARAN_LINE_MAX, "24.5" LINE_END);
    expect(&drive, padded, DARAN_LINE_MAX + 1, "error: line too long" LINE_END);

    printf("consumer (daran-ascii %s, DARAN_LINE_MAX %d): %d passed, %d failed\n",
           daran_version(), DARAN_LINE_MAX, 4 - failed, failed);
    return failed == 0 ? 0 : 1;
}

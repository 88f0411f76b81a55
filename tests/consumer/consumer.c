/* A program that uses daran-ascii the way a firmware project would, built
 * three ways by tools/ci.d/50-package.sh (installed CMake package,
 * add_subdirectory, pkg-config). It also proves that the headers it compiled
 * against agree with the library about the configuration: a line of exactly
 * DARAN_LINE_MAX bytes must be accepted and one byte more refused. */
#include <stdio.h>
#include <string.h>

#include "daran_ascii.h"

#if DARAN_REPLY_CRLF
#define LINE_END "\r\n"
#else
#define LINE_END "\n"
#endif

static char reply[DARAN_REPLY_MAX + 1];

static daran_result_t hal_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    if (prop == DARAN_PROP_CAN_NODE_ID) {
        out->u32 = 1;
    } else if (prop == DARAN_PROP_VBUS_VOLTAGE) {
        out->f32 = 24.5f;
    } else {
        out->u64 = 0;
    }
    return DARAN_OK;
}

static daran_result_t hal_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    (void)prop;
    (void)value;
    return DARAN_OK;
}

static daran_result_t hal_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_OK;
}

static daran_result_t hal_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_OK;
}

static void write_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len > DARAN_REPLY_MAX) {
        len = DARAN_REPLY_MAX;
    }
    memcpy(reply, line, len);
    reply[len] = '\0';
}

static const daran_hal_t hal = {hal_get, hal_set, hal_move, hal_action};

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

    /* daran_init() also compares this file's sizeof(daran_drive_t) with the
     * library's: built with other size options, it must refuse. */
    daran_result_t init = daran_init(&drive, &hal, NULL, write_reply, NULL);
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

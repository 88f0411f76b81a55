/* The one-drive fixture of sim_one_drive.h, and Unity's setUp/tearDown. */
#include "sim_one_drive.h"

#include <string.h>

#include "unity.h"

daran_sim_drive_t sim;
daran_drive_t drive;
static char reply[512];
static size_t reply_len;

static void collect(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len < sizeof reply - reply_len) {
        memcpy(reply + reply_len, line, len);
        reply_len += len;
    }
    reply[reply_len] = '\0';
}

static const daran_hal_t collect_port = {DARAN_SIM_HAL_FUNCTIONS, .write = collect};

void setUp(void)
{
    daran_sim_drive_init(&sim, 0u, 1000u);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive, &collect_port, &sim));
    reply_len = 0u;
    reply[0] = '\0';
}

void tearDown(void)
{
}

const char *sim_say(const char *line)
{
    reply_len = 0u;
    reply[0] = '\0';
    (void)daran_process_line(&drive, line, strlen(line));
    while (reply_len > 0u && (reply[reply_len - 1u] == '\n' || reply[reply_len - 1u] == '\r')) {
        reply[--reply_len] = '\0';
    }
    return reply;
}

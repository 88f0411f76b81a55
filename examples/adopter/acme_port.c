/* The ACME X1's protocol layer as a host program: lines on standard input,
 * the drive's replies on standard output, one millisecond of plant time per
 * line. `tools/replay --target program` plays recorded sessions into it. */
#include <stdio.h>
#include <string.h>

#include "daran_ascii.h"

#include "acme_hal.h"

static void write_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    fwrite(line, 1, len, stdout);
}

int main(void)
{
    static acme_drive_t drive;
    static daran_drive_t protocol;
    static daran_hal_t port; /* the X1's description with this program's writer */
    port = acme_hal;
    port.write = write_reply;
    acme_drive_factory_reset(&drive, 4100000001ull);
    daran_result_t init = daran_init(&protocol, &port, &drive);
    if (init != DARAN_OK) {
        fprintf(stderr, "acme-port: daran_init: %s\n", daran_result_phrase(init));
        return 1;
    }
    char line[1024];
    while (fgets(line, sizeof line, stdin) != NULL) {
        size_t len = strlen(line);
        for (size_t done = 0; done < len;) {
            done += daran_rx_write(&protocol, line + done, len - done);
            (void)daran_poll(&protocol);
        }
        acme_drive_run(&drive, 1);
        fflush(stdout);
    }
    return 0;
}

/* The test port of port/minimal (docs/porting.md's HAL) for the in-tree fuzz
 * target: the file a drive maker writes for daran_ascii_add_fuzz_target()
 * and daran_ascii_add_conformance_test(). */
#include "daran_test_port.h"
#include "minimal_hal.h"

static minimal_drive_t drive;

/* minimal_drive_init() is the drive's power-up: defaults, id 1, closed loop. */
static bool reset(void *ctx)
{
    minimal_drive_init(ctx);
    return true;
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "port/minimal",
        .hal = &minimal_hal,
        .ctx = &drive,
        .reset = reset,
    };
    return &port;
}

/* port/minimal's test-port file: its HAL, its drive and the factory state
 * minimal_drive_init() gives (daran_test_port.h), the file a drive maker
 * writes for daran_ascii_add_conformance_test() and
 * daran_ascii_add_fuzz_target() (tests/conformance, tests/adopter-fuzz). The
 * minimal port keeps no time: no advance(). */
#include "daran_test_port.h"

#include "minimal_hal.h"

static minimal_drive_t axis;

static bool factory_reset(void *ctx)
{
    minimal_drive_init(ctx);
    return true;
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "port/minimal",
        .hal = &minimal_hal,
        .ctx = &axis,
        .reset = factory_reset,
    };
    return &port;
}

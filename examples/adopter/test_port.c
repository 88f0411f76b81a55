/* The ACME X1 handed to daran-ascii's conformance suite and fuzz targets:
 * the HAL, its drive, the factory reset and the CAN glue
 * (testkit/include/daran_test_port.h). */
#include "daran_test_port.h"

#include "acme_hal.h"

#define ACME_TEST_SERIAL 4100000001ull

static acme_drive_t drive;

static bool factory_reset(void *ctx)
{
    acme_drive_factory_reset(ctx, ACME_TEST_SERIAL);
    return true;
}

static void run(void *ctx, uint32_t ms)
{
    acme_drive_run(ctx, ms);
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "ACME X1 (examples/adopter)",
        .hal = &acme_hal,
        .ctx = &drive,
        .reset = factory_reset,
        .advance = run,
        .can_deliver = acme_can_deliver,
    };
    return &port;
}

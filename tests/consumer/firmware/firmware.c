/* The ACME X1's firmware (examples/adopter), bare metal: its HAL and plant
 * behind the protocol core built for its options header, a UART polled in
 * the main loop, one millisecond of control per pass. The UART's registers
 * are a made-up memory map: CI links, sizes and inspects this image, it
 * does not run it (docs/testing-your-drive.md, "Firmware from the package"). */
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

#include "acme_hal.h"

#define UART_BASE 0x40004000u
#define UART_DATA (*(volatile uint32_t *)(UART_BASE + 0x0u))
#define UART_STATE (*(volatile uint32_t *)(UART_BASE + 0x4u))
#define UART_STATE_TX_FULL 0x1u
#define UART_STATE_RX_FULL 0x2u

static acme_drive_t drive;
static daran_drive_t protocol;

static void write_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    for (size_t i = 0; i < len; i++) {
        while ((UART_STATE & UART_STATE_TX_FULL) != 0u) {
        }
        UART_DATA = (uint8_t)line[i];
    }
}

int main(void)
{
    static daran_hal_t port; /* the X1's description with this firmware's UART writer */
    port = acme_hal;
    port.write = write_reply;
    acme_drive_factory_reset(&drive, 4100000001ull);
    if (daran_init(&protocol, &port, &drive) != DARAN_OK) {
        for (;;) { /* built against another options header: never speak */
        }
    }
    for (;;) {
        while ((UART_STATE & UART_STATE_RX_FULL) != 0u) {
            (void)daran_rx_byte(&protocol, (uint8_t)UART_DATA);
        }
        (void)daran_poll(&protocol);
        acme_drive_run(&drive, 1);
    }
}

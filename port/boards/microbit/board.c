/* Board services of the BBC micro:bit (nRF51822: Cortex-M0, 16 MHz, no FPU,
 * no hardware divide), QEMU machine `microbit`, for the core's test images:
 * the API of port/mps2-an386/board.h over the nRF51's UART0 (not a CMSDK
 * UART: tasks, events and a TXD register); the CPU's part is
 * port/mps2-an386/cortex_m.c. */
#include "board.h"

#define REG32(addr) (*(volatile uint32_t *)(addr))


/* nRF51 UART0 (nRF51 Series Reference Manual, UART chapter) */
#define UART0_BASE 0x40002000u
#define UART_TASKS_STARTRX REG32(UART0_BASE + 0x000u)
#define UART_TASKS_STARTTX REG32(UART0_BASE + 0x008u)
#define UART_EVENTS_RXDRDY REG32(UART0_BASE + 0x108u)
#define UART_EVENTS_TXDRDY REG32(UART0_BASE + 0x11Cu)
#define UART_INTENSET REG32(UART0_BASE + 0x304u)
#define UART_INTENCLR REG32(UART0_BASE + 0x308u)
#define UART_ENABLE REG32(UART0_BASE + 0x500u)
#define UART_RXD REG32(UART0_BASE + 0x518u)
#define UART_TXD REG32(UART0_BASE + 0x51Cu)
#define UART_BAUDRATE REG32(UART0_BASE + 0x524u)

#define UART_ENABLE_ON 4u
#define UART_INT_RXDRDY (1u << 2)
#define UART_BAUD_115200 0x01D7E000u
#define UART0_IRQ 2u /* UART0 shares one interrupt for all its events */

#define NVIC_ISER0 REG32(0xE000E100u)
#define NVIC_ICER0 REG32(0xE000E180u)

void daran_board_uart0_init(uint32_t baud)
{
    /* The nRF51 takes a rate code, not a divisor; the tests use 115200
     * only (QEMU does not time the line anyway). */
    (void)baud;
    UART_ENABLE = UART_ENABLE_ON;
    UART_BAUDRATE = UART_BAUD_115200;
    UART_EVENTS_RXDRDY = 0u;
    UART_EVENTS_TXDRDY = 0u;
    UART_INTENSET = UART_INT_RXDRDY;
    UART_TASKS_STARTRX = 1u;
    UART_TASKS_STARTTX = 1u;
}

uint8_t daran_board_uart0_take_rx(void)
{
    /* Clear the event first, as on the MPS2 boards: reading RXD lets the
     * next byte in. */
    UART_EVENTS_RXDRDY = 0u;
    return (uint8_t)UART_RXD;
}

void daran_board_uart0_rx_irq_enable(bool on)
{
    if (on) {
        NVIC_ISER0 = 1u << UART0_IRQ;
    } else {
        NVIC_ICER0 = 1u << UART0_IRQ;
        __asm volatile("dsb\n\tisb" ::: "memory");
    }
}

void daran_board_uart0_write(const char *bytes, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        UART_TXD = (uint8_t)bytes[i];
        /* One byte in flight: wait until it has left. */
        while (UART_EVENTS_TXDRDY == 0u) {
        }
        UART_EVENTS_TXDRDY = 0u;
    }
}

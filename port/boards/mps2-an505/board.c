/* Board services of the Arm MPS2+ with the AN505 FPGA image (Cortex-M33 in
 * an SSE-200 subsystem, QEMU mps2-an505) for the core's test images: the
 * API of port/mps2-an386/board.h over the board's CMSDK APB UART0; the CPU's
 * part is port/mps2-an386/cortex_m.c.
 *
 * The CPU leaves reset in the Secure state and stays there: peripherals are
 * reached through their Secure aliases (address bit 28 set; UART0 at
 * 0x50200000 instead of 0x40200000), which the security controller's
 * defaults allow. UART0's interrupts are IRQ 32 (RX) and 33 (TX), beyond the
 * 32 external vectors of port/mps2-an386/startup.c: these images poll and
 * never enable them (a drive firmware on this board would need a longer
 * vector table). */
#include "board.h"

#define REG32(addr) (*(volatile uint32_t *)(addr))

/* Clock of the AN505 image (QEMU: 20 MHz, "cpuclk"). */

/* CMSDK APB UART0, Secure alias */
#define UART0_BASE 0x50200000u
#define UART_DATA REG32(UART0_BASE + 0x00u)
#define UART_STATE REG32(UART0_BASE + 0x04u)
#define UART_CTRL REG32(UART0_BASE + 0x08u)
#define UART_INTSTATUS REG32(UART0_BASE + 0x0Cu)
#define UART_BAUDDIV REG32(UART0_BASE + 0x10u)

#define UART_STATE_TX_FULL (1u << 0)
#define UART_STATE_RX_OVERRUN (1u << 3)
#define UART_CTRL_TX_EN (1u << 0)
#define UART_CTRL_RX_EN (1u << 1)
#define UART_INT_RX (1u << 1)
#define UART_INT_RX_OVERRUN (1u << 3)


void daran_board_uart0_init(uint32_t baud)
{
    uint32_t div = DARAN_BOARD_SYSCLK_HZ / baud;
    UART_CTRL = 0u;
    UART_BAUDDIV = div >= 16u ? div : 16u; /* the UART's minimum divisor */
    UART_INTSTATUS = UART_INT_RX | UART_INT_RX_OVERRUN;
    /* Transmitter and receiver on, no interrupt (see the file comment). */
    UART_CTRL = UART_CTRL_TX_EN | UART_CTRL_RX_EN;
}

uint8_t daran_board_uart0_take_rx(void)
{
    uint8_t byte;
    UART_INTSTATUS = UART_INT_RX;
    byte = (uint8_t)UART_DATA;
    if ((UART_STATE & UART_STATE_RX_OVERRUN) != 0u) {
        UART_STATE = UART_STATE_RX_OVERRUN;
    }
    return byte;
}

void daran_board_uart0_rx_irq_enable(bool on)
{
    /* No receive interrupt on this board's test images. */
    (void)on;
}

void daran_board_uart0_write(const char *bytes, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        while ((UART_STATE & UART_STATE_TX_FULL) != 0u) {
        }
        UART_DATA = (uint8_t)bytes[i];
    }
}

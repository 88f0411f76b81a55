/* Board services of the MPS2 AN386 example: CMSDK APB UART0 (base 0x40004000,
 * RX interrupt IRQ 0) and NVIC enables; the CPU's part (SysTick, PRIMASK,
 * the exit) is cortex_m.c. */
#include "board.h"

#define REG32(addr) (*(volatile uint32_t *)(addr))

/* CMSDK APB UART0 */
#define UART0_BASE 0x40004000u
#define UART_DATA REG32(UART0_BASE + 0x00u)
#define UART_STATE REG32(UART0_BASE + 0x04u)
#define UART_CTRL REG32(UART0_BASE + 0x08u)
#define UART_INTSTATUS REG32(UART0_BASE + 0x0Cu) /* read: status, write 1: clear */
#define UART_BAUDDIV REG32(UART0_BASE + 0x10u)

#define UART_STATE_TX_FULL (1u << 0)
#define UART_STATE_RX_OVERRUN (1u << 3)
#define UART_CTRL_TX_EN (1u << 0)
#define UART_CTRL_RX_EN (1u << 1)
#define UART_CTRL_RX_INT_EN (1u << 3)
#define UART_CTRL_RX_OVR_INT_EN (1u << 5)
#define UART_INT_RX (1u << 1)
#define UART_INT_RX_OVERRUN (1u << 3)

#define UART0_RX_IRQ 0u

/* System control space */
#define NVIC_ISER0 REG32(0xE000E100u)
#define NVIC_ICER0 REG32(0xE000E180u)
#define NVIC_IPR_BASE 0xE000E400u

void daran_board_uart0_init(uint32_t baud)
{
    UART_CTRL = 0u;
    /* The CMSDK UART refuses divisors below 16. */
    UART_BAUDDIV = DARAN_BOARD_SYSCLK_HZ / baud >= 16u ? DARAN_BOARD_SYSCLK_HZ / baud : 16u;
    UART_INTSTATUS = UART_INT_RX | UART_INT_RX_OVERRUN;
    UART_CTRL = UART_CTRL_TX_EN | UART_CTRL_RX_EN | UART_CTRL_RX_INT_EN;
    /* The byte-input ISR outranks SysTick: a byte must be taken before the
     * next one arrives, a tick may wait (priority 0 is the highest). */
    *(volatile uint8_t *)(NVIC_IPR_BASE + UART0_RX_IRQ) = 0x00u;
    NVIC_ISER0 = 1u << UART0_RX_IRQ;
}

uint8_t daran_board_uart0_take_rx(void)
{
    uint8_t byte;
    /* Acknowledge before reading: reading DATA lets the next byte in at
     * once, and its interrupt must not be cleared with this one's. */
    UART_INTSTATUS = UART_INT_RX;
    byte = (uint8_t)UART_DATA;
    if ((UART_STATE & UART_STATE_RX_OVERRUN) != 0u) {
        UART_STATE = UART_STATE_RX_OVERRUN; /* write 1 to clear */
    }
    return byte;
}

void daran_board_uart0_rx_irq_enable(bool on)
{
    if (on) {
        NVIC_ISER0 = 1u << UART0_RX_IRQ;
    } else {
        NVIC_ICER0 = 1u << UART0_RX_IRQ;
        __asm volatile("dsb\n\tisb" ::: "memory");
    }
}

void daran_board_uart0_write(const char *bytes, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++) {
        while ((UART_STATE & UART_STATE_TX_FULL) != 0u) {
        }
        UART_DATA = (uint8_t)bytes[i];
    }
}

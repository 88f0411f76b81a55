/* Board services of the Arm MPS2+ with the AN505 FPGA image (Cortex-M33 in
 * an SSE-200 subsystem, QEMU mps2-an505) for the core's test images: the
 * API of port/mps2-an386/board.h over the board's CMSDK APB UART0, SysTick,
 * PRIMASK and the semihosting exit.
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
#define AN505_SYSCLK_HZ 20000000u

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

#define SYST_CSR REG32(0xE000E010u)
#define SYST_RVR REG32(0xE000E014u)
#define SYST_CVR REG32(0xE000E018u)
#define SCB_SHPR3 REG32(0xE000ED20u)

void daran_board_uart0_init(uint32_t baud)
{
    uint32_t div = AN505_SYSCLK_HZ / baud;
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

void daran_board_systick_start(uint32_t hz)
{
    SYST_CSR = 0u;
    SYST_RVR = AN505_SYSCLK_HZ / hz - 1u;
    SYST_CVR = 0u;
    SCB_SHPR3 = (SCB_SHPR3 & 0x00FFFFFFu) | (0x80u << 24);
    SYST_CSR = 7u;
}

void daran_board_wait_for_interrupt(void)
{
    __asm volatile("wfi" ::: "memory");
}

uint32_t daran_board_irq_save(void)
{
    uint32_t primask;
    __asm volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask)::"memory");
    return primask;
}

void daran_board_irq_restore(uint32_t primask)
{
    __asm volatile("msr primask, %0" ::"r"(primask) : "memory");
}

/* Arm semihosting (BKPT 0xAB on M-profile): SYS_EXIT_EXTENDED with the
 * status, which QEMU turns into its exit status. */
void daran_board_exit(int code)
{
    uint32_t block[2] = {0x20026u /* ADP_Stopped_ApplicationExit */, (uint32_t)code};
    register uint32_t r0 __asm("r0") = 0x20u; /* SYS_EXIT_EXTENDED */
    register const uint32_t *r1 __asm("r1") = block;
    __asm volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    for (;;) {
    }
}

void daran_board_fatal(int code)
{
    daran_board_exit(code);
}

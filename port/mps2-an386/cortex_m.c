/* The board services that belong to the Cortex-M CPU rather than to the
 * board: SysTick, WFI, PRIMASK and the exit (Arm semihosting in test images,
 * a parked CPU otherwise). Every board of the test images (port/boards)
 * shares this file; each board.c keeps only its UART. The board's core clock
 * is DARAN_BOARD_SYSCLK_HZ (board.h, or the board's build). */
#include "board.h"

#define REG32(addr) (*(volatile uint32_t *)(addr))

#define SYST_CSR REG32(0xE000E010u)
#define SYST_RVR REG32(0xE000E014u)
#define SYST_CVR REG32(0xE000E018u)
#define SCB_SHPR3 REG32(0xE000ED20u)

void daran_board_systick_start(uint32_t hz)
{
    SYST_CSR = 0u;
    SYST_RVR = DARAN_BOARD_SYSCLK_HZ / hz - 1u;
    SYST_CVR = 0u;
    /* SysTick (exception 15) below the UART: priority 0x80. */
    SCB_SHPR3 = (SCB_SHPR3 & 0x00FFFFFFu) | (0x80u << 24);
    SYST_CSR = 7u; /* core clock, interrupt, enable */
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

#if defined(DARAN_FW_SEMIHOSTING) && DARAN_FW_SEMIHOSTING
/* Arm semihosting: operation in r0, argument block in r1, BKPT 0xAB on
 * M-profile (ARMv6-M included). QEMU needs -semihosting-config
 * enable=on,target=native. */
static uint32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm("r0") = op;
    register const void *r1 __asm("r1") = arg;
    __asm volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

void daran_board_exit(int code)
{
    uint32_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)code;
    (void)semihost(SYS_EXIT_EXTENDED, block);
    for (;;) {
    }
}
#else
void daran_board_exit(int code)
{
    (void)code;
    (void)daran_board_irq_save();
    for (;;) {
        __asm volatile("wfi");
    }
}
#endif

void daran_board_fatal(int code)
{
    daran_board_exit(code);
}

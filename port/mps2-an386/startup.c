/* Reset and exception entry of the example firmware: the vector table, the
 * reset handler that prepares C (copy .data, zero .bss, enable the FPU) and
 * the default handler for every exception the firmware does not use. */
#include <stdint.h>

#include "board.h"

/* Interrupt handlers of the application; unset ones fall back to the
 * default handler. */
void daran_fw_systick_isr(void) __attribute__((weak, alias("daran_fw_default_handler")));
void daran_fw_uart0_rx_isr(void) __attribute__((weak, alias("daran_fw_default_handler")));

/* Symbols from mps2_an386.ld. */
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern const uint32_t __data_load[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];
extern uint32_t __stack_top[];

int main(void);
void daran_fw_reset(void);

/* main() returned with @p status. The firmware's main() never returns, so
 * by default this is a fault; a test image (tests/target) overrides it to end
 * the run with main()'s status (a Unity program returns its failure count). */
void daran_fw_main_returned(int status) __attribute__((noreturn));
__attribute__((weak)) void daran_fw_main_returned(int status)
{
    (void)status;
    daran_board_fatal(4);
}

#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)

/* An exception nobody expected: stop where a debugger (or the test runner,
 * through semihosting) can see it, instead of running on in a bad state. */
void daran_fw_default_handler(void);
void daran_fw_default_handler(void)
{
    daran_board_fatal(3);
}

void daran_fw_reset(void)
{
#if defined(__ARM_FP)
    /* Full access to CP10/CP11 before any float instruction: the compiler
     * may use VFP registers anywhere from here on, memcpy included. A CPU
     * without an FPU (Cortex-M0, M3: soft float) has no CPACR. */
    SCB_CPACR |= (0xFu << 20);
    __asm volatile("dsb\n\tisb" ::: "memory");
#endif

    /* Plain loops, not memcpy/memset: .data and .bss are not ready yet. */
    {
        const uint32_t *src = __data_load;
        uint32_t *dst = __data_start;
        while (dst < __data_end) {
            *dst++ = *src++;
        }
    }
    {
        uint32_t *dst = __bss_start;
        while (dst < __bss_end) {
            *dst++ = 0u;
        }
    }
    daran_fw_main_returned(main());
}

typedef void (*daran_fw_vector_t)(void);

/* Cortex-M vector table: initial stack pointer, 15 system exceptions, then
 * the 32 interrupts of the AN386 image (UART0 RX is interrupt 0). */
__attribute__((section(".vectors"), used))
static const daran_fw_vector_t vectors[16 + 32] = {
    (daran_fw_vector_t)(uintptr_t)__stack_top,
    daran_fw_reset,
    daran_fw_default_handler, /* NMI */
    daran_fw_default_handler, /* HardFault */
    daran_fw_default_handler, /* MemManage */
    daran_fw_default_handler, /* BusFault */
    daran_fw_default_handler, /* UsageFault */
    0, 0, 0, 0,      /* reserved */
    daran_fw_default_handler, /* SVCall */
    daran_fw_default_handler, /* DebugMonitor */
    0,               /* reserved */
    daran_fw_default_handler, /* PendSV */
    daran_fw_systick_isr,
    daran_fw_uart0_rx_isr, /* IRQ 0: UART0 RX */
    daran_fw_default_handler,    /* IRQ 1: UART0 TX */
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler, daran_fw_default_handler,
    daran_fw_default_handler, daran_fw_default_handler,
};

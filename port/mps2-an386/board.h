/* The few board services of the MPS2 AN386 example: the CMSDK APB UART0,
 * SysTick, interrupt enables and the semihosting exit the QEMU tests use. */
#ifndef DARAN_FW_BOARD_H
#define DARAN_FW_BOARD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Core clock of the AN386 image (and of QEMU's model of it); another board's
 * build defines its own (port/boards/<board>/board.cmake). */
#ifndef DARAN_BOARD_SYSCLK_HZ
#define DARAN_BOARD_SYSCLK_HZ 25000000u
#endif

/* UART0, 8N1 at @p baud, receiver interrupt on (NVIC IRQ 0), transmitter
 * polled. */
void daran_board_uart0_init(uint32_t baud);
/* Read the received byte and acknowledge the RX interrupt; for the RX ISR. */
uint8_t daran_board_uart0_take_rx(void);
/* Unmask / mask the RX interrupt in the NVIC. A byte left unread stays in
 * the UART, and its interrupt stays pending until unmasked. */
void daran_board_uart0_rx_irq_enable(bool on);
/* Send bytes, waiting for room in the one-byte transmit holding register. */
void daran_board_uart0_write(const char *bytes, size_t len);

/* SysTick interrupt at @p hz from the core clock. */
void daran_board_systick_start(uint32_t hz);

/* Wait for an interrupt (the main loop's idle). */
void daran_board_wait_for_interrupt(void);

/* Mask / unmask interrupts around the few lines the main loop shares with
 * an ISR. */
uint32_t daran_board_irq_save(void);
void daran_board_irq_restore(uint32_t primask);

/* End the program: under QEMU with semihosting (test builds) the emulator
 * exits with @p code; otherwise the CPU stops here. */
void daran_board_exit(int code) __attribute__((noreturn));
/* A fault: daran_board_exit(code) in test builds, a halt otherwise. */
void daran_board_fatal(int code) __attribute__((noreturn));

#endif /* DARAN_FW_BOARD_H */

/* Example drive firmware for the MPS2 AN386 board (Cortex-M4F), runnable on
 * QEMU's mps2-an386 machine: the protocol core on UART0, the simulated motor
 * of port/sim as the plant behind the HAL, SysTick as the control tick.
 *
 *   UART0 RX interrupt --byte--> daran_rx_byte()      (producer, ISR)
 *   main loop ----------------> daran_poll()          (consumer)
 *   daran_poll() --replies----> polled UART0 TX
 *   SysTick ------------------> one model tick per period, run by the loop
 *
 * This file is the board's firmware, whole: daran-fw.elf is this file and
 * the board services. It knows one door for code linked beside it (fw.h's
 * daran_fw_addon(), NULL here): the lock-step test image daran-fw-lockstep.elf
 * is this file plus lockstep.c, an add-on that takes `!` directive lines off
 * the UART and moves time itself, so that time only moves when the test
 * says. */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "board.h"
#include "daran_drive.h"
#include "fw.h"
#include "sim_drive.h"

#ifndef DARAN_FW_TICK_HZ
#define DARAN_FW_TICK_HZ 1000u
#endif
#ifndef DARAN_FW_BAUD
#define DARAN_FW_BAUD 115200u
#endif

/* The drive: plant and protocol instance, reached only through this file
 * (and through the pointer it hands an add-on). */
static daran_fw_t fw;
/* The image's add-on or NULL; set before the RX interrupt is enabled. */
static const daran_fw_addon_t *addon;

/* SysTick counts periods; the main loop runs the model for each. Two
 * counters with one writer each need no lock. */
static volatile uint32_t ticks_raised;
static uint32_t ticks_run;
/* Set by the RX ISR when it queued a byte, cleared before each poll: the
 * main loop may only sleep when nothing arrived since. */
static volatile bool rx_seen;

/* Receive flow control. On a real link at 115200 baud a byte comes every
 * 87 us and the main loop drains the ring long before it fills; QEMU's UART
 * has no baud timing and hands over the next byte as soon as DATA is read,
 * so a pasted or scripted burst would overrun the ring. When the ring may
 * be full the ISR leaves the byte in the UART and masks its interrupt (on a
 * board with RTS/CTS this is where RTS drops); the main loop unmasks it
 * after the next poll has drained the ring. Bytes queued minus bytes
 * drained bounds what the ring holds: rx_queued is written by the ISR
 * only, rx_drained by the main loop only. */
static volatile uint32_t rx_queued;
static volatile uint32_t rx_drained;
static volatile bool rx_paused;

static void reply_to_uart(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    daran_board_uart0_write(line, len);
}

static const daran_hal_t reply_to_uart_port = {DARAN_SIM_HAL_FUNCTIONS, .write = reply_to_uart};

void daran_fw_start_drive(daran_fw_t *d)
{
    /* Fails only for a NULL pointer or HAL member: a build error, really. */
    if (daran_init(&d->drive, &reply_to_uart_port, &d->plant) != DARAN_OK) {
        daran_board_fatal(5);
    }
}

void daran_fw_uart0_rx_isr(void)
{
    uint8_t byte;
    rx_seen = true;
    if (rx_queued - rx_drained >= DARAN_RX_RING_SIZE - 1u) {
        daran_board_uart0_rx_irq_enable(false);
        rx_paused = true;
        return;
    }
    byte = daran_board_uart0_take_rx();
    if (addon != NULL && addon->rx_take(&fw, byte)) {
        return;
    }
    /* Cannot fail with the flow control above; without it a full ring
     * loses the byte and the core answers that line `line too long` (D3). */
    (void)daran_rx_byte(&fw.drive, byte);
    rx_queued = rx_queued + 1u;
}

/* The core's poll, plus the flow-control bookkeeping around it. */
static bool poll_drive(void)
{
    uint32_t queued_before = rx_queued;
    size_t lines;
    rx_seen = false;
    lines = daran_poll(&fw.drive);
    /* daran_poll() drains every byte that was queued when it started. */
    rx_drained = queued_before;
    if (rx_paused && (addon == NULL || !addon->rx_held(&fw))) {
        rx_paused = false;
        daran_board_uart0_rx_irq_enable(true);
    }
    return lines > 0u;
}

void daran_fw_systick_isr(void)
{
    ticks_raised = ticks_raised + 1u;
}

static bool run_due_ticks(void)
{
    bool ran = false;
    while (ticks_run != ticks_raised) {
        daran_sim_model_tick(&fw.plant.model);
        ticks_run++;
        ran = true;
    }
    return ran;
}

/* No add-on: the firmware alone. An image with one defines this again. */
__attribute__((weak)) const daran_fw_addon_t *daran_fw_addon(void)
{
    return NULL;
}

int main(void)
{
    addon = daran_fw_addon();
    daran_sim_drive_init(&fw.plant, 0u, DARAN_FW_TICK_HZ);
    daran_fw_start_drive(&fw);
    daran_board_uart0_init(DARAN_FW_BAUD);
    if (addon == NULL || !addon->moves_time) {
        daran_board_systick_start(DARAN_FW_TICK_HZ);
    }
    for (;;) {
        bool busy = run_due_ticks();
        busy = poll_drive() || busy;
        if (addon != NULL) {
            busy = addon->run(&fw) || busy;
        }
        if (!busy) {
            /* Sleep until the next byte or tick. Interrupts are masked
             * around the last check so none slips in between it and the
             * WFI (a pending interrupt still ends the WFI). */
            uint32_t primask = daran_board_irq_save();
            if (ticks_run == ticks_raised && !rx_seen) {
                daran_board_wait_for_interrupt();
            }
            daran_board_irq_restore(primask);
        }
    }
}

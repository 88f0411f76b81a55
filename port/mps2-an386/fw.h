/* What the parts of the example firmware share: the drive instance, its
 * plant, and the lock-step test hooks. */
#ifndef DARAN_FW_H
#define DARAN_FW_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_drive.h"
#include "sim_drive.h"

#ifndef DARAN_FW_LOCKSTEP
#define DARAN_FW_LOCKSTEP 0
#endif

extern daran_sim_drive_t daran_fw_plant;
extern daran_drive_t daran_fw_drive;

/* (Re)start the protocol instance on the plant's HAL and UART0. */
void daran_fw_start_drive(void);

void daran_fw_uart0_rx_isr(void);
void daran_fw_systick_isr(void);

#if DARAN_FW_LOCKSTEP
/* True while a directive waits for the main loop (the RX interrupt stays
 * masked until it has run). */
bool daran_fw_rx_held_by_directive(void);
/* RX ISR side: true when @p byte belongs to a directive line (a line that
 * starts with '!'), which the core must never see. */
bool daran_fw_lockstep_take(uint8_t byte);
/* Main loop side: run a complete directive; true if one ran. */
bool daran_fw_lockstep_run(void);
#else
#define daran_fw_rx_held_by_directive() false
#endif

#endif /* DARAN_FW_H */

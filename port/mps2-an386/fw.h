/* The example firmware's drive (main.c) and the one door it leaves open for
 * code linked beside it: an add-on, such as the lock-step test harness of
 * daran-fw-lockstep.elf (lockstep.c). main.c knows the door, not what comes
 * through it; an add-on reaches the drive only through the pointer main.c
 * hands it, never through a global. */
#ifndef DARAN_FW_H
#define DARAN_FW_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_drive.h"
#include "sim_drive.h"

/* The drive: the simulated plant and the protocol instance on its HAL. */
typedef struct daran_fw {
    daran_sim_drive_t plant;
    daran_drive_t drive;
} daran_fw_t;

/* (Re)start the protocol instance of @p fw on its plant's HAL, replying on
 * UART0 (the plant keeps its state). */
void daran_fw_start_drive(daran_fw_t *fw);

/* What an add-on gives the firmware's main(). Every function is called with
 * the drive; none may be NULL. */
typedef struct daran_fw_addon {
    /* True: the add-on moves time itself (it runs the plant's ticks), so
     * the firmware starts no SysTick. */
    bool moves_time;
    /* RX ISR, for every byte taken from UART0 before the core sees it: true
     * when the byte is the add-on's (the core never receives it). */
    bool (*rx_take)(daran_fw_t *fw, uint8_t byte);
    /* Main loop: true while the add-on keeps the RX interrupt masked, so the
     * firmware's flow control must not unmask it after a poll. */
    bool (*rx_held)(daran_fw_t *fw);
    /* Main loop, after each poll: do the add-on's work; true if it did any
     * (the loop then does not sleep). */
    bool (*run)(daran_fw_t *fw);
} daran_fw_addon_t;

/* The add-on linked into this image. main.c's default (weak) answers NULL:
 * the firmware alone. An image with an add-on links a file that defines
 * this function again and answers its own. */
const daran_fw_addon_t *daran_fw_addon(void);

/* The firmware's interrupt handlers (startup.c's vector table). */
void daran_fw_uart0_rx_isr(void);
void daran_fw_systick_isr(void);

#endif /* DARAN_FW_H */

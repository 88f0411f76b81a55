/* daran-sim's host adapters on pseudo-terminals, each one node of the
 * simulated CAN bus: --slcan speaks the Lawicel serial-line protocol
 * (sim_slcan.h), --usbcan the vendor USB-CAN adapter's 16-byte packets
 * (sim_usbcan.h). What the client writes becomes frames queued on the
 * adapter's node; every frame the node receives goes to the client.
 *
 * Back-pressure, as on the ASCII pty: the client's bytes are taken one
 * command (or packet) at a time, and not at all while the adapter's
 * transmit queue is full or 64 KiB of output wait for a client that does
 * not read, so a fast writer is slowed down, never dropped. Frames for a
 * client that does not read are dropped once that much waits (counted; the
 * slcan status flags show an overrun). Host program only (POSIX). */
#ifndef SIM_CAN_PTY_H
#define SIM_CAN_PTY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "sim_can_bus.h"
#include "sim_slcan.h"
#include "sim_usbcan.h"

#define SIM_CAN_PTY_OUT_MAX (64u * 1024u)

typedef enum sim_can_pty_kind { SIM_CAN_PTY_SLCAN, SIM_CAN_PTY_USBCAN } sim_can_pty_kind_t;

typedef struct sim_can_pty {
    sim_can_pty_kind_t kind;
    int fd;            /* the master side; -1 when not open */
    int slave_keep;
    char path[256];
    daran_sim_can_bus_t *bus;
    uint32_t node;     /* the adapter's node on the bus */
    daran_sim_slcan_t slcan;
    daran_sim_usbcan_t usbcan;
    uint8_t in[4096];  /* read from the client, not yet taken */
    size_t in_pos;
    size_t in_len;
    uint8_t out[SIM_CAN_PTY_OUT_MAX]; /* for the client, not yet written */
    size_t out_start;
    size_t out_len;
    unsigned long dropped; /* frames for the client dropped (it did not read) */
    unsigned long refused; /* the client's frames the bus refused (bus-off) */
} sim_can_pty_t;

/* Open the pseudo-terminal and connect the adapter as a new node of @p bus.
 * False (errno set, or EMFILE when the bus has no room for a node) when
 * either fails. */
bool sim_can_pty_open(sim_can_pty_t *p, sim_can_pty_kind_t kind, daran_sim_can_bus_t *bus);

/* The poll() events the adapter waits for now (POLLIN, POLLOUT). */
short sim_can_pty_events(const sim_can_pty_t *p);

/* Serve the adapter after poll() reported @p revents: read what the client
 * wrote, run its commands while the adapter can take frames, write what
 * waits for it. */
void sim_can_pty_serve(sim_can_pty_t *p, short revents);

/* Write what waits for the client, as far as the pty takes it now. */
void sim_can_pty_flush(sim_can_pty_t *p);

/* The option that made it: "--slcan" or "--usbcan". */
const char *sim_can_pty_option(const sim_can_pty_t *p);

void sim_can_pty_close(sim_can_pty_t *p);

#endif /* SIM_CAN_PTY_H */

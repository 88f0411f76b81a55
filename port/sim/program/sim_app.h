/* daran-sim's state, shared by the program's files: the drives, their CAN
 * bus and adapters, the open files and what has already been reported. One
 * instance, app; nothing here is thread-safe (the program has one thread). */
#ifndef SIM_APP_H
#define SIM_APP_H

#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "daran_sim.h"
#include "sim_can_pty.h"
#include "sim_file_storage.h"
#include "sim_gateway.h"

/* Host adapters on pseudo-terminals: --slcan, --usbcan. */
#define CAN_PTYS 2u

typedef struct sim_app {
    daran_sim_bus_t bus;
    daran_sim_file_storage_t files[DARAN_SIM_MAX_DRIVES];
    uint32_t lost_reported[DARAN_SIM_MAX_DRIVES]; /* out_lost already told */
    FILE *trace;
    FILE *record;
    double record_start_s;
    uint32_t trace_every;
    bool echo;
    bool pty;       /* --pty: the ASCII link on a pseudo-terminal */
    bool realtime;  /* a pseudo-terminal is open (--pty, --slcan, --usbcan): time is real */
    int pty_fd;
    unsigned long line_no;
    int status;
    /* --can: the drives' CAN bus, the console's node on it (`!can`, the
     * `can ...` lines on stdout) and the host adapters on pseudo-terminals */
    bool can_on;
    daran_sim_can_t can;
    uint32_t console_node;
    sim_can_pty_t can_pty[CAN_PTYS];
    uint32_t can_ptys;
    bool stdout_pending;                          /* console lines not yet flushed */
    uint32_t can_dropped_told[DARAN_SIM_MAX_DRIVES]; /* daran_can_dropped() already told */
    uint32_t can_unsent_told[DARAN_SIM_MAX_DRIVES];  /* daran_can_unsent() already told */
    unsigned long pty_dropped_told[CAN_PTYS];
    unsigned long pty_refused_told[CAN_PTYS];
    /* --bridge: drive 1 a gateway, and where the answer to the query it
     * waits for goes (the sink of the line that asked) */
    sim_gateway_t gateway;
    daran_sim_sink_fn asker;
} sim_app_t;

extern sim_app_t app;
/* The signal that asked us to stop (SIGINT, SIGTERM, SIGHUP), else 0. */
extern volatile sig_atomic_t stop_signal;

/* CLOCK_MONOTONIC in seconds and in nanoseconds. */
double now_s(void);
uint64_t mono_ns(void);

#endif /* SIM_APP_H */

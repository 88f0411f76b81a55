/* A simulated multi-drop line: N drives, each a protocol core instance
 * (daran_drive_t) in front of a simulated drive. Every byte reaches every
 * drive; replies are collected per drive and handed out in id order.
 *
 * Portable C99: no stdio, no heap; the caller owns the bus object. */
#ifndef DARAN_SIM_BUS_H
#define DARAN_SIM_BUS_H

#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"
#include "sim_drive.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DARAN_SIM_MAX_DRIVES 16u
/* Replies a drive holds until they are collected, after each line and each
 * tick: room for the longest answer to one line (`h ID properties`, every
 * row of the table: about 8 KB) with margin. More is counted in out_lost. */
#define DARAN_SIM_OUT_MAX 16384u

typedef struct daran_sim_node {
    daran_sim_drive_t sim;   /* first: the node is its HAL functions' context too */
    daran_drive_t proto;
    /* proto's port description, its context the node: the simulated
     * drive's HAL functions and the node's reply buffer; a CAN bus
     * (sim_can.h) adds its clock and transmit. */
    daran_hal_t port;
    struct daran_sim_can *can; /* the bus it is on, NULL for none */
    uint32_t index;            /* 0-based, on the line and the bus */
    char out[DARAN_SIM_OUT_MAX]; /* replies not yet collected */
    size_t out_len;
    uint32_t out_lost;           /* reply bytes that did not fit */
} daran_sim_node_t;

/* Configures a protocol instance the bus has just started (e.g. gives it
 * the port's own commands, daran_set_port_commands()): drive @p index
 * (0-based) of the bus. */
typedef void (*daran_sim_setup_fn)(void *ctx, uint32_t index, daran_drive_t *proto);

typedef struct daran_sim_bus {
    uint32_t count;
    uint32_t tick_hz;
    uint64_t ticks;
    daran_sim_setup_fn setup;  /* NULL: instances as daran_init() leaves them */
    void *setup_ctx;
    daran_sim_node_t node[DARAN_SIM_MAX_DRIVES];
} daran_sim_bus_t;

/* Receives collected reply bytes of one drive (whole lines). */
typedef void (*daran_sim_sink_fn)(void *ctx, uint32_t drive_id, const char *bytes, size_t len);

/* @p count drives (1..DARAN_SIM_MAX_DRIVES), ids 1..count, RAM storage,
 * no setup function. DARAN_ERR_BAD_ARGUMENT for a bad count or tick rate
 * (nothing initialised). O(count). */
daran_result_t daran_sim_bus_init(daran_sim_bus_t *bus, uint32_t count, uint32_t tick_hz);

/* Call @p setup (with @p ctx) on every drive's protocol instance now, and
 * on each new one a power cycle starts; NULL stops that. A port's own
 * commands survive `!power-cycle` so. */
void daran_sim_bus_set_setup(daran_sim_bus_t *bus, daran_sim_setup_fn setup, void *ctx);

/* Give drive @p index its own storage and power it on again. */
void daran_sim_bus_set_storage(daran_sim_bus_t *bus, uint32_t index,
                               const daran_sim_storage_t *st);

/* Send bytes down the line: every drive receives them through its receive
 * ring (daran_rx_write) and processes the complete lines (daran_poll). */
void daran_sim_bus_send(daran_sim_bus_t *bus, const char *bytes, size_t len);

/* The same for drive @p index alone (nothing for an index past the
 * last): a link that reaches one drive, as a gateway's USB port does. */
void daran_sim_bus_send_to(daran_sim_bus_t *bus, uint32_t index, const char *bytes, size_t len);

/* Hand every drive's pending replies to @p sink, drives in id order (ties in
 * index order), and clear them. Returns how many drives had replies. */
uint32_t daran_sim_bus_collect(daran_sim_bus_t *bus, daran_sim_sink_fn sink, void *ctx);

/* One control tick on every drive (daran_sim_drive_tick(): the model's and
 * the extension's), then each drive's telemetry (its reports wait with the
 * replies for daran_sim_bus_collect()). */
void daran_sim_bus_tick(daran_sim_bus_t *bus);

/* Power-cycle drive @p index: new protocol instance (no preset, empty ring;
 * the setup function runs on it), drive booted from its non-volatile
 * memory. */
void daran_sim_bus_power_cycle(daran_sim_bus_t *bus, uint32_t index);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_BUS_H */

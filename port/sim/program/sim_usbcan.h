/* The vendor USB-CAN adapter's packet format (the project's can.md 1.4), as
 * `DrEmpower_can.py` writes it to the adapter's serial port and reads the
 * adapter's packets back. daran-sim's --usbcan runs it on a
 * pseudo-terminal; this file is only the codec.
 *
 * One packet is 16 bytes, both ways:
 *   byte 0      0xAA (start)
 *   byte 1      0 standard identifier, 1 extended
 *   byte 2      0 data frame, 1 remote frame (the library's `rtr`)
 *   byte 3      DLC, 0..8 (the library always sends 8)
 *   bytes 4..7  the identifier, most significant byte first
 *   bytes 8..15 the data bytes (those past the DLC are 0, and ignored)
 * The vendor documents the host-to-adapter direction only; the library
 * takes a packet back when it is 16 bytes with byte 3 = 8 and reads the
 * identifier from bytes 6..7 and the data from 8..15, so the adapter's
 * packets are given the same layout (docs/simulator.md).
 *
 * Pure: no I/O, no heap, no stdio. */
#ifndef DARAN_SIM_USBCAN_H
#define DARAN_SIM_USBCAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_can.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DARAN_SIM_USBCAN_PACKET 16u
#define DARAN_SIM_USBCAN_START 0xAAu

typedef struct daran_sim_usbcan {
    uint8_t packet[DARAN_SIM_USBCAN_PACKET]; /* the packet under way */
    size_t len;
    uint32_t skipped; /* bytes dropped while looking for a packet (wraps) */
} daran_sim_usbcan_t;

/* No packet under way, nothing skipped. */
void daran_sim_usbcan_init(daran_sim_usbcan_t *u);

/* Take the host's bytes up to the end of the first whole, valid packet
 * among them (all of them when none completes): true in *got with its frame
 * in *frame then. Bytes before a 0xAA are skipped; a packet that is not
 * valid (a byte 1 or 2 above 1, a DLC above 8, an identifier out of range)
 * is dropped up to the next 0xAA inside it, which may start the real one.
 * Returns how many bytes were taken. */
size_t daran_sim_usbcan_take(daran_sim_usbcan_t *u, const uint8_t *bytes, size_t len,
                             daran_can_frame_t *frame, bool *got);

/* One packet as a frame: true with it in *frame; false (nothing written)
 * when it is not a valid packet. */
bool daran_sim_usbcan_decode(const uint8_t packet[DARAN_SIM_USBCAN_PACKET],
                             daran_can_frame_t *frame);

/* The packet @p frame becomes for the host. */
void daran_sim_usbcan_encode(const daran_can_frame_t *frame,
                             uint8_t packet[DARAN_SIM_USBCAN_PACKET]);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_USBCAN_H */

/* daran-sim's text forms of a CAN frame (docs/simulator.md, "CAN bus"):
 *
 *   !can ID [BYTES...]   the console node sends a frame: ID in hex, 1 to 3
 *                        digits for a standard identifier (<= 7FF), 8 for an
 *                        extended one; BYTES in hex, two digits a byte, in
 *                        one or several words (0..8 bytes: the DLC), or `R`
 *                        / `Rn` alone for a remote frame of DLC n (0..8)
 *   can SECONDS ID [DLC] BYTES     a frame the console node received, on
 *                        stdout: the time its last bit passed (simulated
 *                        seconds, 6 decimals), the id as 3 (or 8) upper-case
 *                        hex digits, the DLC, the bytes as two hex digits
 *                        each (`remote` instead for a remote frame).
 *
 * Host program only (stdio). */
#ifndef SIM_CAN_TEXT_H
#define SIM_CAN_TEXT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_can.h"

/* The longest console line, its '\n' and a '\0' included. */
#define SIM_CAN_TEXT_LINE_MAX 80u

/* The frame of `!can`'s @p argc words after the directive's name (@p argv:
 * the id first): true with it in *frame; false with a reason in *why. */
bool sim_can_text_parse(int argc, char *const *argv, daran_can_frame_t *frame, const char **why);

/* The console line of @p frame received at @p ns (simulated nanoseconds),
 * with its '\n', into @p out; returns its length. */
size_t sim_can_text_format(const daran_can_frame_t *frame, uint64_t ns,
                           char out[SIM_CAN_TEXT_LINE_MAX]);

#endif /* SIM_CAN_TEXT_H */

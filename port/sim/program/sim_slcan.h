/* The Lawicel serial-line CAN protocol (slcan) as an adapter speaks it to
 * its host (Linux slcand, python-can's `slcan` interface): the host's
 * commands in, their answers and the bus's frames out. daran-sim's --slcan
 * runs it on a pseudo-terminal; this file is only the codec.
 *
 * A command ends with CR (a LF is ignored, so "...\r\n" works too). The
 * answers: CR for done, BEL (0x07) for refused; `t`/`r` answer "z\r" and
 * `T`/`R` "Z\r" when the frame was queued for the bus. Frames from the bus
 * reach the host, while the channel is open, as
 *   t<3 hex id><dlc><2 hex a byte>\r   (standard data frame)
 *   T<8 hex id><dlc><bytes>\r          (extended)
 *   r<3 hex id><dlc>\r, R<8 hex id><dlc>\r   (remote)
 * with four more hex digits (milliseconds, 0..59999) before the CR when
 * timestamps are on (Z1). docs/simulator.md lists every command.
 *
 * Pure: no I/O, no heap, no stdio; the caller gives the callbacks. */
#ifndef DARAN_SIM_SLCAN_H
#define DARAN_SIM_SLCAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_can.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The longest command kept ("T" + 8 + 1 + 16 digits is 26); a longer one
 * is refused whole when its CR comes. */
#define DARAN_SIM_SLCAN_COMMAND_MAX 32u
/* The longest line a frame becomes (an extended 8-byte frame with its
 * timestamp and CR: 31 bytes). */
#define DARAN_SIM_SLCAN_LINE_MAX 32u

/* The bits of the status flags `F` answers (the Lawicel layout). */
#define DARAN_SIM_SLCAN_STATUS_OVERRUN 0x08u   /* frames for the host were dropped */
#define DARAN_SIM_SLCAN_STATUS_BUS_ERROR 0x80u /* the adapter cannot send (bus-off) */

/* The adapter's identity, as `V`, `v` and `N` answer. */
#define DARAN_SIM_SLCAN_VERSION "0100"
#define DARAN_SIM_SLCAN_SERIAL "SIM1"

typedef struct daran_sim_slcan {
    char command[DARAN_SIM_SLCAN_COMMAND_MAX];
    size_t len;       /* bytes of the current command in command[] */
    bool overlong;    /* the current command did not fit */
    bool open;        /* `O` or `L`: frames flow both ways */
    bool listen_only; /* `L`: the host may not send */
    bool timestamps;  /* `Z1` */
    uint8_t status;   /* DARAN_SIM_SLCAN_STATUS_ bits; the caller sets them,
                         `F` answers them and clears OVERRUN */
} daran_sim_slcan_t;

/* Where the codec's output goes. */
typedef struct daran_sim_slcan_io {
    /* The host's frame for the bus: true when it was queued. */
    bool (*send)(void *ctx, const daran_can_frame_t *frame);
    /* Bytes for the host (an answer). */
    void (*reply)(void *ctx, const char *bytes, size_t len);
    void *ctx;
} daran_sim_slcan_io_t;

/* A closed channel, no command under way, no status bits. */
void daran_sim_slcan_init(daran_sim_slcan_t *s);

/* Take the host's bytes up to and including the first CR among them (all
 * of them when there is none) and, at that CR, run the command: its answer
 * goes to io->reply, a frame to io->send. Returns how many bytes were
 * taken, so the caller can stop between two commands (back-pressure). */
size_t daran_sim_slcan_take(daran_sim_slcan_t *s, const uint8_t *bytes, size_t len,
                            const daran_sim_slcan_io_t *io);

/* The line @p frame becomes for the host, into @p out; @p ms is the time
 * for a timestamp (taken modulo 60000). Returns its length, or 0 when the
 * channel is closed (the host gets no frames then). */
size_t daran_sim_slcan_encode(const daran_sim_slcan_t *s, const daran_can_frame_t *frame,
                              uint32_t ms, char out[DARAN_SIM_SLCAN_LINE_MAX]);

/* A transmit command (`t`, `T`, `r`, `R` with their digits, no CR) as a
 * frame: true with it in *frame; false for any malformed one (an id out of
 * range, a DLC above 8, a digit count that does not match the DLC). Hex
 * digits of either case. */
bool daran_sim_slcan_parse_frame(const char *command, size_t len, daran_can_frame_t *frame);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_SLCAN_H */

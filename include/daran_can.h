/** @file daran_can.h
 * The vendor's CAN protocol: a second front end of a drive, over the same
 * command layer, property table and HAL as its ASCII lines (docs/can.md).
 *
 * A frame (11-bit id = node << 5 | code, 8 data bytes, little-endian) is
 * decoded into the same request an ASCII line becomes, so every range, unit,
 * state rule and HAL call is the line's. CAN has no error reply: a frame the
 * drive refuses has no effect and gets no answer.
 *
 * The port owns a daran_can_t beside its daran_drive_t (whose port
 * description, daran_hal_t, gives the CAN transmit and the millisecond
 * clock), hands it every
 * received frame (daran_can_receive(), from an interrupt or a polling loop)
 * and calls daran_can_poll() from the thread that calls daran_poll(): that is
 * where frames run, replies and status frames go out, the heartbeat is sent
 * and the node guard watches.
 *
 * Threading: daran_can_receive() is the producer (one interrupt or thread),
 * daran_can_poll() the consumer; they share a frame ring with the byte
 * ring's discipline (acquire/release, no locks). */
#ifndef DARAN_CAN_H
#define DARAN_CAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

#ifdef __cplusplus
extern "C" {
#endif

/** daran_can_frame_t.flags: a frame of these kinds is not part of the
 * protocol and is ignored (C21). */
#define DARAN_CAN_FRAME_REMOTE 0x01u   /**< remote (RTR) frame */
#define DARAN_CAN_FRAME_EXTENDED 0x02u /**< 29-bit identifier */
#define DARAN_CAN_FRAME_FD 0x04u       /**< CAN FD frame */

/** One CAN frame as the port's controller gives or takes it. */
typedef struct daran_can_frame {
    uint32_t id;     /**< standard id 0..0x7FF (or 29 bits with DARAN_CAN_FRAME_EXTENDED) */
    uint8_t dlc;     /**< data length 0..8; the protocol's frames have 8 */
    uint8_t flags;   /**< DARAN_CAN_FRAME_ bits; 0 for a classic data frame */
    uint8_t data[8]; /**< data bytes, data[0] first on the bus */
} daran_can_frame_t;

/** @cond INTERNAL  The members below are the library's; read none of them. */
typedef struct daran_can_slot {
    uint16_t id;     /* standard id: frames of another shape never reach the ring */
    uint8_t data[8];
} daran_can_slot_t;
/** @endcond */

struct daran_can_bridge;

/** The CAN front end of one drive. Size: sizeof(daran_can_t). */
/** @cond INTERNAL */
/* What listens to the frames a front end takes for other nodes: a gateway's
 * bridge, waiting for a remote drive's reply (can_bridge.c). */
typedef struct daran_can_listener {
    void (*frame)(void *ctx, const struct daran_can_slot *frame); /* a frame for another node */
    void (*tick)(void *ctx);                                      /* at most once a millisecond */
} daran_can_listener_t;
/** @endcond */

typedef struct daran_can {
    /** @cond INTERNAL */
    daran_drive_t *drive;
    const daran_can_listener_t *listener; /* NULL without one */
    void *listener_ctx;
    daran_atomic_u16_t head;    /* written by daran_can_receive() only */
    daran_atomic_u16_t tail;    /* written by daran_can_poll() only */
    daran_atomic_u32_t dropped; /* frames lost to a full ring; the producer's */
    uint32_t last_frame_ms;     /* the node guard: when the last frame for this drive came */
    uint32_t heartbeat_ms;      /* when the last heartbeat went out */
    uint32_t kept_ms;           /* when the guard and the heartbeat were last looked at */
    uint32_t unsent;            /* replies and status frames the port could not send */
    uint8_t enabled;            /* can.config.protocol was 1 at daran_can_init() */
    uint8_t guard_armed;        /* a frame for this drive came since boot or since the guard
                                   stopped the drive (C16) */
    uint8_t reserved[2];
    daran_can_slot_t slots[DARAN_CAN_RX_FRAMES];
    /** @endcond */
} daran_can_t;

/** Bind a CAN front end to its drive (initialised with daran_init(): the
 * drive's port description gives the transmit and the clock, can_send and
 * now_ms, and the optional can_system hook), and reset it. Reads
 * `can.config.protocol` once: 0 leaves the front end silent (it takes
 * frames and drops them) until the next daran_can_init(), as a drive reads
 * it at boot (C15).
 * Returns DARAN_ERR_BAD_ARGUMENT when a pointer is NULL, the drive was not
 * initialised or its port has no can_send or now_ms, and
 * DARAN_ERR_BUILD_MISMATCH when the caller was compiled with other options
 * (another DARAN_CAN_RX_FRAMES, say) or another property table than the
 * library: the instance is then untouched and unusable. O(sizeof *can). */
#define daran_can_init(can, drive) \
    daran_can_init_checked((can), (drive), DARAN_BUILD_CHECK(daran_can_t))

/** What daran_can_init() calls, with the caller's
 * DARAN_BUILD_CHECK(daran_can_t) (daran_build.h): the library's ring has
 * its own DARAN_CAN_RX_FRAMES slots, so an instance laid out by another
 * build would be written past its end. */
DARAN_NODISCARD daran_result_t daran_can_init_checked(daran_can_t *can, daran_drive_t *drive,
                                                      uint32_t build_check);

/** Producer side: queue one received frame. Safe in an interrupt (one
 * producer). Frames that are not 8-byte standard data frames are dropped
 * here (C21). Returns false when the frame was dropped: of another shape,
 * or the ring was full (counted by daran_can_dropped()). O(1). */
bool daran_can_receive(daran_can_t *can, const daran_can_frame_t *frame);

/** Consumer side: run every queued frame (replies go out through
 * the port's can_send), then the node guard and the heartbeat. Call it once per
 * control tick, from the thread that calls daran_poll(). Returns the
 * number of frames taken. Never blocks. */
size_t daran_can_poll(daran_can_t *can);

/** Frames lost to a full receive ring since daran_can_init() (wraps). */
uint32_t daran_can_dropped(const daran_can_t *can);

/** Replies, status frames and heartbeats the port could not send since
 * daran_can_init() (wraps). */
uint32_t daran_can_unsent(const daran_can_t *can);

/** The most property reads one bridged line waits for (`e`: seven). */
#define DARAN_CAN_BRIDGE_READS 7u

/** @cond INTERNAL */
typedef struct daran_can_bridge_read {
    uint16_t address; /* asked for */
    uint8_t type;     /* the reply's type code */
    uint8_t reserved;
    uint32_t bits;    /* the reply's value */
} daran_can_bridge_read_t;
/** @endcond */

/** A drive's gateway: lines for other ids become frames (docs/can.md, "The
 * bridge"). Size: sizeof(daran_can_bridge_t). */
typedef struct daran_can_bridge {
    /** @cond INTERNAL */
    daran_line_sink_t sink;     /* first: the drive's sink for lines to other ids */
    daran_can_t *can;
    uint32_t asked_ms;          /* when the read now awaited was sent */
    uint8_t node;               /* the drive the pending query is for */
    uint8_t kind;               /* what the answer prints (can_bridge.c) */
    uint8_t count;              /* reads of the pending query, 0 when none */
    uint8_t next;               /* the read awaited */
    uint8_t wants_checksum;     /* the line carried one: so does its answer */
    uint8_t given;              /* a motion line's values, or a start's relative flag */
    uint8_t reserved[2];
    float values[5];            /* a motion line's values (`d` has five), parsed here, not on
                                   the stack; `q` with omitted values sends them after its reads */
    daran_can_bridge_read_t reads[DARAN_CAN_BRIDGE_READS];
    /** @endcond */
} daran_can_bridge_t;

/** Make @p can's drive a gateway (with `can.config.protocol` 1, C31): a line
 * addressed to another id 1..63 is checked like a line for this drive, sent
 * as the frames of the contract's section 5.2 and, for a query, answered
 * with the remote drive's values once they came; daran_poll() reads no
 * further line meanwhile (the bytes wait in the receive ring), and the
 * replies arrive through daran_can_poll(). A broadcast line that is not a
 * read goes out as node-0 frames, then runs here (C34). Lines for other ids
 * no longer reach the forward hook. Returns DARAN_ERR_BAD_ARGUMENT for a
 * NULL pointer or a front end without a drive, and DARAN_ERR_BUILD_MISMATCH
 * (nothing touched) for a caller compiled with other options or another
 * property table than the library. O(1). */
#define daran_can_bridge_init(bridge, can)                                                  \
    daran_can_bridge_init_checked((bridge), (can), DARAN_BUILD_CHECK(daran_can_bridge_t))

/** What daran_can_bridge_init() calls, with the caller's
 * DARAN_BUILD_CHECK(daran_can_bridge_t) (daran_build.h). */
DARAN_NODISCARD daran_result_t daran_can_bridge_init_checked(daran_can_bridge_t *bridge,
                                                             daran_can_t *can,
                                                             uint32_t build_check);

/** Whether a bridged query is waiting for its replies. O(1). */
bool daran_can_bridge_busy(const daran_can_bridge_t *bridge);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_CAN_H */

/** @file daran_drive.h
 * A drive instance: bytes in, replies and HAL calls out.
 *
 * The caller owns the daran_drive_t (static, on the stack or in a struct of
 * its own); the library allocates nothing and keeps no global state, so any
 * number of instances can live in one program.
 *
 * Threading: daran_rx_byte() / daran_rx_write() are the producer side and may
 * run in an interrupt; daran_poll() is the consumer side and runs in the main
 * loop. One producer and one consumer per instance; no locks are needed.
 * daran_process_line() belongs to the consumer side. */
#ifndef DARAN_DRIVE_H
#define DARAN_DRIVE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_build.h"
#include "daran_config.h"
#include "daran_hal.h"
#include "daran_result.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @cond INTERNAL  The members below are the library's; read none of them. */
/* The ring's indices are shared between the interrupt (producer) and the
 * main loop (consumer): C11 atomics with acquire/release ordering where the
 * compiler has them (the library itself is built as C11), otherwise the
 * port's barrier (DARAN_PORT_BARRIER, see daran_config.h) or the GCC/clang
 * __atomic builtins. The object is the same size either way, so a C99 or C++
 * caller that includes this header sees the same layout. */
#if !defined(__cplusplus) && !defined(DARAN_PORT_BARRIER) && defined(__STDC_VERSION__) && \
    __STDC_VERSION__ >= 201112L && !defined(__STDC_NO_ATOMICS__)
#define DARAN_ATOMIC_C11 1
typedef _Atomic uint16_t daran_atomic_u16_t;
typedef _Atomic uint32_t daran_atomic_u32_t;
#else
#define DARAN_ATOMIC_C11 0
typedef uint16_t daran_atomic_u16_t;
typedef uint32_t daran_atomic_u32_t;
#endif

typedef struct daran_rx_ring {
    daran_atomic_u16_t head;     /* written by the producer only */
    daran_atomic_u16_t tail;     /* written by the consumer only */
    daran_atomic_u32_t dropped;  /* bytes lost; written by the producer only */
    uint8_t producer_dropping;   /* producer only: discarding up to the next '\n' */
    /* Received bytes; a line end that closes a line which lost bytes is
     * stored as DARAN_RX_DAMAGED_END (a received 0x8A is stored as 0x80:
     * both are invalid characters), so no mark shares a byte between the
     * two sides. */
    uint8_t bytes[DARAN_RX_RING_SIZE];
} daran_rx_ring_t;
/* The fields of the current line as offsets into it, recorded by the framer
 * as the bytes arrive. They live in the instance, not on the stack: the
 * line's road to the HAL is the core's deepest call chain.
 * DARAN_FIELDS_MAX is the most fields a command has (d: word, id and 5
 * values) plus one to tell "too many". */
#define DARAN_FIELDS_MAX 8u
/* The values of an `ms` preset. */
#define DARAN_PRESET_VALUES 3u
#if DARAN_LINE_MAX <= 255
typedef uint8_t daran_line_offset_t;
#else
typedef uint16_t daran_line_offset_t;
#endif
typedef struct daran_fields {
    daran_line_offset_t start[DARAN_FIELDS_MAX];
    daran_line_offset_t len[DARAN_FIELDS_MAX];
    uint8_t count; /* fields found, saturating at DARAN_FIELDS_MAX */
} daran_fields_t;
struct daran_port_command;
struct daran_request;
struct daran_line_sink;
struct daran_update;
/* What takes a drive's lines for other ids instead of the forward hook (a
 * gateway's bridge, daran_can.h): the sink registers its functions, and the
 * drive knows nothing else of it. */
typedef struct daran_line_sink_ops {
    /* It takes lines now (a bridge: CAN on, C31). */
    bool (*takes)(const struct daran_line_sink *sink);
    /* A line checked up to its values, for another drive or, @p broadcast,
     * for every drive: DARAN_OK when it went out, else the line's error. */
    daran_result_t (*line)(struct daran_line_sink *sink, const struct daran_request *request,
                           bool broadcast);
    /* It still answers an earlier line: the drive reads no further line. */
    bool (*busy)(struct daran_line_sink *sink);
} daran_line_sink_ops_t;
typedef struct daran_line_sink {
    const daran_line_sink_ops_t *ops;
} daran_line_sink_t;
/** @endcond */

/** One drive. Size: sizeof(daran_drive_t), known at compile time. */
typedef struct daran_drive {
    /** @cond INTERNAL */
    const daran_hal_t *hal;
    void *ctx;               /* the one context every HAL function gets */
    const struct daran_port_command *port_commands;
    daran_line_sink_t *sink;  /* takes lines for other ids (a gateway's bridge), NULL without one */
#if DARAN_ENABLE_UPDATE
    struct daran_update *update; /* the update module bound to it (daran_update.h), or NULL */
#endif
    uint32_t telemetry_next; /* tick of the next report */
    daran_rx_ring_t rx;
    uint16_t line_len;       /* bytes of the current line so far (saturates past DARAN_LINE_MAX) */
    uint16_t star_at;        /* index of the line's first '*', DARAN_LINE_MAX when none yet */
    uint16_t reply_len;
    uint8_t line_flags;      /* too long, invalid byte, inside a field */
    uint8_t reply_wants_checksum;  /* the current request carried a checksum field */
    uint8_t has_preset;
    uint8_t port_command_count;
    uint8_t telemetry_due;   /* 1: no report scheduled yet, the next tick reports */
    float preset[DARAN_PRESET_VALUES];
    daran_fields_t fields;
    char line[DARAN_LINE_MAX];
    char reply[DARAN_REPLY_MAX];
    /** @endcond */
} daran_drive_t;

/** Bind an instance to its port (daran_hal_t: functions and reply writer)
 * and reset it (empty receive ring, no partial line, no preset). @p hal
 * must stay valid while the instance is used; @p ctx is given to every one
 * of its functions.
 * O(sizeof *drive). Returns DARAN_ERR_BAD_ARGUMENT if a pointer or a
 * required HAL member (get, set, move, action, write) is NULL, and
 * DARAN_ERR_BUILD_MISMATCH if the caller was compiled with other options or
 * another property table than the library (see daran_init_checked()); the
 * instance is then unusable. */
#define daran_init(drive, hal, ctx) \
    daran_init_checked((drive), DARAN_BUILD_CHECK(daran_drive_t), (hal), (ctx))

/** What daran_init() calls, with the caller's DARAN_BUILD_CHECK(daran_drive_t)
 * (daran_build.h): a program compiled with another options header than the
 * library (other DARAN_LINE_MAX, its own property rows or ranges, omissions,
 * other options) would otherwise corrupt memory or send property ids that
 * mean other properties to the library; here it gets
 * DARAN_ERR_BUILD_MISMATCH instead, before anything is touched. */
DARAN_NODISCARD daran_result_t daran_init_checked(daran_drive_t *drive, uint32_t build_check,
                                                  const daran_hal_t *hal, void *ctx);

/** Producer side: queue one received byte. Safe in an interrupt (one producer).
 * O(1). Returns false when the ring was full: the byte is lost, the line it
 * belonged to will be discarded and answered `line too long`. */
bool daran_rx_byte(daran_drive_t *drive, uint8_t byte);

/** Producer side: queue @p len bytes; returns how many were queued (the rest
 * are lost as in daran_rx_byte()). O(len). */
size_t daran_rx_write(daran_drive_t *drive, const void *data, size_t len);

/** Bytes lost to a full ring since daran_init() (wraps at 2^32). O(1);
 * either side may call it. */
uint32_t daran_rx_dropped(const daran_drive_t *drive);

/** Room left in the receive ring, in bytes: a byte-input routine (a DMA
 * or FIFO drain) can take this many without losing one. O(1); either side
 * may call it (from the consumer side the answer only grows until the
 * producer runs again). */
size_t daran_rx_free(const daran_drive_t *drive);

/** Consumer side: frame the queued bytes and process every complete line,
 * replying through the write callback. Returns the number of lines processed
 * (blank lines included). O(bytes queued); never blocks. */
size_t daran_poll(daran_drive_t *drive);

/** Process one line the caller framed itself (without its `\n`; a trailing
 * `\r` is whitespace). Length and characters are checked as on the byte path.
 * It uses the line buffer of the byte path: a line daran_poll() had begun
 * to frame loses its beginning, and its rest is answered `line too long`
 * when its `\n` arrives, never executed (D38). Use one road per drive, or
 * call this only between lines.
 * All-or-nothing: a line that is answered with an error made no HAL setter,
 * move or action call. Returns DARAN_OK when the line was executed, ignored
 * (blank) or not addressed to this drive, otherwise the error that was
 * answered. O(len). */
daran_result_t daran_process_line(daran_drive_t *drive, const char *line, size_t len);

/** The library version, "MAJOR.MINOR.PATCH" (DARAN_VERSION_TEXT of the
 * library as built; compare with the header's to catch a mismatch). */
const char *daran_version(void);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_DRIVE_H */

/* The recording HAL: a test double that logs every HAL call the core makes,
 * with its arguments and result, and either serves the properties from its
 * own store (no inner HAL: a drive with no physics) or passes each call on to
 * an inner HAL (a shim around the HAL under test). It also captures the
 * replies the core writes, and can make the Nth call of chosen kinds fail.
 *
 * Plain C (host or target): no heap; stdio (snprintf) only in the describe
 * functions.
 * Compile it against the same options header as the core it records. The
 * Unity assertions over it are in daran_recorder_unity.h. */
#ifndef DARAN_RECORDER_H
#define DARAN_RECORDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef DARAN_RECORDER_CALLS_MAX
/** Calls kept in the log; later ones are counted in n_dropped. */
#define DARAN_RECORDER_CALLS_MAX 64
#endif
#ifndef DARAN_RECORDER_OUT_MAX
/** Reply bytes kept; later ones are counted in out_dropped. */
#define DARAN_RECORDER_OUT_MAX 4096
#endif

/** The kind of a logged HAL call. */
typedef enum daran_call_kind {
    DARAN_CALL_GET,
    DARAN_CALL_SET,
    DARAN_CALL_MOVE,
    DARAN_CALL_ACTION
} daran_call_kind_t;

/** daran_recorder_fail() masks. */
#define DARAN_RECORDER_FAIL_GET (1u << DARAN_CALL_GET)
#define DARAN_RECORDER_FAIL_SET (1u << DARAN_CALL_SET)
#define DARAN_RECORDER_FAIL_MOVE (1u << DARAN_CALL_MOVE)
#define DARAN_RECORDER_FAIL_ACTION (1u << DARAN_CALL_ACTION)

/** One logged call. */
typedef struct daran_call {
    daran_call_kind_t kind;
    daran_prop_t prop;     /**< GET, SET */
    daran_value_t value;   /**< SET: the value written; GET: the value read */
    daran_move_t move;     /**< MOVE */
    daran_action_t action; /**< ACTION */
    daran_result_t result; /**< what the call returned */
} daran_call_t;

typedef struct daran_recorder {
    const daran_hal_t *inner; /**< NULL: the store below serves the calls */
    void *inner_ctx;
    daran_value_t store[DARAN_PROP_COUNT];
    bool log_gets;            /**< log GET calls too (default false: counted only) */

    daran_call_t calls[DARAN_RECORDER_CALLS_MAX];
    size_t n_calls;           /**< calls logged (<= DARAN_RECORDER_CALLS_MAX) */
    size_t n_dropped;         /**< calls past the log's end */
    size_t n_gets;            /**< GET calls, logged or not */
    size_t n_mutations;       /**< SET + MOVE + ACTION calls, logged or not */

    unsigned fail_mask;
    unsigned fail_countdown;
    daran_result_t fail_result;
    int fail_prop;

    char out[DARAN_RECORDER_OUT_MAX + 1]; /**< replies, NUL-terminated */
    size_t out_len;
    size_t out_dropped;
    size_t n_replies;         /**< reply lines written */

    /** Optional (NULL: none): called after every call, GET included and
     * logged or not, with its record (result filled in), for a test double
     * of one's own that keeps its own log or checks each call as it comes. */
    void (*observer)(void *ctx, const daran_call_t *call);
    void *observer_ctx;

    /** The inner port's own commands, as daran_recorder_attach_commands()
     * gave them, and the relays the drive holds in their place. */
    const daran_port_command_t *port_commands;
    size_t port_command_count;
    daran_port_command_t relays[255];
} daran_recorder_t;

/** The recording HAL; its context is a daran_recorder_t. Replies go to
 * daran_recorder_write(); the clock and the CAN functions pass to the inner
 * HAL unrecorded; no forward hook. */
extern const daran_hal_t daran_recorder_hal;

/** Record calls to @p inner (with @p inner_ctx), or, with @p inner NULL,
 * serve them from the store as daran_recorder_init_store(rec, 1) does.
 * Forgets everything: calls, replies, fault injection, observer; log_gets
 * false. */
void daran_recorder_init(daran_recorder_t *rec, const daran_hal_t *inner, void *inner_ctx);

/** The store double: no inner HAL, every value 0 except node id @p node_id
 * and closed loop (requested and current state 8), so motion is accepted.
 * It keeps the HAL contract's bookkeeping (docs/porting.md section 3) and
 * nothing more: a set stores (requested_state also sets current_state, a
 * setpoint its output_shaft.input_*), a move stores its targets and given
 * rates in their properties, `st` goes idle with DARAN_FLAG_ESTOP, `sc`
 * clears the error registers, `sz` zeroes the position; no physics, no
 * non-volatile memory. */
void daran_recorder_init_store(daran_recorder_t *rec, uint32_t node_id);

/** Forget the calls and replies (the store and the fault injection stay). */
void daran_recorder_clear(daran_recorder_t *rec);

/** The recording HAL's reply writer: its ctx is a daran_recorder_t. */
void daran_recorder_write(void *ctx, const char *line, size_t len);

/** Give @p drive (bound to daran_recorder_hal with @p rec) the inner port's
 * own commands: the drive holds a relay for each, which hands the line to
 * the port's handler with the inner context, as a drive bound to the port
 * alone would. The table must outlive the drive. Returns what
 * daran_set_port_commands() returns (DARAN_ERR_BAD_ARGUMENT for more than
 * 255 commands). */
DARAN_NODISCARD daran_result_t daran_recorder_attach_commands(daran_recorder_t *rec,
                                                              daran_drive_t *drive,
                                                              const daran_port_command_t *commands,
                                                              size_t count);

/** The @p nth (1-based) call among the kinds in @p mask returns @p result
 * without reaching the inner HAL or the store. @p prop >= 0 counts only
 * GET/SET of that property. nth 0 turns the injection off. */
void daran_recorder_fail(daran_recorder_t *rec, unsigned mask, unsigned nth,
                         daran_result_t result, int prop);

/** What the store double does with a move, for a double of one's own: the
 * targets into the `output_shaft.input_*` rows and a given bandwidth,
 * cruise, acceleration or ramp rate into its setting (docs/porting.md
 * section 3). DARAN_ERR_INVALID_MODE, @p store unchanged, for a kind outside
 * the enum. */
daran_result_t daran_recorder_apply_move(daran_value_t store[DARAN_PROP_COUNT],
                                         const daran_move_t *move);

/** SET, MOVE and ACTION calls since the last clear. */
size_t daran_recorder_mutations(const daran_recorder_t *rec);
/** True when no SET, MOVE or ACTION call was made since the last clear. */
bool daran_recorder_no_effect(const daran_recorder_t *rec);
/** Logged calls of @p kind (and, for ACTION, of @p action; pass -1 for any). */
size_t daran_recorder_count(const daran_recorder_t *rec, daran_call_kind_t kind, int action);
/** The first logged call of @p kind, or NULL. */
const daran_call_t *daran_recorder_first(const daran_recorder_t *rec, daran_call_kind_t kind);

/** SET calls (or logged GET calls) of property @p prop. */
size_t daran_recorder_count_prop(const daran_recorder_t *rec, daran_call_kind_t kind,
                                 daran_prop_t prop);
/** True when the replies captured since the last clear are exactly
 * @p expected, in which each "\n" stands for the configured line end
 * (\r\n with DARAN_REPLY_CRLF 1). False when replies were dropped. */
bool daran_recorder_reply_equals(const daran_recorder_t *rec, const char *expected);

/** The wire path of @p prop ("axis0.controller.config.pos_gain",
 * "vbus_voltage"), NUL terminated, cut to @p size; "?" outside the list.
 * Returns the length it would have had. */
size_t daran_recorder_prop_path(daran_prop_t prop, char *buf, size_t size);
/** "FILTERED_POSITION", "TRAPEZOID", ...; "?" outside the enum. */
const char *daran_recorder_move_name(daran_move_kind_t kind);
/** "SAVE_CONFIG", "ESTOP", ...; "?" outside the enum. */
const char *daran_recorder_action_name(daran_action_t action);

/** @p len bytes of @p text as a C string literal's body would write them
 * (`\n`, `\r`, `\t`, `\"`, `\\`, `\xHH` for any other byte outside printable
 * ASCII), NUL terminated in @p buf; when @p size runs out it ends in "...".
 * Returns @p buf. For reports of lines and replies. */
const char *daran_recorder_escape(const char *text, size_t len, char *buf, size_t size);

/** One call as text ("set axis0.controller.config.pos_gain 20 -> ok"), NUL
 * terminated, cut to @p size. Returns the length it would have had. */
size_t daran_call_describe(const daran_call_t *call, char *buf, size_t size);
/** Every logged call, one per line, cut to @p size ("none" when none). */
size_t daran_recorder_describe(const daran_recorder_t *rec, char *buf, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_RECORDER_H */

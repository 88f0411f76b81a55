/* A minimal, complete port of daran-ascii: the HAL a real drive would start
 * from. It keeps every property in RAM and hands each validated move to the
 * control loop through a one-slot mailbox; the control loop itself (current
 * control, encoder) is the drive's own and not shown. docs/porting.md walks
 * through it. */
#ifndef MINIMAL_HAL_H
#define MINIMAL_HAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "daran_ascii.h"

/* The mailbox holds a move as whole 32-bit words, each an atomic: a reader
 * never sees half a store, and the sequence number tells it whether the
 * words belong together (a sequence lock). C11 atomics on 32-bit words are
 * plain loads and stores with barriers on every Cortex-M: no locks, no
 * read-modify-write, so this works on a Cortex-M0 too. */
#define MINIMAL_MOVE_WORDS ((sizeof(daran_move_t) + 3u) / 4u)

typedef struct minimal_drive {
    daran_value_t props[DARAN_PROP_COUNT]; /* the live values of every property */
    /* Mailbox from the protocol (main loop) to the control loop (interrupt):
     * move_seq is odd while the main loop writes the words, and grows by 2
     * per move. */
    _Atomic uint32_t move_words[MINIMAL_MOVE_WORDS];
    _Atomic uint32_t move_seq;
    uint32_t taken_seq;                    /* the control loop's: the last move it took */
    /* Stands in for the flash driver: `ss` copies the settings here, `se`
     * forgets them, `sr` boots from them (or from the defaults). */
    daran_value_t saved[DARAN_PROP_COUNT];
    bool has_saved;
    uint32_t saved_config_writes;
} minimal_drive_t;

/* Factory state: defaults, id 1, closed loop, no flags, nothing saved. */
void minimal_drive_init(minimal_drive_t *drive);

/* The control loop's side: take the newest move, if there is one it has not
 * taken and the main loop is not writing it just now (then: next tick). */
bool minimal_drive_take_move(minimal_drive_t *drive, daran_move_t *move);

/* The HAL's four functions; their context is a minimal_drive_t (or a struct
 * that begins with one). A program's port description adds its reply
 * writer: `static const daran_hal_t hal = {MINIMAL_HAL_FUNCTIONS, .write = uart_write};`. */
daran_result_t minimal_get(void *ctx, daran_prop_t prop, daran_value_t *out);
daran_result_t minimal_set(void *ctx, daran_prop_t prop, daran_value_t value);
daran_result_t minimal_move(void *ctx, const daran_move_t *request);
daran_result_t minimal_action(void *ctx, daran_action_t which);
#define MINIMAL_HAL_FUNCTIONS \
    .get = minimal_get, .set = minimal_set, .move = minimal_move, .action = minimal_action

/* The four alone, for a HAL that wraps this one (the test kit's recorder,
 * which writes the replies itself). */
extern const daran_hal_t minimal_hal;

#endif /* MINIMAL_HAL_H */

/* A HAL that only remembers: every property in RAM, moves and actions
 * counted and accepted. For test programs, benchmarks and target images
 * that need a drive behind the core but no physics. Compile stub_hal.c
 * into each program: it must see the same options header as its core. */
#ifndef DARAN_STUB_HAL_H
#define DARAN_STUB_HAL_H

#include "daran_ascii.h"

typedef struct daran_stub {
    daran_value_t values[DARAN_PROP_COUNT];
    unsigned sets;
    unsigned moves;
    unsigned actions;
} daran_stub_t;

/* Every value 0, but node id @p id and closed loop (motion is accepted). */
void daran_stub_init(daran_stub_t *stub, uint32_t id);

/* get/set read and store values[], move/action count; all answer DARAN_OK.
 * Their context is a daran_stub_t (or a struct that begins with one). */
daran_result_t daran_stub_get(void *ctx, daran_prop_t prop, daran_value_t *out);
daran_result_t daran_stub_set(void *ctx, daran_prop_t prop, daran_value_t value);
daran_result_t daran_stub_move(void *ctx, const daran_move_t *move);
daran_result_t daran_stub_action(void *ctx, daran_action_t action);
#define DARAN_STUB_HAL_FUNCTIONS \
    .get = daran_stub_get, .set = daran_stub_set, .move = daran_stub_move, .action = daran_stub_action

/* The four, replies dropped (daran_stub_drop_reply). */
extern const daran_hal_t daran_stub_hal;

/* A reply sink that drops the line. */
void daran_stub_drop_reply(void *ctx, const char *line, size_t len);

#endif /* DARAN_STUB_HAL_H */

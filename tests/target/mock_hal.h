/* A recording HAL for the on-target self-test: fixed drive readings, every
 * setter/move/action call written to a text log the cases compare. */
#ifndef DARAN_TARGET_MOCK_HAL_H
#define DARAN_TARGET_MOCK_HAL_H

#include <stddef.h>
#include <stdint.h>

#include "daran_hal.h"

#define TARGET_MOCK_LOG_MAX 160u

typedef struct target_mock {
    daran_value_t value[DARAN_PROP_COUNT];
    char log[TARGET_MOCK_LOG_MAX];
    size_t log_len;
} target_mock_t;

extern const daran_hal_t target_mock_hal;

/* The drive the cases assume: id 1, closed loop, no flags, known readings. */
void target_mock_reset(target_mock_t *m);

#endif /* DARAN_TARGET_MOCK_HAL_H */

/* A drive for the update module's tests: properties in RAM, two slots and a
 * journal page of flash that behave as flash does (erase sets all ones,
 * programming only clears bits) and can lose power at a chosen step, and a
 * boot control that boots a committed image once and reverts it unless it
 * is kept. */
#ifndef UPDATE_DOUBLE_H
#define UPDATE_DOUBLE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"
#include "daran_update.h"

#define DOUBLE_PAGE 256u
#define DOUBLE_SLOT (16u * DOUBLE_PAGE)
#define DOUBLE_HARDWARE 0x00d7a001u

typedef struct update_double {
    daran_value_t props[DARAN_PROP_COUNT];
    uint8_t slot[2][DOUBLE_SLOT];
    uint8_t journal[DOUBLE_PAGE];
    uint32_t version[2];
    uint8_t state[2];   /* daran_update_slot_state_t */
    uint8_t running;
    bool reset_pending; /* a commit asked for a reset */
    /* power: steps (erases and programs) so far, and the step that cuts it */
    uint32_t steps;
    uint32_t cut_at;    /* 0: never */
    bool powered;
    uint32_t noise;     /* what a cut leaves in the cells being changed (update_double.c) */
    uint32_t noise_state;
    uint32_t noise_bytes;
    /* replies of the drive since the last clear */
    char out[512];
    size_t out_len;
    daran_drive_t drive;
    daran_update_t update;
    bool bound; /* daran_init() and daran_update_init() took the drive at its last boot */
} update_double_t;

/* Factory state: slot 0 runs version 1 (kept), slot 1 empty, power on. */
void double_factory(update_double_t *d);
/* Power on (after a cut or a reset): the boot control, then the drive and
 * its update module bound again. */
void double_boot(update_double_t *d);
/* Send one line (no line end); the replies land in out[]. */
daran_result_t double_line(update_double_t *d, const char *line);

#endif /* UPDATE_DOUBLE_H */

/* The smallest complete embedding of daran-ascii: a drive whose "hardware" is
 * an array of property values. Lines come from stdin, replies go to stdout.
 * On a microcontroller getchar() is the UART interrupt and fwrite() the UART. */
#include <stdio.h>

#include "daran_ascii.h"

static daran_value_t props[DARAN_PROP_COUNT]; /* the whole drive */
#define PROP(id) props[DARAN_PROP_##id]

static daran_result_t get(void *ctx, daran_prop_t p, daran_value_t *out)
{
    (void)ctx;
    *out = props[p];
    return DARAN_OK;
}

static daran_result_t set(void *ctx, daran_prop_t p, daran_value_t v)
{
    (void)ctx;
    props[p] = v;
    if (p == DARAN_PROP_REQUESTED_STATE) {
        PROP(CURRENT_STATE) = v; /* state changes take no time here */
    }
    return DARAN_OK;
}

static daran_result_t move(void *ctx, const daran_move_t *m)
{
    (void)ctx; /* a real port hands this to its control loop; this drive arrives at once */
    PROP(INPUT_POS).f32 = PROP(POS_SETPOINT).f32 = PROP(POS_ESTIMATE).f32 = m->pos_deg;
    return DARAN_OK;
}

static daran_result_t action(void *ctx, daran_action_t a)
{
    (void)ctx;
    if (a == DARAN_ACTION_ESTOP) {
        PROP(AXIS_ERROR).u32 |= DARAN_FLAG_ESTOP;
        PROP(CURRENT_STATE).u32 = DARAN_STATE_IDLE;
    } else if (a == DARAN_ACTION_CLEAR_ERRORS) {
        PROP(AXIS_ERROR).u32 = 0;
    }
    return DARAN_OK;
}

static void reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    fwrite(line, 1, len, stdout);
}

int main(void)
{
    static const daran_hal_t hal = {.get = get, .set = set, .move = move, .action = action,
                                    .write = reply};
    static daran_drive_t drive; /* the caller owns all memory; the library never allocates */
    PROP(CAN_NODE_ID).u32 = 1;
    PROP(CURRENT_STATE).u32 = DARAN_STATE_CLOSED_LOOP;
    PROP(VBUS_VOLTAGE).f32 = 24.0f;
    if (daran_init(&drive, &hal, NULL) != DARAN_OK) {
        return 1;
    }
    for (int c; (c = getchar()) != EOF;) {
        (void)daran_rx_byte(&drive, (uint8_t)c); /* the interrupt side */
        (void)daran_poll(&drive);                /* the main-loop side */
    }
    return 0;
}

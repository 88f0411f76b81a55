/* The update module's test drive (update_double.h). */
#include "update_double.h"

#include <string.h>

static bool lose_power_now(update_double_t *d)
{
    if (!d->powered) {
        return true;
    }
    d->steps++;
    return d->cut_at != 0u && d->steps == d->cut_at;
}

/* What a cut leaves in a cell being changed, by the low two bits of
 * `noise`: random, as if done, as if not begun, or every other byte. */
static uint8_t noise_byte(update_double_t *d)
{
    d->noise_bytes++;
    switch (d->noise & 3u) {
    case 1u:
        return 0x00u;
    case 2u:
        return 0xffu;
    case 3u:
        return (d->noise_bytes & 1u) != 0u ? 0x00u : 0xffu;
    default:
        d->noise_state = d->noise_state * 1103515245u + 12345u;
        return (uint8_t)(d->noise_state >> 16);
    }
}

static uint8_t *region(update_double_t *d, daran_update_region_t which, uint32_t offset,
                       size_t len)
{
    uint32_t size = which == DARAN_UPDATE_SLOT ? DOUBLE_SLOT : DOUBLE_PAGE;
    if (offset > size || len > size - offset) {
        return NULL;
    }
    return which == DARAN_UPDATE_SLOT ? &d->slot[d->running ^ 1u][offset] : &d->journal[offset];
}

static daran_result_t flash_erase(void *ctx, daran_update_region_t which, uint32_t offset)
{
    update_double_t *d = ctx;
    uint8_t *page = region(d, which, offset - offset % DOUBLE_PAGE, DOUBLE_PAGE);
    if (page == NULL || !d->powered) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    bool cut = lose_power_now(d);
    for (size_t i = 0; i < DOUBLE_PAGE; i++) {
        /* an erase sets bits; cut short, some of them */
        page[i] |= cut ? noise_byte(d) : 0xffu;
    }
    if (cut) {
        d->powered = false;
        return DARAN_ERR_MOTOR_FAULT;
    }
    return DARAN_OK;
}

static daran_result_t flash_program(void *ctx, daran_update_region_t which, uint32_t offset,
                                    const uint8_t *data, size_t len)
{
    update_double_t *d = ctx;
    uint8_t *cells = region(d, which, offset, len);
    if (cells == NULL || !d->powered) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    bool cut = lose_power_now(d);
    for (size_t i = 0; i < len; i++) {
        /* programming clears bits; cut short, some of the ones it clears */
        cells[i] &= cut ? (uint8_t)(data[i] | noise_byte(d)) : data[i];
    }
    if (cut) {
        d->powered = false;
        return DARAN_ERR_MOTOR_FAULT;
    }
    return DARAN_OK;
}

static daran_result_t flash_read(void *ctx, daran_update_region_t which, uint32_t offset,
                                 uint8_t *data, size_t len)
{
    update_double_t *d = ctx;
    const uint8_t *cells = region(d, which, offset, len);
    if (cells == NULL || !d->powered) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    memcpy(data, cells, len);
    return DARAN_OK;
}

static daran_result_t boot_commit(void *ctx)
{
    update_double_t *d = ctx;
    unsigned other = d->running ^ 1u;
    const uint8_t *version = &d->slot[other][DARAN_UPDATE_AT_VERSION]; /* little-endian */
    d->version[other] = (uint32_t)version[0] | (uint32_t)version[1] << 8 |
                        (uint32_t)version[2] << 16 | (uint32_t)version[3] << 24;
    d->state[other] = DARAN_SLOT_TESTING;
    d->reset_pending = true;
    return DARAN_OK;
}

static daran_result_t boot_confirm(void *ctx)
{
    update_double_t *d = ctx;
    d->state[d->running] = DARAN_SLOT_CONFIRMED;
    return DARAN_OK;
}

static void boot_slots(void *ctx, daran_update_slots_t *out)
{
    const update_double_t *d = ctx;
    out->version[0] = d->version[0];
    out->version[1] = d->version[1];
    out->state[0] = d->state[0];
    out->state[1] = d->state[1];
    out->running = d->running;
}

static const daran_update_port_t double_update_port = {
    .slot_size = DOUBLE_SLOT,
    .page_size = DOUBLE_PAGE,
    .hardware_id = DOUBLE_HARDWARE,
    .require_signature = false,
    .erase = flash_erase,
    .program = flash_program,
    .read = flash_read,
    .commit = boot_commit,
    .confirm = boot_confirm,
    .slots = boot_slots,
};

static daran_result_t prop_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    *out = ((update_double_t *)ctx)->props[prop];
    return DARAN_OK;
}

static daran_result_t prop_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    ((update_double_t *)ctx)->props[prop] = value;
    return DARAN_OK;
}

static daran_result_t start_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_OK;
}

static daran_result_t act(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_OK;
}

static void collect(void *ctx, const char *line, size_t len)
{
    update_double_t *d = ctx;
    if (len < sizeof d->out - d->out_len) {
        memcpy(d->out + d->out_len, line, len);
        d->out_len += len;
        d->out[d->out_len] = '\0';
    }
}

static const daran_hal_t double_port = {.get = prop_get,
                                        .set = prop_set,
                                        .move = start_move,
                                        .action = act,
                                        .write = collect,
                                        .update = &double_update_port};

void double_factory(update_double_t *d)
{
    memset(d, 0, sizeof *d);
    memset(d->slot, 0xff, sizeof d->slot);
    memset(d->journal, 0xff, sizeof d->journal);
    d->version[0] = 1;
    d->state[0] = DARAN_SLOT_CONFIRMED;
    d->noise = 1;
    double_boot(d);
}

void double_boot(update_double_t *d)
{
    d->powered = true;
    unsigned other = d->running ^ 1u;
    if (d->state[d->running] == DARAN_SLOT_TESTING && !d->reset_pending) {
        /* the test image ran and was not kept: back to the other */
        d->state[d->running] = DARAN_SLOT_REVERTED;
        d->running = (uint8_t)other;
    } else if (d->reset_pending && d->state[other] == DARAN_SLOT_TESTING) {
        d->running = (uint8_t)other; /* the committed image, once */
    }
    d->reset_pending = false;
    d->props[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    d->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
    d->props[DARAN_PROP_FW_VERSION].u32 = d->version[d->running];
    d->bound = daran_init(&d->drive, &double_port, d) == DARAN_OK &&
               daran_update_init(&d->update, &d->drive) == DARAN_OK;
}

daran_result_t double_line(update_double_t *d, const char *line)
{
    return daran_process_line(&d->drive, line, strlen(line));
}

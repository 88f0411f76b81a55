/* The two-slot configuration store behind `ss`, `se` and boot.
 *
 * Slot layout (little-endian):
 *   0  magic    commit marker, written last; a slot without it is empty
 *   4  version  u16, DARAN_SIM_NVM_VERSION
 *   6  length   u16, payload bytes
 *   8  sequence u32, higher (mod 2^32) is newer
 *  12  crc      CRC-32 of bytes 4..11 and the payload
 *  16  payload  every configuration property (daran_sim_is_config_prop:
 *               its 32 bits, whatever its type, in property order; a
 *               port's settings after the vendor's, as many as fit), then
 *               the zero offset
 * A save first clears the target slot's magic, then writes header and
 * payload, then the magic: until that last byte lands the slot is not
 * committed and the other slot still holds the previous image. A damaged
 * image is never kept next to a new one: boot would distrust both. */
#include "sim_nvm.h"

#include <math.h>
#include <string.h>

#include "daran_drive.h"
#include "daran_port.h"

#define MAGIC 0x4D495344u /* every byte non-zero and not 0xFF */
#define HEADER_SIZE 16u
/* Room for configuration rows in a slot, after the header and before the
 * zero offset. */
#define ROWS_MAX_BYTES (DARAN_SIM_NVM_SLOT_SIZE - HEADER_SIZE - 4u)

/* Does row @p p go into the image? Rows are taken in property order while
 * they fit (*used counts their bytes so far): the vendor's always do, a
 * port with more settings than fit keeps its last ones in RAM only. */
static bool in_image(int p, uint32_t *used)
{
    if (!daran_sim_is_config_prop((daran_prop_t)p) || *used + 4u > ROWS_MAX_BYTES) {
        return false;
    }
    *used += 4u;
    return true;
}

static bool ram_read(void *ctx, uint32_t offset, uint8_t *buf, uint32_t len)
{
    daran_sim_ram_storage_t *ram = ctx;
    if (offset > DARAN_SIM_NVM_SIZE || len > DARAN_SIM_NVM_SIZE - offset) {
        return false;
    }
    memcpy(buf, &ram->bytes[offset], len);
    return true;
}

static bool ram_write(void *ctx, uint32_t offset, const uint8_t *data, uint32_t len)
{
    daran_sim_ram_storage_t *ram = ctx;
    uint32_t i;
    if (offset > DARAN_SIM_NVM_SIZE || len > DARAN_SIM_NVM_SIZE - offset) {
        return false;
    }
    for (i = 0; i < len; i++) {
        if (ram->power_cut) {
            if (ram->cut_after == 0u) {
                return false;
            }
            ram->cut_after--;
        }
        ram->bytes[offset + i] = data[i];
        ram->bytes_written++;
    }
    return true;
}

void daran_sim_ram_storage_init(daran_sim_ram_storage_t *ram, daran_sim_storage_t *st)
{
    memset(ram->bytes, 0xFF, sizeof ram->bytes);
    ram->power_cut = false;
    ram->cut_after = 0u;
    ram->bytes_written = 0u;
    st->ctx = ram;
    st->read = ram_read;
    st->write = ram_write;
}

uint32_t daran_sim_crc32(const uint8_t *data, uint32_t len, uint32_t crc)
{
    uint32_t i;
    int bit;
    crc = ~crc;
    for (i = 0; i < len; i++) {
        crc ^= data[i];
        for (bit = 0; bit < 8; bit++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

static void put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static uint32_t f32_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static float bits_f32(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static uint32_t payload_size(void)
{
    uint32_t used = 0u;
    int p;
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        (void)in_image(p, &used);
    }
    return used + 4u; /* and the zero offset */
}

uint32_t daran_sim_nvm_save_size(void)
{
    return 4u + (HEADER_SIZE - 4u) + payload_size() + 4u;
}

static uint32_t image_crc(const uint8_t *slot, uint32_t len)
{
    uint32_t crc = daran_sim_crc32(slot + 4, 8u, 0u);
    return daran_sim_crc32(slot + HEADER_SIZE, len, crc);
}

typedef enum { SLOT_EMPTY, SLOT_INTACT, SLOT_DAMAGED } slot_state_t;

static slot_state_t read_slot(const daran_sim_storage_t *st, uint32_t index,
                              uint8_t slot[DARAN_SIM_NVM_SLOT_SIZE], uint32_t *seq)
{
    uint32_t len;
    if (!st->read(st->ctx, index * DARAN_SIM_NVM_SLOT_SIZE, slot, DARAN_SIM_NVM_SLOT_SIZE)) {
        return SLOT_DAMAGED;
    }
    if (get_u32(slot) != MAGIC) {
        return SLOT_EMPTY;
    }
    len = (uint32_t)slot[6] | ((uint32_t)slot[7] << 8);
    if (((uint32_t)slot[4] | ((uint32_t)slot[5] << 8)) != DARAN_SIM_NVM_VERSION ||
        len != payload_size() || image_crc(slot, len) != get_u32(slot + 12)) {
        return SLOT_DAMAGED;
    }
    *seq = get_u32(slot + 8);
    return SLOT_INTACT;
}

/* ---- range checks: a stored value must be one `w` would take ----
 *
 * A config image with a valid CRC can still hold values no host could have
 * written (a foreign or older writer, a tampered file): load_inertia -5,
 * vel_gain -1000, can_node_id 200. Rather than restate the core's ranges
 * here (the sim may use only its public API, and a copy would drift from
 * include/daran_properties.h and src/property_table.c), each stored value
 * is written back through a real `w` line into a scratch protocol instance,
 * whose HAL only notes what reached set(): the same parser, the same range
 * rules (-0 counting as 0, the telemetry field set that must fit a report),
 * in the core as built. What the model refuses on top (a zero gear ratio,
 * non-finite floats) is daran_sim_model_config_ok(). A port's own settings
 * are not probed: they default to 0 whatever their range says, and their
 * meaning is the port's (only non-finite floats are refused). */

#define PROBE_PATH_MAX 100u

typedef struct probe {
    daran_prop_t prop;   /* the property the line writes */
    bool reached_set;    /* the core passed it to the HAL */
} probe_t;

static const struct {
    const char *path;
    bool axis;
    daran_prop_type_t type;
} probe_rows[] = {
#define DARAN_SIM_PROBE_AXIS_AXIS true
#define DARAN_SIM_PROBE_AXIS_SYSTEM false
#define DARAN_SIM_PROBE_ROW_(id, path, scope, type, access, range, unit, can) \
    {path, DARAN_SIM_PROBE_AXIS_##scope, DARAN_TYPE_##type},
    DARAN_PROPERTY_LIST(DARAN_SIM_PROBE_ROW_)
#undef DARAN_SIM_PROBE_ROW_
};

static daran_result_t probe_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    out->u64 = 0u;
    if (prop == DARAN_PROP_CAN_NODE_ID) {
        out->u32 = 1u; /* the probe is drive 1: its lines say axis1. or end in 1 */
    }
    return DARAN_OK;
}

static daran_result_t probe_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    probe_t *p = ctx;
    (void)value;
    p->reached_set = p->reached_set || prop == p->prop;
    return DARAN_OK;
}

static daran_result_t probe_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_ERR_MOTOR_FAULT;
}

static daran_result_t probe_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_ERR_MOTOR_FAULT;
}

static void probe_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
}

static const daran_hal_t probe_hal = {probe_get, probe_set, probe_move, probe_action,
                                      probe_write, NULL, NULL, NULL, NULL, NULL};

static size_t put_text(char *out, size_t at, const char *text)
{
    size_t n = strlen(text);
    memcpy(out + at, text, n);
    return at + n;
}

/* The value as a host would write it: shortest round-trip float, decimal
 * integers (a sign for s32), into out[0..size); the caller's line keeps room
 * for the longest (sign and DARAN_UINT_TEXT_MAX digits). */
static size_t value_text(daran_prop_type_t type, daran_value_t v, char *out, size_t size)
{
    if (type == DARAN_TYPE_F32) {
        return daran_format_float(v.f32, out, size);
    }
    if (type == DARAN_TYPE_S32 && v.s32 < 0) {
        out[0] = '-';
        return 1u + daran_format_uint((uint64_t)(-(int64_t)v.s32), out + 1, size - 1u);
    }
    return daran_format_uint(type == DARAN_TYPE_S32 ? (uint64_t)v.s32 : (uint64_t)v.u32, out,
                             size);
}

bool daran_sim_nvm_config_in_range(const daran_value_t cfg[DARAN_PROP_COUNT],
                                   daran_prop_t *first_bad)
{
    daran_drive_t scratch;
    probe_t probe;
    int p;
    probe.prop = DARAN_PROP_COUNT;
    probe.reached_set = false;
    if (daran_init(&scratch, &probe_hal, &probe) != DARAN_OK) {
        return false;
    }
    for (p = 0; p < (int)DARAN_PROP_COUNT && p < (int)(sizeof probe_rows / sizeof probe_rows[0]);
         p++) {
        /* "w axis1." path ' ' value " 1" (the longest path is 51 bytes) */
        char line[8u + PROBE_PATH_MAX + 1u + DARAN_FLOAT_TEXT_MAX + DARAN_UINT_TEXT_MAX + 2u];
        size_t n;
        daran_result_t r;
        if (!daran_sim_is_config_prop((daran_prop_t)p) ||
            strlen(probe_rows[p].path) > PROBE_PATH_MAX) {
            continue;
        }
        n = put_text(line, 0u, probe_rows[p].axis ? "w axis1." : "w ");
        n = put_text(line, n, probe_rows[p].path);
        line[n++] = ' ';
        n += value_text(probe_rows[p].type, cfg[p], line + n, sizeof line - n);
        if (!probe_rows[p].axis) {
            n = put_text(line, n, " 1");
        }
        probe.prop = (daran_prop_t)p;
        probe.reached_set = false;
        r = daran_process_line(&scratch, line, n);
        if (r == DARAN_ERR_INVALID_PROPERTY || r == DARAN_ERR_LINE_TOO_LONG) {
            /* a row the port left out of its build (no host can write it
             * either), or a path longer than the port's lines: not checked */
            continue;
        }
        if (r != DARAN_OK || !probe.reached_set) {
            if (first_bad != NULL) {
                *first_bad = (daran_prop_t)p;
            }
            return false;
        }
    }
    return true;
}

static bool unpack(const uint8_t *payload, daran_sim_model_t *m)
{
    daran_value_t cfg[DARAN_PROP_COUNT];
    uint32_t off = 0u;
    uint32_t used = 0u;
    int p;
    float zero;
    memcpy(cfg, m->cfg, sizeof cfg);
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        if (!in_image(p, &used)) {
            continue;
        }
        /* f32, u32, s32 and bool all travel as their 32 bits */
        cfg[p].u64 = 0u;
        cfg[p].u32 = get_u32(payload + off);
        off += 4u;
    }
    zero = bits_f32(get_u32(payload + off));
    if (!isfinite(zero) || !daran_sim_model_config_ok(cfg) ||
        !daran_sim_nvm_config_in_range(cfg, NULL)) {
        return false;
    }
    memcpy(m->cfg, cfg, sizeof cfg);
    m->zero_offset_deg = zero;
    return true;
}

/* Index of the newest intact slot, or -1; *damaged tells whether a
 * committed slot failed its checks. */
static int newest_slot(const daran_sim_storage_t *st, uint8_t out[DARAN_SIM_NVM_SLOT_SIZE],
                       bool *damaged, uint32_t *newest_seq)
{
    uint8_t slot[DARAN_SIM_NVM_SLOT_SIZE];
    int best = -1;
    uint32_t i;
    *damaged = false;
    for (i = 0; i < 2u; i++) {
        uint32_t seq = 0u;
        slot_state_t s = read_slot(st, i, slot, &seq);
        if (s == SLOT_DAMAGED) {
            *damaged = true;
        } else if (s == SLOT_INTACT &&
                   (best < 0 || (int32_t)(seq - *newest_seq) > 0)) {
            best = (int)i;
            *newest_seq = seq;
            memcpy(out, slot, DARAN_SIM_NVM_SLOT_SIZE);
        }
    }
    return best;
}

daran_sim_nvm_status_t daran_sim_nvm_load(const daran_sim_storage_t *st, daran_sim_model_t *m)
{
    uint8_t slot[DARAN_SIM_NVM_SLOT_SIZE];
    bool damaged;
    uint32_t seq = 0u;
    int best = newest_slot(st, slot, &damaged, &seq);
    daran_sim_model_default_config(m);
    if (best >= 0 && !unpack(slot + HEADER_SIZE, m)) {
        daran_sim_model_default_config(m);
        damaged = true;
        best = -1;
    }
    if (damaged) {
        /* a damaged newest image could hide a newer config than the intact
         * one: trust neither */
        daran_sim_model_default_config(m);
        return DARAN_SIM_NVM_DAMAGED;
    }
    return best >= 0 ? DARAN_SIM_NVM_LOADED : DARAN_SIM_NVM_BLANK;
}

bool daran_sim_nvm_save(const daran_sim_storage_t *st, const daran_sim_model_t *m)
{
    uint8_t slot[DARAN_SIM_NVM_SLOT_SIZE];
    uint8_t scratch[DARAN_SIM_NVM_SLOT_SIZE];
    uint8_t zero4[4] = {0u, 0u, 0u, 0u};
    bool damaged;
    uint32_t seq = 0u;
    int newest = newest_slot(st, scratch, &damaged, &seq);
    uint32_t target = newest == 0 ? 1u : 0u;
    uint32_t base = target * DARAN_SIM_NVM_SLOT_SIZE;
    uint32_t len = payload_size();
    uint32_t off = HEADER_SIZE;
    uint32_t used = 0u;
    int p;

    memset(slot, 0, sizeof slot);
    slot[4] = (uint8_t)DARAN_SIM_NVM_VERSION;
    slot[5] = (uint8_t)(DARAN_SIM_NVM_VERSION >> 8);
    slot[6] = (uint8_t)len;
    slot[7] = (uint8_t)(len >> 8);
    put_u32(slot + 8, newest >= 0 ? seq + 1u : 1u);
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        if (in_image(p, &used)) {
            put_u32(slot + off, m->cfg[p].u32);
            off += 4u;
        }
    }
    put_u32(slot + off, f32_bits(m->zero_offset_deg));
    put_u32(slot + 12, image_crc(slot, len));
    put_u32(slot, MAGIC);

    if (newest < 0) {
        /* No intact image: the other slot may hold a damaged one that would
         * keep flagging every boot. It is garbage; retire it first. */
        uint32_t seq_other;
        if (read_slot(st, 1u - target, scratch, &seq_other) == SLOT_DAMAGED &&
            !st->write(st->ctx, (1u - target) * DARAN_SIM_NVM_SLOT_SIZE, zero4, 4u)) {
            return false;
        }
    }
    return st->write(st->ctx, base, zero4, 4u) &&
           st->write(st->ctx, base + 4u, slot + 4, HEADER_SIZE - 4u + len) &&
           st->write(st->ctx, base, slot, 4u);
}

bool daran_sim_nvm_erase(const daran_sim_storage_t *st)
{
    uint8_t scratch[DARAN_SIM_NVM_SLOT_SIZE];
    uint8_t zero4[4] = {0u, 0u, 0u, 0u};
    bool damaged;
    uint32_t seq = 0u;
    int newest = newest_slot(st, scratch, &damaged, &seq);
    uint32_t first = newest == 0 ? 1u : 0u;
    return st->write(st->ctx, first * DARAN_SIM_NVM_SLOT_SIZE, zero4, 4u) &&
           st->write(st->ctx, (1u - first) * DARAN_SIM_NVM_SLOT_SIZE, zero4, 4u);
}

bool daran_sim_nvm_corrupt(const daran_sim_storage_t *st)
{
    uint8_t slot[DARAN_SIM_NVM_SLOT_SIZE];
    uint8_t magic[4];
    uint32_t i;
    put_u32(magic, MAGIC);
    for (i = 0; i < 2u; i++) {
        uint32_t seq;
        uint32_t base = i * DARAN_SIM_NVM_SLOT_SIZE;
        slot_state_t s = read_slot(st, i, slot, &seq);
        if (s == SLOT_INTACT) {
            uint8_t b = (uint8_t)(slot[HEADER_SIZE] ^ 0x5Au);
            if (!st->write(st->ctx, base + HEADER_SIZE, &b, 1u)) {
                return false;
            }
        } else if (s == SLOT_EMPTY) {
            /* nothing stored: leave a committed slot whose header is wrong,
             * so the next boot still finds damage */
            uint8_t bad_version[2] = {0xEEu, 0xEEu};
            if (!st->write(st->ctx, base + 4u, bad_version, 2u) ||
                !st->write(st->ctx, base, magic, 4u)) {
                return false;
            }
        }
    }
    return true;
}

/* YARDSTICK ONLY - never linked into the daran-ascii library (see handwritten.h).
 *
 * How a firmware engineer writes this protocol's parser by hand: no libc, a
 * check loop over the line, a switch on the command letter, one reader per
 * field, a hashed property table, fixed-point replies. The contract is the
 * core's (shared/spec/protocol.md, docs/protocol.md): same check order,
 * same error phrases, same HAL calls; only the float conversion is the
 * firmware kind, which rounds some decimals to a neighbouring float. */
#include "handwritten.h"

#include "daran_config.h"

#define LINE_MAX_BYTES DARAN_LINE_MAX
#define FIELDS_MAX 8

#if DARAN_REPLY_CRLF
#define LINE_END "\r\n"
#else
#define LINE_END "\n"
#endif

#if defined(__GNUC__) || defined(__clang__)
#define HW_NOINLINE __attribute__((noinline))
#else
#define HW_NOINLINE
#endif

/* ---- the property table, hashed ----------------------------------------- */

enum { SCOPE_SYSTEM, SCOPE_AXIS };
enum { ACCESS_RO, ACCESS_RW };
#define HW_SCOPE_SYSTEM SCOPE_SYSTEM
#define HW_SCOPE_AXIS SCOPE_AXIS
#define HW_ACCESS_RO ACCESS_RO
#define HW_ACCESS_RW ACCESS_RW

typedef struct hw_property {
    const char *path; /* without "axisN." for axis properties */
    uint8_t len;
    uint8_t scope;
    uint8_t type;   /* daran_prop_type_t */
    uint8_t access;
    uint8_t range;  /* daran_range_t */
} hw_property_t;

/* Row i is property id i (the list order is the id order). */
static const hw_property_t properties[] = {
#define HW_ROW(id, path, scope, type, access, range, unit, can)                                  \
    {path, (uint8_t)(sizeof path - 1u), HW_SCOPE_##scope, DARAN_TYPE_##type,               \
     HW_ACCESS_##access, DARAN_RANGE_##range},
    DARAN_PROPERTY_LIST(HW_ROW)
#undef HW_ROW
};
#define PROPERTY_COUNT (sizeof properties / sizeof properties[0])

/* 512 slots for the ~160 rows: a third full, so most paths land on the
 * first probe. Each slot holds row + 1; 0 is empty. Filled once. */
#define TABLE_BITS 9u
#define TABLE_SIZE (1u << TABLE_BITS)
typedef char hw_table_fits_rows[PROPERTY_COUNT < 255u ? 1 : -1];
static uint8_t table[TABLE_SIZE];
static uint8_t table_built;

static uint32_t hash_path(int scope, const char *name, size_t len)
{
    uint32_t h = 5381u + (uint32_t)scope;
    for (size_t i = 0; i < len; i++) {
        h = h * 33u + (uint8_t)name[i];
    }
    return (h * 2654435761u) >> (32u - TABLE_BITS);
}

static void build_table(void)
{
    for (size_t row = 0; row < PROPERTY_COUNT; row++) {
        uint32_t slot = hash_path(properties[row].scope, properties[row].path, properties[row].len);
        while (table[slot] != 0u) {
            slot = (slot + 1u) & (TABLE_SIZE - 1u);
        }
        table[slot] = (uint8_t)(row + 1u);
    }
    table_built = 1;
}

HW_NOINLINE daran_prop_t handwritten_find_property(int scope, const char *name, size_t len)
{
    uint32_t slot = hash_path(scope, name, len);
    for (;;) {
        unsigned entry = table[slot];
        if (entry == 0u) {
            return DARAN_PROP_COUNT;
        }
        const hw_property_t *row = &properties[entry - 1u];
        if (row->len == len && row->scope == scope) {
            size_t i = 0;
            while (i < len && row->path[i] == name[i]) {
                i++;
            }
            if (i == len) {
                return (daran_prop_t)(entry - 1u);
            }
        }
        slot = (slot + 1u) & (TABLE_SIZE - 1u);
    }
}

/* ---- numbers: grbl's read_float, with the protocol's grammar ---------- */

/* A decimal as read: mantissa (the first 19 significant digits) times
 * 10^exp10. */
typedef struct hw_number {
    uint64_t mantissa;
    int32_t exp10;
    uint8_t negative;
    uint8_t lost_fraction; /* a nonzero fraction digit beyond the 19th */
} hw_number_t;

/* [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?, all of text. */
static daran_result_t read_number(const char *p, size_t n, hw_number_t *out)
{
    const char *end = p + n;
    uint64_t m = 0;
    int32_t e = 0;
    unsigned kept = 0, digits = 0;
    uint8_t dot = 0, lost = 0;
    out->negative = 0;
    if (p < end && (*p == '-' || *p == '+')) {
        out->negative = *p == '-';
        p++;
    }
    for (; p < end; p++) {
        unsigned d = (unsigned)(unsigned char)*p - '0';
        if (d <= 9u) {
            digits++;
            if (m == 0u && d == 0u) {
                e -= dot; /* a leading zero: only its place counts */
            } else if (kept < 19u) {
                m = m * 10u + d; /* the mantissa, accumulated while reading */
                kept++;
                e -= dot;
            } else {
                e += 1 - dot; /* dropped: an integer digit still scales */
                lost |= (uint8_t)(dot & (d != 0u));
            }
        } else if (*p == '.' && !dot) {
            dot = 1;
        } else {
            break;
        }
    }
    if (digits == 0u) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (p < end) {
        if (*p != 'e' && *p != 'E') {
            return DARAN_ERR_INVALID_VALUE;
        }
        p++;
        uint8_t negative_exp = 0;
        if (p < end && (*p == '-' || *p == '+')) {
            negative_exp = *p == '-';
            p++;
        }
        if (p == end) {
            return DARAN_ERR_INVALID_VALUE;
        }
        int32_t x = 0;
        for (; p < end; p++) {
            unsigned d = (unsigned)(unsigned char)*p - '0';
            if (d > 9u) {
                return DARAN_ERR_INVALID_VALUE;
            }
            if (x < 100000) {
                x = x * 10 + (int32_t)d;
            }
        }
        e += negative_exp ? -x : x;
    }
    out->mantissa = m;
    out->exp10 = e;
    out->lost_fraction = lost;
    return DARAN_OK;
}

static const float powers_of_ten[39] = {
    1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f,
    1e8f, 1e9f, 1e10f, 1e11f, 1e12f, 1e13f, 1e14f, 1e15f,
    1e16f, 1e17f, 1e18f, 1e19f, 1e20f, 1e21f, 1e22f, 1e23f,
    1e24f, 1e25f, 1e26f, 1e27f, 1e28f, 1e29f, 1e30f, 1e31f,
    1e32f, 1e33f, 1e34f, 1e35f, 1e36f, 1e37f, 1e38f,
};
static const float negative_powers_of_ten[38] = {
    1e0f, 1e-1f, 1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f, 1e-7f,
    1e-8f, 1e-9f, 1e-10f, 1e-11f, 1e-12f, 1e-13f, 1e-14f, 1e-15f,
    1e-16f, 1e-17f, 1e-18f, 1e-19f, 1e-20f, 1e-21f, 1e-22f, 1e-23f,
    1e-24f, 1e-25f, 1e-26f, 1e-27f, 1e-28f, 1e-29f, 1e-30f, 1e-31f,
    1e-32f, 1e-33f, 1e-34f, 1e-35f, 1e-36f, 1e-37f,
};

/* Mantissa to float, then one multiplication by the (rounded) power of ten:
 * two roundings, the second with an inexact constant. */
static daran_result_t number_to_f32(const hw_number_t *n, float *out)
{
    float f = 0.0f;
    if (n->mantissa != 0u) {
        int32_t e = n->exp10;
        f = (float)n->mantissa;
        if (e > 38) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        if (e >= 0) {
            f *= powers_of_ten[e];
            if (f > 3.40282347e38f) {
                return DARAN_ERR_OUT_OF_RANGE;
            }
        } else if (e < -64) {
            f = 0.0f; /* below half the smallest subnormal */
        } else {
            if (e < -37) {
                f *= 1e-37f;
                e += 37;
            }
            f *= negative_powers_of_ten[-e];
        }
    }
    *out = n->negative ? -f : f;
    return DARAN_OK;
}

daran_result_t handwritten_parse_f32(const char *text, size_t len, float *out)
{
    hw_number_t n;
    daran_result_t result = read_number(text, len, &n);
    return result != DARAN_OK ? result : number_to_f32(&n, out);
}

/* An exact non-negative integer ("5", "5.0", "5e0", "-0"): DARAN_OK,
 * DARAN_ERR_INVALID_VALUE (malformed, or not an integer) or
 * DARAN_ERR_OUT_OF_RANGE (below 0, above UINT64_MAX). */
static daran_result_t number_to_u64(const hw_number_t *n, uint64_t *out)
{
    uint64_t m = n->mantissa;
    int32_t e = n->exp10;
    if (m == 0u) {
        *out = 0;
        return DARAN_OK;
    }
    if (n->lost_fraction) {
        return DARAN_ERR_INVALID_VALUE;
    }
    for (; e < 0; e++) {
        if (m % 10u != 0u) {
            return DARAN_ERR_INVALID_VALUE;
        }
        m /= 10u;
    }
    if (n->negative) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    for (; e > 0; e--) {
        if (m > UINT64_MAX / 10u) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        m *= 10u;
    }
    *out = m;
    return DARAN_OK;
}

static daran_result_t read_f32(const char *p, size_t n, float *out)
{
    return handwritten_parse_f32(p, n, out);
}

static daran_result_t read_u64(const char *p, size_t n, uint64_t *out)
{
    hw_number_t number;
    daran_result_t result = read_number(p, n, &number);
    return result != DARAN_OK ? result : number_to_u64(&number, out);
}

static daran_result_t read_motor(const char *p, size_t n, unsigned *out)
{
    if (n == 1u && (unsigned)(p[0] - '0') <= 9u && (unsigned)(p[0] - '0') <= DARAN_MOTOR_ID_MAX) {
        /* nearly every line */
        *out = (unsigned)(p[0] - '0');
        return DARAN_OK;
    }
    uint64_t id;
    if (read_u64(p, n, &id) != DARAN_OK || id > DARAN_MOTOR_ID_MAX) {
        return DARAN_ERR_INVALID_MOTOR;
    }
    *out = (unsigned)id;
    return DARAN_OK;
}

/* A mode field: malformed or not an integer is an invalid value, an integer
 * whose bit is not in @p allowed an invalid mode. */
static daran_result_t read_mode(const char *p, size_t n, uint32_t allowed, uint32_t *out)
{
    uint64_t mode;
    daran_result_t result = read_u64(p, n, &mode);
    if (result == DARAN_ERR_INVALID_VALUE) {
        return result;
    }
    if (result != DARAN_OK || mode >= 32u || ((allowed >> mode) & 1u) == 0u) {
        return DARAN_ERR_INVALID_MODE;
    }
    *out = (uint32_t)mode;
    return DARAN_OK;
}

/* ---- replies, fixed point ---------------------------------------------- */

static void put(handwritten_t *h, const char *text, size_t n)
{
    for (size_t i = 0; i < n && h->reply_len < sizeof h->reply - 8u; i++) {
        h->reply[h->reply_len++] = text[i];
    }
}

static void put_cstr(handwritten_t *h, const char *text)
{
    while (*text != '\0' && h->reply_len < sizeof h->reply - 8u) {
        h->reply[h->reply_len++] = *text++;
    }
}

static void put_u64(handwritten_t *h, uint64_t v)
{
    char digits[20];
    unsigned n = 0;
    do {
        digits[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (n > 0u && h->reply_len < sizeof h->reply - 8u) {
        h->reply[h->reply_len++] = digits[--n];
    }
}

/* "%f" by hand: integer part, point, six decimals rounded from the float's
 * fraction. Beyond 2^63 a crude d.dddddde+NN. */
static void put_f32(handwritten_t *h, float v)
{
    if (v != v) {
        put(h, "nan", 3);
        return;
    }
    if (v < 0.0f) {
        put(h, "-", 1);
        v = -v;
    }
    if (v > 3.40282347e38f) {
        put(h, "inf", 3);
        return;
    }
    int exp10 = 0;
    if (v >= 9.2e18f) {
        while (v >= 10.0f) {
            v /= 10.0f;
            exp10++;
        }
    }
    uint64_t whole = (uint64_t)v;
    uint32_t micro = (uint32_t)((v - (float)whole) * 1e6f + 0.5f);
    if (micro >= 1000000u) {
        whole++;
        micro -= 1000000u;
    }
    put_u64(h, whole);
    char frac[7] = {'.', '0', '0', '0', '0', '0', '0'};
    for (int i = 6; i > 0; i--) {
        frac[i] = (char)('0' + micro % 10u);
        micro /= 10u;
    }
    put(h, frac, 7);
    if (exp10 != 0) {
        put(h, "e+", 2);
        put_u64(h, (uint64_t)exp10);
    }
}

static void reply_end(handwritten_t *h)
{
    if (h->reply_checksum) {
        uint8_t x = ' ';
        for (unsigned i = 0; i < h->reply_len; i++) {
            x ^= (uint8_t)h->reply[i];
        }
        h->reply[h->reply_len++] = ' ';
        h->reply[h->reply_len++] = '*';
        if (x >= 100u) {
            h->reply[h->reply_len++] = (char)('0' + x / 100u);
        }
        if (x >= 10u) {
            h->reply[h->reply_len++] = (char)('0' + x / 10u % 10u);
        }
        h->reply[h->reply_len++] = (char)('0' + x % 10u);
    }
    for (unsigned i = 0; i < sizeof LINE_END - 1u; i++) {
        h->reply[h->reply_len++] = LINE_END[i];
    }
    h->write(h->write_ctx, h->reply, h->reply_len);
    h->reply_len = 0;
}

static const char *const phrases[] = {
    "ok", "unknown command", "invalid command format", "invalid motor", "invalid value",
    "value out of range", "invalid mode", "invalid property", "read only property",
    "invalid checksum", "checksum mismatch", "line too long", "invalid character", "no preset",
    "trajectory infeasible", "estop active", "motor fault", "motor idle",
};

static daran_result_t reply_error(handwritten_t *h, daran_result_t result)
{
    unsigned index = (unsigned)result < sizeof phrases / sizeof phrases[0]
                         ? (unsigned)result
                         : (unsigned)DARAN_ERR_MOTOR_FAULT;
    h->reply_len = 0;
    put(h, "error: ", 7);
    put_cstr(h, phrases[index]);
    reply_end(h);
    return result;
}

/* ---- the drive ---------------------------------------------------------- */

static daran_result_t from_hal(daran_result_t result)
{
    return (unsigned)result < (unsigned)DARAN_ERR_BAD_ARGUMENT ? result : DARAN_ERR_MOTOR_FAULT;
}

static daran_result_t get(handwritten_t *h, daran_prop_t prop, daran_value_t *out)
{
    out->u64 = 0;
    return from_hal(h->hal->get(h->hal_ctx, prop, out));
}

static daran_result_t motion_allowed(handwritten_t *h)
{
    daran_value_t v;
    daran_result_t result = get(h, DARAN_PROP_AXIS_ERROR, &v);
    if (result != DARAN_OK) {
        return result;
    }
    if ((v.u32 & DARAN_FLAG_ESTOP) != 0u) {
        return DARAN_ERR_ESTOP_ACTIVE;
    }
    if (v.u32 != 0u) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    result = get(h, DARAN_PROP_CURRENT_STATE, &v);
    if (result != DARAN_OK) {
        return result;
    }
    return v.u32 == DARAN_STATE_CLOSED_LOOP ? DARAN_OK : DARAN_ERR_MOTOR_IDLE;
}

static daran_result_t go(handwritten_t *h, const daran_move_t *move)
{
    daran_result_t result = motion_allowed(h);
    if (result != DARAN_OK) {
        return result;
    }
    result = from_hal(h->hal->move(h->hal_ctx, move));
    if (result == DARAN_OK) {
        (void)h->hal->action(h->hal_ctx, DARAN_ACTION_FEED_WATCHDOG);
    }
    return result;
}

static int is_finite(float v)
{
    return v - v == 0.0f;
}

/* ---- commands ----------------------------------------------------------- */

enum command {
    CMD_T, CMD_Q, CMD_P, CMD_V, CMD_C, CMD_D,
    CMD_MS, CMD_MT, CMD_MQ, CMD_MP, CMD_MV, CMD_MC,
    CMD_R, CMD_W, CMD_SS, CMD_SE, CMD_SR, CMD_SC, CMD_SZ, CMD_ST,
    CMD_H, CMD_F, CMD_G, CMD_I, CMD_E, CMD_U,
    CMD_COUNT
};

#define READ 1u
#define PATH 2u
/* min fields << 4 | max fields, command word included; then flags */
static const uint8_t command_fields[CMD_COUNT] = {
    0x35, 0x35, 0x35, 0x35, 0x35, 0x77, 0x55, 0x33, 0x33, 0x33, 0x22, 0x22,
    0x23, 0x34, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22, 0x22,
};
static const uint8_t command_flags[CMD_COUNT] = {
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    READ | PATH, PATH, 0, 0, 0, 0, 0, 0, READ, READ, READ, READ, READ, 0,
};

#define KEY(a, b) ((unsigned)(a) | (unsigned)(b) << 8)

static int command_of(const char *word, size_t n)
{
    if (n > 2u) {
        return -1;
    }
    unsigned a = (unsigned char)word[0], b = n == 2u ? (unsigned char)word[1] : 0u;
    if (a - 'A' < 26u) {
        a += 32u;
    }
    if (b - 'A' < 26u) {
        b += 32u;
    }
    switch (KEY(a, b)) {
    case KEY('t', 0): return CMD_T;
    case KEY('f', 0): return CMD_F;
    case KEY('q', 0): return CMD_Q;
    case KEY('p', 0): return CMD_P;
    case KEY('v', 0): return CMD_V;
    case KEY('c', 0): return CMD_C;
    case KEY('d', 0): return CMD_D;
    case KEY('r', 0): return CMD_R;
    case KEY('w', 0): return CMD_W;
    case KEY('g', 0): return CMD_G;
    case KEY('i', 0): return CMD_I;
    case KEY('e', 0): return CMD_E;
    case KEY('u', 0): return CMD_U;
#if DARAN_ENABLE_HELP
    case KEY('h', 0): return CMD_H;
#endif
#if DARAN_ENABLE_MULTI_MOTOR
    case KEY('m', 's'): return CMD_MS;
    case KEY('m', 't'): return CMD_MT;
    case KEY('m', 'q'): return CMD_MQ;
    case KEY('m', 'p'): return CMD_MP;
    case KEY('m', 'v'): return CMD_MV;
    case KEY('m', 'c'): return CMD_MC;
#endif
    case KEY('s', 's'): return CMD_SS;
    case KEY('s', 'e'): return CMD_SE;
    case KEY('s', 'r'): return CMD_SR;
    case KEY('s', 'c'): return CMD_SC;
    case KEY('s', 'z'): return CMD_SZ;
    case KEY('s', 't'): return CMD_ST;
    default: return -1;
    }
}

/* The fields of a line: offsets into it. */
typedef struct line {
    const char *text;
    uint16_t start[FIELDS_MAX];
    uint16_t len[FIELDS_MAX];
    unsigned count; /* every field, also beyond FIELDS_MAX */
} line_t;

#define FIELD(l, i) ((l)->text + (l)->start[i]), ((l)->len[i])

static daran_result_t read_non_negative(const line_t *l, unsigned i, float *out)
{
    daran_result_t result = read_f32(FIELD(l, i), out);
    return result == DARAN_OK && !(*out >= 0.0f) ? DARAN_ERR_OUT_OF_RANGE : result;
}

#define MODES_VELOCITY ((1u << 1) | (1u << 2))
#define MODES_TORQUE ((1u << 1) | (1u << 2) | (1u << 6))

static daran_result_t command_t(handwritten_t *h, const line_t *l)
{
    daran_move_t m = {DARAN_MOVE_FILTERED_POSITION, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    float ignored, bw = 0.0f;
    daran_result_t result = read_f32(FIELD(l, 2), &m.pos_deg);
    if (result == DARAN_OK && l->count > 3u) {
        result = read_f32(FIELD(l, 3), &ignored);
    }
    if (result == DARAN_OK && l->count > 4u) {
        result = read_non_negative(l, 4, &bw);
        if (bw != 0.0f) { /* bandwidth 0: keep the current one */
            m.given = DARAN_GIVEN_RATE;
            m.rate = bw;
        }
    }
    return result != DARAN_OK ? result : go(h, &m);
}

static daran_result_t command_q(handwritten_t *h, const line_t *l)
{
    daran_move_t m = {DARAN_MOVE_TRAPEZOID, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_result_t result = read_f32(FIELD(l, 2), &m.pos_deg);
    if (result == DARAN_OK && l->count > 3u) {
        result = read_f32(FIELD(l, 3), &m.vel_rpm);
        if (result == DARAN_OK && !(m.vel_rpm > 0.0f)) {
            result = DARAN_ERR_OUT_OF_RANGE;
        }
        m.given = DARAN_GIVEN_VEL;
    }
    if (result == DARAN_OK && l->count > 4u) {
        float acc = 0.0f;
        result = read_non_negative(l, 4, &acc);
        m.given |= DARAN_GIVEN_RATE;
        if (acc == 0.0f) { /* a step to the target, no cruise */
            m.given = DARAN_GIVEN_RATE;
            m.vel_rpm = 0.0f;
        } else {
            m.rate = acc;
        }
    }
    return result != DARAN_OK ? result : go(h, &m);
}

static daran_result_t command_p(handwritten_t *h, const line_t *l)
{
    daran_move_t m = {DARAN_MOVE_PASSTHROUGH, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_result_t result = read_f32(FIELD(l, 2), &m.pos_deg);
    if (result == DARAN_OK && l->count > 3u) {
        result = read_f32(FIELD(l, 3), &m.vel_rpm);
    }
    if (result == DARAN_OK && l->count > 4u) {
        result = read_f32(FIELD(l, 4), &m.torque_nm);
    }
    return result != DARAN_OK ? result : go(h, &m);
}

/* v and c: mode 1 sets at once (v: param is the torque feed-forward), a
 * ramp mode ramps at param >= 0 (0 holds the setpoint). */
static daran_result_t velocity_or_torque(const float *value, uint32_t mode, int torque,
                                         daran_move_t *m)
{
    int ramp = torque ? mode != 1u : mode == 2u;
    if (torque) {
        m->kind = ramp ? DARAN_MOVE_TORQUE_RAMP : DARAN_MOVE_TORQUE;
        m->torque_nm = value[0];
    } else {
        m->kind = ramp ? DARAN_MOVE_VELOCITY_RAMP : DARAN_MOVE_VELOCITY;
        m->vel_rpm = value[0];
        if (!ramp) {
            m->torque_nm = value[1];
        }
    }
    if (ramp) {
        if (!(value[1] >= 0.0f)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        m->rate = value[1] == 0.0f ? 0.0f : value[1];
    }
    return DARAN_OK;
}

static daran_result_t command_v_c(handwritten_t *h, const line_t *l, int torque)
{
    daran_move_t m = {DARAN_MOVE_VELOCITY, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    float value[2] = {0.0f, 0.0f};
    uint32_t mode = 1;
    daran_result_t result = read_f32(FIELD(l, 2), &value[0]);
    if (result == DARAN_OK && l->count > 3u) {
        result = read_f32(FIELD(l, 3), &value[1]);
    }
    if (result == DARAN_OK && l->count > 4u) {
        result = read_mode(FIELD(l, 4), torque ? MODES_TORQUE : MODES_VELOCITY, &mode);
    }
    if (result == DARAN_OK) {
        result = velocity_or_torque(value, mode, torque, &m);
    }
    return result != DARAN_OK ? result : go(h, &m);
}

static daran_result_t command_d(handwritten_t *h, const line_t *l)
{
    daran_move_t m = {DARAN_MOVE_IMPEDANCE, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_result_t result = read_f32(FIELD(l, 2), &m.pos_deg);
    if (result == DARAN_OK) {
        result = read_f32(FIELD(l, 3), &m.vel_rpm);
    }
    if (result == DARAN_OK) {
        result = read_f32(FIELD(l, 4), &m.torque_nm);
    }
    if (result == DARAN_OK) {
        result = read_non_negative(l, 5, &m.kp);
    }
    if (result == DARAN_OK) {
        result = read_non_negative(l, 6, &m.kd);
    }
    return result != DARAN_OK ? result : go(h, &m);
}

#if DARAN_ENABLE_MULTI_MOTOR
static daran_result_t command_ms(handwritten_t *h, const line_t *l)
{
    float v[3];
    for (unsigned i = 0; i < 3u; i++) {
        daran_result_t result = read_f32(FIELD(l, 2u + i), &v[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    h->preset[0] = v[0];
    h->preset[1] = v[1];
    h->preset[2] = v[2];
    h->has_preset = 1;
    return DARAN_OK;
}

/* mq: the cruise velocity that makes the move last exactly the preset's
 * duration (trapezoid, or S-curve with traj_mode 2). */
static daran_result_t timed(handwritten_t *h, float d, float t, float a, daran_move_t *m)
{
    daran_value_t mode;
    daran_result_t result = get(h, DARAN_PROP_TRAJ_MODE, &mode);
    if (result != DARAN_OK && result != DARAN_ERR_INVALID_PROPERTY) {
        return result;
    }
    float ramps = result == DARAN_OK && mode.u32 == 2u ? 8.0f : 4.0f;
    m->given = DARAN_GIVEN_VEL | DARAN_GIVEN_RATE;
    if (d == 0.0f) {
        m->given = 0;
        m->vel_rpm = 0.0f;
        m->rate = 0.0f;
        return DARAN_OK;
    }
    if (t == 0.0f || a == 0.0f) {
        return DARAN_ERR_TRAJECTORY_INFEASIBLE;
    }
    float at = a * t;
    float disc = at * at - ramps * a * d;
    if (!is_finite(disc)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (disc >= 0.0f) {
        float v = 2.0f * a * d / (at + __builtin_sqrtf(disc));
        m->vel_rpm = v / 6.0f;
        m->rate = a / 6.0f;
        return DARAN_OK;
    }
    /* protocol.md 10.5: the time is kept, within the velocity limit unless
     * the duration is the least one pushed a hair short */
    m->vel_rpm = 2.0f * d / t / 6.0f;
    m->rate = ramps * d / (t * t) / 6.0f;
    if (-disc <= 1e-4f * at * at) {
        return DARAN_OK;
    }
    daran_value_t limit;
    result = get(h, DARAN_PROP_SHAFT_VEL_LIMIT, &limit);
    if (result == DARAN_ERR_INVALID_PROPERTY) {
        return DARAN_OK;
    }
    if (result == DARAN_OK && 2.0f * d / t > limit.f32 * 6.0f) {
        result = DARAN_ERR_TRAJECTORY_INFEASIBLE;
    }
    return result;
}

static daran_result_t command_start(handwritten_t *h, const line_t *l, int command,
                                    unsigned motor)
{
    uint32_t rel = 0;
    if (l->count == 3u) {
        daran_result_t result = read_mode(FIELD(l, 2), 3u, &rel);
        if (result != DARAN_OK) {
            return result;
        }
    }
    if (motor == 0u && !h->has_preset) {
        return DARAN_OK; /* a broadcast start: not for a drive without a preset */
    }
    daran_result_t result = motion_allowed(h);
    if (result != DARAN_OK) {
        return result;
    }
    if (!h->has_preset) {
        return DARAN_ERR_NO_PRESET;
    }
    const float *p = h->preset;
    daran_move_t m = {DARAN_MOVE_FILTERED_POSITION, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    uint32_t mode;
    switch (command) {
    case CMD_MT:
        if (!(p[2] >= 0.0f)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        m.pos_deg = p[0];
        if (p[2] != 0.0f) {
            m.given = DARAN_GIVEN_RATE;
            m.rate = p[2];
        }
        break;
    case CMD_MQ:
        if (!(p[1] >= 0.0f) || !(p[2] >= 0.0f)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        m.kind = DARAN_MOVE_TRAPEZOID;
        m.pos_deg = p[0];
        break;
    case CMD_MP:
        m.kind = DARAN_MOVE_PASSTHROUGH;
        m.pos_deg = p[0];
        m.vel_rpm = p[1];
        m.torque_nm = p[2];
        break;
    default: /* mv, mc: the mode is the preset's third value */
        mode = p[2] == 1.0f ? 1u : p[2] == 2.0f ? 2u : p[2] == 6.0f && command == CMD_MC ? 6u : 0u;
        if (mode == 0u) {
            return DARAN_ERR_INVALID_MODE;
        }
        result = velocity_or_torque(p, mode, command == CMD_MC, &m);
        if (result != DARAN_OK) {
            return result;
        }
        break;
    }
    if (command != CMD_MV && command != CMD_MC) {
        daran_value_t setpoint;
        result = get(h, DARAN_PROP_POS_SETPOINT, &setpoint);
        if (result != DARAN_OK) {
            return result;
        }
        if (rel) {
            m.pos_deg += setpoint.f32;
        }
        if (!is_finite(m.pos_deg)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        if (command == CMD_MQ) {
            float d = m.pos_deg - setpoint.f32;
            result = timed(h, d < 0.0f ? -d : d, p[1], p[2] * 6.0f, &m);
            if (result != DARAN_OK) {
                return result;
            }
        }
    }
    m.rate = m.rate == 0.0f ? 0.0f : m.rate;
    result = from_hal(h->hal->move(h->hal_ctx, &m));
    if (result == DARAN_OK) {
        (void)h->hal->action(h->hal_ctx, DARAN_ACTION_FEED_WATCHDOG);
        h->has_preset = 0;
    }
    return result;
}
#endif

static void put_value(handwritten_t *h, int type, daran_value_t v)
{
    switch (type) {
    case DARAN_TYPE_F32:
        put_f32(h, v.f32);
        break;
    case DARAN_TYPE_U64:
        put_u64(h, v.u64);
        break;
    case DARAN_TYPE_S32:
        if (v.s32 < 0) {
            put(h, "-", 1);
            put_u64(h, (uint64_t)(-(int64_t)v.s32));
        } else {
            put_u64(h, (uint64_t)v.s32);
        }
        break;
    default:
        put_u64(h, v.u32);
        break;
    }
}

static daran_result_t command_r(handwritten_t *h, daran_prop_t prop)
{
    daran_value_t v;
    daran_result_t result = get(h, prop, &v);
    if (result != DARAN_OK) {
        return result;
    }
    h->reply_len = 0;
    put_value(h, properties[prop].type, v);
    reply_end(h);
    return DARAN_OK;
}

static int integer_allowed(int range, int64_t v)
{
    switch (range) {
    case DARAN_RANGE_POSITIVE: return v > 0;
    case DARAN_RANGE_NON_NEGATIVE: return v >= 0;
    case DARAN_RANGE_NON_POSITIVE: return v <= 0;
    case DARAN_RANGE_BOOL:
    case DARAN_RANGE_CAN_PROTOCOL: return v == 0 || v == 1;
    case DARAN_RANGE_ZERO: return v == 0;
    case DARAN_RANGE_NODE_ID: return v >= 1 && v <= DARAN_MOTOR_ID_MAX;
    case DARAN_RANGE_UART_BAUD:
        return v == 9600 || v == 19200 || v == 38400 || v == 57600 || v == 115200;
    case DARAN_RANGE_CAN_BAUD: return v == 125000 || v == 250000 || v == 500000 || v == 1000000;
    case DARAN_RANGE_AXIS_STATE:
        return v == DARAN_STATE_IDLE || v == DARAN_STATE_CLOSED_LOOP;
    case DARAN_RANGE_CONTROL_MODE: return v >= 1 && v <= 3;
    case DARAN_RANGE_INPUT_MODE: return v >= 1 && v <= 9 && ((0x26Eu >> v) & 1u);
    case DARAN_RANGE_TRAJ_MODE: return v == 1 || v == 2;
    case DARAN_RANGE_DIRECTION: return v == -1 || v == 1;
    case DARAN_RANGE_MOTOR_TYPE: return v == 0 || v == 2 || v == 3;
    case DARAN_RANGE_POLE_PAIRS: return v >= 1 && v <= 128;
    case DARAN_RANGE_TELEMETRY: return v >= 0 && v <= 511;
    default: return 1;
    }
}

static daran_result_t command_w(handwritten_t *h, const line_t *l, daran_prop_t prop)
{
    const hw_property_t *row = &properties[prop];
    daran_value_t v;
    daran_result_t result;
    if (row->access != ACCESS_RW) {
        return DARAN_ERR_READ_ONLY;
    }
    v.u64 = 0;
    const char *text = l->text + l->start[2];
    size_t n = l->len[2];
    if (row->type == DARAN_TYPE_F32) {
        result = read_f32(text, n, &v.f32);
        if (result == DARAN_OK && ((row->range == DARAN_RANGE_POSITIVE && !(v.f32 > 0.0f)) ||
                                   (row->range == DARAN_RANGE_NON_NEGATIVE && !(v.f32 >= 0.0f)) ||
                                   (row->range == DARAN_RANGE_NON_POSITIVE && !(v.f32 <= 0.0f)))) {
            result = DARAN_ERR_OUT_OF_RANGE;
        }
    } else {
        int negative = 0;
        uint64_t magnitude;
        if (row->type == DARAN_TYPE_S32 && n > 1u && text[0] == '-' && text[1] != '+' &&
            text[1] != '-') {
            negative = 1;
            text++;
            n--;
        }
        result = read_u64(text, n, &magnitude);
        if (result == DARAN_OK && row->type == DARAN_TYPE_U64) {
            v.u64 = magnitude;
        } else if (result == DARAN_OK) {
            uint64_t limit = row->type == DARAN_TYPE_S32 ? (negative ? 0x80000000u : 0x7FFFFFFFu)
                                                          : 0xFFFFFFFFu;
            int64_t value = negative ? -(int64_t)magnitude : (int64_t)magnitude;
            if (magnitude > limit || !integer_allowed(row->range, value)) {
                result = DARAN_ERR_OUT_OF_RANGE;
            } else if (row->type == DARAN_TYPE_S32) {
                v.s32 = (int32_t)value;
            } else {
                v.u32 = (uint32_t)magnitude;
            }
        }
    }
    if (result != DARAN_OK) {
        return result;
    }
    if (prop == DARAN_PROP_REQUESTED_STATE && v.u32 == DARAN_STATE_CLOSED_LOOP) {
        result = motion_allowed(h);
        if (result != DARAN_OK && result != DARAN_ERR_MOTOR_IDLE) {
            return result;
        }
    }
    return from_hal(h->hal->set(h->hal_ctx, prop, v));
}

static daran_result_t reply_floats(handwritten_t *h, daran_prop_t a, daran_prop_t b)
{
    daran_value_t x, y;
    daran_result_t result = get(h, a, &x);
    if (result == DARAN_OK) {
        result = get(h, b, &y);
    }
    if (result != DARAN_OK) {
        return result;
    }
    h->reply_len = 0;
    put_f32(h, x.f32);
    put(h, " ", 1);
    put_f32(h, y.f32);
    reply_end(h);
    return DARAN_OK;
}

static daran_result_t command_i(handwritten_t *h)
{
    daran_value_t fw, hw, serial;
    daran_result_t result = get(h, DARAN_PROP_FW_VERSION, &fw);
    if (result == DARAN_OK) {
        result = get(h, DARAN_PROP_HW_VERSION, &hw);
    }
    if (result == DARAN_OK) {
        result = get(h, DARAN_PROP_SERIAL_NUMBER, &serial);
    }
    if (result != DARAN_OK) {
        return result;
    }
    h->reply_len = 0;
    put_u64(h, fw.u32);
    put(h, " ", 1);
    put_u64(h, hw.u32);
    put(h, " ", 1);
    put_u64(h, serial.u64);
    reply_end(h);
    return DARAN_OK;
}

static daran_result_t command_e(handwritten_t *h)
{
    static const daran_prop_t registers[7] = {
        DARAN_PROP_AXIS_ERROR,          DARAN_PROP_MOTOR_ERROR,
        DARAN_PROP_ENCODER_ERROR,       DARAN_PROP_CONTROLLER_ERROR,
        DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CAN_ERROR,
    };
    static const char *const names[7] = {"axis: ", "motor: ", "encoder: ", "controller: ",
                                         "fet_thermistor: ", "motor_thermistor: ", "can: "};
    uint32_t values[7];
    for (unsigned i = 0; i < 7u; i++) {
        daran_value_t v;
        daran_result_t result = get(h, registers[i], &v);
        if (result == DARAN_ERR_INVALID_PROPERTY) {
            v.u32 = 0;
        } else if (result != DARAN_OK) {
            return result;
        }
        values[i] = v.u32;
    }
    for (unsigned i = 0; i < 7u; i++) {
        h->reply_len = 0;
        put_cstr(h, names[i]);
        put_u64(h, values[i]);
        reply_end(h);
    }
    return DARAN_OK;
}

#if DARAN_ENABLE_HELP
static daran_result_t command_h(handwritten_t *h)
{
    static const char *const lines[] = {
        "t id pos [vel] [bw]", "q id pos [vel] [acc]", "p id pos [vel_ff] [torque_ff]",
        "v id vel [param] [mode]", "c id torque [param] [mode]", "d id pdes vdes tff kp kd",
#if DARAN_ENABLE_MULTI_MOTOR
        "ms id p1 p2 p3", "mt id rel", "mq id rel", "mp id rel", "mv id", "mc id",
#endif
        "r path [id]", "w path value [id]", "ss id", "se id", "sr id", "sc id", "sz id", "st id",
        "h id [properties [prefix]]", "f id", "g id", "i id", "e id", "u id",
    };
    for (unsigned i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        h->reply_len = 0;
        put_cstr(h, lines[i]);
        reply_end(h);
    }
    return DARAN_OK;
}
#endif

static daran_result_t action(handwritten_t *h, daran_action_t a)
{
    daran_result_t result = from_hal(h->hal->action(h->hal_ctx, a));
    if (result == DARAN_OK && a == DARAN_ACTION_REBOOT) {
        h->has_preset = 0;
    }
    return result;
}

/* Steps 3 to 7 of the check order: command, id, field count, property,
 * values, state. */
static daran_result_t dispatch(handwritten_t *h, const line_t *l)
{
    int command = command_of(l->text + l->start[0], l->len[0]);
    if (command < 0) {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }
    unsigned count = l->count;
    if (count < 2u) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    unsigned min = command_fields[command] >> 4, max = command_fields[command] & 15u;
    int count_ok = count >= min && count <= max;
    const char *id = l->text + l->start[1];
    size_t id_len = l->len[1];
    daran_prop_t prop = DARAN_PROP_COUNT;
    if (command_flags[command] & PATH) {
        const char *path = id;
        size_t n = id_len, dot = 4;
        int scope = SCOPE_SYSTEM;
        const char *name = path;
        size_t name_len = n;
        if (n >= 5u && path[0] == 'a' && path[1] == 'x' && path[2] == 'i' && path[3] == 's') {
            while (dot < n && path[dot] != '.') {
                dot++;
            }
            if (dot < n) {
                scope = SCOPE_AXIS;
                id = path + 4;
                id_len = dot - 4u;
                name = path + dot + 1u;
                name_len = n - dot - 1u;
                count_ok = count == min;
            }
        }
        if (scope == SCOPE_SYSTEM) {
            if (count == max) {
                id = l->text + l->start[count - 1u];
                id_len = l->len[count - 1u];
            } else if (count == min) {
                id = NULL;
            } else {
                return DARAN_ERR_INVALID_FORMAT;
            }
        }
        prop = handwritten_find_property(scope, name, name_len);
    }
    unsigned motor = 0;
    if (id != NULL && read_motor(id, id_len, &motor) != DARAN_OK) {
        return DARAN_ERR_INVALID_MOTOR;
    }
    daran_value_t own;
    daran_result_t result = get(h, DARAN_PROP_CAN_NODE_ID, &own);
    if (result != DARAN_OK) {
        return result;
    }
    if (motor != 0u && motor != own.u32) {
        return DARAN_OK; /* another drive's line */
    }
    if (!count_ok) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    switch (command) {
    case CMD_T: return command_t(h, l);
    case CMD_Q: return command_q(h, l);
    case CMD_P: return command_p(h, l);
    case CMD_V: return command_v_c(h, l, 0);
    case CMD_C: return command_v_c(h, l, 1);
    case CMD_D: return command_d(h, l);
#if DARAN_ENABLE_MULTI_MOTOR
    case CMD_MS: return command_ms(h, l);
    case CMD_MT:
    case CMD_MQ:
    case CMD_MP:
    case CMD_MV:
    case CMD_MC: return command_start(h, l, command, motor);
#endif
    case CMD_R:
        return prop == DARAN_PROP_COUNT ? DARAN_ERR_INVALID_PROPERTY : command_r(h, prop);
    case CMD_W:
        return prop == DARAN_PROP_COUNT ? DARAN_ERR_INVALID_PROPERTY : command_w(h, l, prop);
    case CMD_SS: return action(h, DARAN_ACTION_SAVE_CONFIG);
    case CMD_SE: return action(h, DARAN_ACTION_ERASE_CONFIG);
    case CMD_SR: return action(h, DARAN_ACTION_REBOOT);
    case CMD_SC: return action(h, DARAN_ACTION_CLEAR_ERRORS);
    case CMD_SZ: return action(h, DARAN_ACTION_SET_ZERO);
    case CMD_ST: return action(h, DARAN_ACTION_ESTOP);
    case CMD_U: return action(h, DARAN_ACTION_FEED_WATCHDOG);
#if DARAN_ENABLE_HELP
    case CMD_H: return command_h(h);
#endif
    case CMD_F: return reply_floats(h, DARAN_PROP_POS_ESTIMATE, DARAN_PROP_VEL_ESTIMATE);
    case CMD_G: return reply_floats(h, DARAN_PROP_VBUS_VOLTAGE, DARAN_PROP_IQ_MEASURED);
    case CMD_I: return command_i(h);
    case CMD_E: return command_e(h);
    default: return DARAN_ERR_UNKNOWN_COMMAND;
    }
}

void handwritten_init(handwritten_t *h, const daran_hal_t *hal, void *hal_ctx,
                      handwritten_write_fn write, void *write_ctx)
{
    h->hal = hal;
    h->hal_ctx = hal_ctx;
    h->write = write;
    h->write_ctx = write_ctx;
    h->reply_checksum = 0;
    h->has_preset = 0;
    h->reply_len = 0;
    h->rx_len = 0;
    h->rx_overflow = 0;
    if (!table_built) {
        build_table();
    }
}

static int allowed(uint8_t c)
{
    return (uint8_t)(c - 0x20u) < 0x5Fu || c == '\t' || c == '\r';
}

daran_result_t handwritten_process_line(handwritten_t *h, const char *text, size_t len)
{
    const uint8_t *s = (const uint8_t *)text;
    line_t l;
    size_t i = 0, star = len;
    uint8_t x = 0;
    l.text = text;
    l.count = 0;
    h->reply_checksum = 0;
    if (len > LINE_MAX_BYTES) {
        return reply_error(h, DARAN_ERR_LINE_TOO_LONG);
    }
    /* The line check: every byte once. Fields are noted as they pass. */
    while (i < len) {
        uint8_t c = s[i];
        if ((uint8_t)(c - 0x21u) < 0x5Eu && c != '*') {
            size_t first = i;
            do {
                x ^= s[i++];
            } while (i < len && (uint8_t)(s[i] - 0x21u) < 0x5Eu && s[i] != '*');
            if (l.count < FIELDS_MAX) {
                l.start[l.count] = (uint16_t)first;
                l.len[l.count] = (uint16_t)(i - first);
            }
            l.count++;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            x ^= c;
            i++;
        } else if (c == '*') {
            star = i;
            break;
        } else {
            return reply_error(h, DARAN_ERR_INVALID_CHARACTER);
        }
    }
    if (star < len) {
        for (size_t j = star + 1u; j < len; j++) {
            if (!allowed(s[j])) {
                return reply_error(h, DARAN_ERR_INVALID_CHARACTER);
            }
        }
        /* 1 to 3 digits, at most 255, then only blanks */
        unsigned value = 0, digits = 0;
        size_t j = star + 1u;
        while (j < len && (unsigned)(s[j] - '0') <= 9u && digits < 4u) {
            value = value * 10u + (s[j] - '0');
            digits++;
            j++;
        }
        while (j < len && (s[j] == ' ' || s[j] == '\t' || s[j] == '\r')) {
            j++;
        }
        if (digits == 0u || digits > 3u || value > 255u || j != len) {
            return reply_error(h, DARAN_ERR_INVALID_CHECKSUM);
        }
        h->reply_checksum = 1;
        if (value != x) {
            return reply_error(h, DARAN_ERR_CHECKSUM_MISMATCH);
        }
    }
    if (l.count == 0u) {
        return h->reply_checksum ? reply_error(h, DARAN_ERR_UNKNOWN_COMMAND) : DARAN_OK;
    }
    daran_result_t result = dispatch(h, &l);
    if (result != DARAN_OK) {
        (void)reply_error(h, result);
    }
    return result;
}

void handwritten_rx_write(handwritten_t *h, const char *data, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        char c = data[i];
        if (c != '\n') {
            if (h->rx_len < sizeof h->rx) {
                h->rx[h->rx_len++] = c;
            } else {
                h->rx_overflow = 1;
            }
            continue;
        }
        if (h->rx_overflow) {
            h->reply_checksum = 0;
            (void)reply_error(h, DARAN_ERR_LINE_TOO_LONG);
        } else {
            (void)handwritten_process_line(h, h->rx, h->rx_len);
        }
        h->rx_len = 0;
        h->rx_overflow = 0;
    }
}

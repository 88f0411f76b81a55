/* Unit tests of `r` and `w` over every property of daran_properties.h (read
 * formatting per type, write, read-only refusal, range edges on both sides,
 * the axisN. and trailing-id forms of D8/D9, paths one step away from each
 * real one), the s32 grammar (D34), the error registers (D33), plus the float
 * reply format of spec section 4. The rows come from the public X-macro list
 * itself. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mock_hal.h"
#include "property.h"

void setUp(void)
{
}

void tearDown(void)
{
}

enum { SCOPE_SYSTEM, SCOPE_AXIS };
enum { ACCESS_RO, ACCESS_RW };

typedef struct prop_row {
    daran_prop_t id;
    const char *path;
    int scope;
    daran_prop_type_t type;
    int access;
    daran_range_t range;
    const char *name;
} prop_row_t;

static const prop_row_t rows[] = {
#define ROW(id, path, scope, type, access, range, unit, can)                                         \
    {DARAN_PROP_##id, path, SCOPE_##scope, DARAN_TYPE_##type, ACCESS_##access, DARAN_RANGE_##range, \
     #id},
    DARAN_PROPERTY_LIST(ROW)
#undef ROW
};

#define N_ROWS (sizeof rows / sizeof rows[0])

/* "r"/"w" line for drive 1: axisN. prefix or trailing id as the scope says. */
static void line_for(char *buf, size_t size, const prop_row_t *p, const char *word,
                     const char *value, int id)
{
    char idtext[16] = "";
    if (id >= 0)
        snprintf(idtext, sizeof idtext, "%d", id);
    if (p->scope == SCOPE_AXIS)
        snprintf(buf, size, "%s axis%s.%s%s%s", word, id >= 0 ? idtext : "1", p->path,
                 value ? " " : "", value ? value : "");
    else
        snprintf(buf, size, "%s %s%s%s%s%s", word, p->path, value ? " " : "", value ? value : "",
                 id >= 0 ? " " : "", idtext);
}

static void test_the_property_list_has_every_spec_property(void)
{
    TEST_ASSERT_EQUAL_INT64(DARAN_PROP_COUNT, N_ROWS);
    /* spec 10.2: the vendor's 159 paths, serial_number, config.enable_watchdog,
     * config.watchdog_timeout and config_warnings (D32), and the two telemetry
     * settings (spec 11.2) */
    TEST_ASSERT_EQUAL_INT64(165, N_ROWS);
    for (size_t i = 0; i < N_ROWS; i++) {
        TEST_ASSERT_EQUAL_INT64((daran_prop_t)i, rows[i].id);
    }
}

static void test_every_path_is_unique_within_its_scope(void)
{
    for (size_t i = 0; i < N_ROWS; i++)
        for (size_t j = i + 1; j < N_ROWS; j++)
            if (rows[i].scope == rows[j].scope && strcmp(rows[i].path, rows[j].path) == 0) {
                TEST_FAIL_MESSAGE_F("\"%s\" twice", rows[i].path);
            }
}

/* Is @p path a row of @p scope? */
static bool is_real_path(int scope, const char *path)
{
    for (size_t i = 0; i < N_ROWS; i++)
        if (rows[i].scope == scope && strcmp(rows[i].path, path) == 0)
            return true;
    return false;
}

/* ---- read ---- */

static const char *store_sample(mock_t *m, const prop_row_t *p)
{
    switch (p->type) {
    case DARAN_TYPE_F32: m->props[p->id].f32 = -12.5f; return "-12.5";
    case DARAN_TYPE_U32:
        if (p->id == DARAN_PROP_CAN_NODE_ID)
            return "1";
        m->props[p->id].u32 = 4000000000u;
        return "4000000000";
    case DARAN_TYPE_S32: m->props[p->id].s32 = -123456; return "-123456";
    case DARAN_TYPE_U64: m->props[p->id].u64 = UINT64_MAX; return "18446744073709551615";
    case DARAN_TYPE_BOOL: m->props[p->id].u32 = 1; return "1";
    }
    return "";
}

static void read_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    const char *text = store_sample(m, p);
    char line[160], want[64];
    mock_reply_line(want, sizeof want, text, false);
    /* own id and the common id 0 */
    line_for(line, sizeof line, p, "r", NULL, 1);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    TEST_ASSERT_TRUE(m->n_gets >= 1);
    line_for(line, sizeof line, p, "r", NULL, 0);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    if (p->scope == SCOPE_SYSTEM) {
        line_for(line, sizeof line, p, "r", NULL, -1); /* omitted id = 0 */
        TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    }
    /* with a checksum */
    char cline[180];
    line_for(line, sizeof line, p, "r", NULL, 1);
    mock_reply_line(want, sizeof want, text, true);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, mock_with_checksum(cline, sizeof cline, line)));
    /* another drive's id: silent */
    line_for(line, sizeof line, p, "r", NULL, 2);
    ASSERT_SILENT(m, line);
    /* the other form's id is a format error (D9) */
    if (p->scope == SCOPE_AXIS) {
        snprintf(line, sizeof line, "r axis1.%s 1", p->path);
        ASSERT_ERROR(m, line, "invalid command format");
        snprintf(line, sizeof line, "r axis1.%s 1 1", p->path);
        ASSERT_ERROR(m, line, "invalid command format");
    } else {
        snprintf(line, sizeof line, "r %s 1 1", p->path);
        ASSERT_ERROR(m, line, "invalid command format");
    }
    /* a drive with the highest id: its own N in axisN. or the trailing id */
    m = mock_new_id(DARAN_MOTOR_ID_MAX);
    text = store_sample(m, p);
    char max_id[8];
    snprintf(max_id, sizeof max_id, "%d", DARAN_MOTOR_ID_MAX);
    if (p->id == DARAN_PROP_CAN_NODE_ID)
        text = max_id;
    mock_reply_line(want, sizeof want, text, false);
    line_for(line, sizeof line, p, "r", NULL, DARAN_MOTOR_ID_MAX);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    line_for(line, sizeof line, p, "r", NULL, 0);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    line_for(line, sizeof line, p, "r", NULL, 1);
    ASSERT_SILENT(m, line);
}

static void test_bools_read_as_0_and_1(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 0;
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.controller.trajectory_done"));
    m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 1;
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.controller.trajectory_done"));
}

static void test_integers_read_in_decimal(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_SERIAL_NUMBER].u64 = 0;
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r serial_number 1"));
    m->props[DARAN_PROP_SERIAL_NUMBER].u64 = 4294967296ull;
    TEST_ASSERT_EQUAL_STRING("4294967296\n", ASSERT_QUERY(m, "r serial_number"));
    m->props[DARAN_PROP_FW_VERSION].u32 = UINT32_MAX;
    TEST_ASSERT_EQUAL_STRING("4294967295\n", ASSERT_QUERY(m, "r fw_version 0"));
    m->props[DARAN_PROP_AXIS_ERROR].u32 = 0;
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.error"));
}

/* ---- float format (spec section 4) ---- */

typedef struct fmt_case {
    float value;
    const char *text;
} fmt_case_t;

static fmt_case_t fmt_cases[] = {
    {100.5f, "100.5"},       {0.02f, "0.02"},          {160.0f, "160"},
    {-3.0f, "-3"},           {1e-5f, "0.00001"},        {1.5e-7f, "1.5e-07"},
    {3e12f, "3.0e+12"},      {1e9f, "1.0e+09"},         {0.0f, "0"},
    {-0.0f, "-0"},           {0.1f, "0.1"},             {1e8f, "100000000"},
    {123456792.0f, "123456790"}, {1e-6f, "1.0e-06"},    {0.0001f, "0.0001"},
    {3.4028235e38f, "3.4028235e+38"}, {1.4e-45f, "1.0e-45"}, {16777216.0f, "16777216"},
    {1.17549435e-38f, "1.1754944e-38"}, {-2.5e-6f, "-2.5e-06"}, {24.0f, "24"},
    {0.3f, "0.3"},           {1.0f / 3.0f, "0.33333334"}, {999999999.0f, "1.0e+09"},
    {12345.678f, "12345.678"}, {-0.00001f, "-0.00001"},
};

static void fmt_case_run(const void *row_arg)
{
    const fmt_case_t *c = row_arg;
    mock_t *m = mock_new();
    m->props[DARAN_PROP_INPUT_POS].f32 = c->value;
    char want[64];
    mock_reply_line(want, sizeof want, c->text, false);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "r axis1.output_shaft.input_pos"));
}

static void test_non_finite_floats_read_as_nan_inf(void)
{
    mock_t *m = mock_new();
    m->props[DARAN_PROP_INPUT_POS].f32 = NAN;
    TEST_ASSERT_EQUAL_STRING("nan\n", ASSERT_QUERY(m, "r axis1.output_shaft.input_pos"));
    m->props[DARAN_PROP_INPUT_POS].f32 = INFINITY;
    TEST_ASSERT_EQUAL_STRING("inf\n", ASSERT_QUERY(m, "r axis1.output_shaft.input_pos"));
    m->props[DARAN_PROP_INPUT_POS].f32 = -INFINITY;
    TEST_ASSERT_EQUAL_STRING("-inf\n", ASSERT_QUERY(m, "r axis1.output_shaft.input_pos"));
}

/* Random float32 bit patterns read back through `r`: the reply must parse
 * back to the same bits, use the fewest significant digits that can, and
 * pick positional or scientific notation by the decimal exponent. */
static bool some_decimal_with_digits_round_trips(float x, int p)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.*e", p - 1, (double)x);
    if (strtof(buf, NULL) == x)
        return true;
    /* the nearest p-digit decimal may miss an asymmetric interval; try its neighbours */
    char *e = strchr(buf, 'e');
    int ex = atoi(e + 1);
    double mant = strtod(buf, NULL) / pow(10.0, ex);
    for (int d = -1; d <= 1; d += 2) {
        double cand = (mant + d * pow(10.0, -(p - 1))) * pow(10.0, ex);
        snprintf(buf, sizeof buf, "%.*e", p - 1, cand);
        if (strtof(buf, NULL) == x)
            return true;
    }
    return false;
}

static void check_format(const mock_t *m, float x, const char *text)
{
    float back = strtof(text, NULL);
    mock_check(memcmp(&back, &x, sizeof x) == 0, m, __FILE__, __LINE__,
               "\"%s\" does not read back as %a", text, (double)x);
    /* significant digits and decimal exponent of the text */
    const char *c = text;
    if (*c == '-')
        c++;
    char digits[64];
    size_t nd = 0;
    int point = -1, k;
    const char *e = strchr(c, 'e');
    const char *stop = e ? e : c + strlen(c);
    for (const char *q = c; q < stop; q++) {
        if (*q == '.')
            point = (int)nd;
        else
            digits[nd++] = *q;
    }
    if (point < 0)
        point = (int)nd;
    size_t lead = 0;
    while (lead < nd && digits[lead] == '0')
        lead++;
    size_t last = nd;
    while (last > lead && digits[last - 1] == '0')
        last--;
    int sig = (int)(last - lead);
    k = point - (int)lead - 1 + (e ? atoi(e + 1) : 0);
    bool shortest = sig <= 1 || !some_decimal_with_digits_round_trips(x, sig - 1);
    mock_check(shortest, m, __FILE__, __LINE__, "\"%s\" is not the shortest form of %a", text, (double)x);
    if (k >= -5 && k <= 8) {
        mock_check(e == NULL, m, __FILE__, __LINE__, "\"%s\": exponent %d wants positional", text, k);
    } else {
        mock_check(e != NULL && strchr(text, '.') != NULL && strchr(text, '.') < e &&
                       (e[1] == '+' || e[1] == '-') && strlen(e + 2) >= 2,
                   m, __FILE__, __LINE__, "\"%s\": exponent %d wants d.ddde+XX", text, k);
    }
}

static void test_random_floats_read_back_bit_exact_in_shortest_form(void)
{
    mock_t *m = mock_new();
    uint32_t seed = 987654321u;
    for (int i = 0; i < 6000; i++) {
        seed = seed * 1664525u + 1013904223u;
        uint32_t bits = seed;
        if (i % 3 == 0) /* many values near ordinary magnitudes */
            bits = (seed & 0x807FFFFFu) | ((uint32_t)(100 + (seed >> 23) % 56) << 23);
        float x;
        memcpy(&x, &bits, sizeof x);
        if (!isfinite(x))
            continue;
        m->props[DARAN_PROP_INPUT_POS].f32 = x;
        const char *got = ASSERT_QUERY(m, "r axis1.output_shaft.input_pos");
        char text[64];
        size_t n = strcspn(got, "\n");
        memcpy(text, got, n);
        text[n] = '\0';
        check_format(m, x, text);
    }
}

/* ---- write ---- */

/* A value inside the row's range, written as the reply reads it back. */
static const char *write_sample(const prop_row_t *p)
{
    switch (p->range) {
    case DARAN_RANGE_NONE:
        if (p->type == DARAN_TYPE_U32)
            return "4000000000";
        return p->type == DARAN_TYPE_S32 ? "-123456" : "-12.5";
    case DARAN_RANGE_NON_NEGATIVE: return "2.5";
    case DARAN_RANGE_POSITIVE: return p->type == DARAN_TYPE_S32 ? "8192" : "2.5";
    case DARAN_RANGE_NON_POSITIVE: return "-2.5";
    case DARAN_RANGE_BOOL: return "1";
    case DARAN_RANGE_ZERO: return "0";
    case DARAN_RANGE_NODE_ID: return "7";
    case DARAN_RANGE_UART_BAUD: return "9600";
    case DARAN_RANGE_CAN_BAUD: return "250000";
    case DARAN_RANGE_CAN_PROTOCOL: return "1";
    case DARAN_RANGE_AXIS_STATE: return "1";
    case DARAN_RANGE_CONTROL_MODE: return "2";
    case DARAN_RANGE_INPUT_MODE: return "5";
    case DARAN_RANGE_TRAJ_MODE: return "2";
    case DARAN_RANGE_DIRECTION: return "-1";
    case DARAN_RANGE_MOTOR_TYPE: return "2";
    case DARAN_RANGE_POLE_PAIRS: return "21";
    case DARAN_RANGE_TELEMETRY: return "259";
    case DARAN_RANGE_COUNT: break;
    }
    TEST_FAIL_MESSAGE_F("%s: no write sample for range %d", p->name, (int)p->range);
    return "";
}

static void check_value(const mock_t *m, const prop_row_t *p, daran_value_t v, const char *text,
                        int line)
{
    if (p->type == DARAN_TYPE_F32) {
        float want = strtof(text, NULL);
        mock_check(memcmp(&v.f32, &want, sizeof want) == 0, m, __FILE__, line,
                   "%s: expected %a, got %a", p->name, (double)want, (double)v.f32);
    } else if (p->type == DARAN_TYPE_S32) {
        long want = strtol(text, NULL, 10);
        mock_check(v.s32 == want, m, __FILE__, line, "%s: expected %ld, got %ld", p->name, want,
                   (long)v.s32);
    } else {
        unsigned long want = strtoul(text, NULL, 10);
        mock_check(v.u32 == want, m, __FILE__, line, "%s: expected %lu, got %lu", p->name, want,
                   (unsigned long)v.u32);
    }
}

static void write_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    char line[160];
    const char *text = write_sample(p);
    /* own id first: a node-id write moves the drive, id 0 still reaches it */
    static const int ids[] = {1, 0, -1};
    for (size_t k = 0; k < 3; k++) {
        int id = ids[k];
        if (id == -1 && p->scope == SCOPE_AXIS)
            continue;
        line_for(line, sizeof line, p, "w", text, id);
        daran_value_t v = ASSERT_SET(m, line, p->id);
        check_value(m, p, v, text, __LINE__);
    }
    /* the value reads back */
    line_for(line, sizeof line, p, "r", NULL, 0);
    char want[64];
    mock_reply_line(want, sizeof want, text, false);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    /* another drive's id: silent, nothing written */
    line_for(line, sizeof line, p, "w", text, 2);
    ASSERT_SILENT(m, line);
    if (p->range == DARAN_RANGE_NODE_ID)
        return; /* the drive now answers to another id */
    /* malformed and non-finite values */
    line_for(line, sizeof line, p, "w", "abc", 1);
    ASSERT_ERROR(m, line, "invalid value");
    line_for(line, sizeof line, p, "w", "nan", 1);
    ASSERT_ERROR(m, line, "invalid value");
    line_for(line, sizeof line, p, "w", "1e39", 1);
    ASSERT_ERROR(m, line, "value out of range");
    /* D9 field counts */
    if (p->scope == SCOPE_AXIS) {
        snprintf(line, sizeof line, "w axis1.%s %s 1", p->path, text);
        ASSERT_ERROR(m, line, "invalid command format");
    } else {
        snprintf(line, sizeof line, "w %s %s 1 1", p->path, text);
        ASSERT_ERROR(m, line, "invalid command format");
    }
    line_for(line, sizeof line, p, "w", NULL, 1);
    if (p->scope == SCOPE_AXIS) {
        ASSERT_ERROR(m, line, "invalid command format");
    }
}

static void read_only_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    const char *text = store_sample(m, p);
    char line[160];
    line_for(line, sizeof line, p, "w", "1", 1);
    ASSERT_ERROR(m, line, "read only property");
    line_for(line, sizeof line, p, "w", "0", 0);
    ASSERT_ERROR(m, line, "read only property");
    /* the property is checked before the value */
    line_for(line, sizeof line, p, "w", "abc", 1);
    ASSERT_ERROR(m, line, "read only property");
    /* a value of its own type and a checksummed line are refused the same way */
    line_for(line, sizeof line, p, "w", text, 1);
    ASSERT_ERROR(m, line, "read only property");
    char cline[180], want[64];
    mock_send_line(m, mock_with_checksum(cline, sizeof cline, line));
    ASSERT_REPLY(m, mock_reply_line(want, sizeof want, "error: read only property", true));
    ASSERT_NO_EFFECT(m);
    /* and the value it held reads back unchanged */
    line_for(line, sizeof line, p, "r", NULL, 1);
    mock_reply_line(want, sizeof want, text, false);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
}

/* ---- range edges ---- */

typedef struct edge {
    const char *text;
    bool ok;
} edge_t;

static const edge_t edges_positive[] = {
    {"0", false}, {"-0", false}, {"-1", false}, {"-1e-45", false}, {"1e-45", true},
    {"2.5", true}, {"3.4028235e38", true}, {NULL, false}};
static const edge_t edges_non_negative[] = {
    {"0", true}, {"-1e-45", false}, {"-1", false}, {"1e-45", true}, {"2.5", true}, {NULL, false}};
static const edge_t edges_none[] = {
    {"-3.4028235e38", true}, {"3.4028235e38", true}, {"0", true}, {"-1e-45", true}, {NULL, false}};
static const edge_t edges_bool[] = {{"0", true}, {"1", true}, {"2", false}, {"-1", false},
                                    {"4294967297", false}, {NULL, false}};
static const edge_t edges_node_id[] = {{"1", true}, {"63", true}, {"0", false}, {"64", false},
                                       {"-1", false}, {NULL, false}};
static const edge_t edges_uart[] = {
    {"9600", true}, {"19200", true}, {"38400", true}, {"57600", true}, {"115200", true},
    {"4800", false}, {"0", false}, {"115201", false}, {"230400", false}, {"9601", false},
    {NULL, false}};
static const edge_t edges_can[] = {
    {"125000", true}, {"250000", true}, {"500000", true}, {"1000000", true}, {"100000", false},
    {"0", false}, {"2000000", false}, {"125001", false}, {NULL, false}};
static const edge_t edges_state[] = {{"1", true}, {"8", true}, {"0", false}, {"2", false},
                                     {"9", false}, {"3", false}, {NULL, false}};
/* the ranges of the vendor's whole table (spec 10.2, D32-D34) */
static const edge_t edges_non_positive[] = {
    {"0", true}, {"-0", true}, {"-1e-45", true}, {"-3.4028235e38", true}, {"1e-45", false},
    {"1", false}, {"3.4028235e38", false}, {NULL, false}};
static const edge_t edges_u32_any[] = {
    {"0", true}, {"4294967295", true}, {"1.0", true}, {"4294967296", false}, {"-1", false},
    {NULL, false}};
static const edge_t edges_zero[] = {
    {"0", true}, {"-0", true}, {"0.0", true}, {"1", false}, {"2", false},
    {"4294967295", false}, {"4294967296", false}, {"-1", false}, {NULL, false}};
static const edge_t edges_can_protocol[] = {{"0", true}, {"1", true}, {"2", false},
                                            {"-1", false}, {"4294967295", false}, {NULL, false}};
static const edge_t edges_control_mode[] = {{"1", true}, {"2", true}, {"3", true}, {"0", false},
                                            {"4", false}, {"-1", false}, {NULL, false}};
static const edge_t edges_input_mode[] = {
    {"1", true},  {"2", true},  {"3", true},  {"5", true},  {"6", true},
    {"9", true},  {"0", false}, {"4", false}, {"7", false}, {"8", false},
    {"10", false}, {"-1", false}, {NULL, false}};
static const edge_t edges_traj_mode[] = {{"1", true}, {"2", true}, {"0", false}, {"3", false},
                                         {"-1", false}, {NULL, false}};
static const edge_t edges_motor_type[] = {{"0", true}, {"2", true}, {"3", true}, {"1", false},
                                          {"4", false}, {"-1", false}, {NULL, false}};
static const edge_t edges_s32_any[] = {
    {"-2147483648", true}, {"2147483647", true}, {"0", true}, {"-1", true},
    {"2147483648", false}, {"-2147483649", false}, {"4294967295", false}, {NULL, false}};
static const edge_t edges_s32_positive[] = {
    {"1", true}, {"2147483647", true}, {"0", false}, {"-0", false}, {"-1", false},
    {"2147483648", false}, {"-2147483648", false}, {NULL, false}};
static const edge_t edges_direction[] = {{"-1", true}, {"1", true}, {"0", false}, {"2", false},
                                         {"-2", false}, {"4294967295", false}, {NULL, false}};
static const edge_t edges_pole_pairs[] = {{"1", true}, {"128", true}, {"0", false},
                                          {"129", false}, {"-1", false}, {NULL, false}};
/* every field set fits a reply of the default DARAN_REPLY_MAX */
static const edge_t edges_telemetry[] = {{"0", true}, {"511", true}, {"512", false},
                                         {"-1", false}, {NULL, false}};

static const edge_t *edges_for(const prop_row_t *p)
{
    switch (p->range) {
    case DARAN_RANGE_NONE:
        if (p->type == DARAN_TYPE_U32)
            return edges_u32_any;
        return p->type == DARAN_TYPE_S32 ? edges_s32_any : edges_none;
    case DARAN_RANGE_NON_NEGATIVE: return edges_non_negative;
    case DARAN_RANGE_POSITIVE: return p->type == DARAN_TYPE_S32 ? edges_s32_positive : edges_positive;
    case DARAN_RANGE_NON_POSITIVE: return edges_non_positive;
    case DARAN_RANGE_BOOL: return edges_bool;
    case DARAN_RANGE_ZERO: return edges_zero;
    case DARAN_RANGE_NODE_ID: return edges_node_id;
    case DARAN_RANGE_UART_BAUD: return edges_uart;
    case DARAN_RANGE_CAN_BAUD: return edges_can;
    case DARAN_RANGE_CAN_PROTOCOL: return edges_can_protocol;
    case DARAN_RANGE_AXIS_STATE: return edges_state;
    case DARAN_RANGE_CONTROL_MODE: return edges_control_mode;
    case DARAN_RANGE_INPUT_MODE: return edges_input_mode;
    case DARAN_RANGE_TRAJ_MODE: return edges_traj_mode;
    case DARAN_RANGE_DIRECTION: return edges_direction;
    case DARAN_RANGE_MOTOR_TYPE: return edges_motor_type;
    case DARAN_RANGE_POLE_PAIRS: return edges_pole_pairs;
    case DARAN_RANGE_TELEMETRY: return edges_telemetry;
    case DARAN_RANGE_COUNT: break;
    }
    TEST_FAIL_MESSAGE_F("%s: no edges for range %d", p->name, (int)p->range);
    return edges_none;
}

/* Float ranges belong to f32 rows, integer ranges to integer rows: a row that
 * mixed them would be checked by rules that cannot hold. */
static void test_every_row_has_a_range_of_its_type(void)
{
    for (size_t i = 0; i < N_ROWS; i++) {
        const prop_row_t *p = &rows[i];
        bool float_range = p->range == DARAN_RANGE_NONE || p->range == DARAN_RANGE_NON_NEGATIVE ||
                           p->range == DARAN_RANGE_POSITIVE || p->range == DARAN_RANGE_NON_POSITIVE;
        if (p->type == DARAN_TYPE_F32 && !float_range) {
            TEST_FAIL_MESSAGE_F("%s: f32 with an integer range %d", p->name, (int)p->range);
        }
        if (p->type == DARAN_TYPE_BOOL && p->range != DARAN_RANGE_BOOL) {
            TEST_FAIL_MESSAGE_F("%s: bool without the 0|1 range", p->name);
        }
        if (p->type == DARAN_TYPE_U64 && p->access != ACCESS_RO) {
            TEST_FAIL_MESSAGE_F("%s: a writable u64 has no range rule", p->name);
        }
    }
}

static void range_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    char line[160];
    for (const edge_t *e = edges_for(p); e->text; e++) {
        /* id 0 keeps addressing this drive even after a node-id write */
        line_for(line, sizeof line, p, "w", e->text, 0);
        if (e->ok) {
            daran_value_t v = ASSERT_SET(m, line, p->id);
            check_value(m, p, v, e->text, __LINE__);
        } else {
            ASSERT_ERROR(m, line, "value out of range");
        }
    }
}

static void test_non_negative_accepts_negative_zero(void)
{
    /* -0.0 >= 0 holds in IEEE arithmetic: "-0" is not below zero */
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis1.controller.config.pos_gain -0", DARAN_PROP_POS_GAIN);
    TEST_ASSERT_TRUE(v.f32 == 0.0f);
}

/* ---- paths ---- */

static void test_unknown_paths_are_invalid_properties(void)
{
    mock_t *m = mock_new();
    static const char *const lines[] = {
        "r nope", "r nope 1", "r axis1.nope", "r axis1.", "r axis1.output_shaft",
        "r axis1.output_shaft.", "r axis1.output_shaft.input_pos.x", "r axis1.vbus_voltage",
        "r config.can_node_id 1", "r axis1.config.uart_baudrate", "r axis5", "r axis",
        "r vbus_voltag 1", "r vbus_voltagee 1", "r .vbus_voltage 1", "w axis1.nope 1",
        "w nope 1", "w nope 1 1", "r a 1", "r zzzz 1", "r AAAA 1", "r ~ 1",
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        ASSERT_ERROR(m, lines[i], "invalid property");
    }
}

static void test_a_path_for_another_drive_is_silent_whatever_it_names(void)
{
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "r axis2.nope");
    ASSERT_SILENT(m, "w axis2.nope abc");
    ASSERT_SILENT(m, "w axis63.output_shaft.input_pos 1 2 3");
    ASSERT_SILENT(m, "r nope 2");
}

static void test_temperature_and_circular_limits_are_not_cross_checked(void)
{
    mock_t *m = mock_new();
    /* D15: a lower limit above the upper one is accepted as written */
    (void)ASSERT_SET(m, "w axis1.fet_thermistor.config.temp_limit_upper 50", DARAN_PROP_FET_TEMP_LIMIT_UPPER);
    (void)ASSERT_SET(m, "w axis1.fet_thermistor.config.temp_limit_lower 90", DARAN_PROP_FET_TEMP_LIMIT_LOWER);
    (void)ASSERT_SET(m, "w axis1.motor_thermistor.config.temp_limit_lower -300", DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER);
    (void)ASSERT_SET(m, "w axis1.output_shaft.circular_setpoint_min 180", DARAN_PROP_CIRCULAR_SETPOINT_MIN);
    (void)ASSERT_SET(m, "w axis1.output_shaft.circular_setpoint_max -180", DARAN_PROP_CIRCULAR_SETPOINT_MAX);
}

static void test_setpoint_write_reaches_the_hal_once(void)
{
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis1.output_shaft.pos_setpoint 150", DARAN_PROP_POS_SETPOINT);
    TEST_ASSERT_TRUE(v.f32 == 150.0f);
    TEST_ASSERT_EQUAL_STRING("150\n", ASSERT_QUERY(m, "r axis1.output_shaft.pos_setpoint"));
}

static void test_node_id_write_changes_the_address(void)
{
    mock_t *m = mock_new();
    (void)ASSERT_SET(m, "w axis0.config.can_node_id 5", DARAN_PROP_CAN_NODE_ID);
    ASSERT_SILENT(m, "f 1");
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 5"));
    TEST_ASSERT_EQUAL_STRING("5\n", ASSERT_QUERY(m, "r axis5.config.can_node_id"));
    ASSERT_SILENT(m, "r axis1.config.can_node_id");
    (void)ASSERT_SET(m, "w axis5.config.can_node_id 1", DARAN_PROP_CAN_NODE_ID);
    TEST_ASSERT_EQUAL_STRING("0 0\n", ASSERT_QUERY(m, "f 1"));
}

/* ---- paths one step away from a real one ---- */

/* `r` and `w` of a path that is not a row answer invalid property, in the
 * row's own form (axisN. or trailing id), before the value is looked at. */
static void assert_not_a_path(mock_t *m, int scope, const char *variant)
{
    if (is_real_path(scope, variant) || variant[0] == '\0' || strpbrk(variant, " \t*") != NULL)
        return;
    char line[200];
    if (scope == SCOPE_AXIS) {
        snprintf(line, sizeof line, "r axis1.%s", variant);
        ASSERT_ERROR(m, line, "invalid property");
        snprintf(line, sizeof line, "w axis1.%s 0", variant);
        ASSERT_ERROR(m, line, "invalid property");
        snprintf(line, sizeof line, "w axis0.%s abc", variant);
        ASSERT_ERROR(m, line, "invalid property");
    } else {
        snprintf(line, sizeof line, "r %s 1", variant);
        ASSERT_ERROR(m, line, "invalid property");
        snprintf(line, sizeof line, "r %s", variant);
        ASSERT_ERROR(m, line, "invalid property");
        snprintf(line, sizeof line, "w %s 0 1", variant);
        ASSERT_ERROR(m, line, "invalid property");
    }
}

static void near_path_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    char v[160];
    size_t n = strlen(p->path);
    /* a prefix, one character more, the last / first / middle character changed */
    snprintf(v, sizeof v, "%.*s", (int)(n - 1), p->path);
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%sx", p->path);
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%s", p->path);
    v[n - 1] = v[n - 1] == 'x' ? 'y' : 'x';
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%s", p->path);
    v[0] = (char)(v[0] ^ 0x20); /* paths are case-sensitive */
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%s", p->path);
    v[n / 2] = v[n / 2] == '.' ? '_' : (v[n / 2] == 'q' ? 'r' : 'q');
    assert_not_a_path(m, p->scope, v);
    /* one character left out in the middle, two swapped */
    snprintf(v, sizeof v, "%.*s%s", (int)(n / 2), p->path, p->path + n / 2 + 1);
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%s", p->path);
    char t = v[n - 1];
    v[n - 1] = v[n - 2];
    v[n - 2] = t;
    assert_not_a_path(m, p->scope, v);
    /* an extra segment, a segment left out, a leading or doubled dot */
    snprintf(v, sizeof v, "%s.x", p->path);
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, "%s.", p->path);
    assert_not_a_path(m, p->scope, v);
    snprintf(v, sizeof v, ".%s", p->path);
    assert_not_a_path(m, p->scope, v);
    const char *dot = strrchr(p->path, '.');
    if (dot != NULL) {
        snprintf(v, sizeof v, "%.*s", (int)(dot - p->path), p->path);
        assert_not_a_path(m, p->scope, v);
        snprintf(v, sizeof v, "%s", dot + 1);
        assert_not_a_path(m, p->scope, v);
        snprintf(v, sizeof v, "%.*s.%s", (int)(dot - p->path), p->path, dot);
        assert_not_a_path(m, p->scope, v);
    }
    /* the other scope's form: an axis path with a trailing id, a system path behind axisN. */
    assert_not_a_path(m, p->scope == SCOPE_AXIS ? SCOPE_SYSTEM : SCOPE_AXIS, p->path);
    /* the axis prefix written into the path again */
    if (p->scope == SCOPE_AXIS) {
        snprintf(v, sizeof v, "axis1.%s", p->path);
        assert_not_a_path(m, SCOPE_AXIS, v);
    }
}

/* Lookup hashes a name onto the one row it can be, then compares that row's
 * segments in full. Names that hash onto a row while only extending it by a
 * segment, or spelling its dots as other characters, must still be refused:
 * many variants per row make sure some land on the row they imitate. */
static bool refused_as_invalid_property(mock_t *m, int scope, const char *variant)
{
    char line[200];
    int n = scope == SCOPE_AXIS ? snprintf(line, sizeof line, "r axis1.%s", variant)
                                : snprintf(line, sizeof line, "r %s 1", variant);
    mock_clear(m);
    daran_result_t r = daran_process_line(&m->drive, line, (size_t)n);
    return r == DARAN_ERR_INVALID_PROPERTY && m->n_calls == 0 &&
           strcmp(m->out, "error: invalid property\n") == 0;
}

static void test_names_that_hash_onto_a_row_are_compared_in_full(void)
{
    mock_t *m = mock_new();
    /* the separators a dot may be mistaken for: printable, not blank, '.' or '*' */
    char seps[96];
    size_t n_seps = 0;
    for (int c = 0x21; c < 0x7F; c++)
        if (c != '.' && c != '*')
            seps[n_seps++] = (char)c;
    for (size_t i = 0; i < N_ROWS; i++) {
        const prop_row_t *p = &rows[i];
        char v[160];
        for (unsigned k = 0; k < 1024; k++) {
            snprintf(v, sizeof v, "%s.%u", p->path, k);
            mock_check(refused_as_invalid_property(m, p->scope, v), m, __FILE__, __LINE__,
                       "\"%s\" must be an invalid property", v);
        }
        if (strchr(p->path, '.') == NULL)
            continue;
        for (unsigned k = 0; k < 512; k++) {
            snprintf(v, sizeof v, "%s", p->path);
            unsigned digits = k;
            for (char *c = v; *c; c++) {
                if (*c == '.') {
                    *c = seps[digits % n_seps];
                    digits /= (unsigned)n_seps;
                }
            }
            if (digits != 0 || is_real_path(p->scope, v))
                continue; /* every combination of this path's dots is done */
            mock_check(refused_as_invalid_property(m, p->scope, v), m, __FILE__, __LINE__,
                       "\"%s\" must be an invalid property", v);
        }
    }
}

/* The perfect hash is built by tools/gen_property_index.py (Python) and
 * walked by daran_find_property() (C), both from DARAN_HASH_PRIME: they
 * agree only if each row's path, hashed in C, lands on the row Python put
 * in that slot. */
static void test_c_and_python_hash_every_path_alike(void)
{
    for (size_t i = 0; i < N_ROWS; i++) {
        daran_prop_t found = DARAN_PROP_COUNT;
        daran_scope_t scope = rows[i].scope == SCOPE_AXIS ? DARAN_SCOPE_AXIS : DARAN_SCOPE_SYSTEM;
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK,
                                      daran_find_property(scope, rows[i].path,
                                                          strlen(rows[i].path), &found),
                                      rows[i].path);
        TEST_ASSERT_EQUAL_INT_MESSAGE(rows[i].id, found, rows[i].path);
    }
}

/* ---- s32 (D34) ---- */

static void test_s32_direction_minus_1_is_written_and_read_back_with_its_sign(void)
{
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis1.motor.config.direction -1", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(-1, v.s32);
    TEST_ASSERT_EQUAL_STRING("-1\n", ASSERT_QUERY(m, "r axis1.motor.config.direction"));
    v = ASSERT_SET(m, "w axis1.motor.config.direction 1", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(1, v.s32);
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.motor.config.direction"));
}

static void test_s32_direction_0_and_2_are_out_of_range_with_no_effect(void)
{
    mock_t *m = mock_new();
    ASSERT_ERROR(m, "w axis1.motor.config.direction 0", "value out of range");
    ASSERT_ERROR(m, "w axis1.motor.config.direction 2", "value out of range");
    ASSERT_ERROR(m, "w axis1.motor.config.direction -0", "value out of range");
    ASSERT_ERROR(m, "w axis1.motor.config.direction -2", "value out of range");
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.motor.config.direction"));
}

static void test_s32_integral_float_minus_1_point_0_is_accepted_as_minus_1(void)
{
    mock_t *m = mock_new();
    daran_value_t v = ASSERT_SET(m, "w axis1.motor.config.direction -1.0", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(-1, v.s32);
    v = ASSERT_SET(m, "w axis1.motor.config.direction -10e-1", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(-1, v.s32);
    v = ASSERT_SET(m, "w axis1.motor.config.direction -1.000000", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(-1, v.s32);
    v = ASSERT_SET(m, "w axis1.motor.config.direction +1", DARAN_PROP_MOTOR_DIRECTION);
    TEST_ASSERT_EQUAL_INT64(1, v.s32);
    v = ASSERT_SET(m, "w axis1.config.extra_setting.stored_turns_counts -0", DARAN_PROP_STORED_TURNS_COUNTS);
    TEST_ASSERT_EQUAL_INT64(0, v.s32);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, "r axis1.config.extra_setting.stored_turns_counts"));
}

static void test_s32_non_integers_and_doubled_signs_are_invalid_values(void)
{
    mock_t *m = mock_new();
    static const char *const bad[] = {"-1.5", "--1", "-+1", "+-1", "-", "- 1", "1-", "-x",
                                      "-1e", "-nan", "-inf", "-0x1", "-.5", "0.5"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char line[96];
        snprintf(line, sizeof line, "w axis1.motor.config.direction %s", bad[i]);
        if (strchr(bad[i], ' ') != NULL) {
            ASSERT_ERROR(m, line, "invalid command format");
        }
        else {
            ASSERT_ERROR(m, line, "invalid value");
        }
        snprintf(line, sizeof line, "w axis1.config.extra_setting.stored_turns_counts %s", bad[i]);
        if (strchr(bad[i], ' ') == NULL) {
            ASSERT_ERROR(m, line, "invalid value");
        }
    }
}

static void test_s32_beyond_32_bits_is_out_of_range(void)
{
    mock_t *m = mock_new();
    static const char *const far[] = {"2147483648", "-2147483649", "4294967295", "4294967296",
                                      "-4294967296", "18446744073709551615",
                                      "-18446744073709551616", "1e39", "-1e39", "2.147483648e9"};
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++) {
        char line[96];
        snprintf(line, sizeof line, "w axis1.config.extra_setting.stored_turns_counts %s", far[i]);
        ASSERT_ERROR(m, line, "value out of range");
        snprintf(line, sizeof line, "w axis1.motor.config.direction %s", far[i]);
        ASSERT_ERROR(m, line, "value out of range");
    }
    /* the two ends themselves are values */
    daran_value_t v = ASSERT_SET(m, "w axis1.config.extra_setting.stored_turns_counts -2147483648",
                                 DARAN_PROP_STORED_TURNS_COUNTS);
    TEST_ASSERT_TRUE(v.s32 == INT32_MIN);
    TEST_ASSERT_EQUAL_STRING("-2147483648\n", ASSERT_QUERY(m, "r axis1.config.extra_setting.stored_turns_counts"));
    v = ASSERT_SET(m, "w axis1.config.extra_setting.stored_turns_counts 2147483647",
                   DARAN_PROP_STORED_TURNS_COUNTS);
    TEST_ASSERT_TRUE(v.s32 == INT32_MAX);
    TEST_ASSERT_EQUAL_STRING("2147483647\n", ASSERT_QUERY(m, "r axis1.config.extra_setting.stored_turns_counts"));
}

static void test_s32_reads_are_decimal_with_a_minus_when_negative(void)
{
    mock_t *m = mock_new();
    static const struct { int32_t value; const char *text; } cases[] = {
        {0, "0"}, {1, "1"}, {-1, "-1"}, {INT32_MAX, "2147483647"}, {INT32_MIN, "-2147483648"},
        {-16384, "-16384"}, {1000000, "1000000"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char want[32];
        mock_reply_line(want, sizeof want, cases[i].text, false);
        m->props[DARAN_PROP_ENCODER_POS_ABS].s32 = cases[i].value;
        TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "r axis1.encoder.pos_abs"));
        m->props[DARAN_PROP_ENCODER_TURN_ABS].s32 = cases[i].value;
        TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, "r axis0.encoder.turn_abs"));
        char line[48], cline[64];
        mock_reply_line(want, sizeof want, cases[i].text, true);
        snprintf(line, sizeof line, "r axis1.encoder.pos_abs");
        TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, mock_with_checksum(cline, sizeof cline, line)));
    }
}

static void test_a_u32_takes_no_sign(void)
{
    mock_t *m = mock_new();
    /* the s32 sign rule is s32's alone: "-1" is below a u32's range (D7) */
    ASSERT_ERROR(m, "w can.config.heartbeat_ms -1 1", "value out of range");
    ASSERT_ERROR(m, "w can.config.heartbeat_ms --1 1", "invalid value");
    daran_value_t v = ASSERT_SET(m, "w can.config.heartbeat_ms -0 1", DARAN_PROP_CAN_HEARTBEAT_MS);
    TEST_ASSERT_EQUAL_INT64(0, v.u32);
    v = ASSERT_SET(m, "w can.config.heartbeat_ms 4294967295 1", DARAN_PROP_CAN_HEARTBEAT_MS);
    TEST_ASSERT_EQUAL_INT64(UINT32_MAX, v.u32);
}

/* ---- error registers (D33): writable with 0 only ---- */

static void error_register_case(const void *row_arg)
{
    const prop_row_t *p = row_arg;
    mock_t *m = mock_new();
    m->props[p->id].u32 = 0x4000u;
    char line[160], want[32];
    mock_reply_line(want, sizeof want, "16384", false);
    static const char *const refused[] = {"1", "16384", "4294967295", "-1", "4294967296", "1e39"};
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        line_for(line, sizeof line, p, "w", refused[i], 1);
        ASSERT_ERROR(m, line, "value out of range");
        line_for(line, sizeof line, p, "w", refused[i], 0);
        ASSERT_ERROR(m, line, "value out of range");
    }
    line_for(line, sizeof line, p, "w", "0.5", 1);
    ASSERT_ERROR(m, line, "invalid value");
    line_for(line, sizeof line, p, "w", "x", 1);
    ASSERT_ERROR(m, line, "invalid value");
    /* nothing was cleared */
    line_for(line, sizeof line, p, "r", NULL, 1);
    TEST_ASSERT_EQUAL_STRING(want, ASSERT_QUERY(m, line));
    /* 0 reaches the HAL as 0, once, and the register reads 0 */
    line_for(line, sizeof line, p, "w", "0", 1);
    daran_value_t v = ASSERT_SET(m, line, p->id);
    TEST_ASSERT_EQUAL_INT64(0, v.u32);
    line_for(line, sizeof line, p, "r", NULL, 1);
    TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, line));
}

static void test_the_error_registers_are_exactly_the_zero_range_rows(void)
{
    static const daran_prop_t registers[] = {
        DARAN_PROP_AXIS_ERROR, DARAN_PROP_MOTOR_ERROR, DARAN_PROP_ENCODER_ERROR,
        DARAN_PROP_CONTROLLER_ERROR, DARAN_PROP_FET_THERMISTOR_ERROR,
        DARAN_PROP_MOTOR_THERMISTOR_ERROR, DARAN_PROP_CAN_ERROR, DARAN_PROP_CONFIG_WARNINGS,
    };
    size_t zero_rows = 0;
    for (size_t i = 0; i < N_ROWS; i++)
        zero_rows += rows[i].range == DARAN_RANGE_ZERO;
    TEST_ASSERT_EQUAL_INT64(sizeof registers / sizeof registers[0], zero_rows);
    for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
        const prop_row_t *p = &rows[registers[i]];
        TEST_ASSERT_EQUAL_INT64(DARAN_RANGE_ZERO, p->range);
        TEST_ASSERT_EQUAL_INT64(DARAN_TYPE_U32, p->type);
        TEST_ASSERT_EQUAL_INT64(ACCESS_RW, p->access);
    }
}

/* `e` stores its line names as text (commands_query.c): each must be its
 * register's path from the table, without ".error" ("axis" for "error"). */
static void test_e_names_each_register_by_its_path(void)
{
    static const daran_prop_t registers[] = {
        DARAN_PROP_AXIS_ERROR, DARAN_PROP_MOTOR_ERROR, DARAN_PROP_ENCODER_ERROR,
        DARAN_PROP_CONTROLLER_ERROR, DARAN_PROP_FET_THERMISTOR_ERROR,
        DARAN_PROP_MOTOR_THERMISTOR_ERROR, DARAN_PROP_CAN_ERROR,
    };
    char want[512] = "";
    for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
        const char *path = rows[registers[i]].path;
        size_t len = strlen(path) - strlen(".error");
        TEST_ASSERT_EQUAL_STRING(".error", strcmp(path, "error") == 0 ? ".error" : path + len);
        char line[80];
        if (strcmp(path, "error") == 0)
            snprintf(line, sizeof line, "axis: 0\n");
        else
            snprintf(line, sizeof line, "%.*s: 0\n", (int)len, path);
        strcat(want, line);
    }
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_process_line(&m->drive, "e 1", 3));
    TEST_ASSERT_EQUAL_STRING(want, m->out);
}

/* ---- rates that may be 0 (spec 10.1: "the corresponding properties") ---- */

static void test_rate_properties_accept_0_and_refuse_negatives(void)
{
    mock_t *m = mock_new();
    static const char *const paths[] = {
        "controller.config.input_filter_bandwidth", "output_shaft.vel_ramp_rate",
        "output_shaft.torque_ramp_rate", "output_shaft.trap_traj_accel_limit",
        "output_shaft.trap_traj_decel_limit", "trap_traj.config.accel_limit",
        "trap_traj.config.decel_limit", "controller.config.vel_ramp_rate",
        "controller.config.torque_ramp_rate",
    };
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        char line[128];
        snprintf(line, sizeof line, "w axis1.%s 0", paths[i]);
        mock_send_line(m, line);
        ASSERT_REPLY(m, "");
        mock_check(m->n_calls == 1 && m->calls[0].kind == MOCK_CALL_SET &&
                       m->calls[0].value.f32 == 0.0f,
                   m, __FILE__, __LINE__, "0 must reach the HAL");
        snprintf(line, sizeof line, "r axis1.%s", paths[i]);
        TEST_ASSERT_EQUAL_STRING("0\n", ASSERT_QUERY(m, line));
        snprintf(line, sizeof line, "w axis1.%s -1e-45", paths[i]);
        ASSERT_ERROR(m, line, "value out of range");
        snprintf(line, sizeof line, "w axis1.%s -1", paths[i]);
        ASSERT_ERROR(m, line, "value out of range");
    }
}

static void test_the_mock_traj_mode_defaults_to_the_trapezoid(void)
{
    mock_t *m = mock_new();
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.trap_traj.config.traj_mode"));
    (void)ASSERT_SET(m, "w axis1.trap_traj.config.traj_mode 2", DARAN_PROP_TRAJ_MODE);
    TEST_ASSERT_EQUAL_STRING("2\n", ASSERT_QUERY(m, "r axis1.trap_traj.config.traj_mode"));
    m = mock_new();
    TEST_ASSERT_EQUAL_STRING("1\n", ASSERT_QUERY(m, "r axis1.trap_traj.config.traj_mode"));
}

int main(void)
{
    static mock_suite_t s;
    UNITY_BEGIN();
#define ADD(fn) mock_suite_add_test(&s, fn)
    ADD(test_the_property_list_has_every_spec_property);
    ADD(test_every_path_is_unique_within_its_scope);
    ADD(test_every_row_has_a_range_of_its_type);
    for (size_t i = 0; i < N_ROWS; i++) {
        const prop_row_t *p = &rows[i];
        void *st = (void *)(uintptr_t)p;
        mock_suite_add(&s, read_case, st, "test_%s_reads_in_its_type_format", p->path);
        if (p->access == ACCESS_RW) {
            mock_suite_add(&s, write_case, st, "test_%s_writes_through_the_hal", p->path);
            mock_suite_add(&s, range_case, st, "test_%s_write_range_edges", p->path);
        } else {
            mock_suite_add(&s, read_only_case, st, "test_%s_refuses_a_write", p->path);
        }
        if (p->range == DARAN_RANGE_ZERO)
            mock_suite_add(&s, error_register_case, st, "test_%s_is_cleared_by_0_and_refuses_1",
                           p->path);
        mock_suite_add(&s, near_path_case, st, "test_paths_near_%s_are_invalid_properties",
                       p->path);
    }
    ADD(test_bools_read_as_0_and_1);
    ADD(test_integers_read_in_decimal);
    for (size_t i = 0; i < sizeof fmt_cases / sizeof fmt_cases[0]; i++)
        mock_suite_add(&s, fmt_case_run, &fmt_cases[i], "test_float_%a_reads_as_\"%s\"",
                       (double)fmt_cases[i].value, fmt_cases[i].text);
    ADD(test_non_finite_floats_read_as_nan_inf);
    ADD(test_random_floats_read_back_bit_exact_in_shortest_form);
    ADD(test_non_negative_accepts_negative_zero);
    ADD(test_unknown_paths_are_invalid_properties);
    ADD(test_names_that_hash_onto_a_row_are_compared_in_full);
    ADD(test_c_and_python_hash_every_path_alike);
    ADD(test_a_path_for_another_drive_is_silent_whatever_it_names);
    ADD(test_temperature_and_circular_limits_are_not_cross_checked);
    ADD(test_setpoint_write_reaches_the_hal_once);
    ADD(test_node_id_write_changes_the_address);
    ADD(test_s32_direction_minus_1_is_written_and_read_back_with_its_sign);
    ADD(test_s32_direction_0_and_2_are_out_of_range_with_no_effect);
    ADD(test_s32_integral_float_minus_1_point_0_is_accepted_as_minus_1);
    ADD(test_s32_non_integers_and_doubled_signs_are_invalid_values);
    ADD(test_s32_beyond_32_bits_is_out_of_range);
    ADD(test_s32_reads_are_decimal_with_a_minus_when_negative);
    ADD(test_a_u32_takes_no_sign);
    ADD(test_the_error_registers_are_exactly_the_zero_range_rows);
    ADD(test_e_names_each_register_by_its_path);
    ADD(test_rate_properties_accept_0_and_refuse_negatives);
    ADD(test_the_mock_traj_mode_defaults_to_the_trapezoid);
    mock_suite_run(&s);
    return UNITY_END();
}

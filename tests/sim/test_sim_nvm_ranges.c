/* A stored config is loaded only when every value in it is one `w` would
 * have accepted: an image with a valid CRC but values out of the core's
 * ranges (load_inertia -5, vel_gain -1000, can_node_id 200: the attack that
 * sent a shaft to -774312 deg) boots on defaults with the nvm_corrupt
 * warning. The rule is checked as an equivalence, property by property and
 * value by value: the load takes a value exactly when a real `w` line to a
 * real simulated drive takes it. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "daran_ascii.h"
#include "daran_port.h"
#include "sim_drive.h"
#include "sim_nvm.h"

void setUp(void)
{
}

void tearDown(void)
{
}

static const struct {
    const char *path;
    bool axis;
    daran_prop_type_t type;
} rows[] = {
#define ROW_(id, path, scope, type, access, range, unit, can) \
    {path, DARAN_SCOPE_IS_AXIS_##scope, DARAN_TYPE_##type},
#define DARAN_SCOPE_IS_AXIS_AXIS true
#define DARAN_SCOPE_IS_AXIS_SYSTEM false
    DARAN_PROPERTY_LIST(ROW_)
#undef ROW_
};

static void discard(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
}

static const daran_hal_t discard_port = {DARAN_SIM_HAL_FUNCTIONS, .write = discard};

static size_t value_text(daran_prop_t p, daran_value_t v, char *out, size_t size)
{
    switch (rows[p].type) {
    case DARAN_TYPE_F32:
        return daran_format_float(v.f32, out, size);
    case DARAN_TYPE_S32:
        if (v.s32 < 0) {
            out[0] = '-';
            return 1u + daran_format_uint((uint64_t)(-(int64_t)v.s32), out + 1, size - 1u);
        }
        return daran_format_uint((uint64_t)v.s32, out, size);
    default:
        return daran_format_uint(v.u32, out, size);
    }
}

/* Does `w` take value @p v for property @p p on a fresh simulated drive 1? */
static bool w_accepts(daran_prop_t p, daran_value_t v)
{
    static daran_sim_drive_t sim;
    static daran_drive_t core;
    char line[200];
    size_t n = 0u;
    daran_sim_drive_init(&sim, 0u, 1000u);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&core, &discard_port, &sim));
    memcpy(line, "w ", 2u);
    n = 2u;
    if (rows[p].axis) {
        memcpy(line + n, "axis1.", 6u);
        n += 6u;
    }
    memcpy(line + n, rows[p].path, strlen(rows[p].path));
    n += strlen(rows[p].path);
    line[n++] = ' ';
    n += value_text(p, v, line + n, sizeof line - n);
    if (!rows[p].axis) {
        memcpy(line + n, " 1", 2u);
        n += 2u;
    }
    return daran_process_line(&core, line, n) == DARAN_OK;
}

/* Does a stored image holding value @p v for property @p p load? */
static bool load_accepts(daran_prop_t p, daran_value_t v)
{
    static daran_sim_drive_t d;
    daran_sim_drive_init(&d, 0u, 1000u);
    d.model.cfg[p] = v; /* past `w`: as a tampered or foreign image would hold it */
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_drive_power_on(&d);
    if (d.nvm_status == DARAN_SIM_NVM_LOADED) {
        TEST_ASSERT_EQUAL_UINT32(0u, d.model.config_warnings);
        TEST_ASSERT_EQUAL_UINT64(v.u64, d.model.cfg[p].u64);
        return true;
    }
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_NVM_DAMAGED, d.nvm_status);
    TEST_ASSERT_EQUAL_UINT32(DARAN_WARNING_NVM_CORRUPT, d.model.config_warnings);
    return false;
}

static void test_the_attack_image_boots_on_defaults_with_the_warning(void)
{
    static daran_sim_drive_t d;
    daran_sim_drive_init(&d, 0u, 1000u);
    d.model.cfg[DARAN_PROP_LOAD_INERTIA].f32 = -5.0f;
    d.model.cfg[DARAN_PROP_VEL_GAIN].f32 = -1000.0f;
    d.model.cfg[DARAN_PROP_CAN_NODE_ID].u32 = 200u;
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_NVM_DAMAGED, d.nvm_status);
    TEST_ASSERT_EQUAL_UINT32(DARAN_WARNING_NVM_CORRUPT, d.model.config_warnings);
    TEST_ASSERT_EQUAL_UINT32(0u, d.model.error);
    TEST_ASSERT_EQUAL_UINT32(1u, daran_sim_drive_id(&d));
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_LOAD_INERTIA].f32 == 0.0f);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_VEL_GAIN].f32 == 0.16f);
    {
        /* and it moves as a drive on defaults: t 1 10 settles at 10 deg */
        static daran_drive_t core;
        uint32_t k;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&core, &discard_port, &d));
        TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_process_line(&core, "t 1 10", 6u));
        for (k = 0; k < 2000u; k++) {
            daran_sim_model_tick(&d.model);
        }
        TEST_ASSERT_FLOAT_WITHIN(0.2f, 10.0f, daran_sim_model_pos_deg(&d.model));
        TEST_ASSERT_FLOAT_WITHIN(1.0f, 0.0f, d.model.vel_rpm);
    }
}

static void test_the_defaults_and_a_saved_w_config_load(void)
{
    static daran_sim_drive_t d;
    daran_sim_drive_init(&d, 0u, 1000u);
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_NVM_LOADED, d.nvm_status);
    TEST_ASSERT_EQUAL_UINT32(0u, d.model.config_warnings);
}

/* Every configuration property, values around and outside its range: the
 * load agrees with `w` on each. */
static void test_a_stored_value_loads_exactly_when_w_takes_it(void)
{
    static const float floats[] = {-1000.0f, -5.0f, -1.0f, -1e-30f, -0.0f, 0.0f, 1e-30f,
                                   0.5f, 1.0f, 200.0f, 1e30f};
    static const uint32_t uints[] = {0u, 1u, 2u, 3u, 4u, 5u, 8u, 9u, 10u, 63u, 64u, 127u, 128u,
                                     129u, 200u, 255u, 511u, 512u, 9600u, 115200u, 125000u,
                                     1000000u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu};
    static const int32_t sints[] = {INT32_MIN, -129, -2, -1, 0, 1, 2, 7, 128, 129,
                                    16384, INT32_MAX};
    uint32_t checked = 0u;
    uint32_t refused = 0u;
    int p;
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        size_t i;
        size_t n;
        if (!daran_sim_is_config_prop((daran_prop_t)p)) {
            continue;
        }
        n = rows[p].type == DARAN_TYPE_F32 ? sizeof floats / sizeof floats[0]
            : rows[p].type == DARAN_TYPE_S32 ? sizeof sints / sizeof sints[0]
                                             : sizeof uints / sizeof uints[0];
        for (i = 0; i < n; i++) {
            daran_value_t v;
            bool by_w;
            bool by_load;
            char text[24];
            v.u64 = 0u;
            if (rows[p].type == DARAN_TYPE_F32) {
                v.f32 = floats[i];
            } else if (rows[p].type == DARAN_TYPE_S32) {
                v.s32 = sints[i];
            } else {
                v.u32 = uints[i];
            }
            by_w = w_accepts((daran_prop_t)p, v);
            by_load = load_accepts((daran_prop_t)p, v);
            if (by_w != by_load) {
                text[value_text((daran_prop_t)p, v, text, sizeof text - 1u)] = '\0';
                FAIL_F("%s = %s: w %s it, the load %s it", rows[p].path, text,
                       by_w ? "takes" : "refuses", by_load ? "takes" : "refuses");
            }
            checked++;
            refused += by_w ? 0u : 1u;
        }
    }
    NOTE("%u stored values checked against w, %u of them out of range", checked, refused);
    TEST_ASSERT_TRUE(refused > 100u);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_attack_image_boots_on_defaults_with_the_warning);
    RUN_TEST(test_the_defaults_and_a_saved_w_config_load);
    RUN_TEST(test_a_stored_value_loads_exactly_when_w_takes_it);
    return UNITY_END();
}

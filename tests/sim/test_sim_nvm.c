/* Non-volatile memory of the simulated drive: save/load, erase, corruption
 * falling back to defaults with a warning (axis0.config_warnings, never an
 * error), the whole property table round trip, and a power cut at every byte
 * offset of a save or an erase never losing both configs nor loading
 * garbage. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_drive.h"
#include "sim_nvm.h"

/* Blank RAM storage and a model with the default configuration, fresh for
 * every test (setUp()). */
static daran_sim_ram_storage_t ram;
static daran_sim_storage_t st;
static daran_sim_model_t m;

void setUp(void)
{
    memset(&ram, 0, sizeof ram);
    memset(&st, 0, sizeof st);
    daran_sim_ram_storage_init(&ram, &st);
    daran_sim_model_init(&m, 1000u);
}

void tearDown(void)
{
}

/* The UPPER-CASE helpers are macros so that a failure points at the test's
 * line. */
static void save_with_gain_at(int line, float gain)
{
    m.cfg[DARAN_PROP_POS_GAIN].f32 = gain;
    UNITY_TEST_ASSERT(daran_sim_nvm_save(&st, &m), line, "the save failed");
}
/* Save the model with pos_gain @p gain; the save must succeed. */
#define SAVE_WITH_GAIN(gain) save_with_gain_at(__LINE__, (gain))

static float loaded_gain_at(int line, daran_sim_nvm_status_t expect)
{
    daran_sim_model_t fresh;
    daran_sim_model_init(&fresh, 1000u);
    UNITY_TEST_ASSERT_EQUAL_INT64(expect, daran_sim_nvm_load(&st, &fresh), line,
                                  "the load's status");
    return fresh.cfg[DARAN_PROP_POS_GAIN].f32;
}
/* Boot a fresh model from the storage; the load must end in @p expect;
 * the pos_gain it booted with. */
#define LOADED_GAIN(expect) loaded_gain_at(__LINE__, (expect))

static void test_crc32_is_the_ieee_one(void)
{
    TEST_ASSERT_EQUAL_INT64(0xCBF43926u, daran_sim_crc32((const uint8_t *)"123456789", 9u, 0u));
}

static void test_blank_memory_boots_with_defaults_and_no_flag(void)
{
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_BLANK) == 20.0f);
}

static void test_saved_config_and_zero_offset_load_back(void)
{
    daran_sim_model_t fresh;
    m.cfg[DARAN_PROP_CAN_NODE_ID].u32 = 7u;
    m.cfg[DARAN_PROP_LOAD_INERTIA].f32 = 0.0125f;
    m.cfg[DARAN_PROP_ENABLE_WATCHDOG].u32 = 1u;
    m.zero_offset_deg = -12.5f;
    SAVE_WITH_GAIN(25.0f);
    daran_sim_model_init(&fresh, 1000u);
    TEST_ASSERT_EQUAL_INT64(DARAN_SIM_NVM_LOADED, daran_sim_nvm_load(&st, &fresh));
    TEST_ASSERT_TRUE(fresh.cfg[DARAN_PROP_POS_GAIN].f32 == 25.0f);
    TEST_ASSERT_EQUAL_INT64(7u, fresh.cfg[DARAN_PROP_CAN_NODE_ID].u32);
    TEST_ASSERT_TRUE(fresh.cfg[DARAN_PROP_LOAD_INERTIA].f32 == 0.0125f);
    TEST_ASSERT_EQUAL_INT64(1u, fresh.cfg[DARAN_PROP_ENABLE_WATCHDOG].u32);
    TEST_ASSERT_TRUE(fresh.zero_offset_deg == -12.5f);
    /* the newest of several saves wins, whichever slot it is in */
    SAVE_WITH_GAIN(26.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 26.0f);
    SAVE_WITH_GAIN(27.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 27.0f);
}

static void test_erase_brings_defaults_back_at_next_boot(void)
{
    SAVE_WITH_GAIN(30.0f);
    SAVE_WITH_GAIN(31.0f);
    TEST_ASSERT_TRUE(daran_sim_nvm_erase(&st));
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_BLANK) == 20.0f);
}

/* Cut the power after k bytes of a save, for every k: the next boot loads
 * the old config (k < size) or the new one (k = size), never defaults,
 * never a damaged image. Run from blank, one and two earlier saves so both
 * slots are written over. */
static void test_power_cut_at_every_byte_of_a_save_keeps_old_or_new(void)
{
    daran_sim_ram_storage_t before;
    uint32_t size = daran_sim_nvm_save_size();
    int history;
    for (history = 0; history < 3; history++) {
        uint32_t k;
        float old_gain = history == 0 ? 20.0f : 10.0f + (float)history;
        daran_sim_ram_storage_init(&ram, &st);
        if (history >= 1) {
            SAVE_WITH_GAIN(11.0f);
        }
        if (history >= 2) {
            SAVE_WITH_GAIN(12.0f);
        }
        before = ram;
        for (k = 0; k <= size; k++) {
            ram = before;
            ram.power_cut = true;
            ram.cut_after = k;
            m.cfg[DARAN_PROP_POS_GAIN].f32 = 99.0f;
            TEST_ASSERT_EQUAL_INT64(k == size, daran_sim_nvm_save(&st, &m));
            ram.power_cut = false;
            if (k < size) {
                TEST_ASSERT_TRUE(LOADED_GAIN(history == 0 ? DARAN_SIM_NVM_BLANK
                                                          : DARAN_SIM_NVM_LOADED) == old_gain);
            } else {
                TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 99.0f);
            }
        }
    }
    NOTE("power cut checked at each of the %u bytes of a save, 3 histories", size);
}

/* Same for `se`: the stored config stays or is gone; nothing damaged. */
static void test_power_cut_during_erase_never_leaves_damage(void)
{
    daran_sim_ram_storage_t before;
    uint32_t k;
    SAVE_WITH_GAIN(11.0f);
    SAVE_WITH_GAIN(12.0f);
    before = ram;
    for (k = 0; k <= 8u; k++) {
        daran_sim_model_t fresh;
        daran_sim_nvm_status_t s;
        ram = before;
        ram.power_cut = true;
        ram.cut_after = k;
        TEST_ASSERT_EQUAL_INT64(k == 8u, daran_sim_nvm_erase(&st));
        ram.power_cut = false;
        daran_sim_model_init(&fresh, 1000u);
        s = daran_sim_nvm_load(&st, &fresh);
        TEST_ASSERT_NOT_EQUAL(DARAN_SIM_NVM_DAMAGED, s);
        if (s == DARAN_SIM_NVM_LOADED) {
            TEST_ASSERT_TRUE(fresh.cfg[DARAN_PROP_POS_GAIN].f32 == 12.0f);
        }
        /* the newest image goes only once its own magic starts to change */
        TEST_ASSERT_EQUAL_INT64(k <= 4u ? DARAN_SIM_NVM_LOADED : DARAN_SIM_NVM_BLANK, s);
    }
}

static void test_corrupted_memory_boots_defaults_with_a_warning_flag(void)
{
    SAVE_WITH_GAIN(33.0f);
    TEST_ASSERT_TRUE(daran_sim_nvm_corrupt(&st));
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    /* one new save repairs it */
    SAVE_WITH_GAIN(34.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 34.0f);
    SAVE_WITH_GAIN(35.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 35.0f);
    /* corrupting blank memory damages both slots; one save repairs that too */
    daran_sim_ram_storage_init(&ram, &st);
    TEST_ASSERT_TRUE(daran_sim_nvm_corrupt(&st));
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    SAVE_WITH_GAIN(36.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_LOADED) == 36.0f);
}

static void test_a_flipped_byte_anywhere_in_an_image_is_found(void)
{
    uint32_t off;
    daran_sim_ram_storage_t before;
    SAVE_WITH_GAIN(40.0f);
    before = ram;
    for (off = 4u; off < daran_sim_nvm_save_size() - 4u; off++) {
        ram = before;
        ram.bytes[off] ^= 0x01u;
        TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    }
}

/* At drive level: the flag is a warning, motion still works. */
static void test_drive_with_corrupt_memory_moves_and_reports_the_flag(void)
{
    static daran_sim_drive_t d;
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    int k;
    daran_sim_drive_init(&d, 1u, 1000u);
    TEST_ASSERT_EQUAL_INT64(2u, daran_sim_drive_id(&d));
    d.model.cfg[DARAN_PROP_CAN_NODE_ID].u32 = 9u;
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT64(9u, daran_sim_drive_id(&d));
    TEST_ASSERT_TRUE(daran_sim_drive_corrupt_nvm(&d));
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT64(2u, daran_sim_drive_id(&d)); /* default id again */
    TEST_ASSERT_EQUAL_INT64(0u, d.model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_WARNING_NVM_CORRUPT, d.model.config_warnings);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, d.model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&d.model, &mv));
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&d.model);
    }
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 10.0f, daran_sim_model_pos_deg(&d.model));
    /* corrupting blank memory is found at boot too */
    daran_sim_ram_storage_init(&d.ram, &d.storage);
    TEST_ASSERT_TRUE(daran_sim_drive_corrupt_nvm(&d));
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT64(0u, d.model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_WARNING_NVM_CORRUPT, d.model.config_warnings);
}

/* The vendor's whole table is configuration too: s32 values (direction -1,
 * pole pairs, cpr), the gear ratio, the trajectory limits and mode, the
 * under-voltage trip level survive a save and a power cycle, and so does a
 * value written through a rotor-side view. */
static void test_settings_of_the_whole_table_survive_a_save(void)
{
    static daran_sim_drive_t d;
    daran_sim_drive_init(&d, 0u, 1000u);
    d.model.cfg[DARAN_PROP_MOTOR_DIRECTION].s32 = -1;
    d.model.cfg[DARAN_PROP_POLE_PAIRS].s32 = 21;
    d.model.cfg[DARAN_PROP_ENCODER_CPR].s32 = 4096;
    d.model.cfg[DARAN_PROP_STORED_TURNS_COUNTS].s32 = -123456;
    d.model.cfg[DARAN_PROP_GEAR_RATIO].f32 = 8.0f;
    d.model.cfg[DARAN_PROP_TRAJ_MODE].u32 = 2u;
    d.model.cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = 45.0f;
    d.model.cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = 0.0f;
    d.model.cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = 90.0f;
    d.model.cfg[DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL].f32 = 11.5f;
    d.model.cfg[DARAN_PROP_ENABLE_STALL_LIMIT].u32 = 1u;
    d.model.cfg[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 100u;
    {
        daran_value_t v;
        v.u64 = 0u;
        v.f32 = 0.02f; /* rotor Nm/A: 0.16 Nm/A at the shaft */
        TEST_ASSERT_EQUAL_INT64(DARAN_OK,
                                daran_sim_hal.set(&d, DARAN_PROP_MOTOR_TORQUE_CONSTANT, v));
    }
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_model_default_config(&d.model);
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT64(DARAN_SIM_NVM_LOADED, d.nvm_status);
    TEST_ASSERT_EQUAL_INT64(-1, d.model.cfg[DARAN_PROP_MOTOR_DIRECTION].s32);
    TEST_ASSERT_EQUAL_INT64(21, d.model.cfg[DARAN_PROP_POLE_PAIRS].s32);
    TEST_ASSERT_EQUAL_INT64(4096, d.model.cfg[DARAN_PROP_ENCODER_CPR].s32);
    TEST_ASSERT_EQUAL_INT64(-123456, d.model.cfg[DARAN_PROP_STORED_TURNS_COUNTS].s32);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_GEAR_RATIO].f32 == 8.0f);
    TEST_ASSERT_EQUAL_INT64(2u, d.model.cfg[DARAN_PROP_TRAJ_MODE].u32);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 == 45.0f);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 == 0.0f);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 == 90.0f);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL].f32 == 11.5f);
    TEST_ASSERT_EQUAL_INT64(1u, d.model.cfg[DARAN_PROP_ENABLE_STALL_LIMIT].u32);
    TEST_ASSERT_EQUAL_INT64(100u, d.model.cfg[DARAN_PROP_CAN_HEARTBEAT_MS].u32);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_TORQUE_CONSTANT].f32 == 0.16f);
}

/* An image with a valid CRC but a setting the model divides by at 0 (not
 * something a save of a range-checked drive writes) is damage: defaults. */
static void test_an_image_with_a_zero_gear_ratio_is_damage(void)
{
    m.cfg[DARAN_PROP_GEAR_RATIO].f32 = 0.0f;
    SAVE_WITH_GAIN(41.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    m.cfg[DARAN_PROP_GEAR_RATIO].f32 = 1.0f;
    m.cfg[DARAN_PROP_ENCODER_CPR].s32 = -5;
    SAVE_WITH_GAIN(42.0f);
    TEST_ASSERT_TRUE(LOADED_GAIN(DARAN_SIM_NVM_DAMAGED) == 20.0f);
}

/* An image of format version 1 (before the whole table) reads as corrupt:
 * defaults and the warning, never a misread. */
static void test_an_image_of_the_previous_version_is_a_warning_not_a_misread(void)
{
    static daran_sim_drive_t d;
    daran_sim_drive_init(&d, 0u, 1000u);
    d.model.cfg[DARAN_PROP_POS_GAIN].f32 = 44.0f;
    TEST_ASSERT_TRUE(daran_sim_nvm_save(&d.storage, &d.model));
    /* the version field of the committed slot (slot 0, bytes 4..5), CRC
     * made to match as a version-1 firmware would have written it */
    d.ram.bytes[4] = 1u;
    {
        uint32_t len = (uint32_t)d.ram.bytes[6] | ((uint32_t)d.ram.bytes[7] << 8);
        uint32_t crc = daran_sim_crc32(d.ram.bytes + 4, 8u, 0u);
        crc = daran_sim_crc32(d.ram.bytes + 16, len, crc);
        d.ram.bytes[12] = (uint8_t)crc;
        d.ram.bytes[13] = (uint8_t)(crc >> 8);
        d.ram.bytes[14] = (uint8_t)(crc >> 16);
        d.ram.bytes[15] = (uint8_t)(crc >> 24);
    }
    daran_sim_drive_power_on(&d);
    TEST_ASSERT_EQUAL_INT64(DARAN_SIM_NVM_DAMAGED, d.nvm_status);
    TEST_ASSERT_TRUE(d.model.cfg[DARAN_PROP_POS_GAIN].f32 == 20.0f);
    TEST_ASSERT_EQUAL_INT64(DARAN_WARNING_NVM_CORRUPT, d.model.config_warnings);
    TEST_ASSERT_EQUAL_INT64(0u, d.model.error);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc32_is_the_ieee_one);
    RUN_TEST(test_blank_memory_boots_with_defaults_and_no_flag);
    RUN_TEST(test_saved_config_and_zero_offset_load_back);
    RUN_TEST(test_erase_brings_defaults_back_at_next_boot);
    RUN_TEST(test_power_cut_at_every_byte_of_a_save_keeps_old_or_new);
    RUN_TEST(test_power_cut_during_erase_never_leaves_damage);
    RUN_TEST(test_corrupted_memory_boots_defaults_with_a_warning_flag);
    RUN_TEST(test_a_flipped_byte_anywhere_in_an_image_is_found);
    RUN_TEST(test_drive_with_corrupt_memory_moves_and_reports_the_flag);
    RUN_TEST(test_settings_of_the_whole_table_survive_a_save);
    RUN_TEST(test_an_image_with_a_zero_gear_ratio_is_damage);
    RUN_TEST(test_an_image_of_the_previous_version_is_a_warning_not_a_misread);
    return UNITY_END();
}

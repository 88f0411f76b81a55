/* Non-volatile memory of the simulated drive: save/load, erase, corruption
 * falling back to defaults with a warning (axis0.config_warnings, never an
 * error), the whole property table round trip, and a power cut at every byte
 * offset of a save or an erase never losing both configs nor loading
 * garbage. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sim_drive.h"
#include "sim_nvm.h"

static daran_sim_ram_storage_t ram;
static daran_sim_storage_t st;
static daran_sim_model_t m;

static int setup(void **state)
{
    (void)state;
    daran_sim_ram_storage_init(&ram, &st);
    daran_sim_model_init(&m, 1000u);
    return 0;
}

static void save_with_gain(float gain)
{
    m.cfg[DARAN_PROP_POS_GAIN].f32 = gain;
    assert_true(daran_sim_nvm_save(&st, &m));
}

static float loaded_gain(daran_sim_nvm_status_t expect)
{
    daran_sim_model_t fresh;
    daran_sim_model_init(&fresh, 1000u);
    assert_int_equal(daran_sim_nvm_load(&st, &fresh), expect);
    return fresh.cfg[DARAN_PROP_POS_GAIN].f32;
}

static void test_crc32_is_the_ieee_one(void **state)
{
    (void)state;
    assert_int_equal(daran_sim_crc32((const uint8_t *)"123456789", 9u, 0u), 0xCBF43926u);
}

static void test_blank_memory_boots_with_defaults_and_no_flag(void **state)
{
    (void)state;
    assert_true(loaded_gain(DARAN_SIM_NVM_BLANK) == 20.0f);
}

static void test_saved_config_and_zero_offset_load_back(void **state)
{
    daran_sim_model_t fresh;
    (void)state;
    m.cfg[DARAN_PROP_CAN_NODE_ID].u32 = 7u;
    m.cfg[DARAN_PROP_LOAD_INERTIA].f32 = 0.0125f;
    m.cfg[DARAN_PROP_ENABLE_WATCHDOG].u32 = 1u;
    m.zero_offset_deg = -12.5f;
    save_with_gain(25.0f);
    daran_sim_model_init(&fresh, 1000u);
    assert_int_equal(daran_sim_nvm_load(&st, &fresh), DARAN_SIM_NVM_LOADED);
    assert_true(fresh.cfg[DARAN_PROP_POS_GAIN].f32 == 25.0f);
    assert_int_equal(fresh.cfg[DARAN_PROP_CAN_NODE_ID].u32, 7u);
    assert_true(fresh.cfg[DARAN_PROP_LOAD_INERTIA].f32 == 0.0125f);
    assert_int_equal(fresh.cfg[DARAN_PROP_ENABLE_WATCHDOG].u32, 1u);
    assert_true(fresh.zero_offset_deg == -12.5f);
    /* the newest of several saves wins, whichever slot it is in */
    save_with_gain(26.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 26.0f);
    save_with_gain(27.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 27.0f);
}

static void test_erase_brings_defaults_back_at_next_boot(void **state)
{
    (void)state;
    save_with_gain(30.0f);
    save_with_gain(31.0f);
    assert_true(daran_sim_nvm_erase(&st));
    assert_true(loaded_gain(DARAN_SIM_NVM_BLANK) == 20.0f);
}

/* Cut the power after k bytes of a save, for every k: the next boot loads
 * the old config (k < size) or the new one (k = size), never defaults,
 * never a damaged image. Run from blank, one and two earlier saves so both
 * slots are written over. */
static void test_power_cut_at_every_byte_of_a_save_keeps_old_or_new(void **state)
{
    daran_sim_ram_storage_t before;
    uint32_t size = daran_sim_nvm_save_size();
    int history;
    (void)state;
    for (history = 0; history < 3; history++) {
        uint32_t k;
        float old_gain = history == 0 ? 20.0f : 10.0f + (float)history;
        daran_sim_ram_storage_init(&ram, &st);
        if (history >= 1) {
            save_with_gain(11.0f);
        }
        if (history >= 2) {
            save_with_gain(12.0f);
        }
        before = ram;
        for (k = 0; k <= size; k++) {
            ram = before;
            ram.power_cut = true;
            ram.cut_after = k;
            m.cfg[DARAN_PROP_POS_GAIN].f32 = 99.0f;
            assert_int_equal(daran_sim_nvm_save(&st, &m), k == size);
            ram.power_cut = false;
            if (k < size) {
                assert_true(loaded_gain(history == 0 ? DARAN_SIM_NVM_BLANK
                                                     : DARAN_SIM_NVM_LOADED) == old_gain);
            } else {
                assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 99.0f);
            }
        }
    }
    print_message("power cut checked at each of the %u bytes of a save, 3 histories\n", size);
}

/* Same for `se`: the stored config stays or is gone; nothing damaged. */
static void test_power_cut_during_erase_never_leaves_damage(void **state)
{
    daran_sim_ram_storage_t before;
    uint32_t k;
    (void)state;
    save_with_gain(11.0f);
    save_with_gain(12.0f);
    before = ram;
    for (k = 0; k <= 8u; k++) {
        daran_sim_model_t fresh;
        daran_sim_nvm_status_t s;
        ram = before;
        ram.power_cut = true;
        ram.cut_after = k;
        assert_int_equal(daran_sim_nvm_erase(&st), k == 8u);
        ram.power_cut = false;
        daran_sim_model_init(&fresh, 1000u);
        s = daran_sim_nvm_load(&st, &fresh);
        assert_int_not_equal(s, DARAN_SIM_NVM_DAMAGED);
        if (s == DARAN_SIM_NVM_LOADED) {
            assert_true(fresh.cfg[DARAN_PROP_POS_GAIN].f32 == 12.0f);
        }
        /* the newest image goes only once its own magic starts to change */
        assert_int_equal(s, k <= 4u ? DARAN_SIM_NVM_LOADED : DARAN_SIM_NVM_BLANK);
    }
}

static void test_corrupted_memory_boots_defaults_with_a_warning_flag(void **state)
{
    (void)state;
    save_with_gain(33.0f);
    assert_true(daran_sim_nvm_corrupt(&st));
    assert_true(loaded_gain(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    /* one new save repairs it */
    save_with_gain(34.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 34.0f);
    save_with_gain(35.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 35.0f);
    /* corrupting blank memory damages both slots; one save repairs that too */
    daran_sim_ram_storage_init(&ram, &st);
    assert_true(daran_sim_nvm_corrupt(&st));
    assert_true(loaded_gain(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    save_with_gain(36.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_LOADED) == 36.0f);
}

static void test_a_flipped_byte_anywhere_in_an_image_is_found(void **state)
{
    uint32_t off;
    daran_sim_ram_storage_t before;
    (void)state;
    save_with_gain(40.0f);
    before = ram;
    for (off = 4u; off < daran_sim_nvm_save_size() - 4u; off++) {
        ram = before;
        ram.bytes[off] ^= 0x01u;
        assert_true(loaded_gain(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    }
}

/* At drive level: the flag is a warning, motion still works. */
static void test_drive_with_corrupt_memory_moves_and_reports_the_flag(void **state)
{
    static daran_sim_drive_t d;
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    int k;
    (void)state;
    daran_sim_drive_init(&d, 1u, 1000u);
    assert_int_equal(daran_sim_drive_id(&d), 2u);
    d.model.cfg[DARAN_PROP_CAN_NODE_ID].u32 = 9u;
    assert_true(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_drive_power_on(&d);
    assert_int_equal(daran_sim_drive_id(&d), 9u);
    assert_true(daran_sim_drive_corrupt_nvm(&d));
    daran_sim_drive_power_on(&d);
    assert_int_equal(daran_sim_drive_id(&d), 2u); /* default id again */
    assert_int_equal(d.model.error, 0u);
    assert_int_equal(d.model.config_warnings, DARAN_WARNING_NVM_CORRUPT);
    assert_int_equal(d.model.state, DARAN_STATE_CLOSED_LOOP);
    assert_int_equal(daran_sim_model_move(&d.model, &mv), DARAN_OK);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&d.model);
    }
    assert_float_equal(daran_sim_model_pos_deg(&d.model), 10.0f, 0.01f);
    /* corrupting blank memory is found at boot too */
    daran_sim_ram_storage_init(&d.ram, &d.storage);
    assert_true(daran_sim_drive_corrupt_nvm(&d));
    daran_sim_drive_power_on(&d);
    assert_int_equal(d.model.error, 0u);
    assert_int_equal(d.model.config_warnings, DARAN_WARNING_NVM_CORRUPT);
}

/* The vendor's whole table is configuration too: s32 values (direction -1,
 * pole pairs, cpr), the gear ratio, the trajectory limits and mode, the
 * under-voltage trip level survive a save and a power cycle, and so does a
 * value written through a rotor-side view. */
static void test_settings_of_the_whole_table_survive_a_save(void **state)
{
    static daran_sim_drive_t d;
    (void)state;
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
        assert_int_equal(daran_sim_hal.set(&d, DARAN_PROP_MOTOR_TORQUE_CONSTANT, v), DARAN_OK);
    }
    assert_true(daran_sim_nvm_save(&d.storage, &d.model));
    daran_sim_model_default_config(&d.model);
    daran_sim_drive_power_on(&d);
    assert_int_equal(d.nvm_status, DARAN_SIM_NVM_LOADED);
    assert_int_equal(d.model.cfg[DARAN_PROP_MOTOR_DIRECTION].s32, -1);
    assert_int_equal(d.model.cfg[DARAN_PROP_POLE_PAIRS].s32, 21);
    assert_int_equal(d.model.cfg[DARAN_PROP_ENCODER_CPR].s32, 4096);
    assert_int_equal(d.model.cfg[DARAN_PROP_STORED_TURNS_COUNTS].s32, -123456);
    assert_true(d.model.cfg[DARAN_PROP_GEAR_RATIO].f32 == 8.0f);
    assert_int_equal(d.model.cfg[DARAN_PROP_TRAJ_MODE].u32, 2u);
    assert_true(d.model.cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 == 45.0f);
    assert_true(d.model.cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 == 0.0f);
    assert_true(d.model.cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 == 90.0f);
    assert_true(d.model.cfg[DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL].f32 == 11.5f);
    assert_int_equal(d.model.cfg[DARAN_PROP_ENABLE_STALL_LIMIT].u32, 1u);
    assert_int_equal(d.model.cfg[DARAN_PROP_CAN_HEARTBEAT_MS].u32, 100u);
    assert_true(d.model.cfg[DARAN_PROP_TORQUE_CONSTANT].f32 == 0.16f);
}

/* An image with a valid CRC but a setting the model divides by at 0 (not
 * something a save of a range-checked drive writes) is damage: defaults. */
static void test_an_image_with_a_zero_gear_ratio_is_damage(void **state)
{
    (void)state;
    m.cfg[DARAN_PROP_GEAR_RATIO].f32 = 0.0f;
    save_with_gain(41.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_DAMAGED) == 20.0f);
    m.cfg[DARAN_PROP_GEAR_RATIO].f32 = 1.0f;
    m.cfg[DARAN_PROP_ENCODER_CPR].s32 = -5;
    save_with_gain(42.0f);
    assert_true(loaded_gain(DARAN_SIM_NVM_DAMAGED) == 20.0f);
}

/* An image of format version 1 (before the whole table) reads as corrupt:
 * defaults and the warning, never a misread. */
static void test_an_image_of_the_previous_version_is_a_warning_not_a_misread(void **state)
{
    static daran_sim_drive_t d;
    (void)state;
    daran_sim_drive_init(&d, 0u, 1000u);
    d.model.cfg[DARAN_PROP_POS_GAIN].f32 = 44.0f;
    assert_true(daran_sim_nvm_save(&d.storage, &d.model));
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
    assert_int_equal(d.nvm_status, DARAN_SIM_NVM_DAMAGED);
    assert_true(d.model.cfg[DARAN_PROP_POS_GAIN].f32 == 20.0f);
    assert_int_equal(d.model.config_warnings, DARAN_WARNING_NVM_CORRUPT);
    assert_int_equal(d.model.error, 0u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_crc32_is_the_ieee_one, setup),
        cmocka_unit_test_setup(test_blank_memory_boots_with_defaults_and_no_flag, setup),
        cmocka_unit_test_setup(test_saved_config_and_zero_offset_load_back, setup),
        cmocka_unit_test_setup(test_erase_brings_defaults_back_at_next_boot, setup),
        cmocka_unit_test_setup(test_power_cut_at_every_byte_of_a_save_keeps_old_or_new, setup),
        cmocka_unit_test_setup(test_power_cut_during_erase_never_leaves_damage, setup),
        cmocka_unit_test_setup(test_corrupted_memory_boots_defaults_with_a_warning_flag, setup),
        cmocka_unit_test_setup(test_a_flipped_byte_anywhere_in_an_image_is_found, setup),
        cmocka_unit_test_setup(test_drive_with_corrupt_memory_moves_and_reports_the_flag, setup),
        cmocka_unit_test_setup(test_settings_of_the_whole_table_survive_a_save, setup),
        cmocka_unit_test_setup(test_an_image_with_a_zero_gear_ratio_is_damage, setup),
        cmocka_unit_test_setup(test_an_image_of_the_previous_version_is_a_warning_not_a_misread, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

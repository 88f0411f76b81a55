/* A port's own rows on the simulated drive, through daran_sim.h alone, with
 * the core and the simulator built for the brake example's options header
 * (examples/port-brake/brake_options.h: the rows brake.chopper_hz, read-write,
 * and brake.temperature, read-only; five vendor rows left out) as
 * daran_ascii_add_sim() builds them for an adopter. A row no extension
 * serves is a plain store: written, read back, saved by `ss`, 0 after `se`
 * and a reboot; never `read only property` for a row that is not. An
 * extension serves a row from the model's physics, and the port's own
 * command (`sb`) drives the same row through its driver. */
#include <stdint.h>
#include <string.h>

#include "unity.h"

#include "brake_port.h"
#include "daran_sim.h"
#include "sim_one_drive.h"

static void test_the_port_rows_follow_the_vendor_rows(void)
{
    TEST_ASSERT_TRUE(daran_sim_is_port_prop(DARAN_PROP_BRAKE_CHOPPER_HZ));
    TEST_ASSERT_TRUE(daran_sim_is_port_prop(DARAN_PROP_BRAKE_TEMPERATURE));
    TEST_ASSERT_FALSE(daran_sim_is_port_prop(DARAN_PROP_VBUS_VOLTAGE));
    TEST_ASSERT_FALSE(daran_sim_is_port_prop(DARAN_PROP_COUNT));
    TEST_ASSERT_TRUE(daran_sim_is_config_prop(DARAN_PROP_BRAKE_CHOPPER_HZ));
    TEST_ASSERT_FALSE(daran_sim_is_config_prop(DARAN_PROP_BRAKE_TEMPERATURE));
    TEST_ASSERT_EQUAL_INT(DARAN_TYPE_F32, daran_sim_prop_type(DARAN_PROP_BRAKE_CHOPPER_HZ));
}

static void test_a_port_setting_is_written_and_read_back(void)
{
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.brake.chopper_hz"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 20000"));
    TEST_ASSERT_EQUAL_STRING("20000", sim_say("r axis0.brake.chopper_hz"));
    /* the core's own range check still applies (>= 0) */
    TEST_ASSERT_EQUAL_STRING("error: value out of range", sim_say("w axis0.brake.chopper_hz -1"));
}

static void test_a_port_reading_reads_and_refuses_a_write(void)
{
    daran_value_t v;
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.brake.temperature"));
    v.f32 = 41.5f;
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_drive_set_port_value(&sim, DARAN_PROP_BRAKE_TEMPERATURE, v));
    TEST_ASSERT_EQUAL_STRING("41.5", sim_say("r axis0.brake.temperature"));
    TEST_ASSERT_EQUAL_STRING("error: read only property", sim_say("w axis0.brake.temperature 3"));
    /* a reading is state: it stays across a reboot */
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("41.5", sim_say("r axis0.brake.temperature"));
}

static void test_set_port_value_takes_only_port_rows_and_good_values(void)
{
    daran_value_t v;
    v.f32 = 1.0f;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_set_port_value(&sim, DARAN_PROP_VBUS_VOLTAGE, v));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_set_port_value(&sim, DARAN_PROP_COUNT, v));
    v.u32 = 0x7FC00000u; /* a NaN */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_set_port_value(&sim, DARAN_PROP_BRAKE_TEMPERATURE, v));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.brake.temperature"));
}

static void test_a_port_setting_is_saved_and_erased_with_the_config(void)
{
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 12500"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 300"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("12500", sim_say("r axis0.brake.chopper_hz"));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.config_warnings"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("se 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.brake.chopper_hz"));
}

static void test_a_failing_save_keeps_the_stored_port_setting(void)
{
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 12500"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 300"));
    daran_sim_drive_fail_nvm_saves(&sim, 1u);
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("12500", sim_say("r axis0.brake.chopper_hz"));
}

static void test_omitted_vendor_rows_stay_invalid(void)
{
    TEST_ASSERT_EQUAL_STRING("error: invalid property", sim_say("r axis0.encoder.spi_buff_0"));
}

/* An extension serving the brake's temperature from the model's physics:
 * ambient plus a rise with the bus current. */
static daran_result_t temperature_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    const daran_sim_drive_t *d = ctx;
    if (prop != DARAN_PROP_BRAKE_TEMPERATURE) {
        return DARAN_SIM_NOT_MINE;
    }
    out->f32 = d->model.par.ambient_temp + 2.0f * d->model.ibus_a;
    return DARAN_OK;
}

static const daran_sim_extension_t temperature_extension = {temperature_get, NULL, NULL};

static void test_an_extension_serves_a_port_reading_over_the_store(void)
{
    daran_value_t v;
    v.f32 = 99.0f;
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_drive_set_port_value(&sim, DARAN_PROP_BRAKE_TEMPERATURE, v));
    daran_sim_drive_extend(&sim, &temperature_extension, &sim);
    TEST_ASSERT_EQUAL_STRING("25", sim_say("r axis0.brake.temperature"));
    /* rows it does not claim still come from the store */
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.brake.chopper_hz 5"));
    TEST_ASSERT_EQUAL_STRING("5", sim_say("r axis0.brake.chopper_hz"));
}

/* The port's own command drives the same row: its chopper driver is the
 * simulated hardware. */
static daran_result_t chopper_set_frequency(void *ctx, float hz)
{
    daran_value_t v;
    v.f32 = hz;
    return daran_sim_drive_set_port_value(ctx, DARAN_PROP_BRAKE_CHOPPER_HZ, v) == DARAN_OK
               ? DARAN_OK
               : DARAN_ERR_MOTOR_FAULT;
}

static brake_chopper_t chopper = {chopper_set_frequency, &sim};

brake_chopper_t *brake_chopper_of(void *ctx)
{
    (void)ctx;
    return &chopper;
}

static void test_the_ports_own_command_drives_the_simulated_row(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, brake_port_attach(&drive));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sb 1 20000"));
    TEST_ASSERT_EQUAL_STRING("20000", sim_say("r axis0.brake.chopper_hz"));
    TEST_ASSERT_EQUAL_STRING("error: value out of range", sim_say("sb 1 60000"));
    TEST_ASSERT_EQUAL_STRING("20000", sim_say("r axis0.brake.chopper_hz"));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_port_rows_follow_the_vendor_rows);
    RUN_TEST(test_a_port_setting_is_written_and_read_back);
    RUN_TEST(test_a_port_reading_reads_and_refuses_a_write);
    RUN_TEST(test_set_port_value_takes_only_port_rows_and_good_values);
    RUN_TEST(test_a_port_setting_is_saved_and_erased_with_the_config);
    RUN_TEST(test_a_failing_save_keeps_the_stored_port_setting);
    RUN_TEST(test_omitted_vendor_rows_stay_invalid);
    RUN_TEST(test_an_extension_serves_a_port_reading_over_the_store);
    RUN_TEST(test_the_ports_own_command_drives_the_simulated_row);
    return UNITY_END();
}

/* The simulated drive as an adopter's host test uses it, through daran_sim.h
 * alone: a protocol instance over daran_sim_hal, an extension layered over
 * the model, each fault injection with its effect and its reply, a failing
 * NVM write that keeps the old config across a reboot, and the bus's setup
 * function surviving a power cycle. (Vendor build: the extension claims a
 * vendor path; test_sim_port_rows.c covers a port's own rows.) */
#include <stdint.h>
#include <string.h>

#include "unity.h"

#include "daran_sim.h"
#include "sim_one_drive.h"

static void run_ms(uint32_t ms)
{
    uint32_t k;
    for (k = 0; k < ms; k++) {
        daran_sim_drive_tick(&sim);
    }
}

/* ---- an extension over the model ---- */

/* The test's own hardware: a brake resistor whose value the extension keeps
 * (claiming the vendor's config.brake_resistance), refusing more than 10
 * ohm, and a tick counter. */
typedef struct brake_ext {
    float ohm;
    uint32_t gets;
    uint32_t ticks;
} brake_ext_t;

static daran_result_t brake_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    brake_ext_t *b = ctx;
    b->gets++;
    if (prop != DARAN_PROP_BRAKE_RESISTANCE) {
        return DARAN_SIM_NOT_MINE;
    }
    out->f32 = b->ohm;
    return DARAN_OK;
}

static daran_result_t brake_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    brake_ext_t *b = ctx;
    if (prop != DARAN_PROP_BRAKE_RESISTANCE) {
        return DARAN_SIM_NOT_MINE;
    }
    if (value.f32 > 10.0f) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    b->ohm = value.f32;
    return DARAN_OK;
}

static void brake_tick(void *ctx, const daran_sim_model_t *model)
{
    brake_ext_t *b = ctx;
    (void)model;
    b->ticks++;
}

static const daran_sim_extension_t brake_extension = {brake_get, brake_set, brake_tick};

static void test_an_extension_serves_the_property_it_claims(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    TEST_ASSERT_EQUAL_STRING("4.5", sim_say("r config.brake_resistance 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w config.brake_resistance 7.25 1"));
    TEST_ASSERT_EQUAL_FLOAT(7.25f, b.ohm);
    TEST_ASSERT_EQUAL_STRING("7.25", sim_say("r config.brake_resistance 1"));
    /* the model's own value is untouched: the extension owns the row */
    TEST_ASSERT_EQUAL_FLOAT(2.0f, sim.model.cfg[DARAN_PROP_BRAKE_RESISTANCE].f32);
}

static void test_an_extension_falls_through_to_the_model_for_other_rows(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 30"));
    TEST_ASSERT_EQUAL_STRING("30", sim_say("r axis0.controller.config.pos_gain"));
    TEST_ASSERT_EQUAL_STRING("24", sim_say("r vbus_voltage 1"));
    TEST_ASSERT_TRUE(b.gets > 0u); /* asked first, even for the model's rows */
}

static void test_an_extension_refusal_is_the_reply_and_changes_nothing(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    TEST_ASSERT_EQUAL_STRING("error: value out of range", sim_say("w config.brake_resistance 12 1"));
    TEST_ASSERT_EQUAL_FLOAT(4.5f, b.ohm);
}

static void test_the_extension_ticks_with_the_model(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    run_ms(25u);
    TEST_ASSERT_EQUAL_UINT32(25u, b.ticks);
}

static void test_removing_the_extension_gives_the_model_back(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    daran_sim_drive_extend(&sim, NULL, &b);
    TEST_ASSERT_EQUAL_STRING("2", sim_say("r config.brake_resistance 1"));
    run_ms(3u);
    TEST_ASSERT_EQUAL_UINT32(0u, b.ticks);
}

static void test_the_extension_stays_across_a_reboot(void)
{
    brake_ext_t b = {4.5f, 0u, 0u};
    daran_sim_drive_extend(&sim, &brake_extension, &b);
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("4.5", sim_say("r config.brake_resistance 1"));
}

/* ---- physical faults ---- */

static void test_an_injected_stall_trips_the_drive(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_STALL));
    run_ms(1u);
    TEST_ASSERT_EQUAL_STRING("65536", sim_say("r axis0.motor.error"));
    TEST_ASSERT_EQUAL_STRING("64", sim_say("r axis0.error"));
    TEST_ASSERT_EQUAL_STRING("1", sim_say("r axis0.current_state"));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("q 1 90"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sc 1"));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.error"));
}

static void test_an_injected_overspeed_trips_when_the_error_is_enabled(void)
{
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.enable_overspeed_error 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_OVERSPEED));
    run_ms(1u);
    TEST_ASSERT_EQUAL_STRING("1", sim_say("r axis0.controller.error"));
    TEST_ASSERT_EQUAL_STRING("512", sim_say("r axis0.error"));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("v 1 10"));
}

static void test_an_injected_overspeed_is_braked_back_when_the_error_is_off(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_OVERSPEED));
    TEST_ASSERT_TRUE(sim.model.vel_rpm > 1.2f * 600.0f); /* thrown beyond the limit */
    run_ms(2000u);
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.error"));
    TEST_ASSERT_EQUAL_STRING("8", sim_say("r axis0.current_state"));
    TEST_ASSERT_TRUE(sim.model.vel_rpm < 600.0f && sim.model.vel_rpm > -600.0f);
}

static void test_injected_overtemp_and_undervoltage_trip(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_OVERTEMP));
    run_ms(1u);
    TEST_ASSERT_EQUAL_STRING("262144", sim_say("r axis0.error"));
    daran_sim_drive_init(&sim, 0u, 1000u);
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_UNDERVOLTAGE));
    run_ms(1u); /* the bus sags */
    TEST_ASSERT_EQUAL_STRING("6", sim_say("r vbus_voltage 1"));
    run_ms(1u); /* the protection sees it */
    TEST_ASSERT_EQUAL_STRING("2", sim_say("r axis0.error"));
}

static void test_an_injected_nvm_corruption_boots_on_defaults_with_a_warning(void)
{
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 30"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_drive_inject_fault(&sim, DARAN_SIM_FAULT_NVM_CORRUPT));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("20", sim_say("r axis0.controller.config.pos_gain"));
    TEST_ASSERT_EQUAL_STRING("1", sim_say("r axis0.config_warnings"));
}

static void test_a_fault_outside_the_enum_is_refused(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_inject_fault(&sim, (daran_sim_fault_t)99));
}

static void test_fault_names_are_those_of_the_directive(void)
{
    static const daran_sim_fault_t all[] = {
        DARAN_SIM_FAULT_OVERTEMP, DARAN_SIM_FAULT_UNDERVOLTAGE, DARAN_SIM_FAULT_STALL,
        DARAN_SIM_FAULT_OVERSPEED, DARAN_SIM_FAULT_NVM_CORRUPT};
    size_t k;
    daran_sim_fault_t f = DARAN_SIM_FAULT_OVERTEMP;
    for (k = 0; k < sizeof all / sizeof all[0]; k++) {
        const char *name = daran_sim_fault_name(all[k]);
        TEST_ASSERT_NOT_NULL(name);
        TEST_ASSERT_NOT_NULL(strstr(DARAN_SIM_FAULT_NAMES, name));
        TEST_ASSERT_TRUE(daran_sim_fault_from_name(name, &f));
        TEST_ASSERT_EQUAL_INT(all[k], f);
    }
    TEST_ASSERT_TRUE(daran_sim_fault_from_name("stall", &f));
    TEST_ASSERT_FALSE(daran_sim_fault_from_name("Stall", &f));
    TEST_ASSERT_FALSE(daran_sim_fault_from_name("", &f));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_FAULT_STALL, f);
    TEST_ASSERT_NULL(daran_sim_fault_name((daran_sim_fault_t)99));
}

/* ---- HAL refusals ---- */

static void test_a_refused_set_answers_its_result_and_changes_nothing(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_SET, 2u,
                                                                 DARAN_ERR_MOTOR_FAULT));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("w axis0.controller.config.pos_gain 30"));
    TEST_ASSERT_EQUAL_UINT32(1u, daran_sim_drive_refusals_left(&sim, DARAN_SIM_CALL_SET));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("w axis0.controller.config.pos_gain 31"));
    TEST_ASSERT_EQUAL_STRING("20", sim_say("r axis0.controller.config.pos_gain"));
    /* spent: the next write goes through */
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 32"));
    TEST_ASSERT_EQUAL_STRING("32", sim_say("r axis0.controller.config.pos_gain"));
}

static void test_a_refused_move_answers_its_result_and_does_not_move(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_MOVE, 1u,
                                                                 DARAN_ERR_TRAJECTORY_INFEASIBLE));
    TEST_ASSERT_EQUAL_STRING("error: trajectory infeasible", sim_say("q 1 90"));
    run_ms(500u);
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.output_shaft.input_pos"));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.output_shaft.pos_estimate"));
}

static void test_a_refused_action_answers_its_result(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_ACTION, 1u,
                                                                 DARAN_ERR_MOTOR_FAULT));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("sz 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sz 1"));
}

static void test_a_refused_get_fails_the_read(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_GET, 1u,
                                                                 DARAN_ERR_MOTOR_FAULT));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("r vbus_voltage 1"));
    TEST_ASSERT_EQUAL_STRING("24", sim_say("r vbus_voltage 1"));
}

static void test_a_refusal_can_be_cancelled(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_SET, 5u,
                                                                 DARAN_ERR_MOTOR_FAULT));
    daran_sim_drive_clear_injections(&sim);
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_drive_refusals_left(&sim, DARAN_SIM_CALL_SET));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 30"));
}

static void test_a_refusal_needs_a_kind_and_a_protocol_error(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_SET, 1u, DARAN_OK));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_SET, 1u,
                                                       DARAN_ERR_BAD_ARGUMENT));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_SET, 1u,
                                                       DARAN_RESULT_COUNT));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_drive_refuse_calls(&sim, DARAN_SIM_CALL_COUNT, 1u,
                                                       DARAN_ERR_MOTOR_FAULT));
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_drive_refusals_left(&sim, DARAN_SIM_CALL_SET));
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_drive_refusals_left(&sim, DARAN_SIM_CALL_COUNT));
}

/* ---- a failing NVM write ---- */

static void test_a_failing_nvm_write_keeps_the_old_config_after_a_reboot(void)
{
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 30"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 40"));
    daran_sim_drive_fail_nvm_saves(&sim, 1u);
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("30", sim_say("r axis0.controller.config.pos_gain"));
    TEST_ASSERT_EQUAL_STRING("0", sim_say("r axis0.config_warnings"));
    /* the failure was for one save: the next one stores */
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 40"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_STRING("40", sim_say("r axis0.controller.config.pos_gain"));
}

static void test_a_failing_first_save_leaves_the_store_blank(void)
{
    uint32_t written = sim.ram.bytes_written;
    daran_sim_drive_fail_nvm_saves(&sim, 1u);
    TEST_ASSERT_EQUAL_STRING("", sim_say("w axis0.controller.config.pos_gain 40"));
    TEST_ASSERT_EQUAL_STRING("error: motor fault", sim_say("ss 1"));
    TEST_ASSERT_EQUAL_UINT32(written, sim.ram.bytes_written);
    TEST_ASSERT_EQUAL_STRING("", sim_say("sr 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_NVM_BLANK, sim.nvm_status);
    TEST_ASSERT_EQUAL_STRING("20", sim_say("r axis0.controller.config.pos_gain"));
}

/* ---- the bus ---- */

static uint32_t setups[DARAN_SIM_MAX_DRIVES];

static void count_setup(void *ctx, uint32_t index, daran_drive_t *proto)
{
    (void)ctx;
    (void)proto;
    setups[index]++;
}

static void test_the_bus_setup_runs_on_every_new_protocol_instance(void)
{
    static daran_sim_bus_t bus;
    memset(setups, 0, sizeof setups);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_bus_init(&bus, 2u, 1000u));
    daran_sim_bus_set_setup(&bus, count_setup, NULL);
    TEST_ASSERT_EQUAL_UINT32(1u, setups[0]);
    TEST_ASSERT_EQUAL_UINT32(1u, setups[1]);
    daran_sim_bus_power_cycle(&bus, 1u);
    TEST_ASSERT_EQUAL_UINT32(1u, setups[0]);
    TEST_ASSERT_EQUAL_UINT32(2u, setups[1]);
    daran_sim_bus_set_setup(&bus, NULL, NULL);
    daran_sim_bus_power_cycle(&bus, 1u);
    TEST_ASSERT_EQUAL_UINT32(2u, setups[1]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_an_extension_serves_the_property_it_claims);
    RUN_TEST(test_an_extension_falls_through_to_the_model_for_other_rows);
    RUN_TEST(test_an_extension_refusal_is_the_reply_and_changes_nothing);
    RUN_TEST(test_the_extension_ticks_with_the_model);
    RUN_TEST(test_removing_the_extension_gives_the_model_back);
    RUN_TEST(test_the_extension_stays_across_a_reboot);
    RUN_TEST(test_an_injected_stall_trips_the_drive);
    RUN_TEST(test_an_injected_overspeed_trips_when_the_error_is_enabled);
    RUN_TEST(test_an_injected_overspeed_is_braked_back_when_the_error_is_off);
    RUN_TEST(test_injected_overtemp_and_undervoltage_trip);
    RUN_TEST(test_an_injected_nvm_corruption_boots_on_defaults_with_a_warning);
    RUN_TEST(test_a_fault_outside_the_enum_is_refused);
    RUN_TEST(test_fault_names_are_those_of_the_directive);
    RUN_TEST(test_a_refused_set_answers_its_result_and_changes_nothing);
    RUN_TEST(test_a_refused_move_answers_its_result_and_does_not_move);
    RUN_TEST(test_a_refused_action_answers_its_result);
    RUN_TEST(test_a_refused_get_fails_the_read);
    RUN_TEST(test_a_refusal_can_be_cancelled);
    RUN_TEST(test_a_refusal_needs_a_kind_and_a_protocol_error);
    RUN_TEST(test_a_failing_nvm_write_keeps_the_old_config_after_a_reboot);
    RUN_TEST(test_a_failing_first_save_leaves_the_store_blank);
    RUN_TEST(test_the_bus_setup_runs_on_every_new_protocol_instance);
    return UNITY_END();
}

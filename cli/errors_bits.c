/* The vendor's bit names of the error registers (errors_bits.h). ODrive
 * 0.5.1 leaves gaps (axis bits 15 and 16, motor bit 11): those stay
 * unnamed, and `daran errors` prints them as `bit N`. */
#include "errors_bits.h"

#include "daran_client.h"

#define BITS 32u

/* AXIS_ERROR_*: 10.4's bits 1, 6, 9, 11, 14 and 18 are the ones a drive of
 * this library sets. */
static const char *const axis_bits[BITS] = {
    [0] = "INVALID_STATE",
    [1] = "DC_BUS_UNDER_VOLTAGE",
    [2] = "DC_BUS_OVER_VOLTAGE",
    [3] = "CURRENT_MEASUREMENT_TIMEOUT",
    [4] = "BRAKE_RESISTOR_DISARMED",
    [5] = "MOTOR_DISARMED",
    [6] = "MOTOR_FAILED",
    [7] = "SENSORLESS_ESTIMATOR_FAILED",
    [8] = "ENCODER_FAILED",
    [9] = "CONTROLLER_FAILED",
    [10] = "POS_CTRL_DURING_SENSORLESS",
    [11] = "WATCHDOG_TIMER_EXPIRED",
    [12] = "MIN_ENDSTOP_PRESSED",
    [13] = "MAX_ENDSTOP_PRESSED",
    [14] = "ESTOP_REQUESTED",
    [17] = "HOMING_WITHOUT_ENDSTOP",
    [18] = "OVER_TEMP",
};

/* MOTOR_ERROR_*; bit 16 is the vendor's own (the stall limiter of
 * `extra_setting`), beyond ODrive's list. */
static const char *const motor_bits[BITS] = {
    [0] = "PHASE_RESISTANCE_OUT_OF_RANGE",
    [1] = "PHASE_INDUCTANCE_OUT_OF_RANGE",
    [2] = "ADC_FAILED",
    [3] = "DRV_FAULT",
    [4] = "CONTROL_DEADLINE_MISSED",
    [5] = "NOT_IMPLEMENTED_MOTOR_TYPE",
    [6] = "BRAKE_CURRENT_OUT_OF_RANGE",
    [7] = "MODULATION_MAGNITUDE",
    [8] = "BRAKE_DEADTIME_VIOLATION",
    [9] = "UNEXPECTED_TIMER_CALLBACK",
    [10] = "CURRENT_SENSE_SATURATION",
    [12] = "CURRENT_LIMIT_VIOLATION",
    [13] = "BRAKE_DUTY_CYCLE_NAN",
    [14] = "DC_BUS_OVER_REGEN_CURRENT",
    [15] = "DC_BUS_OVER_CURRENT",
    [16] = "STALL",
};

/* ENCODER_ERROR_* */
static const char *const encoder_bits[BITS] = {
    [0] = "UNSTABLE_GAIN",
    [1] = "CPR_POLEPAIRS_MISMATCH",
    [2] = "NO_RESPONSE",
    [3] = "UNSUPPORTED_ENCODER_MODE",
    [4] = "ILLEGAL_HALL_STATE",
    [5] = "INDEX_NOT_FOUND_YET",
    [6] = "ABS_SPI_TIMEOUT",
    [7] = "ABS_SPI_COM_FAIL",
    [8] = "ABS_SPI_NOT_READY",
};

/* CONTROLLER_ERROR_* */
static const char *const controller_bits[BITS] = {
    [0] = "OVERSPEED",
    [1] = "INVALID_INPUT_MODE",
    [2] = "UNSTABLE_GAIN",
    [3] = "INVALID_MIRROR_AXIS",
    [4] = "INVALID_LOAD_ENCODER",
    [5] = "INVALID_ESTIMATE",
};

/* THERMISTOR_CURRENT_LIMITER_ERROR_*: both thermistors */
static const char *const thermistor_bits[BITS] = {
    [0] = "OVER_TEMP",
};

/* CAN_ERROR_* */
static const char *const can_bits[BITS] = {
    [0] = "DUPLICATE_CAN_IDS",
};

/* In `e`'s order (daran_client_error_register_name). */
static const char *const *const registers[DARAN_CLIENT_ERROR_REGISTERS] = {
    axis_bits, motor_bits, encoder_bits, controller_bits, thermistor_bits, thermistor_bits,
    can_bits,
};

const char *cli_error_bit_name(size_t reg, unsigned bit)
{
    if (reg >= DARAN_CLIENT_ERROR_REGISTERS || bit >= BITS) {
        return NULL;
    }
    return registers[reg][bit];
}

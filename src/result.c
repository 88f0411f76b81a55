/* The error phrases of the protocol, one per daran_result_t. */
#include "daran_result.h"

static const char *const phrases[DARAN_RESULT_COUNT] = {
    [DARAN_OK] = "ok",
    [DARAN_ERR_UNKNOWN_COMMAND] = "unknown command",
    [DARAN_ERR_INVALID_FORMAT] = "invalid command format",
    [DARAN_ERR_INVALID_MOTOR] = "invalid motor",
    [DARAN_ERR_INVALID_VALUE] = "invalid value",
    [DARAN_ERR_OUT_OF_RANGE] = "value out of range",
    [DARAN_ERR_INVALID_MODE] = "invalid mode",
    [DARAN_ERR_INVALID_PROPERTY] = "invalid property",
    [DARAN_ERR_READ_ONLY] = "read only property",
    [DARAN_ERR_INVALID_CHECKSUM] = "invalid checksum",
    [DARAN_ERR_CHECKSUM_MISMATCH] = "checksum mismatch",
    [DARAN_ERR_LINE_TOO_LONG] = "line too long",
    [DARAN_ERR_INVALID_CHARACTER] = "invalid character",
    [DARAN_ERR_NO_PRESET] = "no preset",
    [DARAN_ERR_TRAJECTORY_INFEASIBLE] = "trajectory infeasible",
    [DARAN_ERR_ESTOP_ACTIVE] = "estop active",
    [DARAN_ERR_MOTOR_FAULT] = "motor fault",
    [DARAN_ERR_MOTOR_IDLE] = "motor idle",
    [DARAN_ERR_BAD_ARGUMENT] = "bad argument",
};

const char *daran_result_phrase(daran_result_t result)
{
    /* A HAL may hand back any integer; an unknown one is a hardware fault. */
    if ((unsigned)result >= (unsigned)DARAN_RESULT_COUNT) {
        return phrases[DARAN_ERR_MOTOR_FAULT];
    }
    return phrases[result];
}

/* The error phrases of the protocol, one per daran_result_t, kept as one
 * block of NUL-separated strings in enum order (no table of pointers). */
#include "daran_result.h"

static const char phrases[] =
    "ok\0"
    "unknown command\0"
    "invalid command format\0"
    "invalid motor\0"
    "invalid value\0"
    "value out of range\0"
    "invalid mode\0"
    "invalid property\0"
    "read only property\0"
    "invalid checksum\0"
    "checksum mismatch\0"
    "line too long\0"
    "invalid character\0"
    "no preset\0"
    "trajectory infeasible\0"
    "estop active\0"
    "motor fault\0"
    "motor idle\0"
    "bad argument";

const char *daran_result_phrase(daran_result_t result)
{
    /* A HAL may hand back any integer; an unknown one is a hardware fault. */
    unsigned index = (unsigned)result;
    if (index >= (unsigned)DARAN_RESULT_COUNT) {
        index = (unsigned)DARAN_ERR_MOTOR_FAULT;
    }
    const char *phrase = phrases;
    for (unsigned i = 0; i < index; i++) {
        while (*phrase != '\0') {
            phrase++;
        }
        phrase++;
    }
    return phrase;
}

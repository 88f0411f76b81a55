/* The error phrases of the protocol, one per daran_result_t, kept as one
 * block of NUL-separated strings in enum order (no table of pointers). */
#include "internal.h"

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
    "bad argument\0"
    "build mismatch";

const char *daran_nth_text(const char *block, unsigned n)
{
    for (; n > 0u; n--) {
        while (*block++ != '\0') {
        }
    }
    return block;
}

const char *daran_result_phrase(daran_result_t result)
{
    /* A HAL may hand back any integer; an unknown one is a hardware fault. */
    unsigned index = (unsigned)result;
    return daran_nth_text(phrases, index < (unsigned)DARAN_RESULT_COUNT
                                       ? index
                                       : (unsigned)DARAN_ERR_MOTOR_FAULT);
}

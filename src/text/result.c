/* The error phrases of the protocol, one per daran_result_t, kept as one
 * block of NUL-separated strings in enum order (no table of pointers), both
 * made from DARAN_RESULT_LIST. */
#include "daran_result.h"
#include "text.h"

/* Sized to leave out the literal's own final NUL: the last phrase ends the
 * block, as each other one ends at its '\0'. */
#define PHRASE_(name, phrase) phrase "\0"
static const char phrases[sizeof(DARAN_RESULT_LIST(PHRASE_)) - 1u] = DARAN_RESULT_LIST(PHRASE_);
#undef PHRASE_

const char *daran_result_phrase(daran_result_t result)
{
    /* A HAL may hand back any integer; an unknown one is a hardware fault. */
    unsigned index = (unsigned)result;
    return daran_nth_text(phrases, index < (unsigned)DARAN_RESULT_COUNT
                                       ? index
                                       : (unsigned)DARAN_ERR_MOTOR_FAULT);
}

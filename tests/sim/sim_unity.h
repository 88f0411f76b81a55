/* What the simulator's Unity tests add to Unity 2.4.3, which has neither
 * TEST_MESSAGE nor TEST_PRINTF: a printf-style note in the test output and a
 * printf-style failure reported at a given line (the UPPER-CASE helpers of
 * each test file pass their caller's __LINE__, so a failure points at the
 * test, not at the helper). */
#ifndef SIM_UNITY_H
#define SIM_UNITY_H

#include <stdarg.h>
#include <stdio.h>

#include "unity.h"

/* A line of text in the test output, e.g. a measured figure. */
static inline void sim_note(const char *fmt, ...)
{
    char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    UnityPrint(text);
    UNITY_PRINT_EOL();
}

/* Fail the current test at @p line with a formatted message. */
static inline void sim_fail_at(int line, const char *fmt, ...)
{
    static char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, text);
}

#define NOTE(...) sim_note(__VA_ARGS__)
#define FAIL_F(...) sim_fail_at(__LINE__, __VA_ARGS__)

#endif /* SIM_UNITY_H */

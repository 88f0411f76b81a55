/* daran-sim's shared state and clock (sim_app.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_app.h"

#include <time.h>

sim_app_t app;
volatile sig_atomic_t stop_signal;

double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

uint64_t mono_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

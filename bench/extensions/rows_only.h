/* Flash measurement only (bench/extensions/build.sh): the two port rows of
 * examples/port-brake/brake_options.h, without its omissions, so that what
 * a row costs and what an omission saves can be told apart. */
#ifndef BENCH_ROWS_ONLY_H
#define BENCH_ROWS_ONLY_H
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(BRAKE_CHOPPER_HZ,  "brake.chopper_hz",  AXIS, F32, RW, NON_NEGATIVE, "Hz", 0) \
    X(BRAKE_TEMPERATURE, "brake.temperature", AXIS, F32, RO, NONE,         "degC", 0)
#endif

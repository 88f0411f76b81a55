/* An options header with float rows of interval ranges, for
 * test_float_intervals.c: the vendor's table plus four rows whose ranges
 * have decimal, negative and exponent ends, and one that starts with a 9.
 * Only #define here. */
#ifndef FLOAT_INTERVAL_OPTIONS_H
#define FLOAT_INTERVAL_OPTIONS_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(UNIT_INTERVAL, "0..1") \
    X(SYMMETRIC,     "-2.5..2.5") \
    X(WIDE,          "-1e3..0.1") \
    X(NINES,         "9..9.5")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY,   "fan.duty",   AXIS,   F32, RW, UNIT_INTERVAL, "", 0) \
    X(TRIM,       "trim",       SYSTEM, F32, RW, SYMMETRIC,     "deg", 0) \
    X(WIDE_VALUE, "wide_value", SYSTEM, F32, RW, WIDE,          "", 0) \
    X(NINE,       "nine",       SYSTEM, F32, RW, NINES,         "", 0)

#endif /* FLOAT_INTERVAL_OPTIONS_H */

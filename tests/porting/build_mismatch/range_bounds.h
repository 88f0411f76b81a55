/* library_options.h with a range of the same length and other bounds. */
#ifndef BUILD_MISMATCH_RANGE_BOUNDS_H
#define BUILD_MISMATCH_RANGE_BOUNDS_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(PERCENT, "0..125")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY,  "fan.duty", AXIS, F32, RW, PERCENT, "%", 0) \
    X(PUMP_DUTY, "pump.pwm", AXIS, F32, RW, PERCENT, "%", 0)

#endif /* BUILD_MISMATCH_RANGE_BOUNDS_H */

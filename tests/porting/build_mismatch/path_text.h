/* library_options.h with a path of the same length spelt otherwise. */
#ifndef BUILD_MISMATCH_PATH_TEXT_H
#define BUILD_MISMATCH_PATH_TEXT_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(PERCENT, "0..100")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY,  "fan.duty", AXIS, F32, RW, PERCENT, "%", 0) \
    X(PUMP_DUTY, "pump.pct", AXIS, F32, RW, PERCENT, "%", 0)

#endif /* BUILD_MISMATCH_PATH_TEXT_H */

/* library_options.h with a unit of the same length spelt otherwise. */
#ifndef BUILD_MISMATCH_UNIT_TEXT_H
#define BUILD_MISMATCH_UNIT_TEXT_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(PERCENT, "0..100")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY,  "fan.duty", AXIS, F32, RW, PERCENT, "%", 0) \
    X(PUMP_DUTY, "pump.pwm", AXIS, F32, RW, PERCENT, "V", 0)

#endif /* BUILD_MISMATCH_UNIT_TEXT_H */

/* library_options.h with its two rows in the other order: every length,
 * type and range the same, so each id names the other row. */
#ifndef BUILD_MISMATCH_ROWS_SWAPPED_H
#define BUILD_MISMATCH_ROWS_SWAPPED_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(PERCENT, "0..100")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(PUMP_DUTY, "pump.pwm", AXIS, F32, RW, PERCENT, "%", 0) \
    X(FAN_DUTY,  "fan.duty", AXIS, F32, RW, PERCENT, "%", 0)

#endif /* BUILD_MISMATCH_ROWS_SWAPPED_H */

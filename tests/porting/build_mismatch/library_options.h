/* The options header the mismatch tests' core is built with
 * (tests/porting/CMakeLists.txt): two port rows of the same shape and a range
 * of their own. The other headers here differ from it in one point each, as
 * an adopter's program that was not rebuilt with its core's header would. */
#ifndef BUILD_MISMATCH_LIBRARY_OPTIONS_H
#define BUILD_MISMATCH_LIBRARY_OPTIONS_H

#define DARAN_PORT_RANGE_LIST(X) \
    X(PERCENT, "0..100")

#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY,  "fan.duty", AXIS, F32, RW, PERCENT, "%", 0) \
    X(PUMP_DUTY, "pump.pwm", AXIS, F32, RW, PERCENT, "%", 0)

#endif /* BUILD_MISMATCH_LIBRARY_OPTIONS_H */

/* Options of a leaner core for conformance_lean_build: the suite must adapt
 * to what this build has (tests/conformance/CMakeLists.txt). */
#ifndef LEAN_OPTIONS_H
#define LEAN_OPTIONS_H

#define DARAN_ENABLE_HELP 0
#define DARAN_ENABLE_MULTI_MOTOR 0
#define DARAN_MOTOR_ID_MAX 15

/* a fraction of the port's own */
#define DARAN_PORT_RANGE_LIST(X) X(LEAN_FRACTION, "0..1")
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(LEAN_FAN_DUTY, "fan.duty", AXIS, F32, RW, LEAN_FRACTION, "", 0) \
    X(LEAN_BOARD_REVISION, "board_revision", SYSTEM, U32, RO, NONE, "", 0)

#define DARAN_OMIT_PROPERTIES(X) X(ENCODER_POS_ABS) X(ENCODER_TURN_ABS)

#endif /* LEAN_OPTIONS_H */

/* The options header of the ACME X1 drive: what this drive adds to the
 * vendor's protocol and what it leaves out. Named by CONFIG_HEADER in
 * daran_ascii_add_library() (CMakeLists.txt); the property table, range
 * checks and discovery are generated from it when the project configures.
 *
 * Only #define here: the core reads this file before its own headers. */
#ifndef ACME_OPTIONS_H
#define ACME_OPTIONS_H

/* A duty cycle is a fraction: `w` refuses anything outside 0..1, and
 * discovery says so. */
#define DARAN_PORT_RANGE_LIST(X) X(UNIT_INTERVAL, "0..1")

/* The cooling fan of the X1's power stage: DARAN_PROP_FAN_DUTY. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(FAN_DUTY, "fan.duty", AXIS, F32, RW, UNIT_INTERVAL, "", 0)

/* The X1 has an incremental encoder only: no absolute position or turn
 * count. The paths answer `invalid property`; the ids stay. */
#define DARAN_OMIT_PROPERTIES(X) \
    X(ENCODER_POS_ABS) \
    X(ENCODER_TURN_ABS)

#endif /* ACME_OPTIONS_H */

/* An interval whose low end is above its high end. */
#define DARAN_PORT_RANGE_LIST(X) X(BACKWARDS, "1..0")
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(DUTY, "fan.duty", AXIS, F32, RW, BACKWARDS, "", 0)

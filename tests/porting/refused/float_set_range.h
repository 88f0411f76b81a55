/* A float row with a set range, which the core cannot check for a float. */
#define DARAN_PORT_RANGE_LIST(X) X(GEARS, "{1,2,4}")
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(GEAR, "gearbox.gear", AXIS, F32, RW, GEARS, "", 0)

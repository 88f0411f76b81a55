/* A broken options header: a port row named like a vendor row
 * (DARAN_PROP_VBUS_VOLTAGE would be defined twice). The build must stop. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(VBUS_VOLTAGE, "brake.bus_voltage", AXIS, F32, RO, NONE, "V", 0)

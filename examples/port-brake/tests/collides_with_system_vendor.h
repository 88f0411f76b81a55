/* A broken options header: a system-scope port row on the vendor's
 * `vbus_voltage`. The build must stop. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(BUS_VOLTAGE_FILTERED, "vbus_voltage", SYSTEM, F32, RO, NONE, "V", 0)

/* A port row reusing a vendor path without omitting the vendor row. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(MY_BUS_VOLTAGE, "vbus_voltage", SYSTEM, F32, RO, NONE, "V", 0)

/* The brake example's options header, named by DARAN_CONFIG_HEADER (see
 * CMakeLists.txt). The core's daran_config.h includes it before its own
 * defaults, and tools/gen_property_index.py reads the two lists below when
 * the library is built: the port's rows join the vendor's in the one
 * generated table (lookup, range checks, discovery), and the rows it leaves
 * out answer `invalid property`. Nothing in the library is edited.
 *
 * Keep this file free of #include and of anything but #define: it is read
 * before every other header of the core. */
#ifndef BRAKE_OPTIONS_H
#define BRAKE_OPTIONS_H

/* The port's own properties, in the form of DARAN_PROPERTY_LIST
 * (daran_properties.h): X(ID, path, scope, type, access, range, unit). They
 * reach the HAL as DARAN_PROP_BRAKE_CHOPPER_HZ and DARAN_PROP_BRAKE_TEMPERATURE.
 * The core checks `>= 0` before the HAL sees a write; the chopper's own upper
 * limit (50 kHz) is the HAL's to enforce, as for `sb`. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(BRAKE_CHOPPER_HZ,  "brake.chopper_hz",  AXIS, F32, RW, NON_NEGATIVE, "Hz", 0) \
    X(BRAKE_TEMPERATURE, "brake.temperature", AXIS, F32, RO, NONE,         "degC", 0)

/* This board has an incremental encoder only: no SPI absolute encoder, so
 * its buffers and absolute readings are left out. The ids stay (the enum
 * does not change), their paths answer `invalid property` and never reach
 * the HAL. */
#define DARAN_OMIT_PROPERTIES(X) \
    X(ENCODER_SPI_BUFF_0) \
    X(ENCODER_SPI_BUFF_1) \
    X(ENCODER_SPI_BUFF_2) \
    X(ENCODER_POS_ABS) \
    X(ENCODER_TURN_ABS)

#endif /* BRAKE_OPTIONS_H */

/* A broken options header: a port row whose path is a vendor path
 * (`axis0.encoder.pos_abs`) without leaving the vendor row out. The build
 * must stop: tools/gen_property_index.py refuses it. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(BRAKE_CHOPPER_HZ, "brake.chopper_hz", AXIS, F32, RW, NON_NEGATIVE, "Hz", 0) \
    X(ABSOLUTE_POSITION, "encoder.pos_abs", AXIS, S32, RO, NONE, "count", 0)

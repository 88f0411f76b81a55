/* The control case: a vendor row left out, then its path given to a port row
 * of another id (a drive whose absolute position is its own). Accepted. */
#define DARAN_PORT_PROPERTY_LIST(X) \
    X(ABSOLUTE_POSITION, "encoder.pos_abs", AXIS, S32, RO, NONE, "count", 0)
#define DARAN_OMIT_PROPERTIES(X) X(ENCODER_POS_ABS)

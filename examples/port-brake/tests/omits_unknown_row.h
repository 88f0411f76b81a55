/* A broken options header: it leaves out a vendor row that does not exist
 * (a typo would otherwise leave the row in silently). The build must stop. */
#define DARAN_OMIT_PROPERTIES(X) X(ENCODER_POS_ABSOLUTE)

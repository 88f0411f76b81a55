/* A drive without CAN leaving can.error out: `e` names it, so it must stay. */
#define DARAN_OMIT_PROPERTIES(X) X(CAN_ERROR)

/* RAM budget probes: the size of each array is sizeof(daran_drive_t) or
 * sizeof(daran_can_t) with the build's options; check_budgets.py reads them
 * with `nm -S` (nothing runs). */
#include "daran_drive.h"

extern char daran_target_sizeof_drive[sizeof(daran_drive_t)];
char daran_target_sizeof_drive[sizeof(daran_drive_t)];

#if DARAN_ENABLE_CAN
#include "daran_can.h"
/* the CAN front end's state beside the drive (issue 21: <= 160 bytes) */
extern char daran_target_sizeof_can[sizeof(daran_can_t)];
char daran_target_sizeof_can[sizeof(daran_can_t)];
#endif

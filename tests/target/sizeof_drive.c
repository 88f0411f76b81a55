/* RAM budget probe: the size of this array is sizeof(daran_drive_t) with the
 * build's options; check_budgets.py reads it with `nm -S` (nothing runs). */
#include "daran_drive.h"

extern char daran_target_sizeof_drive[sizeof(daran_drive_t)];
char daran_target_sizeof_drive[sizeof(daran_drive_t)];

/* The library version (include/daran_version.h, which the build also reads). */
#include "daran_drive.h"
#include "daran_version.h"

const char *daran_version(void)
{
    return DARAN_VERSION_TEXT;
}

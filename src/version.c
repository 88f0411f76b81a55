/* The library version, set by the build from the CMake project version. */
#include "daran_drive.h"

#ifndef DARAN_VERSION_STRING
#define DARAN_VERSION_STRING "0.0.0"
#endif

const char *daran_version(void)
{
    return DARAN_VERSION_STRING;
}

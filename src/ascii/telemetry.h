/* Telemetry reports (telemetry.c); the tick itself is public. */
#ifndef DARAN_TELEMETRY_H
#define DARAN_TELEMETRY_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_config.h"

#if DARAN_ENABLE_TELEMETRY
/* Can a report with these field bits always fit a reply? */
bool daran_telemetry_fits(uint32_t fields);
#endif

#endif /* DARAN_TELEMETRY_H */

/* Transitional: every stage header at once, for a file not yet moved to
 * the headers of the stages it uses. */
#ifndef DARAN_INTERNAL_H
#define DARAN_INTERNAL_H

#include "checksum.h"
#include "command.h"
#include "compiler.h"
#include "framer.h"
#include "hal.h"
#include "handlers.h"
#include "line.h"
#include "number.h"
#include "property.h"
#include "reply.h"
#include "rx_ring.h"
#include "telemetry.h"
#include "text.h"

#endif /* DARAN_INTERNAL_H */

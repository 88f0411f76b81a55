/* Properties by CAN address (can_address.c), for the front end and the
 * bridge; the frames themselves are the codec's (can_codec.h). */
#ifndef DARAN_CAN_STAGE_H
#define DARAN_CAN_STAGE_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_can.h"
#include "property.h"

/* The property at a CAN address in this build: false when none is. */
bool daran_can_property_at(uint16_t address, daran_prop_t *prop);
#if DARAN_ENABLE_CAN_BRIDGE
/* A property's CAN address, 0 when it has none in this build (the bridge). */
uint16_t daran_can_address_of(daran_prop_t prop);
#endif
/* The type code a property travels with: f32 0, s32 4, u32 and bool 3. */
uint16_t daran_can_type_of(daran_prop_t prop);

#endif /* DARAN_CAN_STAGE_H */

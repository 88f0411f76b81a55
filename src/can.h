/* The CAN front end's own stages (docs/can.md): the address of a property
 * (can_address.c) and the frames of the protocol (can.c). */
#ifndef DARAN_CAN_STAGE_H
#define DARAN_CAN_STAGE_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_can.h"
#include "property.h"

/* The command codes (bits 4..0 of an id) and the system sub-codes. */
#define DARAN_CAN_SYSTEM 0x08u
#define DARAN_CAN_PRESET 0x0Cu
#define DARAN_CAN_TRACK 0x19u
#define DARAN_CAN_TRAPEZOID 0x1Au
#define DARAN_CAN_PASSTHROUGH 0x1Bu
#define DARAN_CAN_VELOCITY 0x1Cu
#define DARAN_CAN_TORQUE 0x1Du
#define DARAN_CAN_READ 0x1Eu
#define DARAN_CAN_WRITE 0x1Fu
#define DARAN_CAN_STATUS 0x01u /* bit 0 of a status frame's code; T is bit 1, E bit 2 */

#define DARAN_CAN_SUB_RESTORE 0x00u
#define DARAN_CAN_SUB_SAVE 0x01u
#define DARAN_CAN_SUB_ESTOP 0x06u
#define DARAN_CAN_SUB_FIRMWARE 0x07u
#define DARAN_CAN_SUB_START_TRACK 0x10u
#define DARAN_CAN_SUB_START_IMPEDANCE 0x15u
#define DARAN_CAN_SUB_FEED 0x20u

/* The type codes of a read or write (bytes 2..3). */
#define DARAN_CAN_TYPE_F32 0u
#define DARAN_CAN_TYPE_U16 1u
#define DARAN_CAN_TYPE_S16 2u
#define DARAN_CAN_TYPE_U32 3u
#define DARAN_CAN_TYPE_S32 4u

/* The codes 0x019..0x01D and the start sub-codes 0x10..0x14 run the motion
 * shapes in their enum order (handlers.h): shape = code - DARAN_CAN_TRACK =
 * sub-code - DARAN_CAN_SUB_START_TRACK. can.c checks the order. */

/* One 8-byte standard frame to the port: true when it took it (can.c, for
 * the front end's own frames and the bridge's). */
bool daran_can_transmit(daran_can_t *can, uint32_t id, const uint8_t *data);

/* The property at a CAN address in this build: false when none is. */
bool daran_can_property_at(uint16_t address, daran_prop_t *prop);
#if DARAN_ENABLE_CAN_BRIDGE
/* A property's CAN address, 0 when it has none in this build (the bridge). */
uint16_t daran_can_address_of(daran_prop_t prop);
#endif
/* The type code a property travels with: f32 0, s32 4, u32 and bool 3. */
uint16_t daran_can_type_of(daran_prop_t prop);

#endif /* DARAN_CAN_STAGE_H */

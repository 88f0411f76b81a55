/* Properties by CAN address: the last column of the property list, grouped
 * by the generator into can_index.h by the address's high byte (the vendor's
 * addresses come in blocks), found by a walk over the groups and then over
 * the group's low bytes. */
#include "can.h"

#if DARAN_ENABLE_CAN

#include "can_index.h"

bool daran_can_property_at(uint16_t address, daran_prop_t *prop)
{
#if DARAN_CAN_ROWS > 0
    unsigned high = (unsigned)address >> 8;
    for (unsigned group = 0; group < DARAN_CAN_GROUPS && can_group_high[group] <= high; group++) {
        if (can_group_high[group] != high) {
            continue;
        }
        for (unsigned row = can_group_first[group]; row < can_group_first[group + 1u]; row++) {
            if (can_low[row] == (address & 0xFFu)) {
                *prop = (daran_prop_t)can_property[row];
                return true;
            }
        }
        break;
    }
#else
    (void)address;
    (void)prop;
#endif
    return false;
}

#if DARAN_ENABLE_CAN_BRIDGE
uint16_t daran_can_address_of(daran_prop_t prop)
{
#if DARAN_CAN_ROWS > 0
    for (unsigned group = 0; group < DARAN_CAN_GROUPS; group++) {
        for (unsigned row = can_group_first[group]; row < can_group_first[group + 1u]; row++) {
            if (can_property[row] == (unsigned)prop) {
                return (uint16_t)(can_group_high[group] << 8 | can_low[row]);
            }
        }
    }
#else
    (void)prop;
#endif
    return 0;
}
#endif

uint16_t daran_can_type_of(daran_prop_t prop)
{
    switch (DARAN_PROPERTY_TYPE(daran_property_row(prop))) {
    case DARAN_TYPE_F32:
        return DARAN_CAN_TYPE_F32;
    case DARAN_TYPE_S32:
        return DARAN_CAN_TYPE_S32;
    default:
        return DARAN_CAN_TYPE_U32;
    }
}

#endif /* DARAN_ENABLE_CAN */

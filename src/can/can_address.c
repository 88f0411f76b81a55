/* Properties by CAN address: the last column of the property list, kept by
 * the generator in can_index.h as runs of consecutive properties whose
 * addresses share their high byte (the vendor numbers a family of paths in
 * a block) and each property's low byte: a frame's property is found by a
 * walk over the runs of its high byte. */
#include "can.h"
#include "can_codec.h"

#if DARAN_ENABLE_CAN

#include "can_index.h"

bool daran_can_property_at(uint16_t address, daran_prop_t *prop)
{
#if DARAN_CAN_ROWS > 0
    /* the runs of the address's high byte, then their low bytes */
    for (unsigned run = 0; run < DARAN_CAN_RUNS; run++) {
        if (can_run_high[run] != (unsigned)address >> 8) {
            continue;
        }
        unsigned first = can_run_first[run];
        for (unsigned p = first; p < first + can_run_count[run]; p++) {
            if (can_low[p] == (address & 0xFFu)) {
                *prop = (daran_prop_t)p;
                return true;
            }
        }
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
    for (unsigned run = 0; run < DARAN_CAN_RUNS; run++) {
        if ((unsigned)prop - can_run_first[run] < can_run_count[run]) {
            return (uint16_t)((unsigned)can_run_high[run] << 8 | can_low[prop]);
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

/* The door's CAN side: the front end's and the bridge's frames to the port's
 * controller and the system sub-codes it leaves to the port. A file of its
 * own so the CAN budget counts it (tests/target/CMakeLists.txt). */
#include <string.h>

#include "daran_can.h"
#include "hal.h"

#if DARAN_ENABLE_CAN
bool daran_send_frame(daran_drive_t *drive, uint32_t id, const uint8_t *data)
{
    daran_can_frame_t frame;
    frame.id = id;
    frame.dlc = 8;
    frame.flags = 0;
    memcpy(frame.data, data, sizeof frame.data);
    return drive->hal->can_send(drive->ctx, &frame);
}

void daran_pass_system(daran_drive_t *drive, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    if (drive->hal->can_system != NULL) {
        drive->hal->can_system(drive->ctx, subcode, data1, data2);
    }
}
#else
typedef int daran_hal_can_needs_daran_enable_can; /* ISO C: no empty file */
#endif

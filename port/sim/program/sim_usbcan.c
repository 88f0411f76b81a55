/* The USB-CAN adapter packet codec of daran-sim's --usbcan (sim_usbcan.h). */
#include "sim_usbcan.h"

#include <string.h>

#define STANDARD_ID_MAX 0x7FFu
#define EXTENDED_ID_MAX 0x1FFFFFFFu
#define DATA_AT 8u

void daran_sim_usbcan_init(daran_sim_usbcan_t *u)
{
    memset(u, 0, sizeof *u);
}

bool daran_sim_usbcan_decode(const uint8_t packet[DARAN_SIM_USBCAN_PACKET],
                             daran_can_frame_t *frame)
{
    uint32_t id = (uint32_t)packet[4] << 24 | (uint32_t)packet[5] << 16 |
                  (uint32_t)packet[6] << 8 | packet[7];
    bool extended = packet[1] == 1u;
    if (packet[0] != DARAN_SIM_USBCAN_START || packet[1] > 1u || packet[2] > 1u ||
        packet[3] > 8u || id > (extended ? EXTENDED_ID_MAX : STANDARD_ID_MAX)) {
        return false;
    }
    memset(frame, 0, sizeof *frame);
    frame->id = id;
    frame->dlc = packet[3];
    frame->flags = (uint8_t)((extended ? DARAN_CAN_FRAME_EXTENDED : 0u) |
                             (packet[2] == 1u ? DARAN_CAN_FRAME_REMOTE : 0u));
    if (packet[2] == 0u) {
        memcpy(frame->data, packet + DATA_AT, packet[3]);
    }
    return true;
}

void daran_sim_usbcan_encode(const daran_can_frame_t *frame,
                             uint8_t packet[DARAN_SIM_USBCAN_PACKET])
{
    bool remote = (frame->flags & DARAN_CAN_FRAME_REMOTE) != 0u;
    uint8_t dlc = frame->dlc > 8u ? 8u : frame->dlc;
    memset(packet, 0, DARAN_SIM_USBCAN_PACKET);
    packet[0] = DARAN_SIM_USBCAN_START;
    packet[1] = (frame->flags & DARAN_CAN_FRAME_EXTENDED) != 0u ? 1u : 0u;
    packet[2] = remote ? 1u : 0u;
    packet[3] = dlc;
    packet[4] = (uint8_t)(frame->id >> 24);
    packet[5] = (uint8_t)(frame->id >> 16);
    packet[6] = (uint8_t)(frame->id >> 8);
    packet[7] = (uint8_t)frame->id;
    if (!remote) {
        memcpy(packet + DATA_AT, frame->data, dlc);
    }
}

/* The packet under way is not valid: keep what follows its next 0xAA. */
static void resynchronise(daran_sim_usbcan_t *u)
{
    size_t start = 1u;
    while (start < u->len && u->packet[start] != DARAN_SIM_USBCAN_START) {
        start++;
    }
    u->skipped += (uint32_t)start;
    memmove(u->packet, u->packet + start, u->len - start);
    u->len -= start;
}

size_t daran_sim_usbcan_take(daran_sim_usbcan_t *u, const uint8_t *bytes, size_t len,
                             daran_can_frame_t *frame, bool *got)
{
    size_t k;
    *got = false;
    for (k = 0; k < len; k++) {
        if (u->len == 0u && bytes[k] != DARAN_SIM_USBCAN_START) {
            u->skipped++;
            continue;
        }
        u->packet[u->len++] = bytes[k];
        if (u->len < DARAN_SIM_USBCAN_PACKET) {
            continue;
        }
        if (daran_sim_usbcan_decode(u->packet, frame)) {
            u->len = 0u;
            *got = true;
            return k + 1u;
        }
        resynchronise(u);
    }
    return len;
}

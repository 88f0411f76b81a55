/* The `!can` directive's frame and the console's line for a received frame
 * (sim_can_text.h). */
#include "sim_can_text.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STANDARD_ID_MAX 0x7FFu
#define EXTENDED_ID_MAX 0x1FFFFFFFu
#define EXTENDED_ID_DIGITS 8u

/* Only hex digits, none of sscanf's signs, spaces or 0x prefixes. */
static bool all_hex(const char *text)
{
    return text[0] != '\0' && strspn(text, "0123456789abcdefABCDEF") == strlen(text);
}

static bool parse_id(const char *text, daran_can_frame_t *frame, const char **why)
{
    size_t digits = strlen(text);
    unsigned long id;
    if (!all_hex(text) || (digits > 3u && digits != EXTENDED_ID_DIGITS)) {
        *why = "the id is 1 to 3 hex digits (standard, up to 7FF) or 8 (extended)";
        return false;
    }
    id = strtoul(text, NULL, 16);
    if (digits == EXTENDED_ID_DIGITS) {
        if (id > EXTENDED_ID_MAX) {
            *why = "an extended id is at most 1FFFFFFF";
            return false;
        }
        frame->flags |= DARAN_CAN_FRAME_EXTENDED;
    } else if (id > STANDARD_ID_MAX) {
        *why = "a standard id is at most 7FF";
        return false;
    }
    frame->id = (uint32_t)id;
    return true;
}

/* `R` or `Rn`: a remote frame of DLC n (0 when not given). */
static bool parse_remote(const char *text, daran_can_frame_t *frame, const char **why)
{
    if (text[1] != '\0' && (text[1] < '0' || text[1] > '8' || text[2] != '\0')) {
        *why = "a remote frame is R or R0..R8 (its DLC)";
        return false;
    }
    frame->flags |= DARAN_CAN_FRAME_REMOTE;
    frame->dlc = (uint8_t)(text[1] == '\0' ? 0 : text[1] - '0');
    return true;
}

bool sim_can_text_parse(int argc, char *const *argv, daran_can_frame_t *frame, const char **why)
{
    int k;
    memset(frame, 0, sizeof *frame);
    if (argc < 1) {
        *why = "usage: !can ID [BYTES...] (hex)";
        return false;
    }
    if (!parse_id(argv[0], frame, why)) {
        return false;
    }
    if (argc == 2 && (argv[1][0] == 'R' || argv[1][0] == 'r')) {
        return parse_remote(argv[1], frame, why);
    }
    for (k = 1; k < argc; k++) {
        const char *hex = argv[k];
        size_t digits = strlen(hex);
        size_t i;
        if (!all_hex(hex) || digits % 2u != 0u) {
            *why = "data bytes are two hex digits each";
            return false;
        }
        if (frame->dlc + digits / 2u > 8u) {
            *why = "a frame holds at most 8 data bytes";
            return false;
        }
        for (i = 0; i < digits; i += 2u) {
            char pair[3] = {hex[i], hex[i + 1u], '\0'};
            frame->data[frame->dlc++] = (uint8_t)strtoul(pair, NULL, 16);
        }
    }
    return true;
}

size_t sim_can_text_format(const daran_can_frame_t *frame, uint64_t ns,
                           char out[SIM_CAN_TEXT_LINE_MAX])
{
    bool extended = (frame->flags & DARAN_CAN_FRAME_EXTENDED) != 0u;
    uint64_t us = ns / 1000u + (ns % 1000u >= 500u ? 1u : 0u); /* ns + 500 may wrap */
    unsigned dlc = frame->dlc > 8u ? 8u : frame->dlc;
    int n = snprintf(out, SIM_CAN_TEXT_LINE_MAX, "can %" PRIu64 ".%06" PRIu64 " %0*" PRIX32 " [%u]",
                     us / 1000000u, us % 1000000u, extended ? 8 : 3, frame->id, dlc);
    unsigned k;
    if ((frame->flags & DARAN_CAN_FRAME_REMOTE) != 0u) {
        n += snprintf(out + n, SIM_CAN_TEXT_LINE_MAX - (size_t)n, " remote");
    } else {
        for (k = 0; k < dlc; k++) {
            n += snprintf(out + n, SIM_CAN_TEXT_LINE_MAX - (size_t)n, " %02X", frame->data[k]);
        }
    }
    out[n++] = '\n';
    out[n] = '\0';
    return (size_t)n;
}

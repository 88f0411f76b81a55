/* The slcan (Lawicel) codec of daran-sim's --slcan (sim_slcan.h). */
#include "sim_slcan.h"

#include <string.h>

#define CR '\r'
#define BEL '\a'
#define STANDARD_ID_MAX 0x7FFu
#define EXTENDED_ID_MAX 0x1FFFFFFFu
#define TIMESTAMP_WRAP_MS 60000u

static const char hex_digits[] = "0123456789ABCDEF";

/* The value of one hex digit, or -1. */
static int hex_value(char c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    return -1;
}

/* @p digits hex digits at @p text as a number: false when one is not hex. */
static bool hex_number(const char *text, size_t digits, uint32_t *out)
{
    uint32_t value = 0u;
    size_t k;
    for (k = 0; k < digits; k++) {
        int v = hex_value(text[k]);
        if (v < 0) {
            return false;
        }
        value = value << 4 | (uint32_t)v;
    }
    *out = value;
    return true;
}

static size_t put_hex(char *out, uint32_t value, size_t digits)
{
    size_t k;
    for (k = 0; k < digits; k++) {
        out[k] = hex_digits[(value >> (4u * (digits - 1u - k))) & 0xFu];
    }
    return digits;
}

bool daran_sim_slcan_parse_frame(const char *command, size_t len, daran_can_frame_t *frame)
{
    bool extended = command[0] == 'T' || command[0] == 'R';
    bool remote = command[0] == 'r' || command[0] == 'R';
    size_t id_digits = extended ? 8u : 3u;
    size_t data_at = 1u + id_digits + 1u;
    uint32_t id;
    uint32_t dlc;
    size_t k;
    if ((command[0] != 't' && command[0] != 'r' && !extended) || len < data_at ||
        !hex_number(command + 1, id_digits, &id) || id > (extended ? EXTENDED_ID_MAX : STANDARD_ID_MAX) ||
        command[data_at - 1u] < '0' || command[data_at - 1u] > '8') {
        return false;
    }
    dlc = (uint32_t)(command[data_at - 1u] - '0');
    if (len != data_at + (remote ? 0u : 2u * dlc)) {
        return false;
    }
    memset(frame, 0, sizeof *frame);
    frame->id = id;
    frame->dlc = (uint8_t)dlc;
    frame->flags = (uint8_t)((extended ? DARAN_CAN_FRAME_EXTENDED : 0u) |
                             (remote ? DARAN_CAN_FRAME_REMOTE : 0u));
    for (k = 0; !remote && k < dlc; k++) {
        uint32_t byte;
        if (!hex_number(command + data_at + 2u * k, 2u, &byte)) {
            return false;
        }
        frame->data[k] = (uint8_t)byte;
    }
    return true;
}

size_t daran_sim_slcan_encode(const daran_sim_slcan_t *s, const daran_can_frame_t *frame,
                              uint32_t ms, char out[DARAN_SIM_SLCAN_LINE_MAX])
{
    bool extended = (frame->flags & DARAN_CAN_FRAME_EXTENDED) != 0u;
    bool remote = (frame->flags & DARAN_CAN_FRAME_REMOTE) != 0u;
    uint32_t dlc = frame->dlc > 8u ? 8u : frame->dlc;
    size_t n = 0u;
    uint32_t k;
    if (!s->open) {
        return 0u;
    }
    out[n++] = remote ? (extended ? 'R' : 'r') : (extended ? 'T' : 't');
    n += put_hex(out + n, frame->id, extended ? 8u : 3u);
    out[n++] = (char)('0' + dlc);
    for (k = 0; !remote && k < dlc; k++) {
        n += put_hex(out + n, frame->data[k], 2u);
    }
    if (s->timestamps) {
        n += put_hex(out + n, ms % TIMESTAMP_WRAP_MS, 4u);
    }
    out[n++] = CR;
    return n;
}

void daran_sim_slcan_init(daran_sim_slcan_t *s)
{
    memset(s, 0, sizeof *s);
}

static void answer(const daran_sim_slcan_io_t *io, const char *text)
{
    io->reply(io->ctx, text, strlen(text));
}

/* A setting that only a closed channel takes (`Sn`, `Zn`, `Xn`, `Un`):
 * its one digit, or -1 when the channel is open or the form is wrong. */
static int closed_setting(const daran_sim_slcan_t *s)
{
    if (s->open || s->len != 2u || s->command[1] < '0' || s->command[1] > '9') {
        return -1;
    }
    return s->command[1] - '0';
}

static void transmit(daran_sim_slcan_t *s, const daran_sim_slcan_io_t *io)
{
    daran_can_frame_t frame;
    if (!s->open || s->listen_only || !daran_sim_slcan_parse_frame(s->command, s->len, &frame) ||
        !io->send(io->ctx, &frame)) {
        answer(io, "\a");
        return;
    }
    answer(io, (frame.flags & DARAN_CAN_FRAME_EXTENDED) != 0u ? "Z\r" : "z\r");
}

static void status_flags(daran_sim_slcan_t *s, const daran_sim_slcan_io_t *io)
{
    char text[4];
    if (!s->open || s->len != 1u) {
        answer(io, "\a");
        return;
    }
    text[0] = 'F';
    (void)put_hex(text + 1, s->status, 2u);
    text[3] = '\0';
    answer(io, text);
    answer(io, "\r");
    s->status &= (uint8_t)~DARAN_SIM_SLCAN_STATUS_OVERRUN; /* read: the latch clears */
}

/* `V`, `v`, `N`: the command's letter, four characters, CR. */
static void identity(const daran_sim_slcan_t *s, const daran_sim_slcan_io_t *io, const char *what)
{
    if (s->len != 1u) {
        answer(io, "\a");
        return;
    }
    io->reply(io->ctx, s->command, 1u);
    answer(io, what);
    answer(io, "\r");
}

/* One whole command (without its CR). */
static void run_command(daran_sim_slcan_t *s, const daran_sim_slcan_io_t *io)
{
    int digit = closed_setting(s);
    if (s->overlong) {
        answer(io, "\a");
        return;
    }
    if (s->len == 0u) {
        answer(io, "\r"); /* a bare CR: hosts send a few to empty the adapter's buffer */
        return;
    }
    switch (s->command[0]) {
    case 'S': /* bit rate: the simulated bus runs at 1 Mbit/s (S8) only */
    case 'X': /* auto-poll: always on (frames go to the host at once) */
        answer(io, digit == (s->command[0] == 'S' ? 8 : 1) ? "\r" : "\a");
        break;
    case 'Z':
        if (digit == 0 || digit == 1) {
            s->timestamps = digit == 1;
        }
        answer(io, digit == 0 || digit == 1 ? "\r" : "\a");
        break;
    case 'U': /* the serial line's speed: a pseudo-terminal has none */
        answer(io, digit >= 0 && digit <= 6 ? "\r" : "\a");
        break;
    case 'O':
    case 'L':
        if (s->open || s->len != 1u) {
            answer(io, "\a");
            break;
        }
        s->open = true;
        s->listen_only = s->command[0] == 'L';
        answer(io, "\r");
        break;
    case 'C':
        s->open = false;
        s->listen_only = false;
        answer(io, s->len == 1u ? "\r" : "\a");
        break;
    case 't':
    case 'T':
    case 'r':
    case 'R':
        transmit(s, io);
        break;
    case 'F':
        status_flags(s, io);
        break;
    case 'V': /* hardware and software version */
    case 'v': /* software version */
        identity(s, io, DARAN_SIM_SLCAN_VERSION);
        break;
    case 'N':
        identity(s, io, DARAN_SIM_SLCAN_SERIAL);
        break;
    default: /* s (BTR registers), M/m (filters), P/A (polling), W, Q: not offered */
        answer(io, "\a");
        break;
    }
}

size_t daran_sim_slcan_take(daran_sim_slcan_t *s, const uint8_t *bytes, size_t len,
                            const daran_sim_slcan_io_t *io)
{
    size_t k;
    for (k = 0; k < len; k++) {
        char c = (char)bytes[k];
        if (c == CR) {
            run_command(s, io);
            s->len = 0u;
            s->overlong = false;
            return k + 1u;
        }
        if (c == '\n') {
            continue;
        }
        if (s->len < sizeof s->command) {
            s->command[s->len++] = c;
        } else {
            s->overlong = true;
        }
    }
    return len;
}

/* daran-sim's --slcan and --usbcan adapters (sim_can_pty.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_can_pty.h"

#include <errno.h>
#include <poll.h>
#include <string.h>
#include <unistd.h>

#include "sim_pty.h"

static bool out_room(const sim_can_pty_t *p, size_t len)
{
    return len <= SIM_CAN_PTY_OUT_MAX - p->out_len;
}

static void out_put(sim_can_pty_t *p, const void *bytes, size_t len)
{
    if (p->out_start + p->out_len + len > SIM_CAN_PTY_OUT_MAX) {
        memmove(p->out, p->out + p->out_start, p->out_len);
        p->out_start = 0u;
    }
    memcpy(p->out + p->out_start + p->out_len, bytes, len);
    p->out_len += len;
}

/* A frame that crossed the bus, for the client (whole, or dropped). */
static void deliver(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    sim_can_pty_t *p = ctx;
    uint8_t bytes[DARAN_SIM_SLCAN_LINE_MAX > DARAN_SIM_USBCAN_PACKET ? DARAN_SIM_SLCAN_LINE_MAX
                                                                      : DARAN_SIM_USBCAN_PACKET];
    size_t len = DARAN_SIM_USBCAN_PACKET;
    if (p->kind == SIM_CAN_PTY_SLCAN) {
        len = daran_sim_slcan_encode(&p->slcan, frame, (uint32_t)(end_ns / 1000000u),
                                     (char *)bytes);
    } else {
        daran_sim_usbcan_encode(frame, bytes);
    }
    if (len == 0u) {
        return; /* a closed slcan channel passes nothing */
    }
    if (!out_room(p, len)) {
        p->dropped++;
        p->slcan.status |= DARAN_SIM_SLCAN_STATUS_OVERRUN;
        return;
    }
    out_put(p, bytes, len);
}

static bool send_frame(void *ctx, const daran_can_frame_t *frame)
{
    sim_can_pty_t *p = ctx;
    if (daran_sim_can_bus_send(p->bus, p->node, frame)) {
        return true;
    }
    p->refused++;
    return false;
}

static void reply(void *ctx, const char *bytes, size_t len)
{
    sim_can_pty_t *p = ctx;
    if (out_room(p, len)) {
        out_put(p, bytes, len);
    } else {
        p->dropped++; /* a client that reads nothing loses answers as it loses frames */
    }
}

bool sim_can_pty_open(sim_can_pty_t *p, sim_can_pty_kind_t kind, daran_sim_can_bus_t *bus)
{
    memset(p, 0, sizeof *p);
    p->kind = kind;
    p->bus = bus;
    daran_sim_slcan_init(&p->slcan);
    daran_sim_usbcan_init(&p->usbcan);
    p->fd = sim_pty_open(p->path, sizeof p->path, &p->slave_keep);
    if (p->fd < 0) {
        return false;
    }
    p->node = daran_sim_can_bus_add_node(bus, deliver, p);
    if (p->node == DARAN_SIM_CAN_ANY_NODE) {
        sim_can_pty_close(p);
        errno = EMFILE;
        return false;
    }
    return true;
}

/* The adapter takes the client's next command or packet only while its
 * transmit queue has room (a bus-off adapter's queue is empty: it takes
 * them, and refuses the frames) and its output is not piling up. */
static bool may_take(const sim_can_pty_t *p)
{
    return p->bus->node[p->node].queued < DARAN_SIM_CAN_TX_FRAMES &&
           out_room(p, SIM_CAN_PTY_OUT_MAX / 2u);
}

short sim_can_pty_events(const sim_can_pty_t *p)
{
    short events = 0;
    if (p->in_pos == p->in_len && may_take(p)) {
        events |= POLLIN;
    }
    if (p->out_len > 0u) {
        events |= POLLOUT;
    }
    return events;
}

static void take_input(sim_can_pty_t *p)
{
    const daran_sim_slcan_io_t io = {send_frame, reply, p};
    bool off = p->bus->bus_off || p->bus->node[p->node].bus_off;
    if (off) {
        p->slcan.status |= DARAN_SIM_SLCAN_STATUS_BUS_ERROR;
    } else {
        p->slcan.status &= (uint8_t)~DARAN_SIM_SLCAN_STATUS_BUS_ERROR;
    }
    while (p->in_pos < p->in_len && may_take(p)) {
        const uint8_t *bytes = p->in + p->in_pos;
        size_t len = p->in_len - p->in_pos;
        if (p->kind == SIM_CAN_PTY_SLCAN) {
            p->in_pos += daran_sim_slcan_take(&p->slcan, bytes, len, &io);
        } else {
            daran_can_frame_t frame;
            bool got;
            p->in_pos += daran_sim_usbcan_take(&p->usbcan, bytes, len, &frame, &got);
            if (got) {
                (void)send_frame(p, &frame);
            }
        }
    }
}

void sim_can_pty_serve(sim_can_pty_t *p, short revents)
{
    if ((revents & POLLIN) != 0 && p->in_pos == p->in_len) {
        ssize_t n = read(p->fd, p->in, sizeof p->in);
        if (n > 0) {
            p->in_pos = 0u;
            p->in_len = (size_t)n;
        }
    }
    take_input(p);
    sim_can_pty_flush(p);
}

void sim_can_pty_flush(sim_can_pty_t *p)
{
    while (p->out_len > 0u) {
        ssize_t n = write(p->fd, p->out + p->out_start, p->out_len);
        if (n > 0) {
            p->out_start += (size_t)n;
            p->out_len -= (size_t)n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            break; /* EAGAIN: the client is not reading; wait for POLLOUT */
        }
    }
    if (p->out_len == 0u) {
        p->out_start = 0u;
    }
}

const char *sim_can_pty_option(const sim_can_pty_t *p)
{
    return p->kind == SIM_CAN_PTY_SLCAN ? "--slcan" : "--usbcan";
}

void sim_can_pty_close(sim_can_pty_t *p)
{
    if (p->slave_keep >= 0) {
        close(p->slave_keep);
        p->slave_keep = -1;
    }
    if (p->fd >= 0) {
        close(p->fd);
        p->fd = -1;
    }
}

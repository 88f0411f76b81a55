/* daran-sim's --pty output queue (sim_outq.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_outq.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

#include "sim_app.h"
#include "sim_diag.h"

/* The queue holds OUTQ_HIGH plus the replies of one line on every drive
 * (DARAN_SIM_OUT_MAX each) and telemetry. */
#define OUTQ_HIGH (1024u * 1024u)
#define OUTQ_CAP (OUTQ_HIGH + DARAN_SIM_MAX_DRIVES * DARAN_SIM_OUT_MAX + 256u * 1024u)

static struct {
    char buf[OUTQ_CAP];
    size_t start;
    size_t len;
    unsigned long dropped_lines; /* whole lines that found the queue full, not yet told */
} outq;

static bool outq_put(const char *bytes, size_t len)
{
    if (len > OUTQ_CAP - outq.len) {
        return false;
    }
    if (outq.start + outq.len + len > OUTQ_CAP) {
        memmove(outq.buf, outq.buf + outq.start, outq.len);
        outq.start = 0u;
    }
    memcpy(outq.buf + outq.start + outq.len, bytes, len);
    outq.len += len;
    return true;
}

void sink_pty(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    (void)id;
    if (outq_put(bytes, len)) {
        return;
    }
    /* Only telemetry can find the queue full (replies are made only below
     * OUTQ_HIGH): keep the whole lines that fit, count the others. */
    while (len > 0u) {
        const char *nl = memchr(bytes, '\n', len);
        size_t n = nl != NULL ? (size_t)(nl - bytes) + 1u : len;
        if (!outq_put(bytes, n)) {
            outq.dropped_lines++;
        }
        bytes += n;
        len -= n;
    }
}

void outq_flush(void)
{
    while (outq.len > 0u) {
        ssize_t n = write(app.pty_fd, outq.buf + outq.start, outq.len);
        if (n > 0) {
            outq.start += (size_t)n;
            outq.len -= (size_t)n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            break; /* the client is not reading: wait for POLLOUT */
        } else {
            diag_msg("--pty: write failed (%s): %zu bytes of replies dropped",
                     n < 0 ? strerror(errno) : "nothing written", outq.len);
            outq.len = 0u;
        }
    }
    if (outq.len == 0u) {
        outq.start = 0u;
    }
}

/* Lines dropped are told at most once a second (and at the end), with
 * their count. */
void outq_report(bool final)
{
    static double last_s = -1.0;
    double t = now_s();
    if (outq.dropped_lines > 0ul && (final || last_s < 0.0 || t - last_s >= 1.0)) {
        diag_urgent("--pty: %lu telemetry lines dropped: the client has not read the last "
                    "%u KiB of output",
                    outq.dropped_lines, (unsigned)(outq.len / 1024u));
        outq.dropped_lines = 0ul;
        last_s = t;
    }
}

size_t outq_pending(void)
{
    return outq.len;
}

bool outq_has_room(void)
{
    return outq.len < OUTQ_HIGH;
}

/* daran-sim in lock-step (sim_lockstep.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_lockstep.h"

#include <errno.h>
#include <poll.h>
#include <string.h>
#include <unistd.h>

#include "sim_app.h"
#include "sim_diag.h"
#include "sim_lines.h"
#include "sim_replies.h"

static line_source_t stdin_source;

/* stdin is polled (a signal's EINTR, or at worst the 250 ms timeout, ends
 * the wait) and read in chunks; lines are taken one at a time. */
void run_lockstep(void)
{
    char buf[4096];
    source_init(&stdin_source, true, sink_stdout);
    while (stop_signal == 0) {
        struct pollfd p = {STDIN_FILENO, POLLIN, 0};
        ssize_t n;
        int r = poll(&p, 1, 250);
        if (r < 0 && errno != EINTR) {
            diag_urgent("stdin: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (r <= 0) {
            continue;
        }
        n = read(STDIN_FILENO, buf, sizeof buf);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) {
            continue;
        }
        if (n < 0) {
            diag_urgent("stdin: %s", strerror(errno));
            app.status = 1;
            break;
        }
        if (n == 0) {
            break;
        }
        source_feed(&stdin_source, buf, (size_t)n);
        diag_tick();
    }
    source_eof(&stdin_source);
}

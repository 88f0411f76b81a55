/* The port: a POSIX serial device (or pseudo-terminal) in raw mode, as the
 * byte transport daran_client's link needs (cli.h). */
#define _DEFAULT_SOURCE /* cfmakeraw, cfsetspeed */
#include "serial.h"

#include <errno.h>
#include <fcntl.h>
#include <glob.h>
#include <poll.h>
#include <sys/file.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

/* How long a write may wait for the port to take bytes before it is a
 * port error (a USB adapter pulled out, a drive holding off forever). */
#define WRITE_STALL_MS 1000

uint32_t cli_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

static bool speed_of(uint32_t baud, speed_t *out)
{
    static const struct { uint32_t baud; speed_t code; } speeds[] = {
        {9600, B9600},     {19200, B19200},   {38400, B38400},     {57600, B57600},
        {115200, B115200}, {230400, B230400}, {460800, B460800},   {500000, B500000},
        {921600, B921600}, {1000000, B1000000}, {2000000, B2000000},
    };
    for (size_t i = 0; i < sizeof speeds / sizeof speeds[0]; i++) {
        if (speeds[i].baud == baud) {
            *out = speeds[i].code;
            return true;
        }
    }
    return false;
}

bool cli_serial_baud_supported(uint32_t baud)
{
    speed_t unused;
    return speed_of(baud, &unused);
}

int cli_serial_open(const char *path, uint32_t baud)
{
    speed_t speed;
    if (!speed_of(baud, &speed)) {
        errno = EINVAL;
        return -1;
    }
    int fd = open(path, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        return -1;
    }
    /* Two programs reading one port would each get half of the replies. */
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        int saved = errno == EWOULDBLOCK ? EBUSY : errno;
        close(fd);
        errno = saved;
        return -1;
    }
    struct termios tio;
    if (!isatty(fd) || tcgetattr(fd, &tio) != 0) {
        int saved = errno ? errno : ENOTTY;
        close(fd);
        errno = saved;
        return -1;
    }
    cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cflag &= ~(tcflag_t)CRTSCTS;
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    cfsetspeed(&tio, speed);
    if (tcsetattr(fd, TCSANOW, &tio) != 0) {
        int saved = errno;
        close(fd);
        errno = saved;
        return -1;
    }
    /* What an earlier program left unread is not a reply to us. */
    tcflush(fd, TCIFLUSH);
    return fd;
}

static bool serial_write(void *ctx, const char *bytes, size_t len)
{
    cli_session_t *s = ctx;
    uint32_t start = cli_now_ms();
    while (len > 0) {
        ssize_t n = write(s->fd, bytes, len);
        if (n > 0) {
            bytes += n;
            len -= (size_t)n;
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR) {
            break;
        }
        uint32_t waited = cli_now_ms() - start;
        if (waited >= WRITE_STALL_MS) {
            errno = ETIMEDOUT;
            break;
        }
        struct pollfd pfd = {.fd = s->fd, .events = POLLOUT};
        (void)poll(&pfd, 1, (int)(WRITE_STALL_MS - waited));
    }
    if (len == 0) {
        return true;
    }
    if (!s->port_failed) {
        s->port_failed = true;
        s->port_errno = errno;
        s->port_what = "write";
    }
    return false;
}

static size_t serial_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms)
{
    cli_session_t *s = ctx;
    if (s->port_failed) {
        return 0;
    }
    struct pollfd pfd = {.fd = s->fd, .events = POLLIN};
    int ready = poll(&pfd, 1, cli_interrupted() ? 0 : (int)timeout_ms);
    if (ready <= 0) {
        return 0; /* timeout, or a signal: the caller looks at cli_interrupted() */
    }
    ssize_t n = read(s->fd, buf, size);
    if (n > 0) {
        return (size_t)n;
    }
    if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
        /* The other end went away (a pseudo-terminal's master closed, a USB
         * adapter unplugged: EIO or end of file). */
        s->port_failed = true;
        s->port_errno = n == 0 ? EIO : errno;
        s->port_what = "read";
    }
    return 0;
}

void cli_serial_wait(cli_session_t *s, uint32_t timeout_ms)
{
    struct pollfd pfd = {.fd = s->fd, .events = POLLIN};
    (void)poll(&pfd, 1, (int)timeout_ms);
}

static uint32_t serial_now(void *ctx)
{
    (void)ctx;
    return cli_now_ms();
}

void cli_serial_transport(cli_session_t *s)
{
    s->transport.write = serial_write;
    s->transport.read = serial_read;
    s->transport.now_ms = serial_now;
    s->transport.ctx = s;
}

size_t cli_serial_candidates(char paths[][256], size_t max)
{
    size_t count = 0;
    static const char *const patterns[] = {"/dev/ttyACM*", "/dev/ttyUSB*"};
    for (size_t p = 0; p < 2; p++) {
        glob_t found;
        if (glob(patterns[p], 0, NULL, &found) != 0) {
            continue;
        }
        for (size_t i = 0; i < found.gl_pathc; i++) {
            if (count < max) {
                (void)snprintf(paths[count], 256, "%s", found.gl_pathv[i]);
            }
            count++;
        }
        globfree(&found);
    }
    return count;
}

/* daran-sim's pseudo-terminals (sim_pty.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_pty.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

int sim_pty_open(char *path, size_t path_size, int *slave_keep)
{
    struct termios tio;
    const char *name;
    int fd = posix_openpt(O_RDWR | O_NOCTTY);
    *slave_keep = -1;
    if (fd < 0) {
        return -1;
    }
    if (grantpt(fd) != 0 || unlockpt(fd) != 0 || (name = ptsname(fd)) == NULL) {
        close(fd);
        return -1;
    }
    snprintf(path, path_size, "%s", name);
    *slave_keep = open(path, O_RDWR | O_NOCTTY);
    if (*slave_keep >= 0 && tcgetattr(*slave_keep, &tio) == 0) {
        cfmakeraw(&tio);
        (void)tcsetattr(*slave_keep, TCSANOW, &tio);
    }
    (void)fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    return fd;
}

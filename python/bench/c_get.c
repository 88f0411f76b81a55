/* The C client's side of docs/python.md's figures: N `r` of one property
 * (daran_client_transact) over a serial port, the time per call. The
 * Python package's side is figures.py; both run against one daran-sim --pty.
 * Usage: c_get PORT N */
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "daran_client.h"

static int port_fd;

static bool port_write(void *ctx, const char *bytes, size_t len)
{
    (void)ctx;
    return write(port_fd, bytes, len) == (ssize_t)len;
}

static size_t port_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms)
{
    (void)ctx;
    struct pollfd p = {port_fd, POLLIN, 0};
    if (poll(&p, 1, (int)timeout_ms) <= 0) {
        return 0;
    }
    ssize_t n = read(port_fd, buf, size);
    return n > 0 ? (size_t)n : 0;
}

static uint32_t now_ms(void *ctx)
{
    (void)ctx;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (uint32_t)(t.tv_sec * 1000 + t.tv_nsec / 1000000);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: c_get PORT N\n");
        return 2;
    }
    port_fd = open(argv[1], O_RDWR | O_NOCTTY);
    struct termios tio;
    if (port_fd < 0 || tcgetattr(port_fd, &tio) != 0) {
        perror(argv[1]);
        return 1;
    }
    cfmakeraw(&tio);
    tcsetattr(port_fd, TCSANOW, &tio);
    long n = atol(argv[2]);
    daran_client_transport_t transport = {port_write, port_read, now_ms, NULL};
    daran_client_link_config_t config = {.retries = 1, .quiet_ms = 5};
    daran_client_link_t link;
    if (daran_client_link_init(&link, &transport, &config) != DARAN_OK) {
        return 1;
    }
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_R, .id = 1,
                                      .path = "output_shaft.vel_limit"};
    struct timespec t0, t1;
    for (long i = -100; i < n; i++) {
        if (i == 0) {
            clock_gettime(CLOCK_MONOTONIC, &t0);
        }
        if (daran_client_transact(&link, &request, 50, NULL, NULL, NULL) != DARAN_OK) {
            fprintf(stderr, "c_get: request %ld failed\n", i);
            return 1;
        }
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double us = ((double)(t1.tv_sec - t0.tv_sec) * 1e9 + (double)(t1.tv_nsec - t0.tv_nsec)) / 1e3;
    printf("%.1f\n", us / (double)n);
    return 0;
}

/* The minimal port's move mailbox between two real threads, as the main
 * loop and the control interrupt: the main thread runs `p 1 N N N` lines
 * through the core (the HAL posts each move), the control thread takes
 * moves as fast as it can. Built with -fsanitize=thread by CTest
 * (tests/stress/CMakeLists.txt): no data race may be reported. The program
 * also checks what ThreadSanitizer cannot: every move taken is whole (its
 * three values agree: no words of two moves mixed), moves arrive in order,
 * and the last one is taken.
 *
 * usage: mailbox_threads [MOVES] */
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

#include "minimal_hal.h"

static minimal_drive_t axis;
static daran_drive_t drive;
static atomic_int done;
static unsigned long moves_total = 100000;
static unsigned long taken, torn, out_of_order;
static float last_taken;

static void write_line(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    fprintf(stderr, "unexpected reply: %.*s", (int)len, line);
    exit(1);
}

static const daran_hal_t write_line_port = {MINIMAL_HAL_FUNCTIONS, .write = write_line};

static void *control_loop(void *arg)
{
    (void)arg;
    daran_move_t move;
    for (;;) {
        int finished = atomic_load(&done);
        if (minimal_drive_take_move(&axis, &move)) {
            if (move.pos_deg != move.vel_rpm || move.pos_deg != move.torque_nm) {
                torn++;
            }
            if (taken > 0 && !(move.pos_deg > last_taken)) {
                out_of_order++;
            }
            last_taken = move.pos_deg;
            taken++;
        } else if (finished) {
            return NULL;
        }
    }
}

int main(int argc, char **argv)
{
    if (argc > 1) {
        moves_total = strtoul(argv[1], NULL, 10);
    }
    minimal_drive_init(&axis);
    if (daran_init(&drive, &write_line_port, &axis) != DARAN_OK) {
        return 2;
    }
    pthread_t thread;
    if (pthread_create(&thread, NULL, control_loop, NULL) != 0) {
        return 2;
    }
    for (unsigned long n = 1; n <= moves_total; n++) {
        char line[64];
        int len = snprintf(line, sizeof line, "p 1 %lu %lu %lu", n, n, n);
        if (daran_process_line(&drive, line, (size_t)len) != DARAN_OK) {
            return 2;
        }
    }
    atomic_store(&done, 1);
    pthread_join(thread, NULL);
    int ok = torn == 0 && out_of_order == 0 && taken > 0 && last_taken == (float)moves_total;
    printf("mailbox_threads: %lu moves posted, %lu taken, %lu torn, %lu out of order, last %.0f\n",
           moves_total, taken, torn, out_of_order, (double)last_taken);
    printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
    return ok ? 0 : 1;
}

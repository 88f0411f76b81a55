/* Two threads on one drive, as an interrupt and a main loop: the producer
 * feeds numbered motion lines in random chunks through daran_rx_write() and
 * daran_rx_byte(), the consumer runs daran_poll(). Built with
 * -fsanitize=thread by CTest (tests/stress/CMakeLists.txt): the ring's
 * shared state must be free of data races. The program also checks what
 * ThreadSanitizer cannot: every line arrives whole and in order, or is
 * answered `line too long` when the ring dropped some of its bytes, and no
 * other reply appears.
 *
 * usage: ring_threads [LINES] */
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_ascii.h"

static daran_drive_t drive;
static atomic_int producer_done;
static unsigned long moves, last_target, out_of_order, errors_other, too_long;

static daran_result_t hal_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    out->u64 = 0;
    if (prop == DARAN_PROP_CAN_NODE_ID) {
        out->u32 = 1;
    } else if (prop == DARAN_PROP_CURRENT_STATE) {
        out->u32 = DARAN_STATE_CLOSED_LOOP;
    }
    return DARAN_OK;
}

static daran_result_t hal_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    (void)prop;
    (void)value;
    return DARAN_OK;
}

static daran_result_t hal_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    unsigned long target = (unsigned long)move->pos_deg;
    if (moves > 0 && target <= last_target) {
        out_of_order++;
    }
    last_target = target;
    moves++;
    return DARAN_OK;
}

static daran_result_t hal_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_OK;
}

static void write_line(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len == 22 && memcmp(line, "error: line too long\r\n", 22) == 0) {
        too_long++;
    } else {
        errors_other++;
        fprintf(stderr, "unexpected reply: %.*s", (int)len, line);
    }
}

static unsigned long lines_total = 200000;

static void *producer(void *arg)
{
    unsigned seed = 12345;
    char text[64];
    (void)arg;
    for (unsigned long n = 1; n <= lines_total; n++) {
        int len = snprintf(text, sizeof text, "t 1 %lu\n", n);
        seed = seed * 1103515245u + 12345u;
        /* Most lines wait for room, as a UART with flow control would; one
         * in 64 is pushed regardless, so the ring also overflows. */
        if ((seed >> 20) % 64u != 0u) {
            while (daran_rx_free(&drive) < (size_t)len) {
                sched_yield();
            }
        }
        if ((seed >> 16) % 4u == 0u) {
            for (int i = 0; i < len; i++) {
                (void)daran_rx_byte(&drive, (uint8_t)text[i]);
            }
        } else {
            int cut = (int)((seed >> 8) % (unsigned)len);
            (void)daran_rx_write(&drive, text, (size_t)cut);
            (void)daran_rx_write(&drive, text + cut, (size_t)(len - cut));
        }
    }
    atomic_store(&producer_done, 1);
    return NULL;
}

int main(int argc, char **argv)
{
    static const daran_hal_t hal = {
        .get = hal_get, .set = hal_set, .move = hal_move, .action = hal_action, .write = write_line};
    if (argc > 1) {
        lines_total = strtoul(argv[1], NULL, 10);
    }
    if (daran_init(&drive, &hal, NULL) != DARAN_OK) {
        return 2;
    }
    pthread_t thread;
    if (pthread_create(&thread, NULL, producer, NULL) != 0) {
        return 2;
    }
    unsigned long lines = 0;
    while (!atomic_load(&producer_done) || daran_rx_free(&drive) < DARAN_RX_RING_SIZE) {
        lines += daran_poll(&drive);
    }
    pthread_join(thread, NULL);
    lines += daran_poll(&drive);
    unsigned long dropped = daran_rx_dropped(&drive);
    printf("ring_threads: %lu lines sent, %lu executed, %lu answered line too long, "
           "%lu bytes dropped, %lu out of order, %lu other replies\n",
           lines_total, moves, too_long, dropped, out_of_order, errors_other);
    /* Every line is executed or lost in a line answered `line too long`;
     * lost bytes always cost a line; most lines get through. */
    int ok = out_of_order == 0 && errors_other == 0 && moves + too_long <= lines_total &&
             moves > lines_total / 2u && (dropped == 0) == (too_long == 0) &&
             moves + too_long == lines;
    printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
    return ok ? 0 : 1;
}

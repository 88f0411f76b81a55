/* The minimal Cortex-M4 image the footprint comparison links (m4_size.sh):
 * a UART polled through two registers, a trivial HAL and one parser.
 *   BENCH_PARSER 0  no parser: the image every figure is measured against
 *   BENCH_PARSER 1  daran-ascii (rx ring + daran_poll)
 *   BENCH_PARSER 2  the baseline yardstick (line buffer + baseline_process_line)
 *   BENCH_PARSER 3  the hand-written yardstick (line buffer + handwritten_process_line)
 * Never run: only linked, so the size of what each parser pulls in is known. */
#include <stddef.h>
#include <stdint.h>

#include "daran_hal.h"

#if BENCH_PARSER == 1
#include "daran_drive.h"
#elif BENCH_PARSER == 2
#include "baseline.h"
#elif BENCH_PARSER == 3
#include "handwritten.h"
#endif

#define UART_STATUS (*(volatile uint32_t *)0x40004000u)
#define UART_DATA (*(volatile uint32_t *)0x40004004u)

static daran_value_t values[DARAN_PROP_COUNT];
static daran_move_t last_move;
static volatile uint32_t actions;

static daran_result_t m4_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    *out = values[prop];
    return DARAN_OK;
}

static daran_result_t m4_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    values[prop] = value;
    return DARAN_OK;
}

static daran_result_t m4_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    last_move = *move;
    return DARAN_OK;
}

static daran_result_t m4_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    actions |= 1u << (unsigned)action;
    return DARAN_OK;
}

static void uart_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    for (size_t i = 0; i < len; i++) {
        UART_DATA = (uint8_t)line[i];
    }
}

static const daran_hal_t hal = {m4_get, m4_set, m4_move, m4_action, uart_write};

#if BENCH_PARSER == 1
static daran_drive_t drive;
#elif BENCH_PARSER == 2
static baseline_t baseline;
static char line[129];
static size_t line_len;
#elif BENCH_PARSER == 3
static handwritten_t handwritten;
static char line[129];
static size_t line_len;
#endif

int main(void)
{
    values[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
#if BENCH_PARSER == 1
    if (daran_init(&drive, &hal, NULL) != DARAN_OK) {
        return 1;
    }
#elif BENCH_PARSER == 2
    baseline_init(&baseline, &hal, NULL, uart_write, NULL);
#elif BENCH_PARSER == 3
    handwritten_init(&handwritten, &hal, NULL, uart_write, NULL);
#else
    (void)hal;
    (void)uart_write;
#endif
    for (;;) {
        if ((UART_STATUS & 1u) == 0u) {
            continue;
        }
        uint8_t byte = (uint8_t)UART_DATA;
#if BENCH_PARSER == 1
        (void)daran_rx_byte(&drive, byte);
        (void)daran_poll(&drive);
#elif BENCH_PARSER == 2
        if (byte == '\n') {
            line[line_len] = '\0';
            (void)baseline_process_line(&baseline, line);
            line_len = 0;
        } else if (line_len < sizeof line - 1) {
            line[line_len++] = (char)byte;
        }
#elif BENCH_PARSER == 3
        if (byte == '\n') {
            (void)handwritten_process_line(&handwritten, line, line_len);
            line_len = 0;
        } else if (line_len < sizeof line - 1) {
            line[line_len++] = (char)byte;
        }
#else
        UART_DATA = byte;
#endif
    }
}

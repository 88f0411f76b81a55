/* Instruction-count image (daran-perf.elf): one protocol line of each
 * command family through daran_rx_write() + daran_poll(), with a marker
 * call after each. tools/qemu-insn-count counts the instructions between
 * markers under QEMU; measure_insns.py turns them into the table in
 * docs/performance.md. The HAL here does no work (stored values, no
 * model), so the counts are the core's alone; replies go to a sink that
 * drops them (no UART time). Labels go out on UART0 in order. */
#include <string.h>

#include "board.h"
#include "daran_can.h"
#include "daran_drive.h"

typedef struct perf_line {
    const char *label;
    const char *text;
} perf_line_t;

static const perf_line_t lines[] = {
    {"t", "t 1 10 0 25\n"},
    {"t with checksum", "t 1 10 0 25 *83\n"},
    {"t, position only", "t 1 12.5\n"},
    {"t, vendor default (bw 0)", "t 1 30 0 0 \n"},
    {"q", "q 1 50.0 7.5 2.5\n"},
    {"p", "p 1 10 5 3\n"},
    {"v (ramp)", "v 1 12.5 2.5 2\n"},
    {"c (ramp)", "c 1 0.1 0.02 6\n"},
    {"d", "d 1 10 0 0.5 0.1 0.01\n"},
    {"f", "f 1\n"},
    {"f with checksum", "f 1 *87\n"},
    {"e (seven lines)", "e 1\n"},
    {"r axis property", "r axis1.output_shaft.pos_setpoint\n"},
    {"r system property", "r config.uart_baudrate 1\n"},
    {"w float property", "w axis1.controller.config.pos_gain 20.5\n"},
    {"w integer property", "w config.uart_baudrate 9600 1\n"},
    {"r s32 property", "r axis1.motor.config.direction\n"},
    {"w s32 property", "w axis1.motor.config.direction -1\n"},
    {"r longest path", "r axis1.config.extra_setting.enable_circular_setpoint_limit\n"},
    {"ms", "ms 1 120 5 10\n"},
    {"mq (after ms)", "mq 1 1\n"},
    {"ss", "ss 1\n"},
    {"line for another id", "t 2 10 0 25\n"},
    {"error: unknown command", "x 1\n"},
    {"error: invalid value", "t 1 1x0\n"},
    {"error: checksum mismatch", "t 1 10 0 25 *84\n"},
    {"blank line", "\n"},
};

static daran_value_t values[DARAN_PROP_COUNT];

static daran_result_t perf_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    *out = values[prop];
    return DARAN_OK;
}

static daran_result_t perf_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    values[prop] = value;
    return DARAN_OK;
}

static daran_result_t perf_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_OK;
}

static daran_result_t perf_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_OK;
}

static void drop_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
}

/* The plugin watches this function's entry. */
void daran_perf_mark(void) __attribute__((noinline));
void daran_perf_mark(void)
{
    __asm volatile("" ::: "memory");
}

#if DARAN_ENABLE_CAN
/* CAN frames for drive 1 (docs/can.md): received, then polled to the HAL
 * call or the reply. */
typedef struct perf_frame {
    const char *label;
    const char *text;
    daran_can_frame_t frame;
    bool tick; /* the clock moves a millisecond before the poll */
} perf_frame_t;

static const perf_frame_t frames[] = {
    {"CAN t frame", "039 00 00 b4 42 00 00 e8 03", {0x039, 8, 0, {0x00, 0x00, 0xb4, 0x42, 0x00, 0x00, 0xe8, 0x03}}, false},
    {"CAN read frame", "03e 11 27 03 00 00 00 00 00", {0x03E, 8, 0, {0x11, 0x27, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00}}, false},
    {"CAN read frame, last row of the longest run", "03e 75 94 00 00 00 00 00 00", {0x03E, 8, 0, {0x75, 0x94, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}}, false},
    {"CAN fast read", "03e 00 00 00 00 00 00 00 00", {0x03E, 8, 0, {0}}, false},
    {"CAN write frame", "03f 11 27 03 00 80 25 00 00", {0x03F, 8, 0, {0x11, 0x27, 0x03, 0x00, 0x80, 0x25, 0x00, 0x00}}, false},
    {"CAN frame for another node", "059 00 00 b4 42 00 00 e8 03", {0x059, 8, 0, {0x00, 0x00, 0xb4, 0x42, 0x00, 0x00, 0xe8, 0x03}}, false},
    /* dropped by daran_can_receive (DLC 0): what a poll costs with no frame,
     * and once a millisecond, with the node guard's and heartbeat's look */
    {"CAN poll, no frame", "009 (DLC 0, dropped)", {0x009, 0, 0, {0}}, false},
    {"CAN poll, no frame, the clock moved", "009 (DLC 0, dropped)", {0x009, 0, 0, {0}}, true},
};

static bool drop_frame(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    (void)frame;
    return true;
}

static uint32_t clock_ms;

static uint32_t perf_clock(void *ctx)
{
    (void)ctx;
    return clock_ms;
}

static daran_can_t can;
#endif

static const daran_hal_t perf_hal = {.get = perf_get,
                                     .set = perf_set,
                                     .move = perf_move,
                                     .action = perf_action,
                                     .write = drop_reply,
#if DARAN_ENABLE_CAN
                                     .now_ms = perf_clock,
                                     .can_send = drop_frame
#endif
};

static daran_drive_t drive;
static size_t lengths[sizeof lines / sizeof lines[0]];

int main(void)
{
    daran_board_uart0_init(115200u);
    values[DARAN_PROP_CAN_NODE_ID].u32 = 1u;
    values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    values[DARAN_PROP_UART_BAUDRATE].u32 = 115200u;
    values[DARAN_PROP_CAN_PROTOCOL].u32 = 1u;
    if (daran_init(&drive, &perf_hal, NULL) != DARAN_OK) {
        daran_board_exit(1);
    }
#if DARAN_ENABLE_CAN
    if (daran_can_init(&can, &drive) != DARAN_OK) {
        daran_board_exit(1);
    }
    (void)daran_can_poll(&can); /* this millisecond's look is taken: frames are measured alone */
#endif
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        lengths[i] = strlen(lines[i].text); /* outside the measured intervals */
    }
    (void)daran_board_irq_save(); /* nothing may run between markers but the line */
    daran_perf_mark();
    daran_perf_mark(); /* empty interval: the marker's own cost */
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        (void)daran_rx_write(&drive, lines[i].text, lengths[i]);
        (void)daran_poll(&drive);
        daran_perf_mark();
    }
#if DARAN_ENABLE_CAN
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        (void)daran_can_receive(&can, &frames[i].frame);
        clock_ms += frames[i].tick ? 1u : 0u;
        (void)daran_can_poll(&can);
        daran_perf_mark();
    }
#endif
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        daran_board_uart0_write(lines[i].label, strlen(lines[i].label));
        daran_board_uart0_write("\t", 1u);
        daran_board_uart0_write(lines[i].text, strlen(lines[i].text));
    }
#if DARAN_ENABLE_CAN
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        daran_board_uart0_write(frames[i].label, strlen(frames[i].label));
        daran_board_uart0_write("\t", 1u);
        daran_board_uart0_write(frames[i].text, strlen(frames[i].text));
        daran_board_uart0_write("\n", 1u);
    }
#endif
    daran_board_exit(0);
}

/* Instruction-count image of the port-extension mechanism (issue 14):
 * what a line costs with and without a port command table, the port's own
 * command (examples/port-brake's `sb`), an unknown word, discovery
 * (`h id properties [prefix]`) and daran_telemetry_tick().
 *
 * Built by bench/extensions/build.sh twice from this one file, against the
 * core compiled as the cortex-m4 preset compiles it: once with no port rows
 * (ext-none.elf) and once with examples/port-brake/brake_options.h
 * (ext-brake.elf). Run under QEMU mps2-an386 with tools/qemu-insn-count,
 * exactly as tests/target/perf_main.c: each step is followed by a call of
 * daran_perf_mark(), and the plugin counts the instructions between marks.
 * The HAL stores values and does no work; the reply sink only counts lines
 * (a few instructions a line, inside the counts). The labels, each with
 * "[<reply lines>]", go out on UART0 once the measured part is over. */
#include <string.h>

#include "board.h"
#include "brake_port.h"
#include "daran_drive.h"
#include "daran_port.h"

static daran_value_t values[DARAN_PROP_COUNT];

static daran_result_t ext_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    *out = values[prop];
    return DARAN_OK;
}

static daran_result_t ext_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    values[prop] = value;
    return DARAN_OK;
}

static daran_result_t ext_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_OK;
}

static daran_result_t ext_action(void *ctx, daran_action_t action)
{
    (void)ctx;
    (void)action;
    return DARAN_OK;
}


static volatile unsigned reply_lines;

static void count_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
    reply_lines = reply_lines + 1u;
}

static const daran_hal_t ext_hal = {
    .get = ext_get, .set = ext_set, .move = ext_move, .action = ext_action, .write = count_reply};

/* The chopper's driver: stores the frequency. */
static float chopper_hz;

static daran_result_t set_chopper(void *ctx, float hz)
{
    (void)ctx;
    chopper_hz = hz;
    return DARAN_OK;
}

static brake_chopper_t chopper = {set_chopper, NULL};

/* The plugin watches this function's entry. */
void daran_perf_mark(void) __attribute__((noinline));
void daran_perf_mark(void)
{
    __asm volatile("" ::: "memory");
}

static daran_drive_t drive;

#define STEPS_MAX 24u
static const char *labels[STEPS_MAX];
static const char *texts[STEPS_MAX];
static unsigned replies[STEPS_MAX];
static unsigned steps;

/* Close the step just measured: the marker, then its bookkeeping, which
 * lands in the next interval. The first two calls have no step before them:
 * start-up, then the empty interval (marker and bookkeeping) that
 * measure_insns.py subtracts from every step. */
static void end_step(const char *label, const char *text) __attribute__((noinline));
static void end_step(const char *label, const char *text)
{
    daran_perf_mark();
    labels[steps] = label;
    texts[steps] = text;
    replies[steps] = reply_lines;
    reply_lines = 0u;
    steps++;
}

/* One line through the byte path, as perf_main.c sends them. */
static inline __attribute__((always_inline)) void line(const char *label, const char *text, size_t len)
{
    (void)daran_rx_write(&drive, text, len);
    (void)daran_poll(&drive);
    end_step(label, text);
}

#define LINE(label, text) line(label, text, sizeof text - 1u)

static inline __attribute__((always_inline)) void tick(const char *label, const char *what, uint32_t t)
{
    (void)daran_telemetry_tick(&drive, t, 1000u);
    end_step(label, what);
}

static void say_uint(unsigned n)
{
    char buf[12];
    size_t len = 0;
    do {
        buf[sizeof buf - 1u - len++] = (char)('0' + n % 10u);
        n /= 10u;
    } while (n != 0u);
    daran_board_uart0_write(&buf[sizeof buf - len], len);
}

int main(void)
{
    daran_board_uart0_init(115200u);
    values[DARAN_PROP_CAN_NODE_ID].u32 = 1u;
    values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    values[DARAN_PROP_UART_BAUDRATE].u32 = 115200u;
    /* what a report reads: typical values (the float formatting's cost
     * depends on the digits) */
    values[DARAN_PROP_POS_ESTIMATE].f32 = 12.3456f;
    values[DARAN_PROP_VEL_ESTIMATE].f32 = -3.25f;
    values[DARAN_PROP_TORQUE_ESTIMATE].f32 = 0.75f;
    values[DARAN_PROP_IQ_MEASURED].f32 = 1.204f;
    values[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.1f;
    values[DARAN_PROP_FET_TEMPERATURE].f32 = 41.5f;
    values[DARAN_PROP_MOTOR_TEMPERATURE].f32 = 37.25f;
    values[DARAN_PROP_AXIS_ERROR].u32 = 0u;
    values[DARAN_PROP_TRAJECTORY_DONE].u32 = 1u;
    values[DARAN_PROP_TELEMETRY_PERIOD].f32 = 0.0f;
    values[DARAN_PROP_TELEMETRY_FIELDS].u32 = 3u; /* the default */
    if (daran_init(&drive, &ext_hal, NULL) != DARAN_OK) {
        daran_board_exit(1);
    }
    (void)daran_board_irq_save(); /* nothing may run between markers but the step */
    end_step("start-up", "");
    end_step("empty step", ""); /* subtracted from every step */

    /* no port command table */
    LINE("core line, no port table", "t 1 10 0 25 *83\n");
    LINE("unknown word, no port table", "x 1\n");
    LINE("unknown two-letter word, no port table", "sx 1\n");
    LINE("discovery, every row", "h 1 properties\n");
    LINE("discovery, prefix", "h 1 properties axis0.output_shaft.\n");
    LINE("discovery, prefix matching nothing", "h 1 properties nothing\n");

    /* the example's table (one command) */
    if (brake_port_attach(&drive, &chopper) != DARAN_OK) {
        daran_board_exit(2);
    }
    end_step("daran_set_port_commands (1 command)", "brake_port_attach()");
    LINE("core line, with port table", "t 1 10 0 25 *83\n");
    LINE("port command", "sb 1 3\n");
    LINE("port command with checksum", "sb 1 3 *51\n");
    LINE("port command, value out of range", "sb 1 60000\n");
    LINE("unknown word, with port table", "x 1\n");
    LINE("unknown two-letter word, with port table", "sx 1\n");
    LINE("h (command list, with the port's line)", "h 1\n");

    /* telemetry */
    tick("telemetry tick, off (period 0)", "daran_telemetry_tick(), period 0", 12344u);
    values[DARAN_PROP_TELEMETRY_PERIOD].f32 = 0.01f;
    tick("telemetry report, default fields (3)", "daran_telemetry_tick(), fields 3", 12345u);
    tick("telemetry tick, on, no report due", "daran_telemetry_tick(), 1 tick later", 12346u);
    values[DARAN_PROP_TELEMETRY_FIELDS].u32 = 511u;
    tick("telemetry report, all fields (511)", "daran_telemetry_tick(), fields 511", 12355u);

    for (unsigned i = 2; i < steps; i++) { /* start-up and the empty step are no steps */
        daran_board_uart0_write(labels[i], strlen(labels[i]));
        daran_board_uart0_write(" [", 2u);
        say_uint(replies[i]);
        daran_board_uart0_write("]\t", 2u);
        size_t n = strlen(texts[i]);
        daran_board_uart0_write(texts[i], n > 0u && texts[i][n - 1u] == '\n' ? n - 1u : n);
        daran_board_uart0_write("\n", 1u);
    }
    daran_board_exit(0);
}

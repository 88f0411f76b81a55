/* Cortex-M0 (no FPU) instruction counts of the core, for a report next to
 * the Cortex-M4 figures: the image runs on QEMU's `microbit` machine (nRF51,
 * Cortex-M0) under tools/qemu-insn-count, exactly as daran-perf.elf does on
 * the Cortex-M4: each line goes through daran_rx_write() + daran_poll() with
 * a HAL that does no work and a reply sink that drops the bytes, then
 * daran_perf_mark() is called; the plugin counts the instructions between
 * marks. The labels go out through semihosting (stdout) once the measured
 * part is over, and the image ends with a semihosting exit.
 *
 * Built by bench/m0/build.sh (the core at -Os for -mcpu=cortex-m0, soft
 * float from libgcc), measured by bench/m0/measure.sh. */
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

typedef struct perf_line {
    const char *label;
    const char *text;
} perf_line_t;

/* The lines of tests/target/perf_main.c (the Cortex-M4 image), same order. */
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
#define LINE_COUNT (sizeof lines / sizeof lines[0])

static daran_value_t values[DARAN_PROP_COUNT];

static daran_result_t m0_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    (void)ctx;
    *out = values[prop];
    return DARAN_OK;
}

static daran_result_t m0_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    (void)ctx;
    values[prop] = value;
    return DARAN_OK;
}

static daran_result_t m0_move(void *ctx, const daran_move_t *move)
{
    (void)ctx;
    (void)move;
    return DARAN_OK;
}

static daran_result_t m0_action(void *ctx, daran_action_t action)
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

static const daran_hal_t m0_hal = {
    .get = m0_get, .set = m0_set, .move = m0_move, .action = m0_action, .write = drop_reply};

/* The plugin watches this function's entry. */
void daran_perf_mark(void) __attribute__((noinline));
void daran_perf_mark(void)
{
    __asm volatile("" ::: "memory");
}

/* Arm semihosting: operation in r0, argument in r1, BKPT 0xAB on M-profile. */
static uint32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm("r0") = op;
    register const void *r1 __asm("r1") = arg;
    __asm volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static void say(const char *text)
{
    (void)semihost(0x04u /* SYS_WRITE0 */, text);
}

static void m0_exit(int code)
{
    /* SYS_EXIT with ADP_Stopped_ApplicationExit (code ignored by the 32-bit form) */
    (void)code;
    (void)semihost(0x18u, (const void *)(uintptr_t)0x20026u);
    for (;;) {
    }
}

static daran_drive_t drive;
static size_t lengths[LINE_COUNT];

int main(void)
{
    values[DARAN_PROP_CAN_NODE_ID].u32 = 1u;
    values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    values[DARAN_PROP_UART_BAUDRATE].u32 = 115200u;
    if (daran_init(&drive, &m0_hal, NULL) != DARAN_OK) {
        m0_exit(1);
    }
    for (size_t i = 0; i < LINE_COUNT; i++) {
        size_t n = 0;
        while (lines[i].text[n] != '\0') {
            n++;
        }
        lengths[i] = n; /* outside the measured intervals */
    }
    __asm volatile("cpsid i" ::: "memory"); /* nothing may run between marks but the line */
    daran_perf_mark();
    daran_perf_mark(); /* empty interval: the marker's own cost */
    for (size_t i = 0; i < LINE_COUNT; i++) {
        (void)daran_rx_write(&drive, lines[i].text, lengths[i]);
        (void)daran_poll(&drive);
        daran_perf_mark();
    }
    for (size_t i = 0; i < LINE_COUNT; i++) {
        say(lines[i].label);
        say("\t");
        say(lines[i].text);
    }
    m0_exit(0);
    return 0;
}

/* ---- reset and vectors ---- */

extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern const uint32_t __data_load[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];
extern uint32_t __stack_top[];

void m0_reset(void);
void m0_fault(void);

void m0_fault(void)
{
    say("fault\n");
    m0_exit(3);
}

void m0_reset(void)
{
    const uint32_t *src = __data_load;
    for (uint32_t *dst = __data_start; dst < __data_end;) {
        *dst++ = *src++;
    }
    for (uint32_t *dst = __bss_start; dst < __bss_end;) {
        *dst++ = 0u;
    }
    (void)main();
    m0_exit(4);
}

typedef void (*m0_vector_t)(void);

__attribute__((section(".vectors"), used))
static const m0_vector_t vectors[16] = {
    (m0_vector_t)(uintptr_t)__stack_top,
    m0_reset,
    m0_fault, /* NMI */
    m0_fault, /* HardFault */
    0, 0, 0, 0, 0, 0, 0,
    m0_fault, /* SVCall */
    0, 0,
    m0_fault, /* PendSV */
    m0_fault, /* SysTick */
};

/* Measured stack of the core's line-processing entry points on the target, a
 * cross-check of the static figure of check_budgets.py (budget_core_stack).
 *
 * The unit test images link with -Wl,--wrap=daran_poll and
 * -Wl,--wrap=daran_process_line: every call the tests make goes through the
 * wrappers below, which paint a window of the stack below their own frame,
 * call the core and find the deepest word that changed. The core is not
 * touched (the wrap is a link-time redirection of the tests' calls; the
 * core never calls either function itself). The figure includes the mock
 * HAL and reply sink the core calls back (tests/unit/mock_hal.c), like the
 * old self-test's figure did: the static budget leaves the port's callbacks
 * out, so the measured figure is expected a little above it.
 *
 * Cost: one window (STACK_WINDOW bytes) painted and scanned per call. */
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

#define STACK_PAINT 0x5AA5C33Cu
#define STACK_WINDOW 2048u

size_t __real_daran_poll(daran_drive_t *drive);
size_t __wrap_daran_poll(daran_drive_t *drive);
daran_result_t __real_daran_process_line(daran_drive_t *drive, const char *line, size_t len);
daran_result_t __wrap_daran_process_line(daran_drive_t *drive, const char *line, size_t len);
void daran_target_report(void);
void daran_test_putchar(int c);

extern uint32_t __stack_limit[];

static uint32_t deepest;      /* bytes below the wrapper's frame */
static uint32_t calls;
static uint32_t window_full;  /* calls that reached the bottom of the window */

static volatile uint32_t *paint(void)
{
    uintptr_t sp;
    __asm volatile("mov %0, sp" : "=r"(sp));
    /* below this function's caller's frame: this frame is gone when the
     * core runs, and the core's frames start where the caller's SP is */
    uintptr_t bottom = (sp - STACK_WINDOW) & ~(uintptr_t)3u;
    if (bottom < (uintptr_t)__stack_limit) {
        bottom = (uintptr_t)__stack_limit;
    }
    volatile uint32_t *p = (volatile uint32_t *)bottom;
    while ((uintptr_t)p < sp) {
        *p++ = STACK_PAINT;
    }
    return (volatile uint32_t *)bottom;
}

static void measure(volatile uint32_t *bottom, uintptr_t top)
{
    volatile uint32_t *p = bottom;
    while ((uintptr_t)p < top && *p == STACK_PAINT) {
        p++;
    }
    if (p == bottom) {
        window_full++;
    }
    uint32_t used = (uint32_t)(top - (uintptr_t)p);
    if ((uintptr_t)p < top && used > deepest) {
        deepest = used;
    }
    calls++;
}

static uintptr_t frame_top(void)
{
    uintptr_t sp;
    __asm volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

size_t __wrap_daran_poll(daran_drive_t *drive)
{
    uintptr_t top = frame_top();
    volatile uint32_t *bottom = paint();
    size_t n = __real_daran_poll(drive);
    measure(bottom, top);
    return n;
}

daran_result_t __wrap_daran_process_line(daran_drive_t *drive, const char *line, size_t len)
{
    uintptr_t top = frame_top();
    volatile uint32_t *bottom = paint();
    daran_result_t r = __real_daran_process_line(drive, line, len);
    measure(bottom, top);
    return r;
}

static void print_text(const char *text)
{
    while (*text != '\0') {
        daran_test_putchar((unsigned char)*text++);
    }
}

static void print_u32(uint32_t value)
{
    char buf[10];
    size_t n = sizeof buf;
    do {
        buf[--n] = (char)('0' + value % 10u);
        value /= 10u;
    } while (value != 0u && n > 0u);
    while (n < sizeof buf) {
        daran_test_putchar(buf[n++]);
    }
}

void daran_target_report(void)
{
    print_text("stack high-water mark: ");
    print_u32(deepest);
    print_text(" bytes in daran_poll()/daran_process_line() with the mock HAL, over ");
    print_u32(calls);
    print_text(" calls");
    if (window_full != 0u) {
        print_text(" (");
        print_u32(window_full);
        print_text(" reached the bottom of the painted window: at least ");
        print_u32(STACK_WINDOW);
        print_text(" bytes)");
    }
    print_text("\n");
}

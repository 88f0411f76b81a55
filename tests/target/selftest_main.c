/* The on-target self-test image (daran-selftest.elf): the protocol cases and
 * the number sample, run on the Cortex-M4 under QEMU. It prints a FAIL line
 * per failure and closes with `N passed, M failed`; the exit status
 * (semihosting) is 0 only when nothing failed. */
#include <string.h>

#include "board.h"
#include "selftest.h"

void selftest_write(const char *bytes, size_t len)
{
    daran_board_uart0_write(bytes, len);
}

void selftest_print(const char *text)
{
    selftest_write(text, strlen(text));
}

void selftest_print_u32(uint32_t value)
{
    char buf[10];
    size_t n = sizeof buf;
    do {
        buf[--n] = (char)('0' + value % 10u);
        value /= 10u;
    } while (value != 0u && n > 0u);
    selftest_write(buf + n, sizeof buf - n);
}

void selftest_print_escaped(const char *text)
{
    static const char hex[] = "0123456789abcdef";
    for (; *text != '\0'; text++) {
        unsigned char c = (unsigned char)*text;
        if (c == '\n') {
            selftest_print("\\n");
        } else if (c == '\r') {
            selftest_print("\\r");
        } else if (c < 0x20u || c > 0x7Eu) {
            char esc[4] = {'\\', 'x', hex[c >> 4], hex[c & 15u]};
            selftest_write(esc, sizeof esc);
        } else {
            selftest_write(text, 1u);
        }
    }
}

/* Stack high-water mark, a measured cross-check of the static analysis in
 * check_budgets.py: the free stack is painted before the cases run, and the
 * lowest word they overwrote shows how deep they went. */
extern uint32_t __stack_limit[];
#define STACK_PAINT 0x5AA5C33Cu

static void paint_stack(void)
{
    uintptr_t sp;
    uint32_t *p = __stack_limit;
    __asm volatile("mov %0, sp" : "=r"(sp));
    /* leave 64 bytes below this frame alone */
    while ((uintptr_t)p < sp - 64u) {
        *p++ = STACK_PAINT;
    }
}

static uint32_t stack_used(void)
{
    extern uint32_t __stack_top[];
    const uint32_t *p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT) {
        p++;
    }
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

int main(void)
{
    selftest_tally_t tally = {0u, 0u};
    daran_board_uart0_init(115200u);
    paint_stack();
    selftest_protocol_cases(&tally);
    selftest_number_cases(&tally);
    selftest_print("stack high-water mark: ");
    selftest_print_u32(stack_used());
    selftest_print(" bytes (self-test harness + core + mock HAL)\n");
    selftest_print_u32(tally.passed);
    selftest_print(" passed, ");
    selftest_print_u32(tally.failed);
    selftest_print(" failed\n");
    daran_board_exit(tally.failed == 0u && tally.passed > 0u ? 0 : 1);
}

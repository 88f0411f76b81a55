/* What a Unity test program needs to run as a firmware image on the MPS2
 * AN386 board (QEMU mps2-an386): the same test sources as on the host, with
 *
 *   - daran_test_putchar(): Unity's output (tests/support/unity_config.h
 *     routes every character here on the target) goes out on UART0, which
 *     QEMU connects to its standard output;
 *   - daran_fw_main_returned(): main() returns Unity's failure count; the run
 *     ends with that status (semihosting SYS_EXIT_EXTENDED, QEMU's exit
 *     status), after the stack figure of stack_mark.c when the image has it;
 *   - the few system calls the full newlib needs for snprintf (its float
 *     conversions allocate from the heap of the linker script) and exit().
 *
 * Nothing else: no stdio stream is used (Unity prints character by
 * character), no file, no clock. */
#include <errno.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>

#include "board.h"

void daran_test_putchar(int c);
void daran_fw_main_returned(int status) __attribute__((noreturn));
/* Optional report of the image (stack_mark.c), printed before the exit. */
void daran_target_report(void) __attribute__((weak));

void daran_test_putchar(int c)
{
    static bool ready;
    char byte = (char)c;
    if (!ready) {
        /* Transmit only: the receive interrupt stays masked in the NVIC, so
         * a stray byte on QEMU's standard input cannot reach a handler. */
        daran_board_uart0_init(115200u);
        daran_board_uart0_rx_irq_enable(false);
        ready = true;
    }
    daran_board_uart0_write(&byte, 1u);
}

void daran_fw_main_returned(int status)
{
    if (daran_target_report) {
        daran_target_report();
    }
    /* Unity returns the number of failures; an exit status keeps 8 bits. */
    daran_board_exit(status < 0 || status > 255 ? 255 : status);
}

/* ---- newlib system calls -------------------------------------------------- */

/* Symbols of mps2_an386.ld: the heap a test image asks for with
 * __daran_heap_size. */
extern char __heap_start[];
extern char __heap_end[];

void *_sbrk(ptrdiff_t increment);
void _exit(int status) __attribute__((noreturn));
int _write(int fd, const char *bytes, int len);
int _read(int fd, char *bytes, int len);
int _close(int fd);
int _lseek(int fd, int offset, int whence);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);
int _kill(int pid, int sig);
int _getpid(void);

void *_sbrk(ptrdiff_t increment)
{
    static char *brk = __heap_start;
    char *old = brk;
    if (increment > __heap_end - brk || increment < __heap_start - brk) {
        errno = ENOMEM;
        return (void *)-1;
    }
    brk += increment;
    return old;
}

void _exit(int status)
{
    daran_fw_main_returned(status);
}

/* stdout and stderr, should anything print through stdio: the UART. */
int _write(int fd, const char *bytes, int len)
{
    if (fd != 1 && fd != 2) {
        errno = EBADF;
        return -1;
    }
    for (int i = 0; i < len; i++) {
        daran_test_putchar((unsigned char)bytes[i]);
    }
    return len;
}

int _read(int fd, char *bytes, int len)
{
    (void)fd;
    (void)bytes;
    (void)len;
    return 0;
}

int _close(int fd)
{
    (void)fd;
    errno = EBADF;
    return -1;
}

int _lseek(int fd, int offset, int whence)
{
    (void)fd;
    (void)offset;
    (void)whence;
    errno = ESPIPE;
    return -1;
}

int _fstat(int fd, struct stat *st)
{
    (void)fd;
    st->st_mode = S_IFCHR;
    return 0;
}

int _isatty(int fd)
{
    return fd >= 0 && fd <= 2;
}

int _kill(int pid, int sig)
{
    (void)pid;
    (void)sig;
    errno = EINVAL;
    return -1;
}

int _getpid(void)
{
    return 1;
}

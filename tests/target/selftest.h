/* Shared parts of the on-target self-test image: the tally, and output that
 * goes to the UART on the target (QEMU's stdio). */
#ifndef DARAN_TARGET_SELFTEST_H
#define DARAN_TARGET_SELFTEST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct selftest_tally {
    uint32_t passed;
    uint32_t failed;
} selftest_tally_t;

void selftest_write(const char *bytes, size_t len);
void selftest_print(const char *text);
void selftest_print_u32(uint32_t value);
/* Text with control bytes shown as \n, \r, \xNN. */
void selftest_print_escaped(const char *text);

void selftest_protocol_cases(selftest_tally_t *tally);
void selftest_number_cases(selftest_tally_t *tally);

#endif /* DARAN_TARGET_SELFTEST_H */

/* Unity's options for daran-ascii's tests. cmake/FindUnity.cmake puts this
 * header before everything in unity.c and in every file of a program that
 * links unity::unity, so Unity and the tests always agree on the options.
 *
 * Host: Unity prints with putchar and flushes after each test (a crash keeps
 * the results before it). Target (DARAN_TEST_TARGET, set by cross builds):
 * every character goes to daran_test_putchar(), which the target's test
 * program defines (a UART register write, or semihosting under QEMU); Unity
 * then needs no stdio. */
#ifndef DARAN_UNITY_CONFIG_H
#define DARAN_UNITY_CONFIG_H

/* 64-bit assertions on 32-bit targets too: the core reads and prints uint64_t. */
#define UNITY_SUPPORT_64

/* The core is single precision: no double assertions, and no soft-double code
 * on the Cortex-M4F (this also overrides the UNITY_INCLUDE_DOUBLE of the
 * examples/unity_config.h that the cjson copy of Unity always includes). */
#define UNITY_EXCLUDE_DOUBLE

#ifdef DARAN_TEST_TARGET
/* Writes one character of test output; defined by the target test program. */
void daran_test_putchar(int c);
#define UNITY_OUTPUT_CHAR(c) daran_test_putchar(c)
#else
#define UNITY_USE_FLUSH_STDOUT
#endif

#endif /* DARAN_UNITY_CONFIG_H */

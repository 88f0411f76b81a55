/** @file daran_config.h
 * Compile-time options of the daran-ascii core.
 *
 * Every option has a default here and may be overridden in a user header
 * named by DARAN_CONFIG_HEADER (CMake: -DDARAN_CONFIG_HEADER=my_daran_config.h,
 * relative to the top-level source folder or absolute; the installed package
 * carries it along), which is included first, or on the compiler command line
 * (-DDARAN_LINE_MAX=200, then the same for every file that includes this
 * header: daran_init() refuses an instance of another size). Impossible
 * combinations stop the build with `#error`. The path is stringified after
 * macro expansion: avoid words the compiler predefines (`linux`, `unix`) in it.
 * A CRLF client's `\r` counts in DARAN_LINE_MAX. */
#ifndef DARAN_CONFIG_H
#define DARAN_CONFIG_H

#ifdef DARAN_CONFIG_HEADER
#define DARAN_STRINGIFY_(x) #x
#define DARAN_STRINGIFY(x) DARAN_STRINGIFY_(x)
#include DARAN_STRINGIFY(DARAN_CONFIG_HEADER)
#endif

/** Longest accepted line, in bytes before its `\n` (checksum field included).
 * A longer line is discarded up to its `\n` and answered `line too long`. */
#ifndef DARAN_LINE_MAX
#define DARAN_LINE_MAX 128
#endif

/** Receive ring between the byte-input (interrupt) side and daran_poll().
 * Must be a power of two; it only needs to hold the bytes that arrive
 * between two calls of daran_poll(). */
#ifndef DARAN_RX_RING_SIZE
#define DARAN_RX_RING_SIZE 128
#endif

/** Longest reply line, in bytes including the optional " *NNN" and the line
 * end. 88 or more: room for every reply the core builds (a discovery line
 * takes 78 at most). A telemetry report with all nine fields can take 159:
 * with less room `w axisN.telemetry.fields` refuses the field sets whose
 * report might not fit (`value out of range`). */
#ifndef DARAN_REPLY_MAX
#define DARAN_REPLY_MAX 160
#endif

/** 1 (default): reply lines end in `\r\n`, as the ODrive firmware's do and as
 * the vendor's error decoder expects; 0: in `\n`. */
#ifndef DARAN_REPLY_CRLF
#define DARAN_REPLY_CRLF 1
#endif

/** Highest motor id of the protocol (ids are 0..DARAN_MOTOR_ID_MAX, 0 = all). */
#ifndef DARAN_MOTOR_ID_MAX
#define DARAN_MOTOR_ID_MAX 63
#endif

/** 0 leaves out the `h` help text (its strings cost flash); `h` then answers
 * `unknown command`. */
#ifndef DARAN_ENABLE_HELP
#define DARAN_ENABLE_HELP 1
#endif

/** 0 leaves out the multi-motor commands ms/mt/mq/mp/mv/mc (they then answer
 * `unknown command`). */
#ifndef DARAN_ENABLE_MULTI_MOTOR
#define DARAN_ENABLE_MULTI_MOTOR 1
#endif

/* DARAN_PORT_BARRIER(): not defined here. Only a core built as C99 (no
 * <stdatomic.h>) by a compiler without the GCC/clang __atomic builtins needs
 * it: the port's options header defines it as a full memory barrier of its
 * CPU (with CMSIS, __DMB()), which orders the receive ring's index stores. */

#if DARAN_LINE_MAX < 32 || DARAN_LINE_MAX > 1024
#error "DARAN_LINE_MAX must be within 32..1024"
#endif
#if DARAN_RX_RING_SIZE < 16 || DARAN_RX_RING_SIZE > 32768 || \
    (DARAN_RX_RING_SIZE & (DARAN_RX_RING_SIZE - 1)) != 0
#error "DARAN_RX_RING_SIZE must be a power of two within 16..32768"
#endif
#if DARAN_REPLY_MAX < 88 || DARAN_REPLY_MAX > 1024
#error "DARAN_REPLY_MAX must be within 88..1024"
#endif
#if DARAN_REPLY_CRLF != 0 && DARAN_REPLY_CRLF != 1
#error "DARAN_REPLY_CRLF must be 0 or 1"
#endif
#if DARAN_ENABLE_HELP != 0 && DARAN_ENABLE_HELP != 1
#error "DARAN_ENABLE_HELP must be 0 or 1"
#endif
#if DARAN_ENABLE_MULTI_MOTOR != 0 && DARAN_ENABLE_MULTI_MOTOR != 1
#error "DARAN_ENABLE_MULTI_MOTOR must be 0 or 1"
#endif
#if DARAN_MOTOR_ID_MAX < 1 || DARAN_MOTOR_ID_MAX > 255
#error "DARAN_MOTOR_ID_MAX must be within 1..255"
#endif

#endif /* DARAN_CONFIG_H */

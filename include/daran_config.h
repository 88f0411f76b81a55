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

/** 1 (default when DARAN_ENABLE_HELP is 1): `h id properties [prefix]`,
 * the property listing (discovery.c). 0 leaves it out: `h` then takes no
 * argument after the id (`h 1 properties` answers `invalid format`, as any
 * line with too many fields). Discovery is part of `h`, so it needs
 * DARAN_ENABLE_HELP; it defaults to that option. */
#ifndef DARAN_ENABLE_DISCOVERY
#define DARAN_ENABLE_DISCOVERY DARAN_ENABLE_HELP
#endif

/** 1 (default): daran_telemetry_tick() writes telemetry reports, and `w`
 * refuses a telemetry field set whose report might not fit DARAN_REPLY_MAX.
 * 0 leaves both out: the tick returns DARAN_OK without a HAL call, and the
 * telemetry rows (if the build keeps them) are plain settings. */
#ifndef DARAN_ENABLE_TELEMETRY
#define DARAN_ENABLE_TELEMETRY 1
#endif

/** 1 (default): the port's own commands (daran_set_port_commands(), the
 * daran_args_*() parsers, daran_reply()). 0 leaves them out: the core knows
 * only its own words, daran_set_port_commands() refuses any non-empty table
 * (DARAN_ERR_BAD_ARGUMENT) and accepts none (count 0), and the parsers and
 * daran_reply() are not in the library (a port that links a handler learns
 * it at link time). */
#ifndef DARAN_ENABLE_PORT_COMMANDS
#define DARAN_ENABLE_PORT_COMMANDS 1
#endif

/** 1 (default): `mq` plans an S-curve when `axis0.trap_traj.config.traj_mode`
 * reads 2 (one HAL get per `mq`). 0: `mq` always plans a trapezoid and never
 * reads traj_mode; the drive must then run a TRAPEZOID move as a trapezoid. */
#ifndef DARAN_ENABLE_S_CURVE
#define DARAN_ENABLE_S_CURVE 1
#endif

/** 1 (default): the vendor's CAN protocol as a second front end
 * (daran_can.h, docs/can.md). 0 compiles it out: a seed-only or ASCII-only
 * build pays nothing for it. */
#ifndef DARAN_ENABLE_CAN
#define DARAN_ENABLE_CAN 1
#endif

/** 1 (default with DARAN_ENABLE_CAN): a drive with a daran_can_bridge_t
 * (daran_can.h) sends lines for other ids to them over CAN and answers
 * their queries with the remote drive's values (docs/can.md, "The bridge").
 * 0 compiles the bridge out. */
#ifndef DARAN_ENABLE_CAN_BRIDGE
#define DARAN_ENABLE_CAN_BRIDGE DARAN_ENABLE_CAN
#endif

/** 1 (default): the firmware update commands `ub uw uv ug uy ua us`
 * (daran_update.h, docs/update.md), answered by a drive bound to a
 * daran_update_t. 0 (default) compiles them out: a build without them pays
 * nothing for them but their four error phrases. */
#ifndef DARAN_ENABLE_UPDATE
#define DARAN_ENABLE_UPDATE 0
#endif

/** How long the bridge waits for each reply of a bridged query, in ms (C32). */
#ifndef DARAN_CAN_BRIDGE_TIMEOUT_MS
#define DARAN_CAN_BRIDGE_TIMEOUT_MS 10
#endif

/** Received frames the CAN front end holds between daran_can_receive() and
 * daran_can_poll(): a power of two, 10 bytes of RAM each. */
#ifndef DARAN_CAN_RX_FRAMES
#define DARAN_CAN_RX_FRAMES 8
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
#if DARAN_ENABLE_DISCOVERY != 0 && DARAN_ENABLE_DISCOVERY != 1
#error "DARAN_ENABLE_DISCOVERY must be 0 or 1"
#endif
#if DARAN_ENABLE_DISCOVERY && !DARAN_ENABLE_HELP
#error "DARAN_ENABLE_DISCOVERY needs DARAN_ENABLE_HELP (discovery is `h id properties`)"
#endif
#if DARAN_ENABLE_TELEMETRY != 0 && DARAN_ENABLE_TELEMETRY != 1
#error "DARAN_ENABLE_TELEMETRY must be 0 or 1"
#endif
#if DARAN_ENABLE_PORT_COMMANDS != 0 && DARAN_ENABLE_PORT_COMMANDS != 1
#error "DARAN_ENABLE_PORT_COMMANDS must be 0 or 1"
#endif
#if DARAN_ENABLE_S_CURVE != 0 && DARAN_ENABLE_S_CURVE != 1
#error "DARAN_ENABLE_S_CURVE must be 0 or 1"
#endif
#if DARAN_ENABLE_CAN != 0 && DARAN_ENABLE_CAN != 1
#error "DARAN_ENABLE_CAN must be 0 or 1"
#endif
#if DARAN_CAN_RX_FRAMES < 2 || DARAN_CAN_RX_FRAMES > 256 || \
    (DARAN_CAN_RX_FRAMES & (DARAN_CAN_RX_FRAMES - 1)) != 0
#error "DARAN_CAN_RX_FRAMES must be a power of two within 2..256"
#endif
#if DARAN_ENABLE_CAN_BRIDGE != 0 && DARAN_ENABLE_CAN_BRIDGE != 1
#error "DARAN_ENABLE_CAN_BRIDGE must be 0 or 1"
#endif
#if DARAN_ENABLE_CAN_BRIDGE && !DARAN_ENABLE_CAN
#error "DARAN_ENABLE_CAN_BRIDGE needs DARAN_ENABLE_CAN"
#endif
#if DARAN_ENABLE_UPDATE != 0 && DARAN_ENABLE_UPDATE != 1
#error "DARAN_ENABLE_UPDATE must be 0 or 1"
#endif
#if DARAN_CAN_BRIDGE_TIMEOUT_MS < 1 || DARAN_CAN_BRIDGE_TIMEOUT_MS > 60000
#error "DARAN_CAN_BRIDGE_TIMEOUT_MS must be within 1..60000"
#endif
#if DARAN_ENABLE_CAN && DARAN_MOTOR_ID_MAX > 63
#error "DARAN_ENABLE_CAN needs DARAN_MOTOR_ID_MAX <= 63 (a CAN node id has 6 bits)"
#endif
#if DARAN_MOTOR_ID_MAX < 1 || DARAN_MOTOR_ID_MAX > 255
#error "DARAN_MOTOR_ID_MAX must be within 1..255"
#endif

#endif /* DARAN_CONFIG_H */

/** @file daran_protocol.h
 * The protocol's requests, written once (docs/protocol.md section 2, docs/can.md).
 *
 * DARAN_PROTOCOL_COMMANDS is one X-list, one row per request a drive answers.
 * The drive's command table and `h` text (src/ascii/command_table.c), the
 * bridge's choice of frames (src/can/can_bridge.c), the client's builder and
 * reply shapes (client/request.c), the CLI's raw lines and the command table
 * of docs/protocol.md (checked by tests/docs) are all made from it. A new
 * core command is a row here plus its handler (and, when it has a CAN form, a
 * layout in the CAN codec); every end then knows it.
 *
 * A row: X(NAME, c0, c1, FEATURE, CLASS, REPLY, RETRY, HANDLER, ARG, CAN, help,
 *          f1, f2, f3, f4, f5, f6)
 *   NAME     the request's name: DARAN_CLIENT_CMD_NAME in the client.
 *   c0, c1   the word's letters, lower case; c1 is 0 for a one-letter word.
 *   FEATURE  when a drive has the command: ALWAYS, MULTI
 *            (DARAN_ENABLE_MULTI_MOTOR), HELP (`h`: DARAN_ENABLE_HELP or
 *            DARAN_ENABLE_DISCOVERY), DISCOVERY (a form of `h` that only a
 *            build with discovery answers: the drive reads it as part of `h`),
 *            UPDATE (DARAN_ENABLE_UPDATE: the firmware update, daran_update.h).
 *   CLASS    what it does: MOTION (moves now), PRESET (stores a preset),
 *            START (starts the preset: moves), QUERY (answers values, no
 *            effect), READ (`r`: a property's value), WRITE (`w`), SYSTEM (a
 *            HAL action), UPDATE (a step of a firmware update: ARG names it).
 *   REPLY    how a drive answers it when it succeeds: SILENT, ONE_LINE,
 *            ERROR_LINES (`e`'s seven lines), UNTIL_END (lines, then `end`),
 *            UNTIL_QUIET (lines, no end marker). A command that fails is
 *            answered by one `error: ...` line instead.
 *   RETRY    RETRY when a client may send it again after a lost or damaged
 *            reply (it has no effect, or the same effect twice), ONCE when a
 *            second copy could act twice (a relative start, a second `q`
 *            from a new start, a second `sz`).
 *   HANDLER  the drive's handler: daran_cmd_HANDLER.
 *   ARG      what the handler is told: a motion shape (DARAN_SHAPE_ARG) for
 *            MOTION and START, a HAL action (DARAN_ACTION_ARG) for SYSTEM,
 *            the properties a QUERY answers (DARAN_QUERY_ARG below), NONE.
 *   CAN      its CAN form (docs/can.md 5.2), which the bridge sends for a
 *            line addressed to a drive behind it: MOTION (the code of its
 *            shape), IMPEDANCE (a preset, then its start), PRESET, START (the
 *            start sub-code of its shape), READ (`r`), WRITE (`w`), ACTION
 *            (the system sub-code of its action), READ_LIST (a read of each
 *            property of its QUERY list), LOCAL (answered by the gateway
 *            itself), NONE (none: `error: not bridged` for another drive).
 *   help     `h`'s text for the fields after the id.
 *   f1..f6   its fields after the word, in order, each REQ_kind or OPT_kind
 *            (an optional field; every optional field follows the required
 *            ones) or NONE: ID (a motor id), F32 (a number), MODE (an
 *            integer mode), FLAG (0 or 1), PATH (a property path; `axisN.`
 *            paths carry the id), VALUE (a value in the property's type),
 *            WORD (a literal word, `properties`), U32 (an unsigned 32-bit
 *            integer, exact), DATA (bytes in the characters
 *            DARAN_UPDATE_DATA_FIRST..LAST: 5 characters for 4 bytes).
 *
 * The table is the protocol's, whatever a build of the drive leaves out; a
 * drive built with an options header may add rows of its own with
 * DARAN_EXTRA_COMMANDS(X) (daran_config.h), same columns. */
#ifndef DARAN_PROTOCOL_H
#define DARAN_PROTOCOL_H

#include "daran_config.h"

/** The word of `h id properties [prefix]` (discovery). */
#define DARAN_H_PROPERTIES_WORD "properties"
/** The text of `h`'s properties form; a drive with discovery lists `h` as
 * "h id [properties [prefix]]". */
#define DARAN_H_PROPERTIES_HELP DARAN_H_PROPERTIES_WORD " [prefix]"

/** The protocol's own requests (the columns are above). */
/* clang-format off */
#define DARAN_PROTOCOL_CORE_COMMANDS(X)                                                            \
    X(T,  't', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, FILTERED, MOTION, "pos [vel] [bw]",      \
      REQ_ID, REQ_F32, OPT_F32, OPT_F32, NONE, NONE)                                               \
    X(Q,  'q', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, TRAPEZOID, MOTION, "pos [vel] [acc]",    \
      REQ_ID, REQ_F32, OPT_F32, OPT_F32, NONE, NONE)                                               \
    X(P,  'p', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, PASSTHROUGH, MOTION,                     \
      "pos [vel_ff] [torque_ff]", REQ_ID, REQ_F32, OPT_F32, OPT_F32, NONE, NONE)                   \
    X(V,  'v', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, VELOCITY, MOTION, "vel [param] [mode]",  \
      REQ_ID, REQ_F32, OPT_F32, OPT_MODE, NONE, NONE)                                              \
    X(C,  'c', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, TORQUE, MOTION, "torque [param] [mode]", \
      REQ_ID, REQ_F32, OPT_F32, OPT_MODE, NONE, NONE)                                              \
    X(D,  'd', 0,   ALWAYS, MOTION, SILENT, ONCE, motion, IMPEDANCE, IMPEDANCE,                    \
      "pdes vdes tff kp kd", REQ_ID, REQ_F32, REQ_F32, REQ_F32, REQ_F32, REQ_F32)                  \
    X(MS, 'm', 's', MULTI,  PRESET, SILENT, ONCE, ms, NONE, PRESET, "p1 p2 p3",                    \
      REQ_ID, REQ_F32, REQ_F32, REQ_F32, NONE, NONE)                                               \
    X(MT, 'm', 't', MULTI,  START,  SILENT, ONCE, start, FILTERED, START, "rel",                   \
      REQ_ID, REQ_FLAG, NONE, NONE, NONE, NONE)                                                    \
    X(MQ, 'm', 'q', MULTI,  START,  SILENT, ONCE, start, TRAPEZOID, START, "rel",                  \
      REQ_ID, REQ_FLAG, NONE, NONE, NONE, NONE)                                                    \
    X(MP, 'm', 'p', MULTI,  START,  SILENT, ONCE, start, PASSTHROUGH, START, "rel",                \
      REQ_ID, REQ_FLAG, NONE, NONE, NONE, NONE)                                                    \
    X(MV, 'm', 'v', MULTI,  START,  SILENT, ONCE, start, VELOCITY, START, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(MC, 'm', 'c', MULTI,  START,  SILENT, ONCE, start, TORQUE, START, "",                        \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(R,  'r', 0,   ALWAYS, READ,   ONE_LINE, RETRY, r, NONE, READ, "path [id]",                   \
      REQ_PATH, OPT_ID, NONE, NONE, NONE, NONE)                                                    \
    X(W,  'w', 0,   ALWAYS, WRITE,  SILENT, ONCE, w, NONE, WRITE, "path value [id]",               \
      REQ_PATH, REQ_VALUE, OPT_ID, NONE, NONE, NONE)                                               \
    X(SS, 's', 's', ALWAYS, SYSTEM, SILENT, ONCE, action, SAVE_CONFIG, ACTION, "",                 \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(SE, 's', 'e', ALWAYS, SYSTEM, SILENT, ONCE, action, ERASE_CONFIG, ACTION, "",                \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(SR, 's', 'r', ALWAYS, SYSTEM, SILENT, ONCE, action, REBOOT, ACTION, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(SC, 's', 'c', ALWAYS, SYSTEM, SILENT, ONCE, action, CLEAR_ERRORS, ACTION, "",                \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(SZ, 's', 'z', ALWAYS, SYSTEM, SILENT, ONCE, action, SET_ZERO, ACTION, "",                    \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(ST, 's', 't', ALWAYS, SYSTEM, SILENT, ONCE, action, ESTOP, ACTION, "",                       \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(H,  'h', 0,   HELP,   QUERY,  UNTIL_QUIET, RETRY, help, NONE, LOCAL, "",                     \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(H_PROPERTIES, 'h', 0, DISCOVERY, QUERY, UNTIL_END, RETRY, help, NONE, LOCAL,                 \
      DARAN_H_PROPERTIES_HELP, REQ_ID, REQ_WORD, OPT_PATH, NONE, NONE, NONE)                       \
    X(F,  'f', 0,   ALWAYS, QUERY,  ONE_LINE, RETRY, query, F, READ_LIST, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(G,  'g', 0,   ALWAYS, QUERY,  ONE_LINE, RETRY, query, G, READ_LIST, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(I,  'i', 0,   ALWAYS, QUERY,  ONE_LINE, RETRY, query, I, READ_LIST, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(E,  'e', 0,   ALWAYS, QUERY,  ERROR_LINES, RETRY, errors, E, READ_LIST, "",                  \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(U,  'u', 0,   ALWAYS, SYSTEM, SILENT, ONCE,  action, FEED_WATCHDOG, ACTION, "",              \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(UB, 'u', 'b', UPDATE, UPDATE, ONE_LINE, RETRY, update, BEGIN, NONE,                          \
      "size crc32 version hardware", REQ_ID, REQ_U32, REQ_U32, REQ_U32, REQ_U32, NONE)             \
    X(UW, 'u', 'w', UPDATE, UPDATE, ONE_LINE, RETRY, update, WRITE, NONE, "offset crc32 data",     \
      REQ_ID, REQ_U32, REQ_U32, REQ_DATA, NONE, NONE)                                              \
    X(UV, 'u', 'v', UPDATE, UPDATE, SILENT, RETRY, update, VERIFY, NONE, "",                       \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(UG, 'u', 'g', UPDATE, UPDATE, SILENT, ONCE, update, COMMIT, NONE, "",                        \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(UY, 'u', 'y', UPDATE, UPDATE, SILENT, RETRY, update, CONFIRM, NONE, "",                      \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(UA, 'u', 'a', UPDATE, UPDATE, SILENT, RETRY, update, ABORT, NONE, "",                        \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)                                                        \
    X(UQ, 'u', 'q', UPDATE, UPDATE, ONE_LINE, RETRY, update, STATUS, NONE, "",                     \
      REQ_ID, NONE, NONE, NONE, NONE, NONE)
/* clang-format on */

/** The alphabet of a DATA field (`uw`): the 85 characters '!'..'~' without
 * '*' (the checksum's mark) from '!' on; 5 characters carry 4 bytes, most
 * significant first, and a last group of n < 5 characters n - 1 bytes. */
#define DARAN_UPDATE_DATA_FIRST '!'
/** The DATA alphabet's last character (see DARAN_UPDATE_DATA_FIRST). */
#define DARAN_UPDATE_DATA_LAST 'v'

#ifndef DARAN_EXTRA_COMMANDS
/** A build's own requests, from its options header (none by default). */
#define DARAN_EXTRA_COMMANDS(X)
#endif

/** Every request: the core's, then the build's own. */
#define DARAN_PROTOCOL_COMMANDS(X) DARAN_PROTOCOL_CORE_COMMANDS(X) DARAN_EXTRA_COMMANDS(X)

/* The properties a QUERY row answers, in the order of its reply line (`e`:
 * its seven lines). On CAN each is read at its own address. */
/** `f`: position and velocity. */
#define DARAN_QUERY_F(X) X(POS_ESTIMATE) X(VEL_ESTIMATE)
/** `g`: bus voltage and current. */
#define DARAN_QUERY_G(X) X(VBUS_VOLTAGE) X(IQ_MEASURED)
/** `i`: firmware and hardware versions, serial number (last: the bridge reads its two halves). */
#define DARAN_QUERY_I(X) X(FW_VERSION) X(HW_VERSION) X(SERIAL_NUMBER)
/** `e`: the seven error registers, one line each. */
#define DARAN_QUERY_E(X)                                                                    \
    X(AXIS_ERROR) X(MOTOR_ERROR) X(ENCODER_ERROR) X(CONTROLLER_ERROR) X(FET_THERMISTOR_ERROR) \
    X(MOTOR_THERMISTOR_ERROR) X(CAN_ERROR)

/** @cond INTERNAL  Reading a row's fields: the fewest and the most fields
 * after the word, and how many of them are values (F32, MODE, FLAG: what
 * the client's request carries as numbers). */
#define DARAN_PF_MIN_NONE 0
#define DARAN_PF_MAX_NONE 0
#define DARAN_PF_VALUES_NONE 0
#define DARAN_PF_KIND_(presence, kind) presence##_##kind
#define DARAN_PF_MIN_REQ_ID 1
#define DARAN_PF_MIN_REQ_F32 1
#define DARAN_PF_MIN_REQ_MODE 1
#define DARAN_PF_MIN_REQ_FLAG 1
#define DARAN_PF_MIN_REQ_PATH 1
#define DARAN_PF_MIN_REQ_VALUE 1
#define DARAN_PF_MIN_REQ_WORD 1
#define DARAN_PF_MIN_REQ_U32 1
#define DARAN_PF_MIN_REQ_DATA 1
#define DARAN_PF_MIN_OPT_ID 0
#define DARAN_PF_MIN_OPT_F32 0
#define DARAN_PF_MIN_OPT_MODE 0
#define DARAN_PF_MIN_OPT_FLAG 0
#define DARAN_PF_MIN_OPT_PATH 0
#define DARAN_PF_MAX_REQ_ID 1
#define DARAN_PF_MAX_REQ_F32 1
#define DARAN_PF_MAX_REQ_MODE 1
#define DARAN_PF_MAX_REQ_FLAG 1
#define DARAN_PF_MAX_REQ_PATH 1
#define DARAN_PF_MAX_REQ_VALUE 1
#define DARAN_PF_MAX_REQ_WORD 1
#define DARAN_PF_MAX_REQ_U32 1
#define DARAN_PF_MAX_REQ_DATA 1
#define DARAN_PF_MAX_OPT_ID 1
#define DARAN_PF_MAX_OPT_F32 1
#define DARAN_PF_MAX_OPT_MODE 1
#define DARAN_PF_MAX_OPT_FLAG 1
#define DARAN_PF_MAX_OPT_PATH 1
#define DARAN_PF_VALUES_REQ_ID 0
#define DARAN_PF_VALUES_REQ_F32 1
#define DARAN_PF_VALUES_REQ_MODE 1
#define DARAN_PF_VALUES_REQ_FLAG 1
#define DARAN_PF_VALUES_REQ_PATH 0
#define DARAN_PF_VALUES_REQ_VALUE 0
#define DARAN_PF_VALUES_REQ_WORD 0
#define DARAN_PF_VALUES_REQ_U32 0
#define DARAN_PF_VALUES_REQ_DATA 0
#define DARAN_PF_VALUES_OPT_ID 0
#define DARAN_PF_VALUES_OPT_F32 1
#define DARAN_PF_VALUES_OPT_MODE 1
#define DARAN_PF_VALUES_OPT_FLAG 1
#define DARAN_PF_VALUES_OPT_PATH 0
#define DARAN_PF_PATH_FIRST_REQ_PATH 1
#define DARAN_PF_PATH_FIRST_REQ_ID 0
/** @endcond */

/** The fewest fields after the word of a row's f1..f6. */
#define DARAN_PROTOCOL_MIN_FIELDS(f1, f2, f3, f4, f5, f6)                                \
    (DARAN_PF_MIN_##f1 + DARAN_PF_MIN_##f2 + DARAN_PF_MIN_##f3 + DARAN_PF_MIN_##f4 + \
     DARAN_PF_MIN_##f5 + DARAN_PF_MIN_##f6)
/** The most fields after the word. */
#define DARAN_PROTOCOL_MAX_FIELDS(f1, f2, f3, f4, f5, f6)                                \
    (DARAN_PF_MAX_##f1 + DARAN_PF_MAX_##f2 + DARAN_PF_MAX_##f3 + DARAN_PF_MAX_##f4 + \
     DARAN_PF_MAX_##f5 + DARAN_PF_MAX_##f6)
/** The fewest values (numbers after the id: F32, MODE, FLAG). */
#define DARAN_PROTOCOL_MIN_VALUES(f1, f2, f3, f4, f5, f6)                                  \
    (DARAN_PF_VALUES_##f1 * DARAN_PF_MIN_##f1 + DARAN_PF_VALUES_##f2 * DARAN_PF_MIN_##f2 + \
     DARAN_PF_VALUES_##f3 * DARAN_PF_MIN_##f3 + DARAN_PF_VALUES_##f4 * DARAN_PF_MIN_##f4 + \
     DARAN_PF_VALUES_##f5 * DARAN_PF_MIN_##f5 + DARAN_PF_VALUES_##f6 * DARAN_PF_MIN_##f6)
/** The most values. */
#define DARAN_PROTOCOL_MAX_VALUES(f1, f2, f3, f4, f5, f6)                                \
    (DARAN_PF_VALUES_##f1 + DARAN_PF_VALUES_##f2 + DARAN_PF_VALUES_##f3 +                \
     DARAN_PF_VALUES_##f4 + DARAN_PF_VALUES_##f5 + DARAN_PF_VALUES_##f6)
/** 1 when the row's first field is a property path (`r`, `w`): the id is
 * in the path or after the value. */
#define DARAN_PROTOCOL_PATH_FIRST(f1) DARAN_PF_PATH_FIRST_##f1

#endif /* DARAN_PROTOCOL_H */

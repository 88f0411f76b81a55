/** @file daran_build.h
 * The build check: what the library and a program using it must agree on,
 * computed by each from the headers it was compiled with.
 *
 * DARAN_BUILD_SIGNATURE is a constant expression: the property table (every
 * row's id, path length, type, access, scope, range, unit length and CAN
 * address; the rows left out by DARAN_OMIT_PROPERTIES and by the CMake list
 * DARAN_PROPERTY_OMIT), the range texts' lengths, and the options that
 * change behaviour without changing an instance's size (the CAN options
 * among them). A string's characters cannot be read in a C constant
 * expression, so daran_port_table_hash() hashes the texts of the port's own
 * rows and ranges (DARAN_PORT_PROPERTY_LIST, DARAN_PORT_RANGE_LIST: the part
 * of the table an options header writes) when it runs; the vendor's rows
 * and ranges are this library's own headers, the same text on both sides.
 *
 * daran_init(), daran_can_init() and daran_can_bridge_init() pass the
 * program's DARAN_BUILD_CHECK() of the instance type, and the library
 * refuses an instance whose check differs from its own
 * (DARAN_ERR_BUILD_MISMATCH) before touching it, instead of running with
 * property ids, ranges, options or a layout that mean something else to
 * it. */
#ifndef DARAN_BUILD_H
#define DARAN_BUILD_H

#include <stdint.h>

#include "daran_config.h"
#include "daran_properties.h"

/** @cond INTERNAL */
#define DARAN_SIG_RO 0u
#define DARAN_SIG_RW 1u
#define DARAN_SIG_SYSTEM 0u
#define DARAN_SIG_AXIS 1u

/* One row: its id picks a multiplier, its attributes the value multiplied. */
#define DARAN_SIG_ROW_(id, path, scope, type, access, range, unit, can)                     \
    +((uint32_t)DARAN_PROP_##id * 0x9E3779B1u + 0x7F4A7C15u) *                             \
         (((uint32_t)sizeof(path) << 20) ^ ((uint32_t)sizeof(unit) << 14) ^                 \
          ((uint32_t)DARAN_TYPE_##type << 11) ^ (DARAN_SIG_##access << 10) ^                 \
          (DARAN_SIG_##scope << 9) ^ (uint32_t)DARAN_RANGE_##range ^                         \
          ((uint32_t)(can) << 15) ^ 0x5BD1E995u)
#define DARAN_SIG_RANGE_(name, text) \
    +((uint32_t)DARAN_RANGE_##name + 1u) * (uint32_t)sizeof(text) * 0x85EBCA6Bu
#define DARAN_SIG_OMIT_(id) +((uint32_t)DARAN_PROP_##id + 1u) * 0xC2B2AE35u

#ifdef DARAN_PORT_PROPERTY_LIST
#define DARAN_SIG_PORT_ROWS_ DARAN_PORT_PROPERTY_LIST(DARAN_SIG_ROW_)
#else
#define DARAN_SIG_PORT_ROWS_
#endif
#ifdef DARAN_PORT_RANGE_LIST
#define DARAN_SIG_PORT_RANGES_ DARAN_PORT_RANGE_LIST(DARAN_SIG_RANGE_)
#else
#define DARAN_SIG_PORT_RANGES_
#endif
#ifdef DARAN_OMIT_PROPERTIES
#define DARAN_SIG_OMITTED_ DARAN_OMIT_PROPERTIES(DARAN_SIG_OMIT_)
#else
#define DARAN_SIG_OMITTED_
#endif
/* Set by the build (daran_ascii_add_library) from DARAN_PROPERTY_OMIT. */
#ifndef DARAN_OMIT_LIST_SIGNATURE
#define DARAN_OMIT_LIST_SIGNATURE 0u
#endif
/** @endcond */

/** The signature of the options and property table this file is compiled with. */
#define DARAN_BUILD_SIGNATURE                                                                \
    ((uint32_t)(0u DARAN_PROPERTY_LIST(DARAN_SIG_ROW_) DARAN_SIG_PORT_ROWS_                   \
                    DARAN_RANGE_LIST(DARAN_SIG_RANGE_) DARAN_SIG_PORT_RANGES_                  \
                        DARAN_SIG_OMITTED_) ^                                                  \
     (uint32_t)DARAN_OMIT_LIST_SIGNATURE ^ (uint32_t)DARAN_PROP_COUNT << 22 ^                  \
     (uint32_t)DARAN_MOTOR_ID_MAX << 8 ^ (uint32_t)DARAN_REPLY_CRLF << 4 ^                     \
     (uint32_t)DARAN_ENABLE_HELP << 5 ^ (uint32_t)DARAN_ENABLE_MULTI_MOTOR << 6 ^               \
     (uint32_t)DARAN_ENABLE_DISCOVERY << 7 ^ (uint32_t)DARAN_ENABLE_TELEMETRY << 16 ^            \
     (uint32_t)DARAN_ENABLE_PORT_COMMANDS << 17 ^ (uint32_t)DARAN_ENABLE_S_CURVE << 18 ^          \
     (uint32_t)DARAN_ENABLE_CAN << 19 ^ (uint32_t)DARAN_ENABLE_CAN_BRIDGE << 20 ^                 \
     (uint32_t)DARAN_ENABLE_UPDATE << 21 ^                                                      \
     (uint32_t)DARAN_CAN_RX_FRAMES * 0x27D4EB2Fu ^ (uint32_t)DARAN_CAN_BRIDGE_TIMEOUT_MS * 0x165667B1u)

/** @cond INTERNAL */
/* The texts of a port row and a port range. Their ids, types, access,
 * scopes, range numbers, CAN addresses and the texts' lengths are in the
 * signature above; here are the characters it cannot read. */
#define DARAN_SIG_ROW_TEXT_(id, path, scope, type, access, range, unit, can) path "\n" unit "\n"
#define DARAN_SIG_RANGE_TEXT_(name, text) text "\n"
#ifdef DARAN_PORT_PROPERTY_LIST
#define DARAN_SIG_PORT_ROW_TEXTS_ DARAN_PORT_PROPERTY_LIST(DARAN_SIG_ROW_TEXT_)
#else
#define DARAN_SIG_PORT_ROW_TEXTS_
#endif
#ifdef DARAN_PORT_RANGE_LIST
#define DARAN_SIG_PORT_RANGE_TEXTS_ DARAN_PORT_RANGE_LIST(DARAN_SIG_RANGE_TEXT_)
#else
#define DARAN_SIG_PORT_RANGE_TEXTS_
#endif
/** @endcond */

/** FNV-1a of the texts of the port's own rows and ranges as this file is
 * compiled: each row's path and unit, then each range's text, in table
 * order, so two rows of the same shape swapped, a range of the same length
 * with other bounds, or a path or unit spelt otherwise change it. One string
 * literal: a program and a library that agree share it in the linked image.
 * Without port rows or ranges it is a constant, and costs nothing. */
static inline uint32_t daran_port_table_hash(void)
{
    uint32_t hash = 2166136261u;
    for (const char *c = "" DARAN_SIG_PORT_ROW_TEXTS_ DARAN_SIG_PORT_RANGE_TEXTS_; *c != '\0';
         c++) {
        hash = (hash ^ (uint8_t)*c) * 16777619u;
    }
    return hash;
}

/** What an init function of the library compares for an instance of type
 * @p instance_type (daran_drive_t, daran_can_t, daran_can_bridge_t): the
 * build signature, the port's table texts and the instance's size, as the
 * caller was compiled. */
#define DARAN_BUILD_CHECK(instance_type)                                                     \
    (DARAN_BUILD_SIGNATURE ^ daran_port_table_hash() ^ (uint32_t)sizeof(instance_type))

#endif /* DARAN_BUILD_H */

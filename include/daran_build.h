/** @file daran_build.h
 * The build signature: one 32-bit number that changes with everything in
 * the options header that the library and a program using it must agree on:
 * the property table (every row's id, path length, type, access, scope,
 * range and unit length; the rows left out by DARAN_OMIT_PROPERTIES and by
 * the CMake list DARAN_PROPERTY_OMIT), the range texts, and the options that
 * change behaviour without changing sizeof(daran_drive_t).
 *
 * It is a constant expression of the headers alone, so the library computes
 * it when it is compiled and a program when it is: daran_init() passes the
 * program's value and the library refuses an instance whose value differs
 * from its own (DARAN_ERR_BUILD_MISMATCH), instead of running with
 * property ids or options that mean something else to it. */
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
     (uint32_t)DARAN_ENABLE_PORT_COMMANDS << 17 ^ (uint32_t)DARAN_ENABLE_S_CURVE << 18)

#endif /* DARAN_BUILD_H */

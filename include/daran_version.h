/** @file daran_version.h
 * The library's version, for code that must check it at compile time (the
 * build takes the project version from here: one place to change). */
#ifndef DARAN_VERSION_H
#define DARAN_VERSION_H

#define DARAN_VERSION_MAJOR 0 /**< incompatible API changes */
#define DARAN_VERSION_MINOR 1 /**< new features, compatible */
#define DARAN_VERSION_PATCH 0 /**< fixes */

/** @cond INTERNAL */
#define DARAN_VERSION_TEXT_(a, b, c) #a "." #b "." #c
#define DARAN_VERSION_TEXT_X_(a, b, c) DARAN_VERSION_TEXT_(a, b, c)
/** @endcond */
/** "MAJOR.MINOR.PATCH" as a string literal. */
#define DARAN_VERSION_TEXT \
    DARAN_VERSION_TEXT_X_(DARAN_VERSION_MAJOR, DARAN_VERSION_MINOR, DARAN_VERSION_PATCH)

#endif /* DARAN_VERSION_H */

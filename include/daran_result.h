/** @file daran_result.h
 * The one return convention of the daran-ascii API.
 *
 * Every function that can fail returns daran_result_t: DARAN_OK (0) is
 * success; every other value names one error reply of the protocol (its
 * phrase is daran_result_phrase()), except DARAN_ERR_BAD_ARGUMENT and
 * DARAN_ERR_BUILD_MISMATCH, which report misuse of the API itself and are
 * never sent on the link.
 * HAL functions return the same type: a HAL that refuses a request returns the
 * protocol error the drive should answer with. */
#ifndef DARAN_RESULT_H
#define DARAN_RESULT_H

#ifdef __cplusplus
extern "C" {
#endif

/** Marks a result the caller must not ignore (warn_unused_result on GCC and clang). */
#if defined(__GNUC__) || defined(__clang__)
#define DARAN_NODISCARD __attribute__((warn_unused_result))
#else
#define DARAN_NODISCARD
#endif

/** Every result with its phrase: X(NAME, "phrase") gives DARAN_<NAME>, in
 * this order, and daran_result_phrase()'s text, so the two cannot drift
 * apart. The phrases are the protocol's error replies (`error: <phrase>`),
 * except the last two, which report misuse of the API and are never sent:
 *
 * | result | phrase |
 * |---|---|
 * | DARAN_OK | ok (success) |
 * | DARAN_ERR_UNKNOWN_COMMAND | unknown command |
 * | DARAN_ERR_INVALID_FORMAT | invalid command format |
 * | DARAN_ERR_INVALID_MOTOR | invalid motor |
 * | DARAN_ERR_INVALID_VALUE | invalid value |
 * | DARAN_ERR_OUT_OF_RANGE | value out of range |
 * | DARAN_ERR_INVALID_MODE | invalid mode |
 * | DARAN_ERR_INVALID_PROPERTY | invalid property |
 * | DARAN_ERR_READ_ONLY | read only property |
 * | DARAN_ERR_INVALID_CHECKSUM | invalid checksum |
 * | DARAN_ERR_CHECKSUM_MISMATCH | checksum mismatch |
 * | DARAN_ERR_LINE_TOO_LONG | line too long |
 * | DARAN_ERR_INVALID_CHARACTER | invalid character |
 * | DARAN_ERR_NO_PRESET | no preset |
 * | DARAN_ERR_TRAJECTORY_INFEASIBLE | trajectory infeasible |
 * | DARAN_ERR_ESTOP_ACTIVE | estop active |
 * | DARAN_ERR_MOTOR_FAULT | motor fault |
 * | DARAN_ERR_MOTOR_IDLE | motor idle |
 * | DARAN_ERR_UPDATE_OPEN | updating |
 * | DARAN_ERR_NOT_IDLE | not idle |
 * | DARAN_ERR_NO_UPDATE | no update |
 * | DARAN_ERR_INVALID_IMAGE | bad image |
 * | DARAN_ERR_BAD_ARGUMENT | bad argument: a NULL pointer or a bad table given to the API |
 * | DARAN_ERR_BUILD_MISMATCH | build mismatch: daran_init(), daran_can_init() or daran_can_bridge_init() of a program built with another options header or property table |
 */
#define DARAN_RESULT_LIST(X) \
    X(OK,                        "ok") \
    X(ERR_UNKNOWN_COMMAND,       "unknown command") \
    X(ERR_INVALID_FORMAT,        "invalid command format") \
    X(ERR_INVALID_MOTOR,         "invalid motor") \
    X(ERR_INVALID_VALUE,         "invalid value") \
    X(ERR_OUT_OF_RANGE,          "value out of range") \
    X(ERR_INVALID_MODE,          "invalid mode") \
    X(ERR_INVALID_PROPERTY,      "invalid property") \
    X(ERR_READ_ONLY,             "read only property") \
    X(ERR_INVALID_CHECKSUM,      "invalid checksum") \
    X(ERR_CHECKSUM_MISMATCH,     "checksum mismatch") \
    X(ERR_LINE_TOO_LONG,         "line too long") \
    X(ERR_INVALID_CHARACTER,     "invalid character") \
    X(ERR_NO_PRESET,             "no preset") \
    X(ERR_TRAJECTORY_INFEASIBLE, "trajectory infeasible") \
    X(ERR_ESTOP_ACTIVE,          "estop active") \
    X(ERR_MOTOR_FAULT,           "motor fault") \
    X(ERR_MOTOR_IDLE,            "motor idle") \
    X(ERR_UPDATE_OPEN,           "updating") /* motion, or another `ub`, while an update is open */ \
    X(ERR_NOT_IDLE,              "not idle") /* an update step while the axis is not idle */ \
    X(ERR_NO_UPDATE,             "no update") /* a step the update's state does not allow */ \
    X(ERR_INVALID_IMAGE,         "bad image") /* foreign hardware, too big, or `uv` found it bad */ \
    X(ERR_NO_REPLY,              "no reply") /* a bridged query's drive did not answer (C32) */ \
    X(ERR_BUS_ERROR,             "bus error") /* the CAN port could not send (C33) */ \
    X(ERR_NOT_BRIDGED,           "not bridged") /* a line for another id with no CAN form (C35) */ \
    X(ERR_BAD_ARGUMENT,          "bad argument") \
    X(ERR_BUILD_MISMATCH,        "build mismatch")

/** DARAN_OK, or the error a request is answered with (DARAN_RESULT_LIST). */
typedef enum daran_result {
/** @cond INTERNAL */
#define DARAN_RESULT_ENUM_(name, phrase) DARAN_##name,
    DARAN_RESULT_LIST(DARAN_RESULT_ENUM_)
#undef DARAN_RESULT_ENUM_
/** @endcond */
    DARAN_RESULT_COUNT /**< how many results there are; not a result */
} daran_result_t;

/** The error phrase of a result ("unknown command"), without "error: ".
 * DARAN_OK gives "ok"; a value outside the enum gives "motor fault", the
 * phrase the core answers when a HAL returns something it does not know.
 * O(1), touches nothing, cannot fail. */
const char *daran_result_phrase(daran_result_t result);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_RESULT_H */

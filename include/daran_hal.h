/** @file daran_hal.h
 * The hardware layer (HAL): everything a drive calls out to, given by the
 * port as one description (daran_hal_t) with one context pointer. Its
 * property, motion and action functions, its reply writer, its forward hook,
 * its clock and its CAN transmit all take that same context.
 *
 * The core never touches hardware. It validates a whole line first, then
 * makes at most one HAL setter, move or action call for it (plus a watchdog
 * feed after an accepted motion command). Getters may be called while a
 * line is validated (the drive's id, state and error flags, the position
 * setpoint for relative moves); they must have no side effects.
 *
 * Every function returns DARAN_OK or the protocol error the drive should
 * answer with (DARAN_ERR_MOTOR_FAULT for a hardware failure); a result from
 * DARAN_ERR_NO_REPLY on (the bridge's own errors, the API's) is answered
 * `motor fault`. A function that
 * returns an error must leave the drive unchanged. All are called from the
 * thread that calls daran_poll() / daran_process_line(), never from the
 * byte-input interrupt. */
#ifndef DARAN_HAL_H
#define DARAN_HAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_properties.h"
#include "daran_result.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Axis states of `requested_state` / `current_state`. */
#define DARAN_STATE_IDLE 1u        /**< motor unpowered; motion commands answer `motor idle` */
#define DARAN_STATE_CLOSED_LOOP 8u /**< under closed-loop control; motion is accepted */

/** Bits of the error registers, as the vendor's tools name them (ODrive's
 * bit meanings: bit i is entry i+1 of the vendor client's `error_codes`
 * lists). The core reads `axis0.error` before every motion command: any bit
 * set there blocks motion until `sc` (DARAN_FLAG_ESTOP answers `estop
 * active`, every other bit `motor fault`). A port sets the bits its
 * hardware detects; docs/porting.md says how to map them. */
#define DARAN_FLAG_UNDERVOLTAGE       (1u << 1)  /**< axis0.error: DC bus under-voltage */
#define DARAN_FLAG_MOTOR_FAILED       (1u << 6)  /**< axis0.error: motor.error is not 0 */
#define DARAN_FLAG_ENCODER_FAILED     (1u << 8)  /**< axis0.error: encoder.error is not 0 */
#define DARAN_FLAG_CONTROLLER_FAILED  (1u << 9)  /**< axis0.error: controller.error is not 0 */
#define DARAN_FLAG_WATCHDOG           (1u << 11) /**< axis0.error: watchdog not fed in time */
#define DARAN_FLAG_ESTOP              (1u << 14) /**< axis0.error: `st` (e-stop requested) */
#define DARAN_FLAG_OVERTEMP           (1u << 18) /**< axis0.error: a thermistor tripped */
#define DARAN_MOTOR_ERROR_STALL       (1u << 16) /**< motor.error: the stall limiter tripped */
#define DARAN_CONTROLLER_ERROR_OVERSPEED (1u << 0) /**< controller.error: speed beyond vel_limit x vel_limit_tolerance */
#define DARAN_THERMISTOR_ERROR_OVERTEMP (1u << 0) /**< fet_/motor_thermistor.error: above temp_limit_upper */
/** axis0.config_warnings: conditions that never block motion; `sc` clears them. */
#define DARAN_WARNING_NVM_CORRUPT     (1u << 0)  /**< the stored config was damaged; defaults loaded */

/** A property value; the property's type says which member is meant
 * (DARAN_TYPE_BOOL uses u32, 0 or 1). */
typedef union daran_value {
    float f32;    /**< DARAN_TYPE_F32 */
    uint32_t u32; /**< DARAN_TYPE_U32, and DARAN_TYPE_BOOL as 0 or 1 */
    int32_t s32;  /**< DARAN_TYPE_S32 */
    uint64_t u64; /**< DARAN_TYPE_U64 */
} daran_value_t;

/** The control modes a motion command selects. */
typedef enum daran_move_kind {
    DARAN_MOVE_FILTERED_POSITION, /**< `t`, `mt`: input filter toward pos_deg */
    DARAN_MOVE_TRAPEZOID,         /**< `q`, `mq`: trapezoidal move to pos_deg */
    DARAN_MOVE_PASSTHROUGH,       /**< `p`, `mp`: pos_deg with vel/torque feed-forward */
    DARAN_MOVE_VELOCITY,          /**< `v`/`mv` mode 1: vel_rpm at once, torque_nm feed-forward */
    DARAN_MOVE_VELOCITY_RAMP,     /**< `v`/`mv` mode 2: ramp to vel_rpm at rate */
    DARAN_MOVE_TORQUE,            /**< `c`/`mc` mode 1: torque_nm at once */
    DARAN_MOVE_TORQUE_RAMP,       /**< `c`/`mc` mode 6 (or 2): ramp to torque_nm at rate */
    DARAN_MOVE_IMPEDANCE          /**< `d`: torque = kp(pos_deg-pos) + torque_nm + kd(vel_rpm-vel) */
} daran_move_kind_t;

/** daran_move_t.given: which optional values the line carried. */
#define DARAN_GIVEN_VEL  (1u << 0) /**< vel_rpm was given (TRAPEZOID) */
#define DARAN_GIVEN_RATE (1u << 1) /**< rate was given (FILTERED_POSITION, TRAPEZOID) */

/** One validated motion command, in protocol units (output shaft).
 *
 * | kind              | pos_deg | vel_rpm        | torque_nm | rate                              |
 * |-------------------|---------|----------------|-----------|-----------------------------------|
 * | FILTERED_POSITION | target  | -              | -         | filter bandwidth 1/s > 0 (*)      |
 * | TRAPEZOID         | target  | cruise > 0 (*) | -         | accel = decel (r/min)/s >= 0 (*)  |
 * | PASSTHROUGH       | target  | feed-forward   | feed-fwd  | -                                 |
 * | VELOCITY          | -       | target         | feed-fwd  | -                                 |
 * | VELOCITY_RAMP     | -       | target         | -         | ramp (r/min)/s >= 0               |
 * | TORQUE            | -       | -              | target    | -                                 |
 * | TORQUE_RAMP       | -       | -              | target    | ramp Nm/s >= 0                    |
 * | IMPEDANCE         | pdes    | vdes           | tff       | -  (kp, kd >= 0)                  |
 *
 * (*) only when the matching DARAN_GIVEN_ bit is set; otherwise the drive
 * keeps its current setting. A given filter bandwidth also becomes
 * `input_filter_bandwidth`; a given trapezoid cruise and acceleration become
 * `output_shaft.trap_traj_vel_limit` and `trap_traj_accel_limit` =
 * `trap_traj_decel_limit`; a velocity ramp `vel_ramp_rate`, a torque ramp
 * `torque_ramp_rate`. The HAL also stores the targets in the
 * `output_shaft.input_*` properties (see docs/porting.md). Unused members
 * are 0.
 *
 * Zero rates are meaningful (protocol.md section 10.1; the vendor's own
 * library sends them by default): a TRAPEZOID whose acceleration is 0 (given
 * or stored) steps the setpoint to the target, bounded only by the drive's
 * velocity and torque limits, and is done at once; a ramp of 0 holds the
 * current setpoint where it is. The core never passes a filter bandwidth of
 * 0 (it clears DARAN_GIVEN_RATE instead: "keep the current one"), nor a
 * cruise velocity with an acceleration of 0 (the step has no cruise).
 * With `axis0.trap_traj.config.traj_mode` 2 a TRAPEZOID runs as an S-curve:
 * each acceleration phase takes 2 v/a (the acceleration rises to a and back
 * to 0). */
typedef struct daran_move {
    daran_move_kind_t kind; /**< the control mode; it says which members below are meant */
    uint8_t given;          /**< DARAN_GIVEN_ bits: optional values the line carried */
    float pos_deg;          /**< position, degrees of the output shaft */
    float vel_rpm;          /**< velocity, r/min of the output shaft */
    float torque_nm;        /**< torque, Nm at the output shaft */
    float rate;             /**< filter bandwidth or ramp rate (see the table above) */
    float kp;               /**< IMPEDANCE stiffness, Nm/deg, >= 0 */
    float kd;               /**< IMPEDANCE damping, Nm/(r/min), >= 0 */
} daran_move_t;

/** Actions without values. */
typedef enum daran_action {
    DARAN_ACTION_SAVE_CONFIG,   /**< `ss`: write the config to non-volatile memory */
    DARAN_ACTION_ERASE_CONFIG,  /**< `se`: erase it; defaults load at next boot */
    DARAN_ACTION_REBOOT,        /**< `sr`: reboot */
    DARAN_ACTION_CLEAR_ERRORS,  /**< `sc`: clear the error flags (state stays idle) */
    DARAN_ACTION_SET_ZERO,      /**< `sz`: current position becomes 0, setpoints shift with it */
    DARAN_ACTION_ESTOP,         /**< `st`: go idle with DARAN_FLAG_ESTOP */
    DARAN_ACTION_FEED_WATCHDOG, /**< `u`, and after every accepted motion command; on CAN every frame for the drive (C18) */
    DARAN_ACTION_NODE_GUARD     /**< CAN node guarding expired (`can.config.timeout_ms`, C16):
                                     go idle with DARAN_FLAG_WATCHDOG, as on an axis watchdog
                                     expiry (idle damping where the port has it) */
} daran_action_t;

struct daran_can_frame;    /* daran_can.h */
struct daran_update_port;  /* daran_update.h */

/** Receives one whole reply line (line end included; never NUL-terminated).
 * Called from daran_poll() / daran_process_line(). */
typedef void (*daran_write_fn)(void *ctx, const char *line, size_t len);

/** Receives a line the drive does not execute alone: a line addressed to
 * another motor id, or a broadcast (id 0) line that is not a read. The line is
 * as received, checksum field included, without its `\n` (a CRLF sender's
 * `\r` stays: it is part of the line). */
typedef void (*daran_forward_fn)(void *ctx, uint8_t motor_id, const char *line, size_t len);

/** The port's description: every function takes the context given to
 * daran_init(). get, set, move, action and write are required; forward and
 * can_system are optional (NULL); now_ms and can_send are required by
 * daran_can_init() and unused without a CAN front end. */
typedef struct daran_hal {
    /** Read a property. Must have no side effects. */
    daran_result_t (*get)(void *ctx, daran_prop_t prop, daran_value_t *out);
    /** Write a property the core has range-checked. Read-only properties
     * never reach it. */
    daran_result_t (*set)(void *ctx, daran_prop_t prop, daran_value_t value);
    /** Start a validated motion command. The core has already checked the
     * drive's state (closed loop, no blocking flag). */
    daran_result_t (*move)(void *ctx, const daran_move_t *move);
    /** Carry out an action. */
    daran_result_t (*action)(void *ctx, daran_action_t action);
    /** Send a reply line (the link's transmit). */
    daran_write_fn write;
    /** Optional (NULL: such lines are dropped): a CAN gateway's hook for
     * lines to other ids. A bridge (daran_can_bridge_init()) takes them
     * instead while it is on. */
    daran_forward_fn forward;
    /** Milliseconds since boot; wraps at 2^32. Read by the CAN front end
     * and the bridge. */
    uint32_t (*now_ms)(void *ctx);
    /** Queue a CAN frame for transmission: true when the controller took
     * it, false when no transmit buffer is free or the controller is
     * bus-off. */
    bool (*can_send)(void *ctx, const struct daran_can_frame *frame);
    /** Optional (NULL: ignored): the CAN system sub-codes the library does
     * not carry out itself, 0x00 (restore initial configuration) and 0x07
     * (firmware-update mode), with their two 16-bit data fields (C19). */
    void (*can_system)(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2);
    /** Optional (NULL: no firmware update): the flash and boot control the
     * update module (daran_update.h) works with. */
    const struct daran_update_port *update;
} daran_hal_t;

#ifdef __cplusplus
}
#endif

#endif /* DARAN_HAL_H */

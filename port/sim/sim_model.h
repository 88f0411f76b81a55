/* The physical model of one simulated drive: a rigid shaft driven by a
 * cascaded position/velocity/torque controller, with its input modes,
 * electrical and thermal behaviour, protections and states.
 *
 * Portable C99 (it is also the plant of the Cortex-M4 example): no stdio, no
 * heap, fixed-size state, float arithmetic. Units inside are the protocol's
 * (degrees, r/min, Nm, seconds) so that what a host writes reads back
 * bit-identical; the gains are applied in turns as their units say. */
#ifndef DARAN_SIM_MODEL_H
#define DARAN_SIM_MODEL_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Plant constants that are not protocol properties. A test may change them
 * after daran_sim_model_init(). */
typedef struct daran_sim_params {
    float rotor_inertia;      /* Nm/(turn/s^2), added to output_shaft.load_inertia */
    float viscous_friction;   /* Nm/(turn/s) */
    float coulomb_friction;   /* Nm */
    float phase_resistance;   /* ohm, copper loss Iq^2 R */
    float vbus_nominal;       /* V */
    float source_resistance;  /* ohm, bus sag under load */
    float undervoltage_trip;  /* V */
    float sag_voltage;        /* V the bus drops to under the undervoltage fault */
    float sag_duration;       /* s the sag lasts */
    float ambient_temp;       /* degC */
    float motor_heat;         /* degC per A^2 at steady state */
    float motor_time_const;   /* s */
    float fet_heat;           /* degC per A^2 at steady state */
    float fet_time_const;     /* s */
    float overtemp_jump;      /* degC above temp_limit_upper the overtemp fault puts */
} daran_sim_params_t;

/* What the controller is doing in closed loop. */
typedef enum daran_sim_mode {
    DARAN_SIM_MODE_PASSTHROUGH, /* p, hold after entering closed loop */
    DARAN_SIM_MODE_FILTER,      /* t */
    DARAN_SIM_MODE_TRAPEZOID,   /* q, mq */
    DARAN_SIM_MODE_VELOCITY,    /* v mode 1 */
    DARAN_SIM_MODE_VELOCITY_RAMP,
    DARAN_SIM_MODE_TORQUE,      /* c mode 1 */
    DARAN_SIM_MODE_TORQUE_RAMP,
    DARAN_SIM_MODE_IMPEDANCE    /* d */
} daran_sim_mode_t;

/* Fault injections (the `!fault` directive). */
typedef enum daran_sim_fault {
    DARAN_SIM_FAULT_OVERTEMP,
    DARAN_SIM_FAULT_UNDERVOLTAGE
} daran_sim_fault_t;

typedef struct daran_sim_model {
    daran_sim_params_t par;
    /* Configuration and every other stored property, by property id. Only
     * the rows that are plain stored values are used. */
    daran_value_t cfg[DARAN_PROP_COUNT];
    float zero_offset_deg;    /* encoder reading that is position 0 (persisted) */

    /* plant */
    float raw_pos_deg;        /* physical shaft angle; survives a power cycle */
    float vel_rpm;
    float torque_nm;          /* torque the current loop delivers (lags the command) */
    float ext_torque_nm;      /* external load torque applied to the shaft */
    float vbus_v;
    float ibus_a;
    float sag_left_s;
    float motor_temp_c;
    float fet_temp_c;

    /* controller */
    uint32_t state;
    uint32_t requested_state;
    uint32_t error;
    uint32_t fet_error;
    uint32_t motor_error;
    daran_sim_mode_t mode;
    float input_pos;          /* deg */
    float input_vel;          /* r/min */
    float input_torque;       /* Nm */
    float pos_sp;             /* deg */
    float vel_sp;             /* r/min */
    float torque_ff;          /* Nm, feed-forward into the velocity loop */
    float torque_cmd;         /* Nm, what the controller commands this tick */
    float integrator;         /* Nm */
    float kp;                 /* d: Nm/deg */
    float kd;                 /* d: Nm/(r/min) */

    /* input filter (t): setpoint = filt_ref + filt_err (deg), velocity deg/s */
    float filt_ref;
    float filt_err;
    float filt_vel;

    /* trapezoid (q, mq): deg, deg/s, deg/s^2, s */
    float trap_start;
    float trap_target;
    float trap_vmax;
    float trap_acc;
    float trap_ta;
    float trap_tc;
    float trap_total;
    uint32_t trap_ticks;
    uint32_t trap_end_tick;   /* the tick the plan ends on */
    bool trajectory_done;
    float trap_vel_rpm;       /* current `q` cruise setting, r/min (D20) */
    float trap_acc_rpms;      /* current `q` accel setting, (r/min)/s (D20) */

    float watchdog_s;         /* time since the last feed */

    uint32_t tick_hz;
    float dt;
    uint64_t ticks;
} daran_sim_model_t;

/* Reset everything to power-on defaults at @p tick_hz (>= 1): default
 * configuration, shaft at rest at angle 0, closed loop. */
void daran_sim_model_init(daran_sim_model_t *m, uint32_t tick_hz);

/* The default value of every configuration property. */
void daran_sim_model_default_config(daran_sim_model_t *m);

/* Power-on after the configuration (cfg, zero_offset_deg) has been loaded:
 * flags cleared, closed loop holding the current position. The physical
 * state (angle, temperatures) is kept. */
void daran_sim_model_boot(daran_sim_model_t *m);

/* Advance one control tick. */
void daran_sim_model_tick(daran_sim_model_t *m);

/* True for properties that are configuration (persisted by `ss`). */
bool daran_sim_is_config_prop(daran_prop_t prop);

daran_result_t daran_sim_model_get(const daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t *out);
daran_result_t daran_sim_model_set(daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t value);
daran_result_t daran_sim_model_move(daran_sim_model_t *m, const daran_move_t *move);

/* Go idle and raise @p flags (0: plain idle). */
void daran_sim_model_trip(daran_sim_model_t *m, uint32_t flags);
/* `sc`: clear every flag; the state stays as it is. */
void daran_sim_model_clear_errors(daran_sim_model_t *m);
/* `sz`: the current position becomes 0, setpoints shift with it. */
void daran_sim_model_set_zero(daran_sim_model_t *m);
/* Enter closed loop holding the current position; refuses while a blocking
 * flag is set. */
daran_result_t daran_sim_model_closed_loop(daran_sim_model_t *m);
void daran_sim_model_feed_watchdog(daran_sim_model_t *m);
void daran_sim_model_fault(daran_sim_model_t *m, daran_sim_fault_t fault);

/* Derived values, in protocol units. */
float daran_sim_model_pos_deg(const daran_sim_model_t *m);
float daran_sim_model_torque_limit(const daran_sim_model_t *m);
float daran_sim_model_vel_limit_rpm(const daran_sim_model_t *m);
float daran_sim_model_inertia(const daran_sim_model_t *m);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_MODEL_H */

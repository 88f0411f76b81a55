/* The physical model of one simulated drive: a rigid shaft driven by a
 * cascaded position/velocity/torque controller, with its input modes,
 * trajectory planner, electrical and thermal behaviour, protections, error
 * registers and states, and every property of include/daran_properties.h.
 *
 * Portable C99 (it is also the plant of the Cortex-M4 example): no stdio, no
 * heap, fixed-size state, single-precision float arithmetic. Units inside
 * are the protocol's, on the output shaft (degrees, r/min, Nm, seconds), so
 * that what a host writes reads back bit-identical; the rotor-side views
 * (controller.*, encoder.*, motor.*, trap_traj.*) are converted through
 * config.extra_setting.gear_ratio when read or written. */
#ifndef DARAN_SIM_MODEL_H
#define DARAN_SIM_MODEL_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* can.error bit 0: another node sends status frames with this drive's id,
 * set by the CAN front end through the HAL (the project's can.md C22); the
 * only non-zero value an error register takes. */
#define DARAN_SIM_CAN_ERROR_DUPLICATE_ID 0x1u

/* Plant constants that are not protocol properties. A test may change them
 * after daran_sim_model_init(). (Phase resistance and the under-voltage trip
 * level are properties: motor.config.phase_resistance and
 * config.dc_bus_undervoltage_trip_level.) */
typedef struct daran_sim_params {
    float rotor_inertia;      /* Nm/(turn/s^2) at the rotor; g^2 of it at the shaft */
    float viscous_friction;   /* Nm/(turn/s), at the shaft */
    float coulomb_friction;   /* Nm, at the shaft */
    float vbus_nominal;       /* V */
    float source_resistance;  /* ohm, bus sag under load */
    float sag_below_trip;     /* V below the trip level the undervoltage fault sags to */
    float sag_duration;       /* s the sag lasts */
    float ambient_temp;       /* degC */
    float motor_heat;         /* degC per A^2 at steady state */
    float motor_time_const;   /* s */
    float fet_heat;           /* degC per A^2 at steady state */
    float fet_time_const;     /* s */
    float overtemp_jump;      /* degC above temp_limit_upper the overtemp fault puts */
    float stall_speed;        /* r/min: below this the shaft counts as stalled */
    float overspeed_kick;     /* the overspeed fault throws the shaft to this many times
                                 vel_limit x vel_limit_tolerance */
    float encoder_battery_v;  /* V, encoder.battery_voltage */
    float encoder_supply_v;   /* V, encoder.encoder_voltage */
} daran_sim_params_t;

/* What the controller is doing in closed loop. Each is one pair of ODrive
 * numbers (controller.config.control_mode, input_mode), see
 * daran_sim_model_get(). */
typedef enum daran_sim_mode {
    DARAN_SIM_MODE_PASSTHROUGH,   /* p, hold after entering closed loop: 3, 1 */
    DARAN_SIM_MODE_FILTER,        /* t: 3, 3 */
    DARAN_SIM_MODE_TRAPEZOID,     /* q, mq: 3, 5 */
    DARAN_SIM_MODE_VELOCITY,      /* v mode 1: 2, 1 */
    DARAN_SIM_MODE_VELOCITY_RAMP, /* v mode 2: 2, 2 */
    DARAN_SIM_MODE_TORQUE,        /* c mode 1: 1, 1 */
    DARAN_SIM_MODE_TORQUE_RAMP,   /* c mode 6: 1, 6 */
    DARAN_SIM_MODE_IMPEDANCE      /* d: 3, 9 */
} daran_sim_mode_t;

/* Fault injections (the `!fault` directive of daran-sim,
 * daran_sim_drive_inject_fault() of sim_faults.h). */
typedef enum daran_sim_fault {
    DARAN_SIM_FAULT_OVERTEMP,     /* temperatures jump above their upper limits */
    DARAN_SIM_FAULT_UNDERVOLTAGE, /* the bus sags below the trip level for a while */
    DARAN_SIM_FAULT_STALL,        /* the stall limiter trips at the next tick */
    DARAN_SIM_FAULT_OVERSPEED,    /* the shaft is thrown beyond the over-speed limit */
    DARAN_SIM_FAULT_NVM_CORRUPT   /* the stored config is damaged (the drive's NVM:
                                     daran_sim_model_fault() ignores it) */
} daran_sim_fault_t;

typedef struct daran_sim_model {
    daran_sim_params_t par;
    /* Configuration, by property id: the rows daran_sim_is_config_prop()
     * names. A port's own rows (daran_sim_is_port_prop()) are a plain
     * store here: its settings (read-write rows) are configuration, its
     * readings (read-only rows) hold what a test put there (0 at first).
     * Other rows are unused (runtime state lives below). */
    daran_value_t cfg[DARAN_PROP_COUNT];
    float zero_offset_deg;    /* shaft angle that is position 0 (persisted) */

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

    /* states and error registers (protocol.md 10.4) */
    uint32_t state;
    uint32_t requested_state;
    uint32_t error;                  /* axis0.error: DARAN_FLAG_* */
    uint32_t motor_error;            /* axis0.motor.error */
    uint32_t controller_error;       /* axis0.controller.error */
    uint32_t encoder_error;          /* axis0.encoder.error (nothing in the model sets it) */
    uint32_t fet_thermistor_error;   /* axis0.fet_thermistor.error */
    uint32_t motor_thermistor_error; /* axis0.motor_thermistor.error */
    uint32_t can_error;              /* can.error: bit 0 set by the CAN front end (C22) */
    uint32_t config_warnings;        /* axis0.config_warnings: DARAN_WARNING_* */
    float stall_s;                   /* how long the stall condition has held */
    bool stall_injected;             /* the stall fault: trip at the next tick */

    /* controller */
    daran_sim_mode_t mode;
    float input_pos;          /* deg */
    float input_vel;          /* r/min */
    float input_torque;       /* Nm */
    float pos_sp;             /* deg */
    float vel_sp;             /* r/min */
    float acc_sp;             /* deg/s^2, the planner's or filter's acceleration */
    float torque_ff;          /* Nm, feed-forward into the velocity loop */
    float torque_cmd;         /* Nm, what the controller commands this tick */
    float integrator;         /* Nm */
    float kp;                 /* d: Nm/deg */
    float kd;                 /* d: Nm/(r/min) */

    /* input filter (t): setpoint = filt_ref + filt_err (deg), velocity deg/s */
    float filt_ref;
    float filt_err;
    float filt_vel;

    /* trajectory (q, mq): deg, deg/s, deg/s^2, s */
    float trap_start;
    float trap_target;
    float trap_vmax;          /* cruise (or peak) velocity */
    float trap_acc;           /* acceleration limit of the rising phase */
    float trap_dec;           /* of the falling phase */
    float trap_ta;            /* duration of the rising phase */
    float trap_tc;            /* of the cruise */
    float trap_td;            /* of the falling phase */
    float trap_pa;            /* distance covered by the rising phase */
    float trap_total;
    uint32_t trap_ticks;
    uint32_t trap_end_tick;   /* the tick the plan ends on */
    bool trap_scurve;         /* planned with traj_mode 2 */
    bool trajectory_done;

    float watchdog_s;         /* time since the last feed */

    uint32_t tick_hz;
    float dt;
    uint64_t ticks;
} daran_sim_model_t;

/* Reset everything to power-on defaults at @p tick_hz (>= 1): default
 * configuration, shaft at rest at angle 0, closed loop. */
void daran_sim_model_init(daran_sim_model_t *m, uint32_t tick_hz);

/* The default value of every configuration property (docs/simulator.md
 * lists them), and zero offset 0. */
void daran_sim_model_default_config(daran_sim_model_t *m);

/* False when a configuration the model divides by is not positive (gear
 * ratio, cpr, steps per turn, torque constant) or a float is not finite:
 * a stored image that says so is not loaded. */
bool daran_sim_model_config_ok(const daran_value_t cfg[DARAN_PROP_COUNT]);

/* Power-on after the configuration (cfg, zero_offset_deg) has been loaded:
 * every error register and warning cleared, closed loop holding the current
 * position (idle when config.startup_closed_loop_control is 0). The physical
 * state (angle, temperatures) is kept. */
void daran_sim_model_boot(daran_sim_model_t *m);

/* Advance one control tick. */
void daran_sim_model_tick(daran_sim_model_t *m);

/* True for properties that are configuration (persisted by `ss`): stored
 * read-write values, not the rotor-side views of them, setpoints, modes,
 * states or error registers. A port's read-write rows are configuration. */
bool daran_sim_is_config_prop(daran_prop_t prop);

/* True for a port's own rows: ids from the end of the vendor's list
 * (DARAN_PROPERTY_LIST) to DARAN_PROP_COUNT, i.e. the rows of
 * DARAN_PORT_PROPERTY_LIST in the build's options header. The model keeps
 * them in cfg[]: a read-write row is stored by a write, read back, saved
 * by `ss` and 0 after `se` and a reboot; a read-only row reads what
 * daran_sim_drive_set_port_value() put there (0 at first). */
bool daran_sim_is_port_prop(daran_prop_t prop);

/* The type of property @p prop, as its row says (a port's rows too);
 * DARAN_TYPE_U32 for an id outside the table. */
daran_prop_type_t daran_sim_prop_type(daran_prop_t prop);

/* Read any property (a port's own rows from the plain store) except
 * fw_version, hw_version and the serial numbers (the drive, sim_drive.c,
 * knows those): DARAN_ERR_INVALID_PROPERTY. */
daran_result_t daran_sim_model_get(const daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t *out);
/* Write a read-write property. A value that is not finite, or one whose
 * conversion to the stored view is not (or turns a non-zero value into 0):
 * DARAN_ERR_OUT_OF_RANGE / DARAN_ERR_INVALID_VALUE, nothing changed. */
daran_result_t daran_sim_model_set(daran_sim_model_t *m, daran_prop_t prop,
                                   daran_value_t value);
/* Start a validated motion command (daran_hal_t.move): the mode, targets
 * and the settings the move carries (daran_move_t). DARAN_OK; when the
 * drive is not in closed loop DARAN_ERR_ESTOP_ACTIVE (after `st`),
 * DARAN_ERR_MOTOR_FAULT (an error register is set) or DARAN_ERR_MOTOR_IDLE;
 * DARAN_ERR_INVALID_MODE for a kind outside the enum. Nothing changed on
 * an error. */
daran_result_t daran_sim_model_move(daran_sim_model_t *m, const daran_move_t *move);

/* Go idle and raise @p flags in axis0.error (0: plain idle). */
void daran_sim_model_trip(daran_sim_model_t *m, uint32_t flags);
/* `sc`: clear every error register and config_warnings; the state stays. */
void daran_sim_model_clear_errors(daran_sim_model_t *m);
/* `sz`: the current position becomes 0, setpoints shift with it. */
void daran_sim_model_set_zero(daran_sim_model_t *m);
/* Enter closed loop holding the current position; refuses while an error
 * register (other than can.error) is not 0. */
daran_result_t daran_sim_model_closed_loop(daran_sim_model_t *m);
/* `u` and every accepted motion command: the watchdog's time starts over. */
void daran_sim_model_feed_watchdog(daran_sim_model_t *m);
/* Inject one of the model's faults (see daran_sim_fault_t); the effect
 * shows at the next tick. DARAN_SIM_FAULT_NVM_CORRUPT is the drive's
 * (daran_sim_drive_inject_fault()): nothing happens here. */
void daran_sim_model_fault(daran_sim_model_t *m, daran_sim_fault_t fault);

/* Derived values, in protocol units (output shaft): the position
 * (output_shaft.pos_estimate), the torque and velocity limits in force,
 * and the inertia the shaft presents (rotor and load). */
float daran_sim_model_pos_deg(const daran_sim_model_t *m);
float daran_sim_model_torque_limit(const daran_sim_model_t *m);
float daran_sim_model_vel_limit_rpm(const daran_sim_model_t *m);
float daran_sim_model_inertia(const daran_sim_model_t *m);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_MODEL_H */

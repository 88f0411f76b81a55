/** @file daran_properties.h
 * The properties a drive exposes to `r` and `w`: the single list from which
 * the core's ids, lookup, range checks and discovery are all made.
 *
 * X(ID, path, scope, type, access, range, unit, can)
 *   ID     suffix of the enum constant DARAN_PROP_<ID>
 *   path   the name on the wire; for AXIS scope the part after "axisN."
 *   scope  SYSTEM: the motor id is the line's last field; AXIS: it is the N
 *          of "axisN." at the front of the path
 *   type   F32, U32, S32, U64 or BOOL (a BOOL travels as U32 0/1)
 *   access RO or RW
 *   range  what a write must satisfy, checked by the core before the HAL
 *          sees it (see daran_range_t)
 *   unit   shown by discovery and in docs; "" when the value has none
 *   can    the property's address in the vendor's CAN protocol (docs/can.md:
 *          read 0x01E / write 0x01F), 0 when it has none; the vendor's rows
 *          carry the vendor's addresses (its interface_enums.py), the
 *          library's extensions 50001..50005, a port's own rows 0 or an
 *          address in 60000..65535 (tools/gen_property_index.py refuses a
 *          duplicate or an address outside those blocks)
 *
 * The vendor's whole table (shared/vendor/properties.csv) plus the
 * extensions serial_number, config.enable_watchdog, config.watchdog_timeout,
 * config_warnings and the telemetry settings (protocol.md section 11). Rows
 * are sorted by the path as a host writes it (`axis0.` in front of AXIS
 * paths), the order discovery lists them in. Lookup does not depend on the
 * order: tools/gen_property_index.py makes a perfect hash of the paths at
 * build time.
 *
 * A port changes the table without editing this file, in its options header
 * (DARAN_CONFIG_HEADER, see daran_config.h and docs/porting.md):
 *   DARAN_PORT_PROPERTY_LIST(X)  its own rows, in the same X form; their ids
 *                                follow the vendor's (DARAN_PROP_<ID>)
 *   DARAN_OMIT_PROPERTIES(X)     X(ID) for each vendor row it leaves out: the
 *                                id stays, the path answers `invalid property`
 * (the CMake list DARAN_PROPERTY_OMIT leaves rows out too). A port path that
 * collides with another stops the build.
 *
 * Rotor-side families (controller.*, encoder.*, motor.*, trap_traj.*) are in
 * ODrive units (turns, turn/s, A, counts); output_shaft.* in protocol units
 * (degrees, r/min, Nm); config.extra_setting.gear_ratio links the two. The
 * ranges and units are in docs/properties.md. */
#ifndef DARAN_PROPERTIES_H
#define DARAN_PROPERTIES_H

#include "daran_config.h"

/** The property list: one X(ID, path, scope, type, access, range, unit, can) per
 * property, in the order described at the top of this file. */
#define DARAN_PROPERTY_LIST(X) \
    X(CALIBRATION_LOCKIN_ACCEL,           "config.calibration_lockin.accel",                     AXIS,   F32,  RW, NON_NEGATIVE, "rad/s^2",       31104) \
    X(CALIBRATION_LOCKIN_CURRENT,         "config.calibration_lockin.current",                   AXIS,   F32,  RW, NON_NEGATIVE, "A",             31101) \
    X(CALIBRATION_LOCKIN_RAMP_DISTANCE,   "config.calibration_lockin.ramp_distance",             AXIS,   F32,  RW, NON_NEGATIVE, "rad",           31103) \
    X(CALIBRATION_LOCKIN_RAMP_TIME,       "config.calibration_lockin.ramp_time",                 AXIS,   F32,  RW, NON_NEGATIVE, "s",             31102) \
    X(CALIBRATION_LOCKIN_VEL,             "config.calibration_lockin.vel",                       AXIS,   F32,  RW, NONE,         "rad/s",         31105) \
    X(CAN_NODE_ID,                        "config.can_node_id",                                  AXIS,   U32,  RW, NODE_ID,      "",              31001) \
    X(ENABLE_STEP_DIR,                    "config.enable_step_dir",                              AXIS,   BOOL, RW, BOOL,         "",              31006) \
    X(ENABLE_WATCHDOG,                    "config.enable_watchdog",                              AXIS,   BOOL, RW, BOOL,         "",              50001) \
    X(EXTRA_CIRCULAR_SETPOINT_MAX,        "config.extra_setting.circular_setpoint_max",          AXIS,   F32,  RW, NONE,         "turn",          31204) \
    X(EXTRA_CIRCULAR_SETPOINT_MIN,        "config.extra_setting.circular_setpoint_min",          AXIS,   F32,  RW, NONE,         "turn",          31203) \
    X(ENABLE_120R,                        "config.extra_setting.enable_120r",                    AXIS,   BOOL, RW, BOOL,         "",              31201) \
    X(ENABLE_ADAPTIVE_GAIN,               "config.extra_setting.enable_adaptive_gain",           AXIS,   BOOL, RW, BOOL,         "",              31212) \
    X(ENABLE_CIRCULAR_SETPOINT_LIMIT,     "config.extra_setting.enable_circular_setpoint_limit", AXIS,   BOOL, RW, BOOL,         "",              31202) \
    X(ENABLE_DAMP_IDLE,                   "config.extra_setting.enable_damp_idle",               AXIS,   BOOL, RW, BOOL,         "",              31215) \
    X(ENABLE_MULTI_CIRCLE,                "config.extra_setting.enable_multi_circle",            AXIS,   BOOL, RW, BOOL,         "",              31207) \
    X(ENABLE_REPLY_STATE,                 "config.extra_setting.enable_reply_state",             AXIS,   BOOL, RW, BOOL,         "",              31214) \
    X(ENABLE_STALL_LIMIT,                 "config.extra_setting.enable_stall_limit",             AXIS,   BOOL, RW, BOOL,         "",              31211) \
    X(ENCODER_OFFSET_CALIBRATED,          "config.extra_setting.encoder_offset_calibrated",      AXIS,   BOOL, RW, BOOL,         "",              31213) \
    X(GEAR_RATIO,                         "config.extra_setting.gear_ratio",                     AXIS,   F32,  RW, POSITIVE,     "",              31208) \
    X(STALL_CURRENT_LIMIT,                "config.extra_setting.stall_current_limit",            AXIS,   F32,  RW, NON_NEGATIVE, "A",             31209) \
    X(STALL_TIME_LIMIT,                   "config.extra_setting.stall_time_limit",               AXIS,   F32,  RW, NON_NEGATIVE, "s",             31210) \
    X(STORED_TURNS_COUNTS,                "config.extra_setting.stored_turns_counts",            AXIS,   S32,  RW, NONE,         "count",         31206) \
    X(ZERO_OFFSET_COUNTS,                 "config.extra_setting.zero_offset_counts",             AXIS,   F32,  RW, NONE,         "count",         31205) \
    X(STARTUP_CLOSED_LOOP_CONTROL,        "config.startup_closed_loop_control",                  AXIS,   BOOL, RW, BOOL,         "",              31005) \
    X(STARTUP_ENCODER_INDEX_SEARCH,       "config.startup_encoder_index_search",                 AXIS,   BOOL, RW, BOOL,         "",              31003) \
    X(STARTUP_ENCODER_OFFSET_CALIBRATION, "config.startup_encoder_offset_calibration",           AXIS,   BOOL, RW, BOOL,         "",              31004) \
    X(STARTUP_MOTOR_CALIBRATION,          "config.startup_motor_calibration",                    AXIS,   BOOL, RW, BOOL,         "",              31002) \
    X(TURNS_PER_STEP,                     "config.turns_per_step",                               AXIS,   F32,  RW, POSITIVE,     "turn",          31007) \
    X(WATCHDOG_TIMEOUT,                   "config.watchdog_timeout",                             AXIS,   F32,  RW, POSITIVE,     "s",             50002) \
    X(CONFIG_WARNINGS,                    "config_warnings",                                     AXIS,   U32,  RW, ZERO,         "flags",         50003) \
    X(CIRCULAR_SETPOINT_RANGE,            "controller.config.circular_setpoint_range",           AXIS,   F32,  RW, POSITIVE,     "turn",          32116) \
    X(CIRCULAR_SETPOINTS,                 "controller.config.circular_setpoints",                AXIS,   BOOL, RW, BOOL,         "",              32115) \
    X(CONTROL_MODE,                       "controller.config.control_mode",                      AXIS,   U32,  RW, CONTROL_MODE, "",              32105) \
    X(ENABLE_CURRENT_MODE_VEL_LIMIT,      "controller.config.enable_current_mode_vel_limit",     AXIS,   BOOL, RW, BOOL,         "",              32103) \
    X(ENABLE_GAIN_SCHEDULING,             "controller.config.enable_gain_scheduling",            AXIS,   BOOL, RW, BOOL,         "",              32101) \
    X(ENABLE_OVERSPEED_ERROR,             "controller.config.enable_overspeed_error",            AXIS,   BOOL, RW, BOOL,         "",              32104) \
    X(ENABLE_VEL_LIMIT,                   "controller.config.enable_vel_limit",                  AXIS,   BOOL, RW, BOOL,         "",              32102) \
    X(GAIN_SCHEDULING_WIDTH,              "controller.config.gain_scheduling_width",             AXIS,   F32,  RW, POSITIVE,     "turn",          32107) \
    X(CONTROLLER_INERTIA,                 "controller.config.inertia",                           AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(turn/s^2)", 32117) \
    X(INPUT_FILTER_BANDWIDTH,             "controller.config.input_filter_bandwidth",            AXIS,   F32,  RW, NON_NEGATIVE, "1/s",           32118) \
    X(INPUT_MODE,                         "controller.config.input_mode",                        AXIS,   U32,  RW, INPUT_MODE,   "",              32106) \
    X(POS_GAIN,                           "controller.config.pos_gain",                          AXIS,   F32,  RW, NON_NEGATIVE, "(turn/s)/turn", 32108) \
    X(CONTROLLER_TORQUE_RAMP_RATE,        "controller.config.torque_ramp_rate",                  AXIS,   F32,  RW, NON_NEGATIVE, "Nm/s",          32114) \
    X(VEL_GAIN,                           "controller.config.vel_gain",                          AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(turn/s)",   32109) \
    X(VEL_INTEGRATOR_GAIN,                "controller.config.vel_integrator_gain",               AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(turn/s^2)", 32110) \
    X(CONTROLLER_VEL_LIMIT,               "controller.config.vel_limit",                         AXIS,   F32,  RW, POSITIVE,     "turn/s",        32111) \
    X(VEL_LIMIT_TOLERANCE,                "controller.config.vel_limit_tolerance",               AXIS,   F32,  RW, POSITIVE,     "",              32112) \
    X(CONTROLLER_VEL_RAMP_RATE,           "controller.config.vel_ramp_rate",                     AXIS,   F32,  RW, NON_NEGATIVE, "(turn/s)/s",    32113) \
    X(CONTROLLER_ERROR,                   "controller.error",                                    AXIS,   U32,  RW, ZERO,         "flags",         32001) \
    X(CONTROLLER_INPUT_POS,               "controller.input_pos",                                AXIS,   F32,  RW, NONE,         "turn",          32002) \
    X(CONTROLLER_INPUT_TORQUE,            "controller.input_torque",                             AXIS,   F32,  RW, NONE,         "Nm",            32004) \
    X(CONTROLLER_INPUT_VEL,               "controller.input_vel",                                AXIS,   F32,  RW, NONE,         "turn/s",        32003) \
    X(CONTROLLER_POS_SETPOINT,            "controller.pos_setpoint",                             AXIS,   F32,  RW, NONE,         "turn",          32005) \
    X(CONTROLLER_TORQUE_SETPOINT,         "controller.torque_setpoint",                          AXIS,   F32,  RW, NONE,         "Nm",            32007) \
    X(TRAJECTORY_DONE,                    "controller.trajectory_done",                          AXIS,   BOOL, RO, BOOL,         "",              32008) \
    X(CONTROLLER_VEL_SETPOINT,            "controller.vel_setpoint",                             AXIS,   F32,  RW, NONE,         "turn/s",        32006) \
    X(CURRENT_STATE,                      "current_state",                                       AXIS,   U32,  RO, NONE,         "",              30002) \
    X(ENCODER_BATTERY_VOLTAGE,            "encoder.battery_voltage",                             AXIS,   F32,  RO, NONE,         "V",             34008) \
    X(ENCODER_CHARGE_STATE,               "encoder.charge_state",                                AXIS,   U32,  RO, NONE,         "",              34015) \
    X(ENCODER_ABS_SPI_CS_GPIO_PIN,        "encoder.config.abs_spi_cs_gpio_pin",                  AXIS,   U32,  RW, NONE,         "",              34106) \
    X(ENCODER_BANDWIDTH,                  "encoder.config.bandwidth",                            AXIS,   F32,  RW, POSITIVE,     "rad/s",         34105) \
    X(ENCODER_CPR,                        "encoder.config.cpr",                                  AXIS,   S32,  RW, POSITIVE,     "count/turn",    34103) \
    X(ENCODER_MODE,                       "encoder.config.mode",                                 AXIS,   U32,  RW, NONE,         "",              34101) \
    X(ENCODER_PRE_CALIBRATED,             "encoder.config.pre_calibrated",                       AXIS,   BOOL, RW, BOOL,         "",              34104) \
    X(ENCODER_USE_INDEX,                  "encoder.config.use_index",                            AXIS,   BOOL, RW, BOOL,         "",              34102) \
    X(ENCODER_VOLTAGE,                    "encoder.encoder_voltage",                             AXIS,   F32,  RO, NONE,         "V",             34014) \
    X(ENCODER_ERROR,                      "encoder.error",                                       AXIS,   U32,  RW, ZERO,         "flags",         34001) \
    X(ENCODER_INDEX_FOUND,                "encoder.index_found",                                 AXIS,   BOOL, RO, BOOL,         "",              34003) \
    X(ENCODER_IS_READY,                   "encoder.is_ready",                                    AXIS,   BOOL, RO, BOOL,         "",              34002) \
    X(ENCODER_POS_ABS,                    "encoder.pos_abs",                                     AXIS,   S32,  RO, NONE,         "count",         34009) \
    X(ENCODER_POS_CIRCULAR,               "encoder.pos_circular",                                AXIS,   F32,  RO, NONE,         "turn",          34005) \
    X(ENCODER_POS_ESTIMATE,               "encoder.pos_estimate",                                AXIS,   F32,  RO, NONE,         "turn",          34004) \
    X(ENCODER_SPI_BUFF_0,                 "encoder.spi_buff_0",                                  AXIS,   U32,  RO, NONE,         "",              34011) \
    X(ENCODER_SPI_BUFF_1,                 "encoder.spi_buff_1",                                  AXIS,   U32,  RO, NONE,         "",              34012) \
    X(ENCODER_SPI_BUFF_2,                 "encoder.spi_buff_2",                                  AXIS,   U32,  RO, NONE,         "",              34013) \
    X(ENCODER_SPI_ERROR_RATE,             "encoder.spi_error_rate",                              AXIS,   F32,  RO, NONE,         "",              34007) \
    X(ENCODER_TURN_ABS,                   "encoder.turn_abs",                                    AXIS,   S32,  RO, NONE,         "turn",          34010) \
    X(ENCODER_VEL_ESTIMATE,               "encoder.vel_estimate",                                AXIS,   F32,  RO, NONE,         "turn/s",        34006) \
    X(AXIS_ERROR,                         "error",                                               AXIS,   U32,  RW, ZERO,         "flags",         30001) \
    X(FET_THERMISTOR_ENABLED,             "fet_thermistor.config.enabled",                       AXIS,   BOOL, RW, BOOL,         "",              36101) \
    X(FET_TEMP_LIMIT_LOWER,               "fet_thermistor.config.temp_limit_lower",              AXIS,   F32,  RW, NONE,         "degC",          36102) \
    X(FET_TEMP_LIMIT_UPPER,               "fet_thermistor.config.temp_limit_upper",              AXIS,   F32,  RW, NONE,         "degC",          36103) \
    X(FET_THERMISTOR_ERROR,               "fet_thermistor.error",                                AXIS,   U32,  RW, ZERO,         "flags",         36001) \
    X(FET_TEMPERATURE,                    "fet_thermistor.temperature",                          AXIS,   F32,  RO, NONE,         "degC",          36002) \
    X(CALIBRATION_CURRENT,                "motor.config.calibration_current",                    AXIS,   F32,  RW, NON_NEGATIVE, "A",             33103) \
    X(CURRENT_CONTROL_BANDWIDTH,          "motor.config.current_control_bandwidth",              AXIS,   F32,  RW, POSITIVE,     "rad/s",         33114) \
    X(CURRENT_LIM,                        "motor.config.current_lim",                            AXIS,   F32,  RW, POSITIVE,     "A",             33110) \
    X(CURRENT_LIM_MARGIN,                 "motor.config.current_lim_margin",                     AXIS,   F32,  RW, NON_NEGATIVE, "A",             33111) \
    X(MOTOR_DIRECTION,                    "motor.config.direction",                              AXIS,   S32,  RW, DIRECTION,    "",              33108) \
    X(MOTOR_TYPE,                         "motor.config.motor_type",                             AXIS,   U32,  RW, MOTOR_TYPE,   "",              33109) \
    X(PHASE_INDUCTANCE,                   "motor.config.phase_inductance",                       AXIS,   F32,  RW, NON_NEGATIVE, "H",             33105) \
    X(PHASE_RESISTANCE,                   "motor.config.phase_resistance",                       AXIS,   F32,  RW, NON_NEGATIVE, "ohm",           33106) \
    X(POLE_PAIRS,                         "motor.config.pole_pairs",                             AXIS,   S32,  RW, POLE_PAIRS,   "",              33102) \
    X(MOTOR_PRE_CALIBRATED,               "motor.config.pre_calibrated",                         AXIS,   BOOL, RW, BOOL,         "",              33101) \
    X(REQUESTED_CURRENT_RANGE,            "motor.config.requested_current_range",                AXIS,   F32,  RW, POSITIVE,     "A",             33113) \
    X(RESISTANCE_CALIB_MAX_VOLTAGE,       "motor.config.resistance_calib_max_voltage",           AXIS,   F32,  RW, NON_NEGATIVE, "V",             33104) \
    X(MOTOR_TORQUE_CONSTANT,              "motor.config.torque_constant",                        AXIS,   F32,  RW, POSITIVE,     "Nm/A",          33107) \
    X(MOTOR_TORQUE_LIM,                   "motor.config.torque_lim",                             AXIS,   F32,  RW, POSITIVE,     "Nm",            33112) \
    X(IBUS_MEASURED,                      "motor.current_control.Ibus",                          AXIS,   F32,  RO, NONE,         "A",             33201) \
    X(ID_MEASURED,                        "motor.current_control.Id_measured",                   AXIS,   F32,  RO, NONE,         "A",             33207) \
    X(ID_SETPOINT,                        "motor.current_control.Id_setpoint",                   AXIS,   F32,  RO, NONE,         "A",             33204) \
    X(IQ_MEASURED,                        "motor.current_control.Iq_measured",                   AXIS,   F32,  RO, NONE,         "A",             33206) \
    X(IQ_SETPOINT,                        "motor.current_control.Iq_setpoint",                   AXIS,   F32,  RO, NONE,         "A",             33205) \
    X(FINAL_V_ALPHA,                      "motor.current_control.final_v_alpha",                 AXIS,   F32,  RO, NONE,         "V",             33202) \
    X(FINAL_V_BETA,                       "motor.current_control.final_v_beta",                  AXIS,   F32,  RO, NONE,         "V",             33203) \
    X(EFFECTIVE_CURRENT_LIM,              "motor.effective_current_lim",                         AXIS,   F32,  RO, NONE,         "A",             33003) \
    X(MOTOR_ERROR,                        "motor.error",                                         AXIS,   U32,  RW, ZERO,         "flags",         33001) \
    X(MOTOR_IS_CALIBRATED,                "motor.is_calibrated",                                 AXIS,   BOOL, RO, BOOL,         "",              33002) \
    X(MOTOR_THERMISTOR_ENABLED,           "motor_thermistor.config.enabled",                     AXIS,   BOOL, RW, BOOL,         "",              37101) \
    X(MOTOR_TEMP_LIMIT_LOWER,             "motor_thermistor.config.temp_limit_lower",            AXIS,   F32,  RW, NONE,         "degC",          37102) \
    X(MOTOR_TEMP_LIMIT_UPPER,             "motor_thermistor.config.temp_limit_upper",            AXIS,   F32,  RW, NONE,         "degC",          37103) \
    X(MOTOR_THERMISTOR_ERROR,             "motor_thermistor.error",                              AXIS,   U32,  RW, ZERO,         "flags",         37001) \
    X(MOTOR_TEMPERATURE,                  "motor_thermistor.temperature",                        AXIS,   F32,  RO, NONE,         "degC",          37002) \
    X(CIRCULAR_SETPOINT_MAX,              "output_shaft.circular_setpoint_max",                  AXIS,   F32,  RW, NONE,         "deg",           38011) \
    X(CIRCULAR_SETPOINT_MIN,              "output_shaft.circular_setpoint_min",                  AXIS,   F32,  RW, NONE,         "deg",           38010) \
    X(HOMING_MOVE_RANGE,                  "output_shaft.homing_move_range",                      AXIS,   F32,  RW, POSITIVE,     "deg",           38025) \
    X(HOMING_POS_SETPOINT,                "output_shaft.homing_pos_setpoint",                    AXIS,   F32,  RW, NONE,         "deg",           38024) \
    X(HOMING_TORQUE_LIM,                  "output_shaft.homing_torque_lim",                      AXIS,   F32,  RW, POSITIVE,     "Nm",            38022) \
    X(HOMING_VEL_LIMIT,                   "output_shaft.homing_vel_limit",                       AXIS,   F32,  RW, POSITIVE,     "r/min",         38023) \
    X(INPUT_POS,                          "output_shaft.input_pos",                              AXIS,   F32,  RW, NONE,         "deg",           38001) \
    X(INPUT_TORQUE,                       "output_shaft.input_torque",                           AXIS,   F32,  RW, NONE,         "Nm",            38003) \
    X(INPUT_VEL,                          "output_shaft.input_vel",                              AXIS,   F32,  RW, NONE,         "r/min",         38002) \
    X(LOAD_INERTIA,                       "output_shaft.load_inertia",                           AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(r/s^2)",    38021) \
    X(POS_ESTIMATE,                       "output_shaft.pos_estimate",                           AXIS,   F32,  RO, NONE,         "deg",           38007) \
    X(POS_SETPOINT,                       "output_shaft.pos_setpoint",                           AXIS,   F32,  RW, NONE,         "deg",           38004) \
    X(STEPS_PER_TURN,                     "output_shaft.steps_per_turn",                         AXIS,   F32,  RW, POSITIVE,     "count/r",       38019) \
    X(TORQUE_CONSTANT,                    "output_shaft.torque_constant",                        AXIS,   F32,  RW, POSITIVE,     "Nm/A",          38020) \
    X(TORQUE_ESTIMATE,                    "output_shaft.torque_estimate",                        AXIS,   F32,  RO, NONE,         "Nm",            38009) \
    X(SHAFT_TORQUE_LIM,                   "output_shaft.torque_lim",                             AXIS,   F32,  RW, POSITIVE,     "Nm",            38013) \
    X(TORQUE_RAMP_RATE,                   "output_shaft.torque_ramp_rate",                       AXIS,   F32,  RW, NON_NEGATIVE, "Nm/s",          38018) \
    X(TORQUE_SETPOINT,                    "output_shaft.torque_setpoint",                        AXIS,   F32,  RW, NONE,         "Nm",            38006) \
    X(TRAP_TRAJ_ACCEL_LIMIT,              "output_shaft.trap_traj_accel_limit",                  AXIS,   F32,  RW, NON_NEGATIVE, "(r/min)/s",     38015) \
    X(TRAP_TRAJ_DECEL_LIMIT,              "output_shaft.trap_traj_decel_limit",                  AXIS,   F32,  RW, NON_NEGATIVE, "(r/min)/s",     38016) \
    X(TRAP_TRAJ_VEL_LIMIT,                "output_shaft.trap_traj_vel_limit",                    AXIS,   F32,  RW, POSITIVE,     "r/min",         38014) \
    X(VEL_ESTIMATE,                       "output_shaft.vel_estimate",                           AXIS,   F32,  RO, NONE,         "r/min",         38008) \
    X(SHAFT_VEL_LIMIT,                    "output_shaft.vel_limit",                              AXIS,   F32,  RW, POSITIVE,     "r/min",         38012) \
    X(VEL_RAMP_RATE,                      "output_shaft.vel_ramp_rate",                          AXIS,   F32,  RW, NON_NEGATIVE, "(r/min)/s",     38017) \
    X(VEL_SETPOINT,                       "output_shaft.vel_setpoint",                           AXIS,   F32,  RW, NONE,         "r/min",         38005) \
    X(REQUESTED_STATE,                    "requested_state",                                     AXIS,   U32,  RW, AXIS_STATE,   "",              30003) \
    X(TELEMETRY_FIELDS,                   "telemetry.fields",                                    AXIS,   U32,  RW, TELEMETRY,    "flags",         50005) \
    X(TELEMETRY_PERIOD,                   "telemetry.period",                                    AXIS,   F32,  RW, NON_NEGATIVE, "s",             50004) \
    X(TRAP_ACCEL_LIMIT,                   "trap_traj.config.accel_limit",                        AXIS,   F32,  RW, NON_NEGATIVE, "(turn/s)/s",    35102) \
    X(TRAP_DECEL_LIMIT,                   "trap_traj.config.decel_limit",                        AXIS,   F32,  RW, NON_NEGATIVE, "(turn/s)/s",    35103) \
    X(TRAJ_MODE,                          "trap_traj.config.traj_mode",                          AXIS,   U32,  RW, TRAJ_MODE,    "",              35104) \
    X(TRAP_VEL_LIMIT,                     "trap_traj.config.vel_limit",                          AXIS,   F32,  RW, POSITIVE,     "turn/s",        35101) \
    X(CAN_BAUD_RATE,                      "can.config.baud_rate",                                SYSTEM, U32,  RW, CAN_BAUD,     "bit/s",         21001) \
    X(CAN_HEARTBEAT_MS,                   "can.config.heartbeat_ms",                             SYSTEM, U32,  RW, NONE,         "ms",            21004) \
    X(CAN_PROTOCOL,                       "can.config.protocol",                                 SYSTEM, U32,  RW, CAN_PROTOCOL, "",              21002) \
    X(CAN_TIMEOUT_MS,                     "can.config.timeout_ms",                               SYSTEM, U32,  RW, NONE,         "ms",            21003) \
    X(CAN_ERROR,                          "can.error",                                           SYSTEM, U32,  RW, ZERO,         "flags",         20001) \
    X(BRAKE_RESISTANCE,                   "config.brake_resistance",                             SYSTEM, F32,  RW, NON_NEGATIVE, "ohm",           10007) \
    X(DC_BUS_OVERVOLTAGE_TRIP_LEVEL,      "config.dc_bus_overvoltage_trip_level",                SYSTEM, F32,  RW, POSITIVE,     "V",             10003) \
    X(DC_BUS_UNDERVOLTAGE_TRIP_LEVEL,     "config.dc_bus_undervoltage_trip_level",               SYSTEM, F32,  RW, NON_NEGATIVE, "V",             10002) \
    X(DC_MAX_NEGATIVE_CURRENT,            "config.dc_max_negative_current",                      SYSTEM, F32,  RW, NON_POSITIVE, "A",             10005) \
    X(DC_MAX_POSITIVE_CURRENT,            "config.dc_max_positive_current",                      SYSTEM, F32,  RW, NON_NEGATIVE, "A",             10004) \
    X(ENABLE_UART,                        "config.enable_uart",                                  SYSTEM, BOOL, RW, BOOL,         "",              10008) \
    X(MAX_REGEN_CURRENT,                  "config.max_regen_current",                            SYSTEM, F32,  RW, NON_NEGATIVE, "A",             10006) \
    X(UART_BAUDRATE,                      "config.uart_baudrate",                                SYSTEM, U32,  RW, UART_BAUD,    "baud",          10001) \
    X(FW_VERSION,                         "fw_version",                                          SYSTEM, U32,  RO, NONE,         "",                  6) \
    X(HW_VERSION,                         "hw_version",                                          SYSTEM, U32,  RO, NONE,         "",                  5) \
    X(IBUS,                               "ibus",                                                SYSTEM, F32,  RO, NONE,         "A",                 2) \
    X(SERIAL_NUMBER,                      "serial_number",                                       SYSTEM, U64,  RO, NONE,         "",                  0) \
    X(SERIAL_NUMBER_H,                    "serial_number_h",                                     SYSTEM, U32,  RO, NONE,         "",                  4) \
    X(SERIAL_NUMBER_L,                    "serial_number_l",                                     SYSTEM, U32,  RO, NONE,         "",                  3) \
    X(VBUS_VOLTAGE,                       "vbus_voltage",                                        SYSTEM, F32,  RO, NONE,         "V",                 1)

/** Property ids: DARAN_PROP_<ID> for each row of DARAN_PROPERTY_LIST, in
 * list order, then DARAN_PROP_COUNT (how many there are). */
typedef enum daran_prop {
/** @cond INTERNAL */
#define DARAN_PROP_ENUM_(id, path, scope, type, access, range, unit, can) DARAN_PROP_##id,
    DARAN_PROPERTY_LIST(DARAN_PROP_ENUM_)
#ifdef DARAN_PORT_PROPERTY_LIST
    DARAN_PORT_PROPERTY_LIST(DARAN_PROP_ENUM_)
#endif
#undef DARAN_PROP_ENUM_
/** @endcond */
    DARAN_PROP_COUNT
} daran_prop_t;

/** How a property's value travels in daran_value_t. */
typedef enum daran_prop_type {
    DARAN_TYPE_F32,  /**< float32, member f32 */
    DARAN_TYPE_U32,  /**< unsigned 32-bit, member u32 */
    DARAN_TYPE_S32,  /**< signed 32-bit, member s32 */
    DARAN_TYPE_U64,  /**< unsigned 64-bit, member u64 */
    DARAN_TYPE_BOOL  /**< 0 or 1 in member u32 */
} daran_prop_type_t;

/** @cond INTERNAL */
#define DARAN_RANGE_STR_(x) #x
#define DARAN_RANGE_STR(x) DARAN_RANGE_STR_(x)
/** @endcond */

/** The ranges: X(NAME, text). The text is what discovery prints and what
 * `w` checks (src/table/property_table.c reads it): a sign condition (">=0",
 * ">0", "<=0"), an interval ("a..b"), a set ("{a,b,...}" or "a|b", one
 * value "a"), or "" for any value of the type. Float properties take the
 * sign conditions and intervals ("0..1", "-0.5..2.5e3": decimal ends, the
 * value compared as the float it parsed to, both ends included); integer
 * ones take integer ends.
 *
 * A port adds its own in its options header, in the same form:
 *   DARAN_PORT_RANGE_LIST(X)  X(NAME, "text") for its rows' RANGE column;
 * 32 ranges in all (tools/gen_property_index.py refuses more, and a range a
 * row's type cannot take). */
#define DARAN_RANGE_LIST(X) \
    X(NONE,         "") \
    X(NON_NEGATIVE, ">=0") \
    X(POSITIVE,     ">0") \
    X(NON_POSITIVE, "<=0") \
    X(BOOL,         "0|1") \
    X(ZERO,         "0") /* an error register: writing 0 clears it */ \
    X(NODE_ID,      "1.." DARAN_RANGE_STR(DARAN_MOTOR_ID_MAX)) \
    X(UART_BAUD,    "{9600,19200,38400,57600,115200}") \
    X(CAN_BAUD,     "{125000,250000,500000,1000000}") \
    X(CAN_PROTOCOL, "0..1") /* ODrive's CAN protocols: none, simple */ \
    X(AXIS_STATE,   "{1,8}") /* DARAN_STATE_IDLE, DARAN_STATE_CLOSED_LOOP */ \
    X(CONTROL_MODE, "1..3") /* ODrive: torque, velocity, position */ \
    X(INPUT_MODE,   "{1,2,3,5,6,9}") /* ODrive's input modes the protocol uses */ \
    X(TRAJ_MODE,    "1..2") /* trapezoid, S-curve */ \
    X(DIRECTION,    "{-1,1}") \
    X(MOTOR_TYPE,   "{0,2,3}") /* ODrive: high current, gimbal, ACIM */ \
    X(POLE_PAIRS,   "1..128") \
    X(TELEMETRY,    "0..511") /* the telemetry field bits */

/** What a written value must satisfy (DARAN_RANGE_LIST); the core checks it
 * before the HAL's set(). */
typedef enum daran_range {
/** @cond INTERNAL */
#define DARAN_RANGE_ENUM_(name, text) DARAN_RANGE_##name,
    DARAN_RANGE_LIST(DARAN_RANGE_ENUM_)
#ifdef DARAN_PORT_RANGE_LIST
    DARAN_PORT_RANGE_LIST(DARAN_RANGE_ENUM_)
#endif
#undef DARAN_RANGE_ENUM_
/** @endcond */
    DARAN_RANGE_COUNT /**< how many ranges there are; not a range */
} daran_range_t;

#endif /* DARAN_PROPERTIES_H */

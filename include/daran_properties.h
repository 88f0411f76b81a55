/** @file daran_properties.h
 * The properties a drive exposes to `r` and `w`: the single list from which
 * the core builds its lookup table and the HAL gets its property ids.
 *
 * X(ID, path, scope, type, access, range, unit)
 *   ID     suffix of the enum constant DARAN_PROP_<ID>
 *   path   the name on the wire; for AXIS scope the part after "axisN."
 *   scope  SYSTEM: the motor id is the line's last field; AXIS: it is the N
 *          of "axisN." at the front of the path
 *   type   F32, U32, U64 or BOOL (a BOOL travels as U32 0/1)
 *   access RO or RW
 *   range  what a write must satisfy, checked by the core before the HAL
 *          sees it (see daran_range_t)
 *   unit   shown in docs and help; "" when the value has none
 *
 * Rows are sorted by (scope SYSTEM first, then path in byte order): the core
 * finds a path by binary search, and a unit test checks the order. */
#ifndef DARAN_PROPERTIES_H
#define DARAN_PROPERTIES_H

/** The property list: one X(ID, path, scope, type, access, range, unit) per
 * property, in the order described at the top of this file. */
#define DARAN_PROPERTY_LIST(X) \
    X(CAN_BAUD_RATE,                  "can.config.baud_rate",                                 SYSTEM, U32,  RW, CAN_BAUD,     "bit/s") \
    X(UART_BAUDRATE,                  "config.uart_baudrate",                                 SYSTEM, U32,  RW, UART_BAUD,    "baud") \
    X(FW_VERSION,                     "fw_version",                                           SYSTEM, U32,  RO, NONE,         "") \
    X(HW_VERSION,                     "hw_version",                                           SYSTEM, U32,  RO, NONE,         "") \
    X(IBUS,                           "ibus",                                                 SYSTEM, F32,  RO, NONE,         "A") \
    X(SERIAL_NUMBER,                  "serial_number",                                        SYSTEM, U64,  RO, NONE,         "") \
    X(VBUS_VOLTAGE,                   "vbus_voltage",                                         SYSTEM, F32,  RO, NONE,         "V") \
    X(CAN_NODE_ID,                    "config.can_node_id",                                   AXIS,   U32,  RW, NODE_ID,      "") \
    X(ENABLE_WATCHDOG,                "config.enable_watchdog",                               AXIS,   BOOL, RW, BOOL,         "") \
    X(ENABLE_CIRCULAR_SETPOINT_LIMIT, "config.extra_setting.enable_circular_setpoint_limit",  AXIS,   BOOL, RW, BOOL,         "") \
    X(WATCHDOG_TIMEOUT,               "config.watchdog_timeout",                              AXIS,   F32,  RW, POSITIVE,     "s") \
    X(ENABLE_CURRENT_MODE_VEL_LIMIT,  "controller.config.enable_current_mode_vel_limit",      AXIS,   BOOL, RW, BOOL,         "") \
    X(INPUT_FILTER_BANDWIDTH,         "controller.config.input_filter_bandwidth",             AXIS,   F32,  RW, POSITIVE,     "1/s") \
    X(POS_GAIN,                       "controller.config.pos_gain",                           AXIS,   F32,  RW, NON_NEGATIVE, "(turn/s)/turn") \
    X(VEL_GAIN,                       "controller.config.vel_gain",                           AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(turn/s)") \
    X(VEL_INTEGRATOR_GAIN,            "controller.config.vel_integrator_gain",                AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(turn/s^2)") \
    X(CONTROLLER_VEL_LIMIT,           "controller.config.vel_limit",                          AXIS,   F32,  RW, POSITIVE,     "turn/s") \
    X(TRAJECTORY_DONE,                "controller.trajectory_done",                           AXIS,   BOOL, RO, BOOL,         "") \
    X(CURRENT_STATE,                  "current_state",                                        AXIS,   U32,  RO, NONE,         "") \
    X(AXIS_ERROR,                     "error",                                                AXIS,   U32,  RO, NONE,         "flags") \
    X(FET_THERMISTOR_ENABLED,         "fet_thermistor.config.enabled",                        AXIS,   BOOL, RW, BOOL,         "") \
    X(FET_TEMP_LIMIT_LOWER,           "fet_thermistor.config.temp_limit_lower",               AXIS,   F32,  RW, NONE,         "degC") \
    X(FET_TEMP_LIMIT_UPPER,           "fet_thermistor.config.temp_limit_upper",               AXIS,   F32,  RW, NONE,         "degC") \
    X(FET_THERMISTOR_ERROR,           "fet_thermistor.error",                                 AXIS,   U32,  RO, NONE,         "flags") \
    X(FET_TEMPERATURE,                "fet_thermistor.temperature",                           AXIS,   F32,  RO, NONE,         "degC") \
    X(CURRENT_CONTROL_BANDWIDTH,      "motor.config.current_control_bandwidth",               AXIS,   F32,  RW, POSITIVE,     "rad/s") \
    X(CURRENT_LIM,                    "motor.config.current_lim",                             AXIS,   F32,  RW, POSITIVE,     "A") \
    X(MOTOR_TORQUE_LIM,               "motor.config.torque_lim",                              AXIS,   F32,  RW, POSITIVE,     "Nm") \
    X(IQ_MEASURED,                    "motor.current_control.Iq_measured",                    AXIS,   F32,  RO, NONE,         "A") \
    X(MOTOR_THERMISTOR_ENABLED,       "motor_thermistor.config.enabled",                      AXIS,   BOOL, RW, BOOL,         "") \
    X(MOTOR_TEMP_LIMIT_LOWER,         "motor_thermistor.config.temp_limit_lower",             AXIS,   F32,  RW, NONE,         "degC") \
    X(MOTOR_TEMP_LIMIT_UPPER,         "motor_thermistor.config.temp_limit_upper",             AXIS,   F32,  RW, NONE,         "degC") \
    X(MOTOR_THERMISTOR_ERROR,         "motor_thermistor.error",                               AXIS,   U32,  RO, NONE,         "flags") \
    X(MOTOR_TEMPERATURE,              "motor_thermistor.temperature",                         AXIS,   F32,  RO, NONE,         "degC") \
    X(CIRCULAR_SETPOINT_MAX,          "output_shaft.circular_setpoint_max",                   AXIS,   F32,  RW, NONE,         "deg") \
    X(CIRCULAR_SETPOINT_MIN,          "output_shaft.circular_setpoint_min",                   AXIS,   F32,  RW, NONE,         "deg") \
    X(INPUT_POS,                      "output_shaft.input_pos",                               AXIS,   F32,  RW, NONE,         "deg") \
    X(INPUT_TORQUE,                   "output_shaft.input_torque",                            AXIS,   F32,  RW, NONE,         "Nm") \
    X(INPUT_VEL,                      "output_shaft.input_vel",                               AXIS,   F32,  RW, NONE,         "r/min") \
    X(LOAD_INERTIA,                   "output_shaft.load_inertia",                            AXIS,   F32,  RW, NON_NEGATIVE, "Nm/(r/s^2)") \
    X(POS_ESTIMATE,                   "output_shaft.pos_estimate",                            AXIS,   F32,  RO, NONE,         "deg") \
    X(POS_SETPOINT,                   "output_shaft.pos_setpoint",                            AXIS,   F32,  RW, NONE,         "deg") \
    X(STEPS_PER_TURN,                 "output_shaft.steps_per_turn",                          AXIS,   F32,  RW, POSITIVE,     "count/r") \
    X(TORQUE_CONSTANT,                "output_shaft.torque_constant",                         AXIS,   F32,  RW, POSITIVE,     "Nm/A") \
    X(TORQUE_ESTIMATE,                "output_shaft.torque_estimate",                         AXIS,   F32,  RO, NONE,         "Nm") \
    X(SHAFT_TORQUE_LIM,               "output_shaft.torque_lim",                              AXIS,   F32,  RW, POSITIVE,     "Nm") \
    X(TORQUE_RAMP_RATE,               "output_shaft.torque_ramp_rate",                        AXIS,   F32,  RW, POSITIVE,     "Nm/s") \
    X(TORQUE_SETPOINT,                "output_shaft.torque_setpoint",                         AXIS,   F32,  RW, NONE,         "Nm") \
    X(VEL_ESTIMATE,                   "output_shaft.vel_estimate",                            AXIS,   F32,  RO, NONE,         "r/min") \
    X(SHAFT_VEL_LIMIT,                "output_shaft.vel_limit",                               AXIS,   F32,  RW, POSITIVE,     "r/min") \
    X(VEL_RAMP_RATE,                  "output_shaft.vel_ramp_rate",                           AXIS,   F32,  RW, POSITIVE,     "(r/min)/s") \
    X(VEL_SETPOINT,                   "output_shaft.vel_setpoint",                            AXIS,   F32,  RW, NONE,         "r/min") \
    X(REQUESTED_STATE,                "requested_state",                                      AXIS,   U32,  RW, AXIS_STATE,   "")

/** Property ids: DARAN_PROP_<ID> for each row of DARAN_PROPERTY_LIST, in
 * list order, then DARAN_PROP_COUNT (how many there are). */
typedef enum daran_prop {
/** @cond INTERNAL */
#define DARAN_PROP_ENUM_(id, path, scope, type, access, range, unit) DARAN_PROP_##id,
    DARAN_PROPERTY_LIST(DARAN_PROP_ENUM_)
#undef DARAN_PROP_ENUM_
/** @endcond */
    DARAN_PROP_COUNT
} daran_prop_t;

/** How a property's value travels in daran_value_t. */
typedef enum daran_prop_type {
    DARAN_TYPE_F32, /**< float32, member f32 */
    DARAN_TYPE_U32, /**< unsigned 32-bit, member u32 */
    DARAN_TYPE_U64, /**< unsigned 64-bit, member u64 */
    DARAN_TYPE_BOOL /**< 0 or 1 in member u32 */
} daran_prop_type_t;

/** What a written value must satisfy; the core checks it before the HAL's set(). */
typedef enum daran_range {
    DARAN_RANGE_NONE,         /**< any finite value */
    DARAN_RANGE_NON_NEGATIVE, /**< >= 0 */
    DARAN_RANGE_POSITIVE,     /**< > 0 */
    DARAN_RANGE_BOOL,         /**< 0 or 1 */
    DARAN_RANGE_NODE_ID,      /**< 1..DARAN_MOTOR_ID_MAX */
    DARAN_RANGE_UART_BAUD,    /**< 9600, 19200, 38400, 57600, 115200 */
    DARAN_RANGE_CAN_BAUD,     /**< 125000, 250000, 500000, 1000000 */
    DARAN_RANGE_AXIS_STATE    /**< DARAN_STATE_IDLE or DARAN_STATE_CLOSED_LOOP */
} daran_range_t;

#endif /* DARAN_PROPERTIES_H */

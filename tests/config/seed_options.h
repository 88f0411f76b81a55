/* The seed-only build: the protocol of the vendor's seed document and no
 * more, as an options header (DARAN_CONFIG_HEADER). The `cortex-m4-seed`
 * preset builds the core with it and measures its flash against 8,192
 * bytes (docs/performance.md, "Seed-only build"); tools/ci.d/50-package.sh
 * runs tests/config against it on the host. docs/porting.md section 5.1.
 *
 * It compiles out what the seed document does not have: discovery (`h id
 * properties`), telemetry, the port's own commands and S-curve planning of
 * `mq` (which then never reads traj_mode), and the CAN front end. `h`, `ms`/`m*` and every other
 * command of the seed's command table stay.
 *
 * It keeps 57 property rows and leaves the other 108 vendor rows out:
 *   - the 53 of the contract's table (docs/protocol.md section 7): the seed
 *     document's 43 (its section 1.4.2: vbus_voltage, ibus,
 *     config.uart_baudrate, can.config.baud_rate, config.can_node_id,
 *     controller.trajectory_done, controller.config.{pos_gain, vel_gain,
 *     vel_integrator_gain, vel_limit, input_filter_bandwidth},
 *     motor.config.{current_lim, torque_lim, current_control_bandwidth},
 *     motor.current_control.Iq_measured, the five rows of each thermistor,
 *     and 18 output_shaft rows) and the ten extensions the vendor's own host
 *     libraries use (controller.config.enable_current_mode_vel_limit,
 *     config.extra_setting.enable_circular_setpoint_limit, requested_state,
 *     current_state, axis0.error, config.enable_watchdog,
 *     config.watchdog_timeout, serial_number, hw_version, fw_version);
 *   - the four error registers `e` reports that the table does not list:
 *     motor.error, encoder.error, controller.error, can.error (the generator
 *     refuses to leave any of the seven out: `e` names its lines by them).
 *
 * Like every options header: only #define, no #include. */
#ifndef DARAN_SEED_OPTIONS_H
#define DARAN_SEED_OPTIONS_H

#define DARAN_ENABLE_DISCOVERY 0
#define DARAN_ENABLE_TELEMETRY 0
#define DARAN_ENABLE_PORT_COMMANDS 0
#define DARAN_ENABLE_S_CURVE 0
#define DARAN_ENABLE_CAN 0
#define DARAN_ENABLE_UPDATE 0

/* Every vendor row the seed's protocol does not name (108 of 165). */
#define DARAN_OMIT_PROPERTIES(X) \
    X(CALIBRATION_LOCKIN_ACCEL) \
    X(CALIBRATION_LOCKIN_CURRENT) \
    X(CALIBRATION_LOCKIN_RAMP_DISTANCE) \
    X(CALIBRATION_LOCKIN_RAMP_TIME) \
    X(CALIBRATION_LOCKIN_VEL) \
    X(ENABLE_STEP_DIR) \
    X(EXTRA_CIRCULAR_SETPOINT_MAX) \
    X(EXTRA_CIRCULAR_SETPOINT_MIN) \
    X(ENABLE_120R) \
    X(ENABLE_ADAPTIVE_GAIN) \
    X(ENABLE_DAMP_IDLE) \
    X(ENABLE_MULTI_CIRCLE) \
    X(ENABLE_REPLY_STATE) \
    X(ENABLE_STALL_LIMIT) \
    X(ENCODER_OFFSET_CALIBRATED) \
    X(GEAR_RATIO) \
    X(STALL_CURRENT_LIMIT) \
    X(STALL_TIME_LIMIT) \
    X(STORED_TURNS_COUNTS) \
    X(ZERO_OFFSET_COUNTS) \
    X(STARTUP_CLOSED_LOOP_CONTROL) \
    X(STARTUP_ENCODER_INDEX_SEARCH) \
    X(STARTUP_ENCODER_OFFSET_CALIBRATION) \
    X(STARTUP_MOTOR_CALIBRATION) \
    X(TURNS_PER_STEP) \
    X(CONFIG_WARNINGS) \
    X(CIRCULAR_SETPOINT_RANGE) \
    X(CIRCULAR_SETPOINTS) \
    X(CONTROL_MODE) \
    X(ENABLE_GAIN_SCHEDULING) \
    X(ENABLE_OVERSPEED_ERROR) \
    X(ENABLE_VEL_LIMIT) \
    X(GAIN_SCHEDULING_WIDTH) \
    X(CONTROLLER_INERTIA) \
    X(INPUT_MODE) \
    X(CONTROLLER_TORQUE_RAMP_RATE) \
    X(VEL_LIMIT_TOLERANCE) \
    X(CONTROLLER_VEL_RAMP_RATE) \
    X(CONTROLLER_INPUT_POS) \
    X(CONTROLLER_INPUT_TORQUE) \
    X(CONTROLLER_INPUT_VEL) \
    X(CONTROLLER_POS_SETPOINT) \
    X(CONTROLLER_TORQUE_SETPOINT) \
    X(CONTROLLER_VEL_SETPOINT) \
    X(ENCODER_BATTERY_VOLTAGE) \
    X(ENCODER_CHARGE_STATE) \
    X(ENCODER_ABS_SPI_CS_GPIO_PIN) \
    X(ENCODER_BANDWIDTH) \
    X(ENCODER_CPR) \
    X(ENCODER_MODE) \
    X(ENCODER_PRE_CALIBRATED) \
    X(ENCODER_USE_INDEX) \
    X(ENCODER_VOLTAGE) \
    X(ENCODER_INDEX_FOUND) \
    X(ENCODER_IS_READY) \
    X(ENCODER_POS_ABS) \
    X(ENCODER_POS_CIRCULAR) \
    X(ENCODER_POS_ESTIMATE) \
    X(ENCODER_SPI_BUFF_0) \
    X(ENCODER_SPI_BUFF_1) \
    X(ENCODER_SPI_BUFF_2) \
    X(ENCODER_SPI_ERROR_RATE) \
    X(ENCODER_TURN_ABS) \
    X(ENCODER_VEL_ESTIMATE) \
    X(CALIBRATION_CURRENT) \
    X(CURRENT_LIM_MARGIN) \
    X(MOTOR_DIRECTION) \
    X(MOTOR_TYPE) \
    X(PHASE_INDUCTANCE) \
    X(PHASE_RESISTANCE) \
    X(POLE_PAIRS) \
    X(MOTOR_PRE_CALIBRATED) \
    X(REQUESTED_CURRENT_RANGE) \
    X(RESISTANCE_CALIB_MAX_VOLTAGE) \
    X(MOTOR_TORQUE_CONSTANT) \
    X(IBUS_MEASURED) \
    X(ID_MEASURED) \
    X(ID_SETPOINT) \
    X(IQ_SETPOINT) \
    X(FINAL_V_ALPHA) \
    X(FINAL_V_BETA) \
    X(EFFECTIVE_CURRENT_LIM) \
    X(MOTOR_IS_CALIBRATED) \
    X(HOMING_MOVE_RANGE) \
    X(HOMING_POS_SETPOINT) \
    X(HOMING_TORQUE_LIM) \
    X(HOMING_VEL_LIMIT) \
    X(TRAP_TRAJ_ACCEL_LIMIT) \
    X(TRAP_TRAJ_DECEL_LIMIT) \
    X(TRAP_TRAJ_VEL_LIMIT) \
    X(TELEMETRY_FIELDS) \
    X(TELEMETRY_PERIOD) \
    X(TRAP_ACCEL_LIMIT) \
    X(TRAP_DECEL_LIMIT) \
    X(TRAJ_MODE) \
    X(TRAP_VEL_LIMIT) \
    X(CAN_HEARTBEAT_MS) \
    X(CAN_PROTOCOL) \
    X(CAN_TIMEOUT_MS) \
    X(BRAKE_RESISTANCE) \
    X(DC_BUS_OVERVOLTAGE_TRIP_LEVEL) \
    X(DC_BUS_UNDERVOLTAGE_TRIP_LEVEL) \
    X(DC_MAX_NEGATIVE_CURRENT) \
    X(DC_MAX_POSITIVE_CURRENT) \
    X(ENABLE_UART) \
    X(MAX_REGEN_CURRENT) \
    X(SERIAL_NUMBER_H) \
    X(SERIAL_NUMBER_L)

#endif /* DARAN_SEED_OPTIONS_H */

/* The protocol cases of the on-target self-test: request bytes in, expected
 * reply bytes and HAL calls out, on the recording mock HAL. They run the
 * same core code the firmware links, compiled for the Cortex-M4, so that a
 * target-only difference (float arithmetic, char signedness, alignment)
 * shows up here and not on a drive. */
#include "selftest.h"

#include <string.h>

#include "daran_drive.h"
#include "mock_hal.h"

#define LONG_130 \
    "t 1 1000000000000000000000000000000000000000000000000000000000000000000000000" \
    "000000000000000000000000000000000000000000000000000000\n"

/* Every reply line ends in CR LF by default (protocol.md section 4). */
#if DARAN_REPLY_CRLF
#define EOL "\r\n"
#else
#define EOL "\n"
#endif

/* `e` on a drive without errors: the seven registers, one line each. */
#define E_CLEAR                                                                          \
    "axis: 0" EOL "motor: 0" EOL "encoder: 0" EOL "controller: 0" EOL "fet_thermistor: 0" EOL \
    "motor_thermistor: 0" EOL "can: 0" EOL

#define ESTOP DARAN_FLAG_ESTOP
#define FAULTS (DARAN_FLAG_ESTOP | DARAN_FLAG_MOTOR_FAILED | DARAN_FLAG_OVERTEMP)

typedef struct protocol_case {
    const char *input;    /* one or more lines, each with its '\n' */
    const char *reply;    /* every reply byte */
    const char *hal;      /* the mock's log of setter/move/action calls */
    uint32_t error_flags; /* axis0.error before the input (the registers behind
                           * its summary bits follow, see run_case) */
    uint32_t state;       /* current_state before the input (0: closed loop) */
    uint32_t warnings;    /* axis0.config_warnings before the input */
} protocol_case_t;

/* Move kinds: 0 filtered 1 trapezoid 2 passthrough 3 velocity 4 velocity
 * ramp 5 torque 6 torque ramp 7 impedance. Action 6 is the watchdog feed
 * after every accepted motion command. The mock starts at pos setpoint 100. */
static const protocol_case_t cases[] = {
    /* motion commands, the contract's worked examples */
    {"t 1 10 0 25\n", "", "move 0 10 0 0 25 0 0 g2; action 6", 0, 0, 0},
    {"t 1 10 0 25 *83\n", "", "move 0 10 0 0 25 0 0 g2; action 6", 0, 0, 0},
    {"t 1 12.5\n", "", "move 0 12.5 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"t 0 5\n", "", "move 0 5 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"q 1 50.0 7.5 2.5\n", "", "move 1 50 7.5 0 2.5 0 0 g3; action 6", 0, 0, 0},
    {"q 1 50\n", "", "move 1 50 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"q 2 160 30 10\n", "", "", 0, 0, 0},
    {"p 0 10 5 3\n", "", "move 2 10 5 3 0 0 0 g0; action 6", 0, 0, 0},
    {"v 1 12.5 0.0 1\n", "", "move 3 0 12.5 0 0 0 0 g0; action 6", 0, 0, 0},
    {"v 1 12.5 2.5 2\n", "", "move 4 0 12.5 0 2.5 0 0 g0; action 6", 0, 0, 0},
    {"c 1 0.1 0 1\n", "", "move 5 0 0 0.1 0 0 0 g0; action 6", 0, 0, 0},
    {"c 1 0.1 0.02 6\n", "", "move 6 0 0 0.1 0.02 0 0 g0; action 6", 0, 0, 0},
    {"c 2 5 3 6\n", "", "", 0, 0, 0},
    {"d 1 10 0 0.5 0.1 0.01\n", "", "move 7 10 0 0.5 0 0.1 0.01 g0; action 6", 0, 0, 0},
    /* zero rates (section 10.1): the vendor library's defaults */
    {"t 1 30 0 0 \n", "", "move 0 30 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"t 1 30 0 -0\n", "", "move 0 30 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"q 1 50 7.5 0\n", "", "move 1 50 0 0 0 0 0 g2; action 6", 0, 0, 0},
    {"q 1 50 0 5\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"v 1 12.5 0 2\n", "", "move 4 0 12.5 0 0 0 0 g0; action 6", 0, 0, 0},
    {"c 1 0.1 0 6\n", "", "move 6 0 0 0.1 0 0 0 g0; action 6", 0, 0, 0},
    {"c 1 0.1 -0 2\n", "", "move 6 0 0 0.1 0 0 0 g0; action 6", 0, 0, 0},
    {"ms 1 120 5 0\nmt 1 0\n", "", "move 0 120 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"ms 1 100 0 0\nmq 1 0\n", "", "move 1 100 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"ms 1 0 0.0 10\nmq 0 1\n", "", "move 1 100 0 0 0 0 0 g0; action 6", 0, 0, 0},
    {"ms 1 120 0 10\nmq 1 0\n", "error: trajectory infeasible" EOL, "", 0, 0, 0},
    {"ms 1 120 2 0\nmq 1 0\n", "error: trajectory infeasible" EOL, "", 0, 0, 0},
    {"ms 1 120 -1 10\nmq 1 0\n", "error: value out of range" EOL, "", 0, 0, 0},
    /* presets and starts: mq's cruise for distance 60, 2 s, 30 (r/min)/s,
     * trapezoid, then S-curve (section 10.3) */
    {"ms 1 120 5 10\nmt 1 0\n", "", "move 0 120 0 0 10 0 0 g2; action 6", 0, 0, 0},
    {"ms 1 120 5 10\nmt 1 1\n", "", "move 0 220 0 0 10 0 0 g2; action 6", 0, 0, 0},
    {"ms 1 160 2 30\nmq 1 0\n", "", "move 1 160 5.505102 0 30 0 0 g3; action 6", 0, 0, 0},
    {"w axis1.trap_traj.config.traj_mode 2\nms 1 160 2 30\nmq 1 0\n", "",
     "set TRAJ_MODE 2; move 1 160 6.3397465 0 30 0 0 g3; action 6", 0, 0, 0},
    {"mq 1 0\n", "error: no preset" EOL, "", 0, 0, 0},
    {"mq 0 1\n", "", "", 0, 0, 0},
    {"ms 1 1 2 3\nmt 1 2\n", "error: invalid mode" EOL, "", 0, 0, 0},
    /* queries */
    {"f 1\n", "12.5 -3" EOL, "", 0, 0, 0},
    {"f 1 \n", "12.5 -3" EOL, "", 0, 0, 0},
    {"f 1\r\n", "12.5 -3" EOL, "", 0, 0, 0},
    {"f 1 *87\n", "12.5 -3 *6" EOL, "", 0, 0, 0},
    {"F 0\n", "12.5 -3" EOL, "", 0, 0, 0},
    {"g 1\n", "24 0.5" EOL, "", 0, 0, 0},
    {"i 1\n", "100 3 2026000001" EOL, "", 0, 0, 0},
    {"e 1\n", E_CLEAR, "", 0, 0, 0},
    {"e 1\n", E_CLEAR, "", 0, 0, DARAN_WARNING_NVM_CORRUPT},
    {"e 1\n",
     "axis: 16384" EOL "motor: 0" EOL "encoder: 0" EOL "controller: 0" EOL
     "fet_thermistor: 0" EOL "motor_thermistor: 0" EOL "can: 0" EOL,
     "", ESTOP, 1, 0},
    {"e 1\n",
     "axis: 278592" EOL "motor: 65536" EOL "encoder: 0" EOL "controller: 0" EOL
     "fet_thermistor: 1" EOL "motor_thermistor: 0" EOL "can: 0" EOL,
     "", FAULTS, 1, 0},
    {"e 1 *84\n",
     "axis: 0 *9" EOL "motor: 0 *97" EOL "encoder: 0 *126" EOL "controller: 0 *22" EOL
     "fet_thermistor: 0 *55" EOL "motor_thermistor: 0 *43" EOL "can: 0 *102" EOL,
     "", 0, 0, 0},
    {"f 2\n", "", "", 0, 0, 0},
    /* properties */
    {"r axis1.output_shaft.pos_setpoint\n", "100" EOL, "", 0, 0, 0},
    {"r axis0.config.can_node_id\n", "1" EOL, "", 0, 0, 0},
    {"r config.uart_baudrate 1\n", "115200" EOL, "", 0, 0, 0},
    {"r vbus_voltage\n", "24" EOL, "", 0, 0, 0},
    {"r axis5.motor.current_control.Iq_measured\n", "", "", 0, 0, 0},
    {"w config.uart_baudrate 9600 1\n", "", "set UART_BAUDRATE 9600", 0, 0, 0},
    {"w config.uart_baudrate 9601 1\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis0.config.can_node_id 5\n", "", "set CAN_NODE_ID 5", 0, 0, 0},
    {"w axis0.config.can_node_id 5 *58\n", "", "set CAN_NODE_ID 5", 0, 0, 0},
    {"w axis1.controller.config.pos_gain 20.5\n", "", "set POS_GAIN 20.5", 0, 0, 0},
    {"w axis1.controller.config.pos_gain -1\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis1.controller.config.input_filter_bandwidth 0\n", "",
     "set INPUT_FILTER_BANDWIDTH 0", 0, 0, 0},
    {"w axis1.requested_state 8\n", "", "set REQUESTED_STATE 8", 0, 0, 0},
    {"w axis1.requested_state 8\n", "", "set REQUESTED_STATE 8", 0, 1, 0},
    {"w axis1.requested_state 8\n", "error: motor fault" EOL, "", DARAN_FLAG_OVERTEMP, 1, 0},
    {"w axis1.requested_state 3\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w vbus_voltage 3\n", "error: read only property" EOL, "", 0, 0, 0},
    {"r axis1.no.such.property\n", "error: invalid property" EOL, "", 0, 0, 0},
    /* the vendor's table (section 10.2): s32, new ranges, error registers */
    {"r axis1.encoder.pos_abs\n", "-16384" EOL, "", 0, 0, 0},
    {"r axis1.encoder.turn_abs\n", "-2147483648" EOL, "", 0, 0, 0},
    {"w axis1.encoder.pos_abs 5\n", "error: read only property" EOL, "", 0, 0, 0},
    {"w axis1.motor.config.direction -1\nr axis1.motor.config.direction\n", "-1" EOL,
     "set MOTOR_DIRECTION -1", 0, 0, 0},
    {"w axis1.motor.config.direction 0\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis1.motor.config.pole_pairs 14\n", "", "set POLE_PAIRS 14", 0, 0, 0},
    {"w axis1.motor.config.pole_pairs 129\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis1.config.extra_setting.stored_turns_counts -2147483648\n", "",
     "set STORED_TURNS_COUNTS -2147483648", 0, 0, 0},
    {"w axis1.config.extra_setting.stored_turns_counts 2147483648\n",
     "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis1.trap_traj.config.traj_mode 3\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w config.dc_max_negative_current -10 1\n", "", "set DC_MAX_NEGATIVE_CURRENT -10", 0, 0, 0},
    {"w config.dc_max_negative_current 1 1\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w axis1.error 0\n", "", "set AXIS_ERROR 0", ESTOP, 1, 0},
    {"w axis1.error 1\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"w can.error 0 1\n", "", "set CAN_ERROR 0", 0, 0, 0},
    {"r serial_number_l 1\n", "0" EOL, "", 0, 0, 0},
    /* system commands */
    {"ss 1\n", "", "action 0", 0, 0, 0},
    {"SS 1\n", "", "action 0", 0, 0, 0},
    {"se 1\n", "", "action 1", 0, 0, 0},
    {"sr 1\n", "", "action 2", 0, 0, 0},
    {"sc 1\n", "", "action 3", 0, 0, 0},
    {"sz 1\n", "", "action 4", 0, 0, 0},
    {"st 1\n", "", "action 5", 0, 0, 0},
    {"u 1\n", "", "action 6", 0, 0, 0},
    /* errors, in the contract's check order */
    {LONG_130, "error: line too long" EOL, "", 0, 0, 0},
    {"t 1 \001 10\n", "error: invalid character" EOL, "", 0, 0, 0},
    {"t 1 10 *256\n", "error: invalid checksum" EOL, "", 0, 0, 0},
    {"t 1 10 *5\n", "error: checksum mismatch *107" EOL, "", 0, 0, 0},
    {"x 1\n", "error: unknown command" EOL, "", 0, 0, 0},
    {"t\n", "error: invalid command format" EOL, "", 0, 0, 0},
    {"t 1.5 10\n", "error: invalid motor" EOL, "", 0, 0, 0},
    {"t 64 10\n", "error: invalid motor" EOL, "", 0, 0, 0},
    {"t 1 abc\n", "error: invalid value" EOL, "", 0, 0, 0},
    {"t 1 1e39\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"t 1 10 0 -1\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"v 1 20 -1 2\n", "error: value out of range" EOL, "", 0, 0, 0},
    {"v 1 20 0 7\n", "error: invalid mode" EOL, "", 0, 0, 0},
    /* the drive's state: any bit of axis0.error blocks motion (section 10.4) */
    {"t 1 10\n", "error: estop active" EOL, "", ESTOP, 1, 0},
    {"t 1 10\n", "error: estop active" EOL, "", FAULTS, 1, 0},
    {"t 1 10\n", "error: motor fault" EOL, "", DARAN_FLAG_OVERTEMP, 1, 0},
    {"t 1 10\n", "error: motor fault" EOL, "", DARAN_FLAG_UNDERVOLTAGE, 1, 0},
    {"t 1 10\n", "error: motor fault" EOL, "", DARAN_FLAG_WATCHDOG, 1, 0},
    {"t 1 10\n", "error: motor fault" EOL, "", DARAN_FLAG_MOTOR_FAILED, 0, 0},
    {"t 1 10\n", "error: motor fault" EOL, "", 1u, 0, 0},
    {"t 1 10\n", "", "move 0 10 0 0 0 0 0 g0; action 6", 0, 0, DARAN_WARNING_NVM_CORRUPT},
    {"t 1 10\n", "error: motor idle" EOL, "", 0, 1, 0},
    {"  \n", "", "", 0, 0, 0},
};

typedef struct reply_sink {
    char bytes[384];
    size_t len;
} reply_sink_t;

static void collect_reply(void *ctx, const char *line, size_t len)
{
    reply_sink_t *sink = ctx;
    if (len > sizeof sink->bytes - 1u - sink->len) {
        len = sizeof sink->bytes - 1u - sink->len;
    }
    memcpy(sink->bytes + sink->len, line, len);
    sink->len += len;
    sink->bytes[sink->len] = '\0';
}

static daran_drive_t drive;
static target_mock_t mock;
static reply_sink_t sink;

static bool run_case(const protocol_case_t *c)
{
    target_mock_reset(&mock);
    mock.value[DARAN_PROP_AXIS_ERROR].u32 = c->error_flags;
    /* The registers behind axis0.error's summary bits, as a drive sets them. */
    if ((c->error_flags & DARAN_FLAG_MOTOR_FAILED) != 0u) {
        mock.value[DARAN_PROP_MOTOR_ERROR].u32 = DARAN_MOTOR_ERROR_STALL;
    }
    if ((c->error_flags & DARAN_FLAG_CONTROLLER_FAILED) != 0u) {
        mock.value[DARAN_PROP_CONTROLLER_ERROR].u32 = DARAN_CONTROLLER_ERROR_OVERSPEED;
    }
    if ((c->error_flags & DARAN_FLAG_OVERTEMP) != 0u) {
        mock.value[DARAN_PROP_FET_THERMISTOR_ERROR].u32 = DARAN_THERMISTOR_ERROR_OVERTEMP;
    }
    mock.value[DARAN_PROP_CONFIG_WARNINGS].u32 = c->warnings;
    if (c->state != 0u) {
        mock.value[DARAN_PROP_CURRENT_STATE].u32 = c->state;
    }
    sink.len = 0u;
    sink.bytes[0] = '\0';
    if (daran_init(&drive, &target_mock_hal, &mock, collect_reply, &sink) != DARAN_OK) {
        return false;
    }
    /* The byte path the UART ISR takes, polled as the main loop does. */
    for (const char *p = c->input; *p != '\0'; p++) {
        if (!daran_rx_byte(&drive, (uint8_t)*p)) {
            (void)daran_poll(&drive);
            (void)daran_rx_byte(&drive, (uint8_t)*p);
        }
    }
    (void)daran_poll(&drive);
    return strcmp(sink.bytes, c->reply) == 0 && strcmp(mock.log, c->hal) == 0;
}

void selftest_protocol_cases(selftest_tally_t *tally)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (run_case(&cases[i])) {
            tally->passed++;
            continue;
        }
        tally->failed++;
        selftest_print("FAIL protocol case ");
        selftest_print_u32((uint32_t)i);
        selftest_print(": ");
        selftest_print_escaped(cases[i].input);
        selftest_print("\n  reply    ");
        selftest_print_escaped(sink.bytes);
        selftest_print("\n  expected ");
        selftest_print_escaped(cases[i].reply);
        selftest_print("\n  hal      ");
        selftest_print(mock.log);
        selftest_print("\n  expected ");
        selftest_print(cases[i].hal);
        selftest_print("\n");
    }
}

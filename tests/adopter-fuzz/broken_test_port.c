/* A port with four mistakes drive makers make, over port/minimal's HAL.
 * Each has a CTest (tests/adopter-fuzz/CMakeLists.txt) that passes only
 * when the fuzz harness fails on it with the report it owes:
 *  - its HAL keeps a gain per control mode in a table indexed by the mode
 *    as if it counted from 0: the core lets modes 1..3 through, so mode 3
 *    reads past the table (invariant 1: the sanitizers report it);
 *  - its `tb` command answers the brake temperature with a degree sign in
 *    UTF-8 (invariant 4: replies are printable ASCII, the vendor's client
 *    decodes them as such);
 *  - its `cal` command answers a progress line and then fails (an error
 *    reply is the whole answer: a host reads the first line and would take
 *    "calibrating" for the result);
 *  - its `home` command waits for the encoder's index pulse, which an
 *    interrupt would report, in a loop: without the interrupt it never ends
 *    (invariant 1: no hang; the replay's alarm, libFuzzer's -timeout). */
#include "daran_port.h"
#include "daran_test_port.h"
#include "minimal_hal.h"

static minimal_drive_t drive;

static const float gain_of_mode[3] = {1.0f, 0.5f, 0.25f};
static volatile float mode_gain;

static daran_result_t broken_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    return minimal_hal.get(ctx, prop, out);
}

static daran_result_t broken_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    if (prop == DARAN_PROP_CONTROL_MODE) {
        mode_gain = gain_of_mode[value.u32]; /* the mistake: modes are 1..3 */
    }
    return minimal_hal.set(ctx, prop, value);
}

static daran_result_t broken_move(void *ctx, const daran_move_t *move)
{
    return minimal_hal.move(ctx, move);
}

static daran_result_t broken_action(void *ctx, daran_action_t action)
{
    return minimal_hal.action(ctx, action);
}

static const daran_hal_t broken_hal = {.get = broken_get, .set = broken_set, .move = broken_move, .action = broken_action};

static daran_result_t brake_temperature(daran_drive_t *d, const daran_args_t *args, void *ctx)
{
    static const char text[] = "41.5 \xc2\xb0" "C"; /* the mistake: not ASCII */
    (void)args;
    (void)ctx;
    daran_reply(d, text, sizeof text - 1u);
    return DARAN_OK;
}

static daran_result_t calibrate(daran_drive_t *d, const daran_args_t *args, void *ctx)
{
    static const char text[] = "calibrating";
    (void)args;
    (void)ctx;
    daran_reply(d, text, sizeof text - 1u); /* the mistake: an answer before the outcome */
    return DARAN_ERR_MOTOR_FAULT;           /* the encoder did not answer */
}

static volatile bool index_pulse_seen; /* set by the encoder's interrupt, on the drive */

static daran_result_t home(daran_drive_t *d, const daran_args_t *args, void *ctx)
{
    (void)d;
    (void)args;
    (void)ctx;
    while (!index_pulse_seen) {
        /* the mistake: no time-out (and no interrupt on the host) */
    }
    return DARAN_OK;
}

static const daran_port_command_t commands[] = {
    {"tb", 0, 0, DARAN_PORT_COMMAND_QUERY, brake_temperature, ""},
    {"cal", 0, 0, 0, calibrate, ""},
    {"home", 0, 0, 0, home, ""},
};

static bool reset(void *ctx)
{
    minimal_drive_init(ctx);
    return true;
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "broken (tests/adopter-fuzz)",
        .hal = &broken_hal,
        .ctx = &drive,
        .reset = reset,
        .commands = commands,
        .command_count = sizeof commands / sizeof commands[0],
    };
    return &port;
}

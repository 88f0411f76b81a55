/* `sb id hz`: the brake example's own command (see brake_port.h). */
#include "brake_port.h"

bool brake_chopper_hz_ok(float hz)
{
    return hz >= 0.0f && hz <= BRAKE_CHOPPER_HZ_MAX; /* false for NaN */
}

/* The core has already checked the line as for its own commands: framing,
 * checksum, the id (this drive, or 0 for every drive) and one value after
 * it. The handler reads the value with the core's parser (its grammar, its
 * `invalid value`, its `value out of range` beyond FLT_MAX), checks the
 * chopper's range, and only then touches the hardware: once. An error
 * returned before that call has had no effect, as the core's own commands
 * promise. No reply: like the vendor's setters, `sb` is silent when it
 * succeeds. */
static daran_result_t command_sb(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    const brake_chopper_t *chopper = brake_chopper_of(ctx);
    float hz;
    (void)drive;
    daran_result_t result = daran_args_f32(args, 0, &hz);
    if (result != DARAN_OK) {
        return result;
    }
    if (!brake_chopper_hz_ok(hz)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    return chopper->set_frequency(chopper->ctx, hz + 0.0f); /* -0 is off, as 0 */
}

const daran_port_command_t brake_commands[] = {
    /* word, values after the id (at least, at most), flags, handler, `h` text */
    {"sb", 1, 1, 0, command_sb, "hz"},
};
const size_t brake_command_count = sizeof brake_commands / sizeof brake_commands[0];

daran_result_t brake_port_attach(daran_drive_t *drive)
{
    return daran_set_port_commands(drive, brake_commands, brake_command_count);
}

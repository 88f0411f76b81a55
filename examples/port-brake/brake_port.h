/* The brake example's own command, `sb id hz`: a hypothetical brake chopper
 * (the switch that dumps regenerated energy into the brake resistor) set to a
 * frequency in Hz, 0 switching it off. The command is data the core reads
 * (brake_commands), its handler parses every value with the core's
 * daran_args_*() parsers and checks the range before it calls the chopper's
 * driver once. The driver is the port's own hardware layer: the example's
 * printing HAL (main.c), its test and the fuzz harness
 * (tests/fuzz/fuzz_port.c) each give one, through brake_chopper_of(). */
#ifndef BRAKE_PORT_H
#define BRAKE_PORT_H

#include <stdbool.h>
#include <stddef.h>

#include "daran_ascii.h"

/** Highest chopper frequency the hardware takes, Hz. */
#define BRAKE_CHOPPER_HZ_MAX 50000.0f

/** The chopper's driver. set_frequency() gets a frequency within
 * 0..BRAKE_CHOPPER_HZ_MAX (+0 = off) and returns DARAN_OK, or the error the
 * drive answers, having changed nothing. */
typedef struct brake_chopper {
    daran_result_t (*set_frequency)(void *ctx, float hz);
    void *ctx;
} brake_chopper_t;

/** The port's command table: `sb id hz`. */
extern const daran_port_command_t brake_commands[];
extern const size_t brake_command_count;

/** Does the chopper take @p hz? (0..BRAKE_CHOPPER_HZ_MAX; NaN does not.) */
bool brake_chopper_hz_ok(float hz);

/** The chopper of the drive whose context (daran_init()'s, which a port
 * command's handler gets) is @p ctx. Defined by the program: the handler
 * finds its hardware through the port's own context, as the HAL does. */
brake_chopper_t *brake_chopper_of(void *ctx);

/** Give @p drive the port's commands. DARAN_ERR_BAD_ARGUMENT from
 * daran_set_port_commands() if the table were malformed. */
DARAN_NODISCARD daran_result_t brake_port_attach(daran_drive_t *drive);

#endif /* BRAKE_PORT_H */

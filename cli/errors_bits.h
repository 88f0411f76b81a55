/* The names of the bits of `e`'s seven registers (docs/cli.md, "errors,
 * clear"), as the vendor's Python client names them: its `error_codes`
 * lists follow ODrive 0.5.1's enums (AXIS_ERROR_*, MOTOR_ERROR_*, …), bit i
 * being entry i+1 (protocol.md 10.4). */
#ifndef DARAN_CLI_ERRORS_BITS_H
#define DARAN_CLI_ERRORS_BITS_H

#include <stddef.h>

/** The name of bit `bit` (0..31) of `e`'s register `reg` (0 axis, 1 motor,
 * 2 encoder, 3 controller, 4 fet_thermistor, 5 motor_thermistor, 6 can),
 * without its enum's prefix (`ESTOP_REQUESTED`); NULL when the vendor names
 * no such bit. */
const char *cli_error_bit_name(size_t reg, unsigned bit);

#endif /* DARAN_CLI_ERRORS_BITS_H */

/* What the docs' complete examples call but leave to the adopter: their own
 * HAL, UART, clock and CAN controller (tests/docs/check_snippets.py compiles
 * each example after this header). Declarations only: an example is
 * compiled, not linked. A name an example needs that is neither here nor in
 * a public header fails the check, as it would fail the reader. */
#ifndef DARAN_DOCS_SNIPPET_PRELUDE_H
#define DARAN_DOCS_SNIPPET_PRELUDE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

extern const daran_hal_t my_hal;
/* the adopter's HAL functions */
daran_result_t my_get(void *ctx, daran_prop_t prop, daran_value_t *out);
daran_result_t my_set(void *ctx, daran_prop_t prop, daran_value_t value);
daran_result_t my_move(void *ctx, const daran_move_t *move);
daran_result_t my_action(void *ctx, daran_action_t action);
void my_uart_write(void *ctx, const char *line, size_t len);
void uart_write_line(void *ctx, const char *line, size_t len);
uint32_t my_millis(void);
void control_tick(void);
/* the CAN controller: transmit (false: no mailbox free, or bus-off), and
 * read one received frame (false: none waiting) */
bool my_can_try_transmit(uint32_t id, const uint8_t *data, uint8_t dlc);
bool my_can_read_fifo(daran_can_frame_t *frame);

#endif

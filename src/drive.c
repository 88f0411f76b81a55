/* A drive instance and the road a line takes through the core. Both entry
 * roads start here: daran_poll() takes bytes from the ring, and
 * daran_process_line() a whole line; each goes through the framer, then the
 * framer's verdict -> checksum -> command table -> addressing -> handler ->
 * reply. This file runs the road; no stage calls back into it. */
#include "bridge.h"
#include "checksum.h"
#include "command.h"
#include "daran_port.h"
#include "framer.h"
#include "hal.h"
#include "handlers.h"
#include "line.h"
#include "property.h"
#include "reply.h"
#include "rx_ring.h"

static daran_result_t run_framed_line(daran_drive_t *drive);

daran_result_t daran_init_checked(daran_drive_t *drive, uint32_t build_check,
                                  const daran_hal_t *hal, void *hal_ctx, daran_write_fn write,
                                  void *write_ctx)
{
    if (drive == NULL || hal == NULL || write == NULL || hal->get == NULL || hal->set == NULL ||
        hal->move == NULL || hal->action == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (build_check != DARAN_BUILD_CHECK(daran_drive_t)) {
        return DARAN_ERR_BUILD_MISMATCH;
    }
    unsigned char *raw = (unsigned char *)drive;
    for (size_t i = 0; i < sizeof *drive; i++) {
        raw[i] = 0;
    }
    drive->hal = hal;
    drive->hal_ctx = hal_ctx;
    drive->write = write;
    drive->write_ctx = write_ctx;
    drive->telemetry_due = 1;
    daran_framer_reset(drive);
    return DARAN_OK;
}

void daran_set_forward(daran_drive_t *drive, daran_forward_fn forward, void *ctx)
{
    drive->forward = forward;
    drive->forward_ctx = ctx;
}

daran_result_t daran_process_line(daran_drive_t *drive, const char *text, size_t len)
{
    /* The same road as received bytes: through the framer into the line
     * buffer, so length, characters, fields and checksum are judged in one
     * place. A '\n' inside the text is an invalid character here. The line
     * buffer is shared with the byte path: a line it was receiving loses its
     * beginning, so its rest is answered `line too long` (D38). */
    bool interrupted = drive->line_len != 0u || drive->line_flags != 0u;
    daran_framer_reset(drive);
    bool ended = false;
    size_t taken = daran_framer_feed(drive, (const uint8_t *)text, len, false, &ended);
    if (ended || taken < len) {
        drive->line_flags |= DARAN_LINE_INVALID_BYTE;
    }
    daran_result_t result = run_framed_line(drive);
    if (interrupted) {
        drive->line_flags = DARAN_LINE_DAMAGED;
    }
    return result;
}

size_t daran_poll(daran_drive_t *drive)
{
    /* The bytes queued now, and no more: a producer that keeps sending
     * cannot keep this call from returning. */
    size_t left = daran_rx_queued(&drive->rx);
    size_t lines = 0;
    while (left != 0u) {
#if DARAN_ENABLE_CAN_BRIDGE
        if (drive->bridge != NULL && daran_bridge_waiting(drive->bridge)) {
            break; /* a bridged query waits: the next line waits for its answer (C32) */
        }
#endif
        const uint8_t *bytes;
        size_t run = daran_rx_run(&drive->rx, left, &bytes);
        if (*bytes == '\n' && drive->line_len == 0u && drive->line_flags == 0u) {
            /* An empty line: nothing to frame and nothing to answer (D5). */
            daran_rx_skip(&drive->rx, 1);
            left--;
            lines++;
            continue;
        }
        bool ended = false;
        size_t taken = daran_framer_feed(drive, bytes, run, true, &ended);
        left -= taken;
        /* Free the line's slots before it runs: the producer may refill them. */
        daran_rx_skip(&drive->rx, taken);
        if (ended) {
            (void)run_framed_line(drive);
            lines++;
        }
    }
    return lines;
}

/* An `axisN.` path: N is the motor, the rest is looked up among the axis
 * properties (D8). Anything else is a system path. */
static bool split_axis_path(const daran_field_t *path, daran_field_t *number,
                            daran_field_t *name)
{
    if (path->len <= DARAN_AXIS_WORD_LEN || path->text[0] != DARAN_AXIS_WORD[0] ||
        path->text[1] != DARAN_AXIS_WORD[1] || path->text[2] != DARAN_AXIS_WORD[2] ||
        path->text[3] != DARAN_AXIS_WORD[3]) {
        return false;
    }
    for (uint16_t dot = DARAN_AXIS_WORD_LEN; dot < path->len; dot++) {
        if (path->text[dot] == '.') {
            number->text = path->text + DARAN_AXIS_WORD_LEN;
            number->len = (uint16_t)(dot - DARAN_AXIS_WORD_LEN);
            name->text = path->text + dot + 1;
            name->len = (uint16_t)(path->len - dot - 1u);
            return true;
        }
    }
    return false;
}

static daran_result_t own_id(daran_drive_t *drive, uint32_t *id)
{
    daran_value_t value;
    daran_result_t result = daran_get(drive, DARAN_PROP_CAN_NODE_ID, &value);
    *id = value.u32;
    return result;
}

/* Steps 3 to 5 of the check order (spec section 8), then the handler. */
static daran_result_t dispatch(daran_drive_t *drive, const daran_line_t *line)
{
    const daran_fields_t *fields = &drive->fields;
    uint8_t count = fields->count;
    if (count == 0u) {
        /* Blank lines are ignored; a checksum with no command is not (D5). */
        return drive->reply_wants_checksum ? DARAN_ERR_UNKNOWN_COMMAND : DARAN_OK;
    }
    daran_field_t word = daran_field_of(line->text, fields, 0);
    /* The core's commands first, then the port's: a port cannot shadow one. */
    const daran_command_t *command = daran_find_command(&word);
    const daran_port_command_t *port = NULL;
    uint8_t flags;
    unsigned min_fields;
    unsigned max_fields;
    if (command != NULL) {
        flags = command->flags;
        min_fields = DARAN_MIN_FIELDS(command);
        max_fields = DARAN_MAX_FIELDS(command);
    } else if ((port = daran_find_port_command(drive, &word)) != NULL) {
        flags = (port->flags & DARAN_PORT_COMMAND_QUERY) != 0u ? DARAN_CMD_READ : 0u;
        min_fields = 2u + port->min_values;
        max_fields = 2u + port->max_values;
    } else {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }
    if (count < 2u) {
        return DARAN_ERR_INVALID_FORMAT;
    }

    /* Where the id is: field 1; for r/w the N of `axisN.`, or the last field
     * of a system path, absent meaning 0 (D8, D9). The property is looked up
     * here but reported after the id and the field count, in spec order. */
    daran_request_t request = {command, line->text, fields, 0, DARAN_PROP_COUNT};
    bool count_ok = count >= min_fields && count <= max_fields;
    daran_result_t property = DARAN_OK;
    daran_field_t id = daran_field_of(line->text, fields, 1);
    if ((flags & DARAN_CMD_PATH) != 0u) {
        daran_field_t path = id;
        daran_field_t name = path;
        daran_scope_t scope = DARAN_SCOPE_SYSTEM;
        if (split_axis_path(&path, &id, &name)) {
            scope = DARAN_SCOPE_AXIS;
            count_ok = count == min_fields;
        } else if (count == max_fields) {
            id = daran_field_of(line->text, fields, count - 1u);
        } else if (count == min_fields) {
            id.text = NULL; /* no id: every drive */
        } else {
            return DARAN_ERR_INVALID_FORMAT;
        }
        property = daran_find_property(scope, name.text, name.len, &request.prop);
    }
    daran_result_t result;
    if (id.text != NULL && (result = daran_field_motor(&id, &request.motor)) != DARAN_OK) {
        return result;
    }

    uint32_t own;
    result = own_id(drive, &own);
    if (result != DARAN_OK) {
        return result;
    }
    /* Another drive's line, or a broadcast that is not a read, goes to the
     * gateway too (D10); only the broadcast also runs here. */
    bool elsewhere = request.motor != 0u && request.motor != own;
    bool broadcast = request.motor == 0u && (flags & DARAN_CMD_READ) == 0u;
#if DARAN_ENABLE_CAN_BRIDGE
    if ((elsewhere || broadcast) && daran_bridge_active(drive)) {
        /* Checked like a line for this drive, then sent; a broadcast then
         * runs here too, below (C31, C34). A port command has no CAN form:
         * for another id it is not bridged, a broadcast one runs here alone. */
        if (port != NULL) {
            if (elsewhere) {
                return DARAN_ERR_NOT_BRIDGED;
            }
        } else if (!count_ok) {
            return DARAN_ERR_INVALID_FORMAT;
        } else if (property != DARAN_OK) {
            return property;
        } else if ((result = daran_bridge_line(drive->bridge, &request, broadcast)) != DARAN_OK ||
                   elsewhere) {
            return result;
        }
    } else
#endif
    if ((elsewhere || broadcast) && drive->forward != NULL) {
        drive->forward(drive->forward_ctx, request.motor, line->text, line->len);
    }
    if (elsewhere) {
        return DARAN_OK;
    }
    if (!count_ok) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    if (property != DARAN_OK) {
        return property;
    }
    if (port != NULL) {
        return daran_from_hal(port->handler(drive, &request, drive->port_ctx));
    }
    return daran_run_command(drive, &request);
}

/* Run the line the framer finished (or reject it), and reset the framer.
 * Returns what daran_process_line() returns. */
static daran_result_t run_framed_line(daran_drive_t *drive)
{
    uint8_t flags = drive->line_flags;
    daran_line_t line = {drive->line, drive->line_len, drive->star_at};
    if (line.star_at == DARAN_LINE_MAX) {
        line.star_at = line.len;
    }
    daran_result_t result;
    drive->reply_wants_checksum = 0;
    if ((flags & (DARAN_LINE_DAMAGED | DARAN_LINE_TOO_LONG)) != 0u) {
        result = DARAN_ERR_LINE_TOO_LONG;
    } else if ((flags & DARAN_LINE_INVALID_BYTE) != 0u) {
        result = DARAN_ERR_INVALID_CHARACTER;
    } else {
        result = daran_checksum_check(&line, &drive->reply_wants_checksum);
        if (result == DARAN_OK) {
            result = dispatch(drive, &line);
        }
    }
    if (result != DARAN_OK) {
        daran_reply_error(drive, result);
    }
    daran_framer_reset(drive);
    return result;
}

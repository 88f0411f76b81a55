/* A drive instance and the road a line takes through the core. Both entry
 * roads start here: daran_poll() takes bytes from the ring, and
 * daran_process_line() a whole line; each goes through the framer, then the
 * framer's verdict -> checksum -> command table -> addressing -> handler ->
 * reply. This file runs the road; no stage calls back into it. */
#include "checksum.h"
#include "command.h"
#include "daran_port.h"
#include "framer.h"
#include "hal.h"
#include "handlers.h"
#include "line.h"
#include "port_commands.h"
#include "property.h"
#include "reply.h"
#include "rx_ring.h"

static daran_result_t run_framed_line(daran_drive_t *drive);

daran_result_t daran_init_checked(daran_drive_t *drive, uint32_t build_check,
                                  const daran_hal_t *hal, void *ctx)
{
    if (drive == NULL || hal == NULL || hal->get == NULL || hal->set == NULL ||
        hal->move == NULL || hal->action == NULL || hal->write == NULL) {
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
    drive->ctx = ctx;
    drive->telemetry_due = 1;
    daran_framer_reset(drive);
    return DARAN_OK;
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
#if DARAN_ENABLE_CAN_BRIDGE /* the one sink the library has */
        if (drive->sink != NULL && drive->sink->ops->busy(drive->sink)) {
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

/* What the dispatcher needs of a line's command: the core's row or the
 * port's command, its flags and its field counts, word included. */
typedef struct command_of_line {
    const daran_command_t *command; /* NULL for a port command */
    const daran_port_command_t *port;
    uint8_t flags;
    uint8_t min_fields;
    uint8_t max_fields;
} command_of_line_t;

/* The core's commands first, then the port's: a port cannot shadow one. */
static bool find_command(const daran_drive_t *drive, const daran_field_t *word,
                         command_of_line_t *found)
{
    found->command = daran_find_command(word);
    found->port = NULL;
    if (found->command != NULL) {
        found->flags = found->command->flags;
        found->min_fields = (uint8_t)DARAN_MIN_FIELDS(found->command);
        found->max_fields = (uint8_t)DARAN_MAX_FIELDS(found->command);
        return true;
    }
    found->port = daran_find_port_command(drive, word);
    if (found->port == NULL) {
        return false;
    }
    found->flags = (found->port->flags & DARAN_PORT_COMMAND_QUERY) != 0u ? DARAN_CMD_READ : 0u;
    found->min_fields = (uint8_t)(2u + found->port->min_values);
    found->max_fields = (uint8_t)(2u + found->port->max_values);
    return true;
}

/* Where the id is: field 1; for r/w the N of `axisN.`, or the last field of
 * a system path, absent meaning 0 (D8, D9). The property is looked up here
 * but its error is reported after the id and the field count, in spec
 * order (*property). */
static daran_result_t address(const daran_line_t *line, const command_of_line_t *found,
                              daran_request_t *request, bool *count_ok,
                              daran_result_t *property)
{
    const daran_fields_t *fields = request->fields;
    uint8_t count = fields->count;
    *count_ok = count >= found->min_fields && count <= found->max_fields;
    *property = DARAN_OK;
    daran_field_t id = daran_field_of(line->text, fields, 1);
    if ((found->flags & DARAN_CMD_PATH) != 0u) {
        daran_field_t path = id;
        daran_field_t name = path;
        daran_scope_t scope = DARAN_SCOPE_SYSTEM;
        if (split_axis_path(&path, &id, &name)) {
            scope = DARAN_SCOPE_AXIS;
            *count_ok = count == found->min_fields;
        } else if (count == found->max_fields) {
            id = daran_field_of(line->text, fields, count - 1u);
        } else if (count == found->min_fields) {
            id.text = NULL; /* no id: every drive */
        } else {
            return DARAN_ERR_INVALID_FORMAT;
        }
        *property = daran_find_property(scope, name.text, name.len, &request->prop);
    }
    return id.text != NULL ? daran_field_motor(&id, &request->motor) : DARAN_OK;
}

#if DARAN_ENABLE_CAN_BRIDGE /* the one sink the library has */
/* A line for another drive, or a broadcast, to the drive's sink (a
 * gateway's bridge): checked like a line for this drive, then handed over;
 * a broadcast then runs here too (C31, C34). A port command is not the
 * sink's: for another id it is not bridged, a broadcast one runs here
 * alone. *done: nothing is left to do here. */
static daran_result_t sink_line(daran_drive_t *drive, const command_of_line_t *found,
                                  const daran_request_t *request, bool count_ok,
                                  daran_result_t property, bool elsewhere, bool *done)
{
    *done = true;
    if (found->port != NULL) {
        *done = elsewhere;
        return elsewhere ? DARAN_ERR_NOT_BRIDGED : DARAN_OK;
    }
    if (!count_ok) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    if (property != DARAN_OK) {
        return property;
    }
    daran_result_t result = drive->sink->ops->line(drive->sink, request, !elsewhere);
    *done = result != DARAN_OK || elsewhere;
    return result;
}
#endif

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
    command_of_line_t found;
    if (!find_command(drive, &word, &found)) {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }
    if (count < 2u) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    daran_request_t request = {found.command, line->text, fields, 0, DARAN_PROP_COUNT};
    bool count_ok;
    daran_result_t property;
    daran_result_t result = address(line, &found, &request, &count_ok, &property);
    uint32_t own;
    if (result != DARAN_OK || (result = own_id(drive, &own)) != DARAN_OK) {
        return result;
    }
    /* Another drive's line, or a broadcast that is not a read, goes to the
     * gateway too (D10); only the broadcast also runs here. */
    bool elsewhere = request.motor != 0u && request.motor != own;
    bool broadcast = request.motor == 0u && (found.flags & DARAN_CMD_READ) == 0u;
#if DARAN_ENABLE_CAN_BRIDGE
    if ((elsewhere || broadcast) && drive->sink != NULL && drive->sink->ops->takes(drive->sink)) {
        bool done;
        result = sink_line(drive, &found, &request, count_ok, property, elsewhere, &done);
        if (done) {
            return result;
        }
    } else
#endif
    if (elsewhere || broadcast) {
        (void)daran_forward_line(drive, request.motor, line->text, line->len);
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
    if (found.port != NULL) {
        return daran_from_hal(found.port->handler(drive, &request, drive->ctx));
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

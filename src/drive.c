/* A drive instance and the road a framed line takes through the core:
 * checksum -> fields -> command table -> addressing -> handler -> reply. */
#include "internal.h"

daran_result_t daran_init(daran_drive_t *drive, const daran_hal_t *hal, void *hal_ctx,
                          daran_write_fn write, void *write_ctx)
{
    if (drive == NULL || hal == NULL || write == NULL || hal->get == NULL ||
        hal->set == NULL || hal->move == NULL || hal->action == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    unsigned char *raw = (unsigned char *)drive;
    for (size_t i = 0; i < sizeof *drive; i++) {
        raw[i] = 0;
    }
    drive->hal = hal;
    drive->hal_ctx = hal_ctx;
    drive->write = write;
    drive->write_ctx = write_ctx;
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
     * buffer, so length, characters and checksum are judged in one place. A
     * '\n' inside the text stops the framer; it is an invalid character here. */
    daran_framer_reset(drive);
    size_t taken = daran_framer_append(drive, (const uint8_t *)text, len);
    if (taken < len) {
        drive->line_flags |= DARAN_LINE_INVALID_BYTE;
    }
    return daran_framer_end_line(drive, false);
}

/* An `axisN.` path: N is the motor, the rest is looked up among the axis
 * properties (D8). Anything else is a system path. */
static bool split_axis_path(const daran_field_t *path, daran_field_t *number,
                            daran_field_t *name)
{
    if (path->len < 5u || path->text[0] != 'a' || path->text[1] != 'x' ||
        path->text[2] != 'i' || path->text[3] != 's') {
        return false;
    }
    for (uint16_t dot = 4; dot < path->len; dot++) {
        if (path->text[dot] == '.') {
            number->text = path->text + 4;
            number->len = (uint16_t)(dot - 4u);
            name->text = path->text + dot + 1;
            name->len = (uint16_t)(path->len - dot - 1u);
            return true;
        }
    }
    return false;
}

/* Step 4 and 5 of the check order for r/w: the id from the path or the
 * trailing field (D9), then the field count, then the property. */
static daran_result_t address_property(const daran_command_t *command,
                                       const daran_fields_t *fields, daran_request_t *request,
                                       bool *count_ok, daran_scope_t *scope, daran_field_t *name)
{
    if (fields->count < 2u) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    daran_field_t number;
    daran_field_t path = daran_field_at(fields, 1);
    if (split_axis_path(&path, &number, name)) {
        *scope = DARAN_SCOPE_AXIS;
        *count_ok = fields->count == DARAN_MIN_FIELDS(command);
        return daran_field_motor(&number, &request->motor);
    }
    *scope = DARAN_SCOPE_SYSTEM;
    *name = path;
    if (fields->count == DARAN_MIN_FIELDS(command)) {
        *count_ok = true;
        request->motor = 0;
        return DARAN_OK;
    }
    if (fields->count == DARAN_MAX_FIELDS(command)) {
        *count_ok = true;
        daran_field_t id = daran_field_at(fields, DARAN_MAX_FIELDS(command) - 1u);
        return daran_field_motor(&id, &request->motor);
    }
    return DARAN_ERR_INVALID_FORMAT;
}

static daran_result_t own_id(daran_drive_t *drive, uint32_t *id)
{
    daran_value_t value;
    daran_result_t result = daran_get(drive, DARAN_PROP_CAN_NODE_ID, &value);
    *id = value.u32;
    return result;
}

static daran_result_t dispatch(daran_drive_t *drive, const daran_line_t *line)
{
    daran_fields_t *fields = &drive->fields;
    daran_split_fields(line->text, line->star_at, fields);
    if (fields->count == 0u) {
        /* Blank lines are ignored; a checksum with no command is not (D5). */
        return drive->reply_checksum ? DARAN_ERR_UNKNOWN_COMMAND : DARAN_OK;
    }
    daran_field_t word = daran_field_at(fields, 0);
    const daran_command_t *command = daran_find_command(&word);
    if (command == NULL) {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }

    daran_request_t request = {command, fields, 0, DARAN_PROP_COUNT};
    daran_result_t result;
    bool count_ok;
    daran_scope_t scope = DARAN_SCOPE_SYSTEM;
    daran_field_t name = {NULL, 0};
    if ((command->flags & DARAN_CMD_PATH) != 0u) {
        result = address_property(command, fields, &request, &count_ok, &scope, &name);
    } else if (fields->count < 2u) {
        return DARAN_ERR_INVALID_FORMAT;
    } else {
        daran_field_t id = daran_field_at(fields, 1);
        result = daran_field_motor(&id, &request.motor);
        count_ok = fields->count >= DARAN_MIN_FIELDS(command) && fields->count <= DARAN_MAX_FIELDS(command);
    }
    if (result != DARAN_OK) {
        return result;
    }

    uint32_t id;
    result = own_id(drive, &id);
    if (result != DARAN_OK) {
        return result;
    }
    /* Another drive's line, or a broadcast that is not a read, goes to the
     * gateway too (D10); only the broadcast also runs here. */
    bool elsewhere = request.motor != 0u && request.motor != id;
    bool broadcast = request.motor == 0u && (command->flags & DARAN_CMD_READ) == 0u;
    if ((elsewhere || broadcast) && drive->forward != NULL) {
        drive->forward(drive->forward_ctx, request.motor, line->text, line->len);
    }
    if (elsewhere) {
        return DARAN_OK;
    }

    if (!count_ok) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    if ((command->flags & DARAN_CMD_PATH) != 0u) {
        result = daran_find_property(scope, name.text, name.len, &request.prop);
        if (result != DARAN_OK) {
            return result;
        }
    }
    return daran_run_command(drive, &request);
}

daran_result_t daran_execute_line(daran_drive_t *drive, const daran_line_t *line)
{
    daran_result_t result = daran_checksum_check(line, &drive->reply_checksum);
    if (result == DARAN_OK) {
        result = dispatch(drive, line);
    }
    if (result != DARAN_OK) {
        daran_reply_error(drive, result);
    }
    return result;
}

/* The port's own commands: checking and keeping its table, finding a word
 * in it, and what a handler uses (the field parsers the core's handlers use,
 * and reply lines). A build with DARAN_ENABLE_PORT_COMMANDS 0 keeps only a
 * daran_set_port_commands() that takes no table; the lookup that finds
 * nothing is inline in command.h, so the dispatcher's port branch goes. */
#include "command.h"
#include "port_commands.h"
#include "handlers.h"
#include "number.h"
#include "reply.h"
#include "text.h"

#include "daran_port.h"

#if DARAN_ENABLE_PORT_COMMANDS

/* The length of a word of 1..DARAN_PORT_WORD_MAX lower-case letters, or 0. */
static size_t word_length(const char *word)
{
    size_t len = 0;
    while (word[len] >= 'a' && word[len] <= 'z') {
        if (++len > DARAN_PORT_WORD_MAX) {
            return 0;
        }
    }
    return word[len] == '\0' ? len : 0u;
}

const daran_port_command_t *daran_port_command_in(const daran_port_command_t *commands,
                                                  size_t count, const daran_field_t *word)
{
    for (size_t i = 0; i < count; i++) {
        /* command words are case-insensitive (spec 1); the table's are lower case */
        if (daran_word_is(word->text, word->len, commands[i].word, SIZE_MAX)) {
            return &commands[i];
        }
    }
    return NULL;
}

#if !DARAN_ENABLE_HELP || !DARAN_ENABLE_MULTI_MOTOR
/* The vendor's words whose commands an option compiled out stay reserved:
 * the vendor's tools still send them, and must never reach a port's handler. */
static bool compiled_out_vendor_word(const daran_field_t *word)
{
    static const char words[][3] = {
#if !DARAN_ENABLE_HELP
        "h",
#endif
#if !DARAN_ENABLE_MULTI_MOTOR
        "ms", "mt", "mq", "mp", "mv", "mc",
#endif
    };
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++) {
        if (daran_word_is(word->text, word->len, words[i], sizeof words[i])) {
            return true;
        }
    }
    return false;
}
#else
#define compiled_out_vendor_word(word) false
#endif

daran_result_t daran_set_port_commands(daran_drive_t *drive, const daran_port_command_t *commands,
                                       size_t count)
{
    if (drive == NULL || (commands == NULL && count != 0u) || count > 255u) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    for (size_t i = 0; i < count; i++) {
        const daran_port_command_t *c = &commands[i];
        daran_field_t word = {c->word, 0};
        if (c->word != NULL) {
            word.len = (uint16_t)word_length(c->word);
        }
        /* a word of lower-case letters, no vendor's, not twice */
        if (word.len == 0u || c->handler == NULL || c->help == NULL ||
            c->min_values > c->max_values || c->max_values > DARAN_FIELDS_MAX - 3u ||
            daran_find_command(&word) != NULL || compiled_out_vendor_word(&word) ||
            daran_port_command_in(commands, i, &word) != NULL) {
            return DARAN_ERR_BAD_ARGUMENT;
        }
    }
    drive->port_commands = count != 0u ? commands : NULL;
    drive->port_command_count = (uint8_t)count;
    return DARAN_OK;
}

size_t daran_args_count(const daran_args_t *args)
{
    return (size_t)args->fields->count - 2u;
}

const char *daran_args_word(const daran_args_t *args, size_t *len)
{
    *len = args->fields->len[0];
    return args->line + args->fields->start[0];
}

uint8_t daran_args_motor(const daran_args_t *args)
{
    return args->motor;
}

/* Value @p index after the id, or false past the last. */
static bool value_field(const daran_args_t *args, size_t index, daran_field_t *field)
{
    if (index >= daran_args_count(args)) {
        return false;
    }
    *field = daran_field_at(args, (unsigned)(2u + index));
    return true;
}

daran_result_t daran_args_f32(const daran_args_t *args, size_t index, float *out)
{
    daran_field_t field;
    return value_field(args, index, &field) ? daran_field_f32(&field, out)
                                            : DARAN_ERR_INVALID_FORMAT;
}

daran_result_t daran_args_u32(const daran_args_t *args, size_t index, uint32_t *out)
{
    daran_field_t field;
    uint64_t value;
    if (!value_field(args, index, &field)) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    daran_result_t result = daran_parse_u64(field.text, field.len, &value);
    if (result == DARAN_OK && value > UINT32_MAX) {
        result = DARAN_ERR_OUT_OF_RANGE;
    }
    if (result == DARAN_OK) {
        *out = (uint32_t)value;
    }
    return result;
}

daran_result_t daran_args_mode(const daran_args_t *args, size_t index, uint32_t allowed,
                               uint32_t *out)
{
    daran_field_t field;
    return value_field(args, index, &field) ? daran_field_mode(&field, allowed, out)
                                            : DARAN_ERR_INVALID_FORMAT;
}

void daran_reply(daran_drive_t *drive, const char *payload, size_t len)
{
    daran_reply_begin(drive);
    daran_reply_text(drive, payload, len);
    daran_reply_end(drive);
}

#else /* !DARAN_ENABLE_PORT_COMMANDS */

daran_result_t daran_set_port_commands(daran_drive_t *drive, const daran_port_command_t *commands,
                                       size_t count)
{
    (void)commands;
    /* no table to keep: an empty one is what the drive has already */
    return drive == NULL || count != 0u ? DARAN_ERR_BAD_ARGUMENT : DARAN_OK;
}

#endif /* DARAN_ENABLE_PORT_COMMANDS */

/* The drive's command table: its rows, word lookup, handlers and `h` text,
 * all made from the protocol's one list (daran_protocol.h), so the drive,
 * the bridge and the client cannot drift apart. */
#include "command.h"
#include "compiler.h"
#include "handlers.h"
#include "reply.h"
#include "text.h"

#include "daran_port.h"

/* Which rows of the protocol (daran_protocol.h) this build's drive has: the
 * row's FEATURE column against the options. The DISCOVERY form of `h` is
 * not a row of its own here: the `h` row takes its fields (below). */
#define ON_DRIVE_ALWAYS(...) __VA_ARGS__
#if DARAN_ENABLE_MULTI_MOTOR
#define ON_DRIVE_MULTI(...) __VA_ARGS__
#else
#define ON_DRIVE_MULTI(...)
#endif
#if DARAN_ENABLE_HELP
#define ON_DRIVE_HELP(...) __VA_ARGS__
#else
#define ON_DRIVE_HELP(...)
#endif
#define ON_DRIVE_DISCOVERY(...)
#if DARAN_ENABLE_UPDATE
#define ON_DRIVE_UPDATE(...) __VA_ARGS__
#else
#define ON_DRIVE_UPDATE(...)
#endif

/* The most fields of `h id properties [prefix]`, word included. */
#define DISCOVERY_MAX_OF(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, \
                         f2, f3, f4, f5, f6)                                                    \
    DISCOVERY_MAX_##feature(DARAN_PROTOCOL_MAX_FIELDS(f1, f2, f3, f4, f5, f6))
#define DISCOVERY_MAX_ALWAYS(n)
#define DISCOVERY_MAX_MULTI(n)
#define DISCOVERY_MAX_HELP(n)
#define DISCOVERY_MAX_DISCOVERY(n) +1 + (n)
#define DISCOVERY_MAX_UPDATE(n)
enum { DISCOVERY_FIELDS = 0 DARAN_PROTOCOL_COMMANDS(DISCOVERY_MAX_OF) };
#undef DISCOVERY_MAX_OF

/* A row's field counts, word included; `h` with discovery takes its
 * properties form's too. */
#define MIN_FIELDS_OF(f1, f2, f3, f4, f5, f6) (1 + DARAN_PROTOCOL_MIN_FIELDS(f1, f2, f3, f4, f5, f6))
#define MAX_FIELDS_OF(feature, f1, f2, f3, f4, f5, f6)                      \
    (DARAN_ENABLE_DISCOVERY && DRIVE_IS_HELP_##feature ? DISCOVERY_FIELDS \
                                                      : 1 + DARAN_PROTOCOL_MAX_FIELDS(f1, f2, f3, f4, f5, f6))
#define DRIVE_IS_HELP_ALWAYS 0
#define DRIVE_IS_HELP_MULTI 0
#define DRIVE_IS_HELP_HELP 1
#define DRIVE_IS_HELP_DISCOVERY 0
#define DRIVE_IS_HELP_UPDATE 0

/* The handler's argument of a row: its shape, its action or its query. */
#define ARG_MOTION(arg) DARAN_SHAPE_##arg
#define ARG_START(arg) DARAN_SHAPE_##arg
#define ARG_SYSTEM(arg) DARAN_ACTION_##arg
#define ARG_QUERY(arg) DARAN_QUERY_LIST_##arg
#define ARG_PRESET(arg) 0
#define ARG_READ(arg) 0
#define ARG_WRITE(arg) 0
#define ARG_UPDATE(arg) DARAN_UPDATE_OP_##arg

/* The flags of a row: answered for id 0 (a query or a read), the id in a
 * path, and its CAN form for the bridge. */
#define READS_MOTION 0u
#define READS_START 0u
#define READS_PRESET 0u
#define READS_SYSTEM 0u
#define READS_WRITE 0u
#define READS_QUERY DARAN_CMD_READ
#define READS_READ DARAN_CMD_READ
#define READS_UPDATE 0u
#define FLAGS_OF(cls, can, f1)                                                                \
    (uint8_t)(READS_##cls | (DARAN_PROTOCOL_PATH_FIRST(f1) ? DARAN_CMD_PATH : 0u) |          \
              (unsigned)DARAN_CAN_FORM_##can << DARAN_CMD_CAN_SHIFT)

#define DRIVE_COMMANDS(X) DARAN_PROTOCOL_COMMANDS(X)

/* Every row's handler, declared from the table: a row a build adds
 * (DARAN_EXTRA_COMMANDS) needs no header of the library's. */
#define DECLARE_HANDLER(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, \
                        f3, f4, f5, f6)                                                          \
    ON_DRIVE_##feature(daran_result_t daran_cmd_##handler(daran_drive_t *drive,                 \
                                                          const daran_request_t *request);)
DRIVE_COMMANDS(DECLARE_HANDLER)
#undef DECLARE_HANDLER

/* What the dispatcher and the handlers take for granted, checked by the
 * compiler: every command has its id and fits the field views with room to
 * tell "too many" (the count saturates at DARAN_FIELDS_MAX); a motion
 * command's values fit the handler's array; `w` has a value field; `ms`
 * carries the preset's values. */
#define FIELDS_WRONG(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, \
                     f3, f4, f5, f6)                                                            \
    ON_DRIVE_##feature(| (MIN_FIELDS_OF(f1, f2, f3, f4, f5, f6) >= 2 &&                         \
                                  MAX_FIELDS_OF(feature, f1, f2, f3, f4, f5, f6) < DARAN_FIELDS_MAX \
                              ? 0                                                               \
                              : 1))
DARAN_STATIC_ASSERT((0 DRIVE_COMMANDS(FIELDS_WRONG)) == 0, command_field_counts_fit_the_fields);
#undef FIELDS_WRONG
#define MOTION_VALUES_WRONG_MOTION(n) | ((n) <= (int)DARAN_MOTION_VALUES_MAX ? 0 : 1)
#define MOTION_VALUES_WRONG_PRESET(n) | ((n) == (int)DARAN_PRESET_VALUES ? 0 : 1)
#define MOTION_VALUES_WRONG_START(n)
#define MOTION_VALUES_WRONG_QUERY(n)
#define MOTION_VALUES_WRONG_READ(n)
#define MOTION_VALUES_WRONG_WRITE(n)
#define MOTION_VALUES_WRONG_SYSTEM(n)
#define MOTION_VALUES_WRONG_UPDATE(n)
#define MOTION_VALUES_WRONG(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, \
                            f2, f3, f4, f5, f6)                                                    \
    MOTION_VALUES_WRONG_##cls(DARAN_PROTOCOL_MAX_VALUES(f1, f2, f3, f4, f5, f6))
DARAN_STATIC_ASSERT((0 DRIVE_COMMANDS(MOTION_VALUES_WRONG)) == 0, motion_values_fit_the_handler);
#undef MOTION_VALUES_WRONG

#define COMMAND_ROW(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, \
                    f3, f4, f5, f6)                                                             \
    ON_DRIVE_##feature({{c0, c1},                                                               \
                        (uint8_t)(MIN_FIELDS_OF(f1, f2, f3, f4, f5, f6) << 4 |                  \
                                  MAX_FIELDS_OF(feature, f1, f2, f3, f4, f5, f6)),             \
                        FLAGS_OF(cls, can, f1),                                                 \
                        (uint8_t)(ARG_##cls(arg))}, )
static const daran_command_t commands[] = {DRIVE_COMMANDS(COMMAND_ROW)};
#undef COMMAND_ROW

#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

/* Where a word is found: its two lower-case letters XORed give one of 64
 * slots, which holds its row number + 1 (0: no command). No two of the
 * words share a slot: a second initializer of one is an error
 * (-Woverride-init, part of -Wextra, under -Werror). */
#define WORD_SLOT(c0, c1) (((unsigned)(c0) ^ (unsigned)(c1)) & 63u)
#define ROW_NUMBER(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, \
                   f4, f5, f6)                                                                 \
    ON_DRIVE_##feature(ROW_##name, )
enum command_row { DRIVE_COMMANDS(ROW_NUMBER) ROW_COUNT };
#undef ROW_NUMBER
#define SLOT_OF(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, f4, \
                f5, f6)                                                                         \
    ON_DRIVE_##feature([WORD_SLOT(c0, c1)] = (uint8_t)(ROW_##name + 1), )
static const uint8_t row_of_slot[64] = {DRIVE_COMMANDS(SLOT_OF)};
#undef SLOT_OF

#if DARAN_ENABLE_HELP
/* Every command's help arguments after the id, each ending in '\0', in table order. */
#define HELP_LINE(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, \
                  f4, f5, f6)                                                                 \
    ON_DRIVE_##feature(HELP_TEXT_##feature(help) "\0")
#define HELP_TEXT_ALWAYS(help) help
#define HELP_TEXT_MULTI(help) help
#define HELP_TEXT_UPDATE(help) help
#if DARAN_ENABLE_DISCOVERY
#define HELP_TEXT_HELP(help) "[" DARAN_H_PROPERTIES_HELP "]"
#else
#define HELP_TEXT_HELP(help) help
#endif
static const char help_text[] = DRIVE_COMMANDS(HELP_LINE);
#undef HELP_LINE

/* `h id`: a line per command, the core's then the port's; `h id properties
 * [prefix]`: discovery (discovery.c), in a build with it. */
/* One `h` line: "<word> id <arguments>" (r and w take no id there). */
static void help_line(daran_drive_t *drive, const char *word, size_t len, bool id,
                      const char *arguments)
{
    daran_reply_begin(drive);
    daran_reply_text(drive, word, len);
    if (id) {
        daran_reply_text(drive, " id", 3);
    }
    if (*arguments != '\0') {
        daran_reply_space(drive);
        daran_reply_cstr(drive, arguments);
    }
    daran_reply_end(drive);
}

daran_result_t daran_cmd_help(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_help(drive, request, false);
}

daran_result_t daran_help(daran_drive_t *drive, const daran_request_t *request, bool bridged)
{
#if DARAN_ENABLE_DISCOVERY
    if (request->fields->count > 2u) {
        return daran_discovery(drive, request, bridged);
    }
#else
    (void)request;
#endif
    (void)bridged; /* a build without port commands lists the core's alone anyway */
    const char *arguments = help_text;
    for (size_t i = 0; i < COMMAND_COUNT; i++) {
        const daran_command_t *command = &commands[i];
        help_line(drive, command->word, command->word[1] != '\0' ? 2u : 1u,
                  (command->flags & DARAN_CMD_PATH) == 0u, arguments);
        arguments = daran_nth_text(arguments, 1);
    }
#if DARAN_ENABLE_PORT_COMMANDS
    /* a bridged `h` lists the commands the bridge takes: the core's alone (C35) */
    for (size_t i = 0; !bridged && i < drive->port_command_count; i++) {
        const daran_port_command_t *command = &drive->port_commands[i];
        help_line(drive, command->word, daran_text_len(command->word), true, command->help);
    }
#endif
    return DARAN_OK;
}
#endif

/* Row i's handler, from the same list: a row names its handler, and a row
 * stays 5 bytes (a pointer in it would pad it to 12). */
typedef daran_result_t (*handler_fn)(daran_drive_t *drive, const daran_request_t *request);
#define HANDLER_OF(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, \
                   f4, f5, f6)                                                                 \
    ON_DRIVE_##feature(daran_cmd_##handler, )
static handler_fn const command_handlers[] = {DRIVE_COMMANDS(HANDLER_OF)};
#undef HANDLER_OF

const daran_command_t *daran_find_command(const daran_field_t *word)
{
    if (word->len == 0u || word->len > 2u) {
        return NULL;
    }
    /* one bit lowers a letter, and maps nothing else onto one */
    unsigned c0 = (unsigned char)word->text[0] | 0x20u;
    unsigned c1 = word->len == 2u ? (unsigned char)word->text[1] | 0x20u : 0u;
    unsigned row = row_of_slot[WORD_SLOT(c0, c1)];
    if (row == 0u) {
        return NULL;
    }
    /* the row's letters against the ones already lowered: a field holds
     * neither NUL nor blank, so c1 is 0 for a one-letter word alone */
    const daran_command_t *command = &commands[row - 1u];
    return (unsigned char)command->word[0] == c0 && (unsigned char)command->word[1] == c1 ? command
                                                                                        : NULL;
}

daran_result_t daran_run_command(daran_drive_t *drive, const daran_request_t *request)
{
    return command_handlers[request->command - commands](drive, request);
}

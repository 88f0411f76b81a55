/* The command table: the only place that knows which commands exist, their
 * field counts, handlers and help text. One list, DARAN_COMMANDS, makes both
 * the rows and the `h` text, so they cannot drift apart. */
#include "command.h"
#include "compiler.h"
#include "handlers.h"
#include "reply.h"
#include "text.h"

#include "daran_port.h"

#define READ DARAN_CMD_READ
#define PATH DARAN_CMD_PATH
#define READ_PATH (DARAN_CMD_READ | DARAN_CMD_PATH)

/* X(name, the word's letters (the second 0 for a one-letter word), min
 * fields, max fields, flags, arg, handler, arguments for `h` after the id:
 * every command but r and w takes the motor id first, and `h` prints it).
 * The order is `h`'s. */
#define SINGLE_MOTION_COMMANDS(X)                                                               \
    X(T, 't', 0, 3, 5, 0, DARAN_SHAPE_FILTERED, daran_cmd_motion, "pos [vel] [bw]")                \
    X(Q, 'q', 0, 3, 5, 0, DARAN_SHAPE_TRAPEZOID, daran_cmd_motion, "pos [vel] [acc]")              \
    X(P, 'p', 0, 3, 5, 0, DARAN_SHAPE_PASSTHROUGH, daran_cmd_motion, "pos [vel_ff] [torque_ff]")   \
    X(V, 'v', 0, 3, 5, 0, DARAN_SHAPE_VELOCITY, daran_cmd_motion, "vel [param] [mode]")            \
    X(C, 'c', 0, 3, 5, 0, DARAN_SHAPE_TORQUE, daran_cmd_motion, "torque [param] [mode]")           \
    X(D, 'd', 0, 7, 7, 0, DARAN_SHAPE_IMPEDANCE, daran_cmd_motion, "pdes vdes tff kp kd")

#if DARAN_ENABLE_MULTI_MOTOR
#define PRESET_FIELDS (2 + DARAN_PRESET_VALUES) /* ms id p1 p2 p3 */
#define MULTI_MOTION_COMMANDS(X)                                                                \
    X(MS, 'm', 's', PRESET_FIELDS, PRESET_FIELDS, 0, 0, daran_cmd_ms, "p1 p2 p3")                  \
    X(MT, 'm', 't', 3, 3, 0, DARAN_SHAPE_FILTERED, daran_cmd_start, "rel")                         \
    X(MQ, 'm', 'q', 3, 3, 0, DARAN_SHAPE_TRAPEZOID, daran_cmd_start, "rel")                        \
    X(MP, 'm', 'p', 3, 3, 0, DARAN_SHAPE_PASSTHROUGH, daran_cmd_start, "rel")                      \
    X(MV, 'm', 'v', 2, 2, 0, DARAN_SHAPE_VELOCITY, daran_cmd_start, "")                            \
    X(MC, 'm', 'c', 2, 2, 0, DARAN_SHAPE_TORQUE, daran_cmd_start, "")
#else
#define MULTI_MOTION_COMMANDS(X)
#endif

#define PROPERTY_AND_SYSTEM_COMMANDS(X)                                      \
    X(R, 'r', 0, 2, 3, READ_PATH, 0, daran_cmd_r, "path [id]")                                     \
    X(W, 'w', 0, 3, 4, PATH, 0, daran_cmd_w, "path value [id]")                                    \
    X(SS, 's', 's', 2, 2, 0, DARAN_ACTION_SAVE_CONFIG, daran_cmd_action, "")                       \
    X(SE, 's', 'e', 2, 2, 0, DARAN_ACTION_ERASE_CONFIG, daran_cmd_action, "")                      \
    X(SR, 's', 'r', 2, 2, 0, DARAN_ACTION_REBOOT, daran_cmd_action, "")                            \
    X(SC, 's', 'c', 2, 2, 0, DARAN_ACTION_CLEAR_ERRORS, daran_cmd_action, "")                      \
    X(SZ, 's', 'z', 2, 2, 0, DARAN_ACTION_SET_ZERO, daran_cmd_action, "")                          \
    X(ST, 's', 't', 2, 2, 0, DARAN_ACTION_ESTOP, daran_cmd_action, "")

#if DARAN_ENABLE_DISCOVERY
#define HELP_COMMAND(X) X(H, 'h', 0, 2, 4, READ, 0, help_command, "[properties [prefix]]")
#elif DARAN_ENABLE_HELP
#define HELP_COMMAND(X) X(H, 'h', 0, 2, 2, READ, 0, help_command, "")
#else
#define HELP_COMMAND(X)
#endif

#define QUERY_COMMANDS(X)                                                                       \
    X(F, 'f', 0, 2, 2, READ, 0, daran_cmd_feedback, "")                                            \
    X(G, 'g', 0, 2, 2, READ, 0, daran_cmd_power, "")                                               \
    X(I, 'i', 0, 2, 2, READ, 0, daran_cmd_identity, "")                                            \
    X(E, 'e', 0, 2, 2, READ, 0, daran_cmd_errors, "")                                              \
    X(U, 'u', 0, 2, 2, 0, DARAN_ACTION_FEED_WATCHDOG, daran_cmd_action, "")

#define DARAN_COMMANDS(X)                                                  \
    SINGLE_MOTION_COMMANDS(X) MULTI_MOTION_COMMANDS(X)                     \
    PROPERTY_AND_SYSTEM_COMMANDS(X) HELP_COMMAND(X) QUERY_COMMANDS(X)

/* What the dispatcher and the handlers take for granted, checked by the
 * compiler: every command has its id and fits the field views with room to
 * tell "too many" (the count saturates at DARAN_FIELDS_MAX); a motion
 * command's values fit the handler's array and its shape; `w` has a value
 * field; discovery's `h id properties prefix` fits. */
#define FIELDS_WRONG(name, c0, c1, min, max, flags, arg, handler, help) \
    | ((min) >= 2 && (min) <= (max) && (max) < DARAN_FIELDS_MAX ? 0 : 1)
DARAN_STATIC_ASSERT((0 DARAN_COMMANDS(FIELDS_WRONG)) == 0, command_field_counts_fit_the_fields);
#undef FIELDS_WRONG
#define MOTION_VALUES_WRONG(name, c0, c1, min, max, flags, arg, handler, help) \
    | ((max) - 2 <= (int)DARAN_MOTION_VALUES_MAX ? 0 : 1)
DARAN_STATIC_ASSERT((0 SINGLE_MOTION_COMMANDS(MOTION_VALUES_WRONG)) == 0,
                    motion_values_fit_the_handler);
#undef MOTION_VALUES_WRONG
#define W_WRONG(name, c0, c1, min, max, flags, arg, handler, help) \
    | ((flags) == PATH && (min) < 3 ? 1 : 0)
DARAN_STATIC_ASSERT((0 DARAN_COMMANDS(W_WRONG)) == 0, w_has_a_value);
#undef W_WRONG
#define H_WRONG(name, c0, c1, min, max, flags, arg, handler, help) | ((max) > 4 ? 1 : 0)
DARAN_STATIC_ASSERT((0 HELP_COMMAND(H_WRONG)) == 0, h_has_at_most_a_prefix);
#undef H_WRONG

#define COMMAND_ROW(name, c0, c1, min, max, flags, arg, handler, help) \
    {{c0, c1}, (uint8_t)((min) << 4 | (max)), flags, (uint8_t)(arg)},
static const daran_command_t commands[] = {DARAN_COMMANDS(COMMAND_ROW)};
#undef COMMAND_ROW

#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

/* Where a word is found: its two lower-case letters XORed give one of 64
 * slots, which holds its row number + 1 (0: no command). No two of the
 * words share a slot: a second initializer of one is an error
 * (-Woverride-init, part of -Wextra, under -Werror). */
#define WORD_SLOT(c0, c1) (((unsigned)(c0) ^ (unsigned)(c1)) & 63u)
#define ROW_NUMBER(name, c0, c1, min, max, flags, arg, handler, help) ROW_##name,
enum command_row { DARAN_COMMANDS(ROW_NUMBER) ROW_COUNT };
#undef ROW_NUMBER
#define SLOT_OF(name, c0, c1, min, max, flags, arg, handler, help) \
    [WORD_SLOT(c0, c1)] = (uint8_t)(ROW_##name + 1),
static const uint8_t row_of_slot[64] = {DARAN_COMMANDS(SLOT_OF)};
#undef SLOT_OF

#if DARAN_ENABLE_HELP
/* Every command's help arguments after the id, each ending in '\0', in table order. */
#define HELP_LINE(name, c0, c1, min, max, flags, arg, handler, help) help "\0"
static const char help_text[] = DARAN_COMMANDS(HELP_LINE);
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

static daran_result_t help_command(daran_drive_t *drive, const daran_request_t *request)
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
#define HANDLER_OF(name, c0, c1, min, max, flags, arg, handler, help) handler,
static handler_fn const command_handlers[] = {DARAN_COMMANDS(HANDLER_OF)};
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

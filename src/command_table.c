/* The command table: the only place that knows which commands exist, their
 * field counts, handlers and help text. One list, DARAN_COMMANDS, makes both
 * the rows and the `h` text, so they cannot drift apart. */
#include "internal.h"

#include "daran_port.h"

enum handler {
    HANDLER_MOTION,
    HANDLER_MS,
    HANDLER_START,
    HANDLER_R,
    HANDLER_W,
    HANDLER_ACTION,
    HANDLER_H,
    HANDLER_FEEDBACK,
    HANDLER_POWER,
    HANDLER_IDENTITY,
    HANDLER_ERRORS,
    HANDLER_COUNT
};

#define READ DARAN_CMD_READ
#define PATH DARAN_CMD_PATH
#define READ_PATH (DARAN_CMD_READ | DARAN_CMD_PATH)

/* X(word, min fields, max fields, flags, arg, handler, arguments for `h`
 * after the id: every command but r and w takes the motor id first, and `h`
 * prints it). t first: it is the command a host streams at 1 kHz. */
#define SINGLE_MOTION_COMMANDS(X)                                                               \
    X("t", 3, 5, 0, DARAN_SHAPE_FILTERED, HANDLER_MOTION, "pos [vel] [bw]")                     \
    X("q", 3, 5, 0, DARAN_SHAPE_TRAPEZOID, HANDLER_MOTION, "pos [vel] [acc]")                   \
    X("p", 3, 5, 0, DARAN_SHAPE_PASSTHROUGH, HANDLER_MOTION, "pos [vel_ff] [torque_ff]")        \
    X("v", 3, 5, 0, DARAN_SHAPE_VELOCITY, HANDLER_MOTION, "vel [param] [mode]")                 \
    X("c", 3, 5, 0, DARAN_SHAPE_TORQUE, HANDLER_MOTION, "torque [param] [mode]")                \
    X("d", 7, 7, 0, DARAN_SHAPE_IMPEDANCE, HANDLER_MOTION, "pdes vdes tff kp kd")

#if DARAN_ENABLE_MULTI_MOTOR
#define MULTI_MOTION_COMMANDS(X)                                                                \
    X("ms", 2 + DARAN_PRESET_VALUES, 2 + DARAN_PRESET_VALUES, 0, 0, HANDLER_MS, "p1 p2 p3")     \
    X("mt", 3, 3, 0, DARAN_SHAPE_FILTERED, HANDLER_START, "rel")                                \
    X("mq", 3, 3, 0, DARAN_SHAPE_TRAPEZOID, HANDLER_START, "rel")                               \
    X("mp", 3, 3, 0, DARAN_SHAPE_PASSTHROUGH, HANDLER_START, "rel")                             \
    X("mv", 2, 2, 0, DARAN_SHAPE_VELOCITY, HANDLER_START, "")                                   \
    X("mc", 2, 2, 0, DARAN_SHAPE_TORQUE, HANDLER_START, "")
#else
#define MULTI_MOTION_COMMANDS(X)
#endif

#define PROPERTY_AND_SYSTEM_COMMANDS(X)                                      \
    X("r", 2, 3, READ_PATH, 0, HANDLER_R, "path [id]")                       \
    X("w", 3, 4, PATH, 0, HANDLER_W, "path value [id]")                      \
    X("ss", 2, 2, 0, DARAN_ACTION_SAVE_CONFIG, HANDLER_ACTION, "")         \
    X("se", 2, 2, 0, DARAN_ACTION_ERASE_CONFIG, HANDLER_ACTION, "")        \
    X("sr", 2, 2, 0, DARAN_ACTION_REBOOT, HANDLER_ACTION, "")              \
    X("sc", 2, 2, 0, DARAN_ACTION_CLEAR_ERRORS, HANDLER_ACTION, "")        \
    X("sz", 2, 2, 0, DARAN_ACTION_SET_ZERO, HANDLER_ACTION, "")            \
    X("st", 2, 2, 0, DARAN_ACTION_ESTOP, HANDLER_ACTION, "")

#if DARAN_ENABLE_HELP
#define HELP_COMMAND(X) X("h", 2, 4, READ, 0, HANDLER_H, "[properties [prefix]]")
#else
#define HELP_COMMAND(X)
#endif

#define QUERY_COMMANDS(X)                                                                       \
    X("f", 2, 2, READ, 0, HANDLER_FEEDBACK, "")                                                 \
    X("g", 2, 2, READ, 0, HANDLER_POWER, "")                                                    \
    X("i", 2, 2, READ, 0, HANDLER_IDENTITY, "")                                                 \
    X("e", 2, 2, READ, 0, HANDLER_ERRORS, "")                                                   \
    X("u", 2, 2, 0, DARAN_ACTION_FEED_WATCHDOG, HANDLER_ACTION, "")

#define DARAN_COMMANDS(X)                                                  \
    SINGLE_MOTION_COMMANDS(X) MULTI_MOTION_COMMANDS(X)                     \
    PROPERTY_AND_SYSTEM_COMMANDS(X) HELP_COMMAND(X) QUERY_COMMANDS(X)

/* What the dispatcher and the handlers take for granted, checked by the
 * compiler: every command has its id and fits the field views with room to
 * tell "too many" (the count saturates at DARAN_FIELDS_MAX); a motion
 * command's values fit the handler's array and its shape; `w` has a value
 * field; discovery's `h id properties prefix` fits. */
#define FIELDS_WRONG(word, min, max, flags, arg, handler, help) \
    | ((min) >= 2 && (min) <= (max) && (max) < DARAN_FIELDS_MAX ? 0 : 1)
DARAN_STATIC_ASSERT((0 DARAN_COMMANDS(FIELDS_WRONG)) == 0, command_field_counts_fit_the_fields);
#undef FIELDS_WRONG
#define MOTION_VALUES_WRONG(word, min, max, flags, arg, handler, help) \
    | ((max) - 2 <= (int)DARAN_MOTION_VALUES_MAX ? 0 : 1)
DARAN_STATIC_ASSERT((0 SINGLE_MOTION_COMMANDS(MOTION_VALUES_WRONG)) == 0,
                    motion_values_fit_the_handler);
#undef MOTION_VALUES_WRONG
#define W_AND_H_WRONG(word, min, max, flags, arg, handler, help) \
    | ((handler) == HANDLER_W && (min) < 3 ? 1 : 0) | ((handler) == HANDLER_H && (max) > 4 ? 1 : 0)
DARAN_STATIC_ASSERT((0 DARAN_COMMANDS(W_AND_H_WRONG)) == 0, w_has_a_value_and_h_at_most_a_prefix);
#undef W_AND_H_WRONG

#define COMMAND_ROW(word, min, max, flags, arg, handler, help) \
    {word, (uint8_t)((min) << 4 | (max)), flags, (uint8_t)(arg), handler},
static const daran_command_t commands[] = {DARAN_COMMANDS(COMMAND_ROW)};
#undef COMMAND_ROW

#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

#if DARAN_ENABLE_HELP
/* Every command's help arguments after the id, each ending in '\0', in table order. */
#define HELP_LINE(word, min, max, flags, arg, handler, help) help "\0"
static const char help_text[] = DARAN_COMMANDS(HELP_LINE);
#undef HELP_LINE

/* `h id`: a line per command, the core's then the port's; `h id properties
 * [prefix]`: discovery (discovery.c). */
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

static daran_result_t command_h(daran_drive_t *drive, const daran_request_t *request)
{
    if (request->fields->count > 2u) {
        return daran_cmd_discovery(drive, request);
    }
    const char *arguments = help_text;
    for (size_t i = 0; i < COMMAND_COUNT; i++) {
        const daran_command_t *command = &commands[i];
        help_line(drive, command->word, command->word[1] != '\0' ? 2u : 1u,
                  (command->flags & DARAN_CMD_PATH) == 0u, arguments);
        while (*arguments++ != '\0') {
        }
    }
    for (size_t i = 0; i < drive->port_command_count; i++) {
        const daran_port_command_t *command = &drive->port_commands[i];
        const char *word = command->word;
        size_t len = 0;
        while (word[len] != '\0') {
            len++;
        }
        help_line(drive, word, len, true, command->help);
    }
    return DARAN_OK;
}
#endif

static daran_handler_fn const handlers[HANDLER_COUNT] = {
    [HANDLER_MOTION] = daran_cmd_motion,
#if DARAN_ENABLE_MULTI_MOTOR
    [HANDLER_MS] = daran_cmd_ms,
    [HANDLER_START] = daran_cmd_start,
#endif
    [HANDLER_R] = daran_cmd_r,
    [HANDLER_W] = daran_cmd_w,
    [HANDLER_ACTION] = daran_cmd_action,
#if DARAN_ENABLE_HELP
    [HANDLER_H] = command_h,
#endif
    [HANDLER_FEEDBACK] = daran_cmd_feedback,
    [HANDLER_POWER] = daran_cmd_power,
    [HANDLER_IDENTITY] = daran_cmd_identity,
    [HANDLER_ERRORS] = daran_cmd_errors,
};

static char lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

const daran_command_t *daran_find_command(const daran_field_t *word)
{
    if (word->len == 0u || word->len > 2u) {
        return NULL;
    }
    char first = lower(word->text[0]);
    char second = word->len == 2u ? lower(word->text[1]) : '\0';
    for (size_t i = 0; i < COMMAND_COUNT; i++) {
        if (commands[i].word[0] == first && commands[i].word[1] == second) {
            return &commands[i];
        }
    }
    return NULL;
}

daran_result_t daran_run_command(daran_drive_t *drive, const daran_request_t *request)
{
    return handlers[request->command->handler](drive, request);
}

/* The command table: the only place that knows which commands exist, their
 * field counts, handlers and help text. */
#include "internal.h"

#if DARAN_ENABLE_HELP
#define HELP(text) , text
#else
#define HELP(text)
#endif

const daran_command_t daran_commands[] = {
    /* t first: it is the command a host streams at 1 kHz. */
    {"t", 3, 5, 0, 0, daran_cmd_t HELP("id pos [vel] [bw]")},
    {"q", 3, 5, 0, 0, daran_cmd_q HELP("id pos [vel] [acc]")},
    {"p", 3, 5, 0, 0, daran_cmd_p HELP("id pos [vel_ff] [torque_ff]")},
    {"v", 3, 5, 0, 0, daran_cmd_v HELP("id vel [param] [mode]")},
    {"c", 3, 5, 0, 0, daran_cmd_c HELP("id torque [param] [mode]")},
    {"d", 7, 7, 0, 0, daran_cmd_d HELP("id pdes vdes tff kp kd")},
#if DARAN_ENABLE_MULTI_MOTOR
    {"ms", 5, 5, 0, 0, daran_cmd_ms HELP("id p1 p2 p3")},
    {"mt", 3, 3, 0, 0, daran_cmd_mt HELP("id rel")},
    {"mq", 3, 3, 0, 0, daran_cmd_mq HELP("id rel")},
    {"mp", 3, 3, 0, 0, daran_cmd_mp HELP("id rel")},
    {"mv", 2, 2, 0, 0, daran_cmd_mv HELP("id")},
    {"mc", 2, 2, 0, 0, daran_cmd_mc HELP("id")},
#endif
    {"r", 2, 3, DARAN_CMD_READ | DARAN_CMD_PATH, 0, daran_cmd_r HELP("path [id]")},
    {"w", 3, 4, DARAN_CMD_PATH, 0, daran_cmd_w HELP("path value [id]")},
    {"ss", 2, 2, 0, DARAN_ACTION_SAVE_CONFIG, daran_cmd_action HELP("id")},
    {"se", 2, 2, 0, DARAN_ACTION_ERASE_CONFIG, daran_cmd_action HELP("id")},
    {"sr", 2, 2, 0, DARAN_ACTION_REBOOT, daran_cmd_action HELP("id")},
    {"sc", 2, 2, 0, DARAN_ACTION_CLEAR_ERRORS, daran_cmd_action HELP("id")},
    {"sz", 2, 2, 0, DARAN_ACTION_SET_ZERO, daran_cmd_action HELP("id")},
    {"st", 2, 2, 0, DARAN_ACTION_ESTOP, daran_cmd_action HELP("id")},
#if DARAN_ENABLE_HELP
    {"h", 2, 2, DARAN_CMD_READ, 0, daran_cmd_h HELP("id")},
#endif
    {"f", 2, 2, DARAN_CMD_READ, 0, daran_cmd_f HELP("id")},
    {"g", 2, 2, DARAN_CMD_READ, 0, daran_cmd_g HELP("id")},
    {"i", 2, 2, DARAN_CMD_READ, 0, daran_cmd_i HELP("id")},
    {"e", 2, 2, DARAN_CMD_READ, 0, daran_cmd_e HELP("id")},
    {"u", 2, 2, 0, DARAN_ACTION_FEED_WATCHDOG, daran_cmd_action HELP("id")},
};

#define COMMAND_COUNT (sizeof daran_commands / sizeof daran_commands[0])

const uint8_t daran_command_count = (uint8_t)COMMAND_COUNT;

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
        if (daran_commands[i].word[0] == first && daran_commands[i].word[1] == second) {
            return &daran_commands[i];
        }
    }
    return NULL;
}

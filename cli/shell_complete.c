/* daran shell: Tab completion (shell.h). The first word of a line
 * completes to a command word (the tool's commands, the shell's own words,
 * the protocol's words); a property path after `r `, `w `, `get ID ` and
 * `set ID ` to the paths of that drive (its discovery, else the built-in
 * table), one dotted part at a time. One candidate is inserted; several are
 * completed to what they share, or listed when they share no more. */
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "shell.h"

#define CANDIDATES_MAX (CLI_PROPERTIES_MAX + 64u)
#define CANDIDATE_LEN (CLI_PATH_MAX + 8u)

typedef struct candidates {
    const char *word; /* what is typed so far (not NUL-terminated) */
    size_t word_len;
    char text[CANDIDATES_MAX][CANDIDATE_LEN];
    size_t count;
} candidates_t;

/* One shell per process: the candidates of the Tab being handled. */
static candidates_t found;

/* Keep `text` if it extends the word, cut after the first dot past the
 * word (one part of a path at a time), once. */
static void consider(candidates_t *c, const char *text)
{
    size_t len = strlen(text);
    if (len < c->word_len || memcmp(text, c->word, c->word_len) != 0) {
        return;
    }
    const char *dot = memchr(text + c->word_len, '.', len - c->word_len);
    if (dot != NULL) {
        len = (size_t)(dot - text) + 1;
    }
    if (len >= CANDIDATE_LEN || c->count == CANDIDATES_MAX) {
        return;
    }
    for (size_t i = 0; i < c->count; i++) {
        if (strncmp(c->text[i], text, len) == 0 && c->text[i][len] == '\0') {
            return;
        }
    }
    memcpy(c->text[c->count], text, len);
    c->text[c->count][len] = '\0';
    c->count++;
}

size_t shell_command_words(const char **out, size_t max)
{
    size_t count = 0;
    size_t tools;
    const cli_command_t *const *commands = cli_commands(&tools);
    for (size_t i = 0; i < tools; i++) {
        if (count < max) {
            out[count++] = commands[i]->name;
        }
    }
    static const char *const own[] = {"help", "quit", "exit"};
    for (size_t i = 0; i < sizeof own / sizeof own[0] && count < max; i++) {
        out[count++] = own[i];
    }
    for (int c = 0; c < (int)DARAN_CLIENT_CMD_COUNT && count < max; c++) {
        const char *word = daran_client_command_word((daran_client_command_t)c);
        /* `h` twice: help and discovery */
        if (word != NULL && (count == 0 || strcmp(out[count - 1], word) != 0)) {
            out[count++] = word;
        }
    }
    return count;
}

/* ------------------------------------------------------------ property lists */

/* Drive id's properties, loaded on first use (id 0: the built-in table).
 * *loaded: the drive was asked now (its reply, or a failure, may have
 * printed over the line). A drive that cannot tell gets the built-in table,
 * not kept, so the next Tab asks again. */
static const cli_property_list_t *properties_of(shell_t *sh, uint8_t id, bool *loaded)
{
    if (sh->properties[id] != NULL) {
        return sh->properties[id];
    }
    cli_property_list_t *list = malloc(sizeof *list);
    if (list == NULL) {
        return NULL;
    }
    if (id == 0) {
        cli_properties_builtin(NULL, list);
    } else {
        *loaded = true;
        if (sh->at_prompt) {
            fputc('\n', stdout); /* a failure's message takes a row of its own */
            fflush(stdout);
        }
        if (cli_properties_load(sh->s, id, NULL, list) != CLI_OK) {
            free(list);
            return properties_of(sh, 0, loaded);
        }
    }
    sh->properties[id] = list;
    return list;
}

void shell_properties_preload(shell_t *sh, uint8_t id)
{
    bool loaded = false;
    (void)properties_of(sh, id, &loaded);
}

void shell_properties_free(shell_t *sh)
{
    for (size_t id = 0; id <= DARAN_CLIENT_ID_MAX; id++) {
        free(sh->properties[id]);
        sh->properties[id] = NULL;
    }
}

/* The length of an `axisN.` at the start of the word (0: none); *id its N. */
static size_t axis_prefix(const char *word, size_t len, uint8_t *id)
{
    if (len < 6 || memcmp(word, "axis", 4) != 0) {
        return 0;
    }
    size_t i = 4;
    uint32_t n = 0;
    while (i < len && word[i] >= '0' && word[i] <= '9' && n <= DARAN_CLIENT_ID_MAX) {
        n = n * 10u + (uint32_t)(word[i] - '0');
        i++;
    }
    if (i == 4 || i == len || word[i] != '.' || n > DARAN_CLIENT_ID_MAX) {
        return 0;
    }
    *id = (uint8_t)n;
    return i + 1;
}

/* The paths of drive id that extend the word: with the `axisN.` typed,
 * the axis rows under it; else the system rows, the axis rows without
 * `axis0.` when `bare_axis` (get, set: the tool adds the id), and
 * `axisN.` itself. */
static void consider_paths(shell_t *sh, candidates_t *c, uint8_t id, bool bare_axis,
                           bool *loaded)
{
    uint8_t typed_id = 0;
    size_t typed = axis_prefix(c->word, c->word_len, &typed_id);
    if (typed > 0 && typed_id != 0) {
        id = typed_id;
    }
    const cli_property_list_t *list = properties_of(sh, id, loaded);
    if (list == NULL) {
        return;
    }
    char text[CANDIDATE_LEN];
    for (size_t i = 0; i < list->count; i++) {
        const char *path = list->items[i].path;
        bool axis_row = strncmp(path, "axis0.", 6) == 0;
        const char *rest = axis_row ? path + 6 : path;
        if (typed > 0) {
            if (axis_row) {
                (void)snprintf(text, sizeof text, "%.*s%s", (int)typed, c->word, rest);
                consider(c, text);
            }
        } else if (!axis_row || bare_axis) {
            consider(c, rest);
        }
    }
    if (typed == 0) {
        if (id != 0) {
            (void)snprintf(text, sizeof text, "axis%u.", id);
            consider(c, text);
        } else {
            consider(c, "axis");
        }
    }
}

/* ------------------------------------------------------------ the Tab key */

static bool is_word(const cli_field_t *field, const char *word)
{
    return field->len == strlen(word) && memcmp(field->text, word, field->len) == 0;
}

static uint8_t id_of(const cli_field_t *field)
{
    char text[8];
    uint8_t id;
    if (field->len >= sizeof text) {
        return 0;
    }
    memcpy(text, field->text, field->len);
    text[field->len] = '\0';
    return cli_parse_id(text, false, &id) ? id : 0;
}

/* What the word at this place of the line completes to. */
static void gather(shell_t *sh, const cli_field_t *before, size_t index, bool *loaded)
{
    const char *words[64];
    if (index == 0 || (index == 1 && is_word(&before[0], "help"))) {
        size_t count = shell_command_words(words, sizeof words / sizeof words[0]);
        for (size_t i = 0; i < count; i++) {
            if (index == 0 || cli_command_find(words[i]) != NULL) {
                consider(&found, words[i]);
            }
        }
        return;
    }
    uint8_t default_id = sh->default_id;
    if ((is_word(&before[0], "r") || is_word(&before[0], "w")) && index == 1) {
        consider_paths(sh, &found, default_id, false, loaded);
    } else if (is_word(&before[0], "get") && index >= 2) {
        consider_paths(sh, &found, id_of(&before[1]), true, loaded);
    } else if (is_word(&before[0], "set") && index >= 2 && index % 2 == 0) {
        consider_paths(sh, &found, id_of(&before[1]), true, loaded);
    }
}

static int by_text(const void *a, const void *b)
{
    return strcmp(a, b);
}

/* Several candidates that share no more than the word: list them in columns
 * below the line (libedit draws the line again after them). */
static void list_candidates(EditLine *el)
{
    int columns = 80;
    (void)el_get(el, EL_GETTC, "co", &columns, NULL);
    qsort(found.text, found.count, sizeof found.text[0], by_text);
    size_t widest = 0;
    for (size_t i = 0; i < found.count; i++) {
        size_t len = strlen(found.text[i]);
        widest = len > widest ? len : widest;
    }
    size_t per_row = columns > 0 ? (size_t)columns / (widest + 2) : 1;
    per_row = per_row > 0 ? per_row : 1;
    fputc('\n', stdout);
    for (size_t i = 0; i < found.count; i++) {
        bool row_end = (i + 1) % per_row == 0 || i + 1 == found.count;
        printf("%-*s%s", row_end ? 0 : (int)(widest + 2), found.text[i], row_end ? "\n" : "");
    }
    fflush(stdout);
}

unsigned char shell_complete(EditLine *el, int key)
{
    (void)key;
    shell_t *sh = NULL;
    if (el_get(el, EL_CLIENTDATA, &sh) != 0 || sh == NULL) {
        return CC_ERROR;
    }
    const LineInfo *info = el_line(el);
    size_t cursor = (size_t)(info->cursor - info->buffer);
    size_t start = cursor;
    while (start > 0 && info->buffer[start - 1] != ' ') {
        start--;
    }
    cli_field_t before[4];
    size_t index = cli_split_fields(info->buffer, start, before, 4);
    found.word = info->buffer + start;
    found.word_len = cursor - start;
    found.count = 0;
    bool loaded = false;
    gather(sh, before, index, &loaded);
    unsigned char redraw = loaded ? CC_REDISPLAY : CC_REFRESH;
    if (found.count == 0) {
        return loaded ? CC_REDISPLAY : CC_ERROR;
    }
    /* how far every candidate agrees */
    size_t shared = strlen(found.text[0]);
    for (size_t i = 1; i < found.count; i++) {
        size_t k = 0;
        while (k < shared && found.text[i][k] == found.text[0][k]) {
            k++;
        }
        shared = k;
    }
    char insert[CANDIDATE_LEN + 1];
    if (found.count == 1) {
        const char *whole = found.text[0];
        size_t len = strlen(whole);
        /* a finished word gets its blank; a part of a path (`output_shaft.`,
         * `axis`) is continued */
        bool partial = whole[len - 1] == '.' || strcmp(whole, "axis") == 0;
        (void)snprintf(insert, sizeof insert, "%s%s", whole + found.word_len, partial ? "" : " ");
    } else if (shared > found.word_len) {
        (void)snprintf(insert, sizeof insert, "%.*s", (int)(shared - found.word_len),
                       found.text[0] + found.word_len);
    } else {
        list_candidates(el);
        return CC_REDISPLAY;
    }
    if (insert[0] != '\0' && el_insertstr(el, insert) != 0) {
        return CC_ERROR;
    }
    return redraw;
}

/* The example port's set-up, checked without the transcript:
 *  - daran_set_port_commands() refuses, all or nothing, a table that reuses
 *    any vendor command word (or is malformed otherwise), and the drive
 *    keeps the table it had: `sb` still runs, the refused word stays the
 *    vendor's;
 *  - the options header's rows and omissions are in the generated table.
 * Plain C (the example takes no test framework): each failed check prints
 * its line and the program exits 1. */
#include <stdio.h>
#include <string.h>

#include "brake_port.h"
#include "daran_ascii.h"

static int failures;
#define CHECK(cond)                                                   \
    do {                                                              \
        if (!(cond)) {                                                \
            printf("%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            failures++;                                               \
        }                                                             \
    } while (0)

static daran_value_t props[DARAN_PROP_COUNT];
static int mutations;    /* set, move, action */
static int chopper_calls;
static float chopper_hz;
static char out[2048];
static size_t out_len;

static daran_result_t get(void *ctx, daran_prop_t p, daran_value_t *v)
{
    (void)ctx;
    *v = props[p];
    return DARAN_OK;
}

static daran_result_t set(void *ctx, daran_prop_t p, daran_value_t v)
{
    (void)ctx;
    props[p] = v;
    mutations++;
    return DARAN_OK;
}

static daran_result_t move(void *ctx, const daran_move_t *m)
{
    (void)ctx;
    (void)m;
    mutations++;
    return DARAN_OK;
}

static daran_result_t action(void *ctx, daran_action_t a)
{
    (void)ctx;
    (void)a;
    mutations++;
    return DARAN_OK;
}

static void write_line(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    if (len <= sizeof out - out_len) {
        memcpy(out + out_len, line, len);
        out_len += len;
    }
}

static daran_result_t chopper_set(void *ctx, float hz)
{
    (void)ctx;
    chopper_calls++;
    chopper_hz = hz;
    return DARAN_OK;
}

static daran_result_t other_handler(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)drive;
    (void)args;
    (void)ctx;
    return DARAN_OK;
}

static daran_drive_t drive;
static brake_chopper_t chopper = {chopper_set, NULL};

brake_chopper_t *brake_chopper_of(void *ctx)
{
    (void)ctx;
    return &chopper;
}

/* Run one line; the reply text (without line ends) in out. */
static daran_result_t run(const char *line)
{
    out_len = 0;
    mutations = 0;
    chopper_calls = 0;
    return daran_process_line(&drive, line, strlen(line));
}

static int replied(const char *text)
{
    size_t n = strlen(text);
    return out_len >= n + 1u && memcmp(out, text, n) == 0 &&
           (out[n] == '\r' || out[n] == '\n');
}

int main(void)
{
    static const daran_hal_t hal = {.get = get, .set = set, .move = move, .action = action,
                                    .write = write_line};
    props[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    CHECK(daran_init(&drive, &hal, NULL) == DARAN_OK);
    CHECK(brake_port_attach(&drive) == DARAN_OK);
    CHECK(run("sb 1 1000") == DARAN_OK && chopper_calls == 1 && chopper_hz == 1000.0f &&
          out_len == 0u);

    /* Every vendor word, in a table that is otherwise the example's: refused. */
    static const char *const vendor[] = {"t",  "q",  "p",  "v",  "c",  "d",  "ms", "mt", "mq",
                                         "mp", "mv", "mc", "r",  "w",  "ss", "se", "sr", "sc",
                                         "sz", "st", "h",  "f",  "g",  "i",  "e",  "u"};
    for (size_t i = 0; i < sizeof vendor / sizeof vendor[0]; i++) {
        const daran_port_command_t table[] = {
            {"sb", 1, 1, 0, other_handler, "hz"},
            {vendor[i], 0, 1, 0, other_handler, ""},
        };
        daran_result_t r = daran_set_port_commands(&drive, table, 2);
        if (r != DARAN_ERR_BAD_ARGUMENT) {
            printf("a table with the vendor word \"%s\" was accepted (%d)\n", vendor[i], (int)r);
            failures++;
        }
    }
    /* Other malformed tables: a word in upper case, too long, not letters,
     * empty, twice; no handler or help; min above max; more values than a
     * line has fields. */
    const daran_port_command_t bad[][2] = {
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"SB", 1, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"chopperhz", 1, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sb2", 1, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"", 1, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sb", 1, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sa", 1, 1, 0, NULL, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sa", 1, 1, 0, other_handler, NULL}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sa", 2, 1, 0, other_handler, ""}},
        {{"sb", 1, 1, 0, other_handler, "hz"}, {"sa", 0, 6, 0, other_handler, ""}},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        if (daran_set_port_commands(&drive, bad[i], 2) != DARAN_ERR_BAD_ARGUMENT) {
            printf("malformed table %zu was accepted\n", i);
            failures++;
        }
    }
    /* The longest word (8 letters) and 5 values are fine. */
    const daran_port_command_t longest[] = {{"abcdefgh", 0, 5, 0, other_handler, ""}};
    daran_drive_t other;
    CHECK(daran_init(&other, &hal, NULL) == DARAN_OK);
    CHECK(daran_set_port_commands(&other, longest, 1) == DARAN_OK);

    /* All or nothing: the drive still has the example's table after every
     * refusal, and the vendor's `t` is still the vendor's. */
    CHECK(run("sb 1 2500") == DARAN_OK && chopper_calls == 1 && chopper_hz == 2500.0f);
    CHECK(run("t 1 90") == DARAN_OK && mutations == 2 && chopper_calls == 0); /* move + feed */
    CHECK(run("h 1") == DARAN_OK);
    CHECK(out_len > 10u && memcmp(out + out_len - 10u, "sb id hz\r\n", 10) == 0);

    /* Validation errors reach neither the chopper nor the HAL. */
    static const struct {
        const char *line;
        daran_result_t result;
    } refused[] = {
        {"sb 1", DARAN_ERR_INVALID_FORMAT},     {"sb 1 1 2", DARAN_ERR_INVALID_FORMAT},
        {"sb 1 x", DARAN_ERR_INVALID_VALUE},    {"sb 1 nan", DARAN_ERR_INVALID_VALUE},
        {"sb 1 60000", DARAN_ERR_OUT_OF_RANGE}, {"sb 1 1.5e39", DARAN_ERR_OUT_OF_RANGE},
        {"sb 1 -1", DARAN_ERR_OUT_OF_RANGE},    {"sb 1 50000.004", DARAN_ERR_OUT_OF_RANGE},
        {"sb 64 1", DARAN_ERR_INVALID_MOTOR},   {"sb 1 1 *1", DARAN_ERR_CHECKSUM_MISMATCH},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        daran_result_t r = run(refused[i].line);
        if (r != refused[i].result || chopper_calls != 0 || mutations != 0) {
            printf("\"%s\": result %d (want %d), %d chopper calls, %d HAL calls\n",
                   refused[i].line, (int)r, (int)refused[i].result, chopper_calls, mutations);
            failures++;
        }
    }
    CHECK(run("sb 1 50000") == DARAN_OK && chopper_calls == 1 && chopper_hz == 50000.0f);
    CHECK(run("sb 1 -0") == DARAN_OK && chopper_calls == 1 && chopper_hz == 0.0f &&
          !(1.0f / chopper_hz < 0.0f)); /* off is +0 */
    CHECK(run("sb 2 100") == DARAN_OK && chopper_calls == 0 && out_len == 0u);

    /* The options header's rows are in the table; the omitted ones are not. */
    CHECK(DARAN_PROP_BRAKE_TEMPERATURE == DARAN_PROP_BRAKE_CHOPPER_HZ + 1);
    CHECK(DARAN_PROP_COUNT == DARAN_PROP_BRAKE_TEMPERATURE + 1);
    props[DARAN_PROP_BRAKE_TEMPERATURE].f32 = 31.5f;
    CHECK(run("r axis0.brake.temperature") == DARAN_OK && replied("31.5"));
    CHECK(run("w axis0.brake.temperature 1") == DARAN_ERR_READ_ONLY && mutations == 0);
    CHECK(run("w axis1.brake.chopper_hz 100") == DARAN_OK && mutations == 1 &&
          props[DARAN_PROP_BRAKE_CHOPPER_HZ].f32 == 100.0f);
    CHECK(run("w axis1.brake.chopper_hz -1") == DARAN_ERR_OUT_OF_RANGE && mutations == 0);
    static const char *const omitted[] = {"encoder.spi_buff_0", "encoder.spi_buff_1",
                                          "encoder.spi_buff_2", "encoder.pos_abs",
                                          "encoder.turn_abs"};
    for (size_t i = 0; i < sizeof omitted / sizeof omitted[0]; i++) {
        char line[64];
        snprintf(line, sizeof line, "r axis0.%s", omitted[i]);
        CHECK(run(line) == DARAN_ERR_INVALID_PROPERTY && replied("error: invalid property"));
    }
    CHECK(run("r axis0.encoder.pos_estimate") == DARAN_OK); /* its neighbours stay */

    if (failures != 0) {
        printf("test_port_brake: %d failures\n", failures);
        return 1;
    }
    printf("test_port_brake: all checks passed\n");
    return 0;
}

/* Unit tests of the public API itself: daran_init argument checks, reset,
 * daran_version, daran_result_phrase, and the order of the property list
 * (the order discovery lists it in; lookup is a perfect hash and does not
 * depend on it). */
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"
#include "stub_hal.h"

void setUp(void)
{
}

void tearDown(void)
{
}

/* The HAL functions, for tables of HALs with one of them missing. */
#define ok_get (daran_stub_hal.get)
#define ok_set (daran_stub_hal.set)
#define ok_move (daran_stub_hal.move)
#define ok_action (daran_stub_hal.action)

#define ok_write daran_stub_drop_reply

static daran_drive_t api_drive;

static void test_init_accepts_a_complete_hal_without_its_optional_members(void)
{
    /* forward, now_ms, can_send and can_system left NULL */
    const daran_hal_t hal = {ok_get, ok_set, ok_move, ok_action, ok_write, NULL, NULL, NULL, NULL};
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_init(&api_drive, &hal, NULL));
}

static void test_init_rejects_a_null_drive_or_hal(void)
{
    const daran_hal_t hal = {ok_get, ok_set, ok_move, ok_action, ok_write, NULL, NULL, NULL, NULL};
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(NULL, &hal, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, NULL, NULL));
}

static void test_init_rejects_a_hal_without_a_required_member(void)
{
    const daran_hal_t no_get = {NULL, ok_set, ok_move, ok_action, ok_write, NULL, NULL, NULL, NULL};
    const daran_hal_t no_set = {ok_get, NULL, ok_move, ok_action, ok_write, NULL, NULL, NULL, NULL};
    const daran_hal_t no_move = {ok_get, ok_set, NULL, ok_action, ok_write, NULL, NULL, NULL, NULL};
    const daran_hal_t no_action = {ok_get, ok_set, ok_move, NULL, ok_write, NULL, NULL, NULL, NULL};
    const daran_hal_t no_write = {ok_get, ok_set, ok_move, ok_action, NULL, NULL, NULL, NULL, NULL};
    const daran_hal_t none = {NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &no_get, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &no_set, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &no_move, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &no_action, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &no_write, NULL));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_init(&api_drive, &none, NULL));
}

static void test_init_resets_ring_partial_line_and_preset(void)
{
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    TEST_ASSERT_EQUAL_INT64(2, daran_rx_write(&m->drive, "f ", 2));
    (void)daran_poll(&m->drive);
    TEST_ASSERT_EQUAL_INT64(1, daran_rx_write(&m->drive, "g", 1));
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_init(&m->drive, &m->hal, m));
    mock_clear(m);
    mock_send_raw(m, "f 1\n");
    ASSERT_REPLY(m, "0 0\n");
    ASSERT_ERROR(m, "mt 1 0", "no preset");
    TEST_ASSERT_EQUAL_INT64(0, daran_rx_dropped(&m->drive));
}

static void test_poll_with_nothing_queued_processes_nothing(void)
{
    mock_t *m = mock_new();
    mock_clear(m);
    TEST_ASSERT_EQUAL_INT64(0, daran_poll(&m->drive));
    TEST_ASSERT_EQUAL_INT64(0, daran_rx_write(&m->drive, "", 0));
    TEST_ASSERT_EQUAL_INT64(0, daran_poll(&m->drive));
    ASSERT_REPLY(m, "");
}

static void test_version_is_major_minor_patch(void)
{
    const char *v = daran_version();
    TEST_ASSERT_NOT_NULL(v);
    TEST_ASSERT_TRUE(strlen(v) >= 5);
    int dots = 0;
    bool digit_before = false;
    for (const char *c = v; *c; c++) {
        if (*c == '.') {
            TEST_ASSERT_TRUE(digit_before);
            digit_before = false;
            dots++;
        } else {
            TEST_ASSERT_TRUE(*c >= '0' && *c <= '9');
            digit_before = true;
        }
    }
    TEST_ASSERT_EQUAL_INT64(2, dots);
    TEST_ASSERT_TRUE(digit_before);
}

static void test_result_phrases_match_the_protocol(void)
{
    static const char *const want[] = {
        "ok", "unknown command", "invalid command format", "invalid motor", "invalid value",
        "value out of range", "invalid mode", "invalid property", "read only property",
        "invalid checksum", "checksum mismatch", "line too long", "invalid character",
        "no preset", "trajectory infeasible", "estop active", "motor fault", "motor idle",
        "updating", "not idle", "no update", "bad image",
        "no reply", "bus error", "not bridged",
    };
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, sizeof want / sizeof want[0]);
    for (int r = 0; r < DARAN_ERR_BAD_ARGUMENT; r++) {
        TEST_ASSERT_EQUAL_STRING(want[r], daran_result_phrase((daran_result_t)r));
    }
    const char *bad = daran_result_phrase(DARAN_ERR_BAD_ARGUMENT);
    TEST_ASSERT_NOT_NULL(bad);
    TEST_ASSERT_TRUE(bad[0] != '\0');
}

static void test_result_phrase_of_an_unknown_value_is_motor_fault(void)
{
    TEST_ASSERT_EQUAL_STRING("motor fault", daran_result_phrase(DARAN_RESULT_COUNT));
    TEST_ASSERT_EQUAL_STRING("motor fault", daran_result_phrase((daran_result_t)1000));
    TEST_ASSERT_EQUAL_STRING("motor fault", daran_result_phrase((daran_result_t)-1));
}

static void test_no_result_phrase_contains_a_digit(void)
{
    for (int r = -1; r <= DARAN_RESULT_COUNT; r++) {
        const char *p = daran_result_phrase((daran_result_t)r);
        TEST_ASSERT_NOT_NULL(p);
        for (; *p; p++) {
            TEST_ASSERT_FALSE(*p >= '0' && *p <= '9');
        }
    }
}

enum { SCOPE_SYSTEM, SCOPE_AXIS };

typedef struct sorted_row {
    int scope;
    const char *path;
} sorted_row_t;

static const sorted_row_t sorted_rows[] = {
#define ROW(id, path, scope, type, access, range, unit, can) {SCOPE_##scope, path},
    DARAN_PROPERTY_LIST(ROW)
#undef ROW
};

/* The path as a host writes it: "axis0." in front of an axis path. */
static void host_path(char *buf, size_t size, const sorted_row_t *row)
{
    snprintf(buf, size, "%s%s", row->scope == SCOPE_AXIS ? "axis0." : "", row->path);
}

static void test_property_list_is_sorted_by_the_path_a_host_writes(void)
{
    size_t n = sizeof sorted_rows / sizeof sorted_rows[0];
    for (size_t i = 1; i < n; i++) {
        char a[160], b[160];
        host_path(a, sizeof a, &sorted_rows[i - 1]);
        host_path(b, sizeof b, &sorted_rows[i]);
        if (strcmp(a, b) >= 0) {
            TEST_FAIL_MESSAGE_F("\"%s\" must come after \"%s\"", b, a);
        }
    }
}

static void test_property_list_and_ids_have_165_rows(void)
{
    TEST_ASSERT_EQUAL_INT64(165, sizeof sorted_rows / sizeof sorted_rows[0]);
    TEST_ASSERT_EQUAL_INT64(165, DARAN_PROP_COUNT);
}

static void test_value_union_holds_every_type_in_64_bits(void)
{
    daran_value_t v;
    TEST_ASSERT_EQUAL_INT64(sizeof(uint64_t), sizeof v);
    v.s32 = -1;
    TEST_ASSERT_TRUE(v.s32 == -1);
    v.u64 = UINT64_MAX;
    TEST_ASSERT_TRUE(v.u64 == UINT64_MAX);
}

static void test_property_paths_are_printable_and_fit_a_line(void)
{
    size_t n = sizeof sorted_rows / sizeof sorted_rows[0];
    for (size_t i = 0; i < n; i++) {
        const char *p = sorted_rows[i].path;
        /* "w axis63.<path> <value>" must fit a line */
        TEST_ASSERT_TRUE(strlen(p) + 30 < DARAN_LINE_MAX);
        for (; *p; p++) {
            TEST_ASSERT_TRUE(*p > ' ' && *p < 0x7f && *p != '*');
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_accepts_a_complete_hal_without_its_optional_members);
    RUN_TEST(test_init_rejects_a_null_drive_or_hal);
    RUN_TEST(test_init_rejects_a_hal_without_a_required_member);
    RUN_TEST(test_init_resets_ring_partial_line_and_preset);
    RUN_TEST(test_poll_with_nothing_queued_processes_nothing);
    RUN_TEST(test_version_is_major_minor_patch);
    RUN_TEST(test_result_phrases_match_the_protocol);
    RUN_TEST(test_result_phrase_of_an_unknown_value_is_motor_fault);
    RUN_TEST(test_no_result_phrase_contains_a_digit);
    RUN_TEST(test_property_list_is_sorted_by_the_path_a_host_writes);
    RUN_TEST(test_property_list_and_ids_have_165_rows);
    RUN_TEST(test_value_union_holds_every_type_in_64_bits);
    RUN_TEST(test_property_paths_are_printable_and_fit_a_line);
    return UNITY_END();
}

/* Unit tests of the public API itself: daran_init argument checks, reset,
 * daran_version, daran_result_phrase, and the order of the property list
 * (the order discovery lists it in; lookup is a perfect hash and does not
 * depend on it). */
#include <stdio.h>
#include <string.h>

#include "mock_hal.h"

static daran_result_t ok_get(void *c, daran_prop_t p, daran_value_t *o)
{
    (void)c;
    (void)p;
    o->u64 = 0;
    return DARAN_OK;
}
static daran_result_t ok_set(void *c, daran_prop_t p, daran_value_t v)
{
    (void)c;
    (void)p;
    (void)v;
    return DARAN_OK;
}
static daran_result_t ok_move(void *c, const daran_move_t *m)
{
    (void)c;
    (void)m;
    return DARAN_OK;
}
static daran_result_t ok_action(void *c, daran_action_t a)
{
    (void)c;
    (void)a;
    return DARAN_OK;
}
static void ok_write(void *c, const char *l, size_t n)
{
    (void)c;
    (void)l;
    (void)n;
}

static daran_drive_t api_drive;

static void test_init_accepts_a_complete_hal(void **state)
{
    (void)state;
    const daran_hal_t hal = {ok_get, ok_set, ok_move, ok_action};
    assert_int_equal(daran_init(&api_drive, &hal, NULL, ok_write, NULL), DARAN_OK);
}

static void test_init_rejects_a_null_drive_hal_or_write(void **state)
{
    (void)state;
    const daran_hal_t hal = {ok_get, ok_set, ok_move, ok_action};
    assert_int_equal(daran_init(NULL, &hal, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, NULL, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, &hal, NULL, NULL, NULL), DARAN_ERR_BAD_ARGUMENT);
}

static void test_init_rejects_a_hal_with_a_null_member(void **state)
{
    (void)state;
    const daran_hal_t no_get = {NULL, ok_set, ok_move, ok_action};
    const daran_hal_t no_set = {ok_get, NULL, ok_move, ok_action};
    const daran_hal_t no_move = {ok_get, ok_set, NULL, ok_action};
    const daran_hal_t no_action = {ok_get, ok_set, ok_move, NULL};
    const daran_hal_t none = {NULL, NULL, NULL, NULL};
    assert_int_equal(daran_init(&api_drive, &no_get, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, &no_set, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, &no_move, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, &no_action, NULL, ok_write, NULL),
                     DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init(&api_drive, &none, NULL, ok_write, NULL), DARAN_ERR_BAD_ARGUMENT);
}

static void test_init_resets_ring_partial_line_and_preset(void **state)
{
    (void)state;
    SKIP_IF_NO_MULTI();
    mock_t *m = mock_new();
    ASSERT_SILENT(m, "ms 1 10 0 5");
    assert_int_equal(daran_rx_write(&m->drive, "f ", 2), 2);
    (void)daran_poll(&m->drive);
    assert_int_equal(daran_rx_write(&m->drive, "g", 1), 1);
    assert_int_equal(daran_init(&m->drive, &mock_hal_fns, m, mock_write, m), DARAN_OK);
    mock_clear(m);
    mock_send_raw(m, "f 1\n");
    ASSERT_REPLY(m, "0 0\n");
    ASSERT_ERROR(m, "mt 1 0", "no preset");
    assert_int_equal(daran_rx_dropped(&m->drive), 0);
}

static void test_poll_with_nothing_queued_processes_nothing(void **state)
{
    (void)state;
    mock_t *m = mock_new();
    mock_clear(m);
    assert_int_equal(daran_poll(&m->drive), 0);
    assert_int_equal(daran_rx_write(&m->drive, "", 0), 0);
    assert_int_equal(daran_poll(&m->drive), 0);
    ASSERT_REPLY(m, "");
}

static void test_version_is_major_minor_patch(void **state)
{
    (void)state;
    const char *v = daran_version();
    assert_non_null(v);
    assert_true(strlen(v) >= 5);
    int dots = 0;
    bool digit_before = false;
    for (const char *c = v; *c; c++) {
        if (*c == '.') {
            assert_true(digit_before);
            digit_before = false;
            dots++;
        } else {
            assert_true(*c >= '0' && *c <= '9');
            digit_before = true;
        }
    }
    assert_int_equal(dots, 2);
    assert_true(digit_before);
}

static void test_result_phrases_match_the_protocol(void **state)
{
    (void)state;
    static const char *const want[] = {
        "ok", "unknown command", "invalid command format", "invalid motor", "invalid value",
        "value out of range", "invalid mode", "invalid property", "read only property",
        "invalid checksum", "checksum mismatch", "line too long", "invalid character",
        "no preset", "trajectory infeasible", "estop active", "motor fault", "motor idle",
    };
    assert_int_equal(sizeof want / sizeof want[0], DARAN_ERR_BAD_ARGUMENT);
    for (int r = 0; r < DARAN_ERR_BAD_ARGUMENT; r++)
        assert_string_equal(daran_result_phrase((daran_result_t)r), want[r]);
    const char *bad = daran_result_phrase(DARAN_ERR_BAD_ARGUMENT);
    assert_non_null(bad);
    assert_true(bad[0] != '\0');
}

static void test_result_phrase_of_an_unknown_value_is_motor_fault(void **state)
{
    (void)state;
    assert_string_equal(daran_result_phrase(DARAN_RESULT_COUNT), "motor fault");
    assert_string_equal(daran_result_phrase((daran_result_t)1000), "motor fault");
    assert_string_equal(daran_result_phrase((daran_result_t)-1), "motor fault");
}

static void test_no_result_phrase_contains_a_digit(void **state)
{
    (void)state;
    for (int r = -1; r <= DARAN_RESULT_COUNT; r++) {
        const char *p = daran_result_phrase((daran_result_t)r);
        assert_non_null(p);
        for (; *p; p++)
            assert_false(*p >= '0' && *p <= '9');
    }
}

enum { SCOPE_SYSTEM, SCOPE_AXIS };

typedef struct sorted_row {
    int scope;
    const char *path;
} sorted_row_t;

static const sorted_row_t sorted_rows[] = {
#define ROW(id, path, scope, type, access, range, unit) {SCOPE_##scope, path},
    DARAN_PROPERTY_LIST(ROW)
#undef ROW
};

/* The path as a host writes it: "axis0." in front of an axis path. */
static void host_path(char *buf, size_t size, const sorted_row_t *row)
{
    snprintf(buf, size, "%s%s", row->scope == SCOPE_AXIS ? "axis0." : "", row->path);
}

static void test_property_list_is_sorted_by_the_path_a_host_writes(void **state)
{
    (void)state;
    size_t n = sizeof sorted_rows / sizeof sorted_rows[0];
    for (size_t i = 1; i < n; i++) {
        char a[160], b[160];
        host_path(a, sizeof a, &sorted_rows[i - 1]);
        host_path(b, sizeof b, &sorted_rows[i]);
        if (strcmp(a, b) >= 0)
            fail_msg("\"%s\" must come after \"%s\"", b, a);
    }
}

static void test_property_list_and_ids_have_163_rows(void **state)
{
    (void)state;
    assert_int_equal(sizeof sorted_rows / sizeof sorted_rows[0], 163);
    assert_int_equal(DARAN_PROP_COUNT, 163);
}

static void test_value_union_holds_every_type_in_64_bits(void **state)
{
    (void)state;
    daran_value_t v;
    assert_int_equal(sizeof v, sizeof(uint64_t));
    v.s32 = -1;
    assert_true(v.s32 == -1);
    v.u64 = UINT64_MAX;
    assert_true(v.u64 == UINT64_MAX);
}

static void test_property_paths_are_printable_and_fit_a_line(void **state)
{
    (void)state;
    size_t n = sizeof sorted_rows / sizeof sorted_rows[0];
    for (size_t i = 0; i < n; i++) {
        const char *p = sorted_rows[i].path;
        /* "w axis63.<path> <value>" must fit a line */
        assert_true(strlen(p) + 30 < DARAN_LINE_MAX);
        for (; *p; p++)
            assert_true(*p > ' ' && *p < 0x7f && *p != '*');
    }
}

static void test_drive_size_is_a_compile_time_constant(void **state)
{
    (void)state;
    static daran_drive_t drives[4]; /* the caller owns the memory, any count */
    assert_true(sizeof drives == 4 * sizeof(daran_drive_t));
    assert_true(sizeof(daran_drive_t) >= DARAN_LINE_MAX + DARAN_RX_RING_SIZE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_init_accepts_a_complete_hal),
        cmocka_unit_test(test_init_rejects_a_null_drive_hal_or_write),
        cmocka_unit_test(test_init_rejects_a_hal_with_a_null_member),
        cmocka_unit_test(test_init_resets_ring_partial_line_and_preset),
        cmocka_unit_test(test_poll_with_nothing_queued_processes_nothing),
        cmocka_unit_test(test_version_is_major_minor_patch),
        cmocka_unit_test(test_result_phrases_match_the_protocol),
        cmocka_unit_test(test_result_phrase_of_an_unknown_value_is_motor_fault),
        cmocka_unit_test(test_no_result_phrase_contains_a_digit),
        cmocka_unit_test(test_property_list_is_sorted_by_the_path_a_host_writes),
        cmocka_unit_test(test_property_list_and_ids_have_163_rows),
        cmocka_unit_test(test_value_union_holds_every_type_in_64_bits),
        cmocka_unit_test(test_property_paths_are_printable_and_fit_a_line),
        cmocka_unit_test(test_drive_size_is_a_compile_time_constant),
    };
    return cmocka_run_group_tests_name("api", tests, NULL, NULL);
}

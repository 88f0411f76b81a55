/* The minimal port of docs/porting.md does what the document says. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "minimal_hal.h"

typedef struct link {
    char replies[512];
    size_t len;
} link_t;

static void write_line(void *ctx, const char *line, size_t len)
{
    link_t *link = ctx;
    assert_true(link->len + len < sizeof link->replies);
    memcpy(link->replies + link->len, line, len);
    link->len += len;
    link->replies[link->len] = '\0';
}

typedef struct fixture {
    minimal_drive_t axis;
    daran_drive_t drive;
    link_t link;
} fixture_t;

static fixture_t fixture;

static int setup(void **state)
{
    memset(&fixture, 0, sizeof fixture);
    minimal_drive_init(&fixture.axis);
    assert_int_equal(daran_init(&fixture.drive, &minimal_hal, &fixture.axis, write_line, &fixture.link),
                     DARAN_OK);
    *state = &fixture;
    return 0;
}

/* What an interrupt would do byte by byte, then one pass of the main loop. */
static const char *send(fixture_t *f, const char *text)
{
    f->link.len = 0;
    f->link.replies[0] = '\0';
    for (const char *c = text; *c != '\0'; c++) {
        assert_true(daran_rx_byte(&f->drive, (uint8_t)*c));
    }
    (void)daran_poll(&f->drive);
    return f->link.replies;
}

static void test_a_t_line_reaches_the_control_loop_mailbox(void **state)
{
    fixture_t *f = *state;
    daran_move_t move;
    assert_string_equal(send(f, "t 1 10 0 25\n"), "");
    assert_true(minimal_drive_take_move(&f->axis, &move));
    assert_int_equal(move.kind, DARAN_MOVE_FILTERED_POSITION);
    assert_true(move.pos_deg == 10.0f);
    assert_true(move.rate == 25.0f);
    assert_false(minimal_drive_take_move(&f->axis, &move));
}

static void test_targets_read_back_at_once(void **state)
{
    fixture_t *f = *state;
    assert_string_equal(send(f, "p 1 12.25 5 0.3\n"), "");
    assert_string_equal(send(f, "r axis1.output_shaft.input_pos\n"), "12.25\n");
    assert_string_equal(send(f, "r axis1.output_shaft.input_torque\n"), "0.3\n");
}

static void test_estop_blocks_motion_until_cleared_and_closed(void **state)
{
    fixture_t *f = *state;
    assert_string_equal(send(f, "st 1\n"), "");
    assert_string_equal(send(f, "t 1 5\n"), "error: estop active\n");
    assert_string_equal(send(f, "sc 1\n"), "");
    assert_string_equal(send(f, "t 1 5\n"), "error: motor idle\n");
    assert_string_equal(send(f, "w axis1.requested_state 8\n"), "");
    assert_string_equal(send(f, "t 1 5\n"), "");
}

static void test_save_reaches_the_flash_driver(void **state)
{
    fixture_t *f = *state;
    assert_string_equal(send(f, "ss 1*17\n"), "");
    assert_int_equal(f->axis.saved_config_writes, 1);
}

static void test_queries_answer_from_the_property_store(void **state)
{
    fixture_t *f = *state;
    assert_string_equal(send(f, "g 1\n"), "24 0\n");
    assert_string_equal(send(f, "i 1\n"), "100 1 0\n");
    assert_string_equal(send(f, "f 1 *87\n"), "0 0 *0\n");
}

static void test_an_instance_of_another_size_is_refused(void **state)
{
    fixture_t *f = *state;
    /* What a caller compiled with other DARAN_* size options would pass. */
    assert_int_equal(daran_init_sized(&f->drive, sizeof(daran_drive_t) - 4u, &minimal_hal, &f->axis,
                                      write_line, &f->link),
                     DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_init_sized(&f->drive, sizeof(daran_drive_t), &minimal_hal, &f->axis,
                                      write_line, &f->link),
                     DARAN_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_a_t_line_reaches_the_control_loop_mailbox, setup),
        cmocka_unit_test_setup(test_targets_read_back_at_once, setup),
        cmocka_unit_test_setup(test_estop_blocks_motion_until_cleared_and_closed, setup),
        cmocka_unit_test_setup(test_save_reaches_the_flash_driver, setup),
        cmocka_unit_test_setup(test_queries_answer_from_the_property_store, setup),
        cmocka_unit_test_setup(test_an_instance_of_another_size_is_refused, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

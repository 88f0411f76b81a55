/* The minimal port of docs/porting.md does what the document says. */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "unity.h"

#include "minimal_hal.h"

/* Every reply line ends in the configured line end: "\r\n" by default
 * (DARAN_REPLY_CRLF, include/daran_config.h). */
#if DARAN_REPLY_CRLF
#define EOL "\r\n"
#else
#define EOL "\n"
#endif

typedef struct link {
    char replies[512];
    size_t len;
} link_t;

static void write_line(void *ctx, const char *line, size_t len);

/* The port's drive, the core's instance bound to it and the UART's other
 * end: fresh for every test (setUp()). The fixture is the port's context:
 * its first member is the drive minimal's functions take. */
typedef struct fixture {
    minimal_drive_t axis;
    daran_drive_t drive;
    link_t link;
} fixture_t;

static const daran_hal_t port = {MINIMAL_HAL_FUNCTIONS, .write = write_line};

static void write_line(void *ctx, const char *line, size_t len)
{
    link_t *link = &((fixture_t *)ctx)->link;
    TEST_ASSERT_TRUE(link->len + len < sizeof link->replies);
    memcpy(link->replies + link->len, line, len);
    link->len += len;
    link->replies[link->len] = '\0';
}

static fixture_t fixture;

void setUp(void)
{
    memset(&fixture, 0, sizeof fixture);
    minimal_drive_init(&fixture.axis);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_init(&fixture.drive, &port, &fixture));
}

void tearDown(void)
{
}

/* What an interrupt would do byte by byte, then one pass of the main loop;
 * the replies. A macro so that a failure points at the test's line. */
static const char *send_at(int line, const char *text)
{
    fixture.link.len = 0;
    fixture.link.replies[0] = '\0';
    for (const char *c = text; *c != '\0'; c++) {
        UNITY_TEST_ASSERT(daran_rx_byte(&fixture.drive, (uint8_t)*c), line,
                          "the receive ring refused a byte");
    }
    (void)daran_poll(&fixture.drive);
    return fixture.link.replies;
}
#define SEND(text) send_at(__LINE__, (text))

static void test_a_t_line_reaches_the_control_loop_mailbox(void)
{
    daran_move_t move;
    TEST_ASSERT_EQUAL_STRING("", SEND("t 1 10 0 25\n"));
    TEST_ASSERT_TRUE(minimal_drive_take_move(&fixture.axis, &move));
    TEST_ASSERT_EQUAL_INT64(DARAN_MOVE_FILTERED_POSITION, move.kind);
    TEST_ASSERT_TRUE(move.pos_deg == 10.0f);
    TEST_ASSERT_TRUE(move.rate == 25.0f);
    TEST_ASSERT_FALSE(minimal_drive_take_move(&fixture.axis, &move));
}

static void test_targets_read_back_at_once(void)
{
    TEST_ASSERT_EQUAL_STRING("", SEND("p 1 12.25 5 0.3\n"));
    TEST_ASSERT_EQUAL_STRING("12.25" EOL, SEND("r axis1.output_shaft.input_pos\n"));
    TEST_ASSERT_EQUAL_STRING("0.3" EOL, SEND("r axis1.output_shaft.input_torque\n"));
}

static void test_estop_blocks_motion_until_cleared_and_closed(void)
{
    TEST_ASSERT_EQUAL_STRING("", SEND("st 1\n"));
    TEST_ASSERT_EQUAL_STRING("error: estop active" EOL, SEND("t 1 5\n"));
    TEST_ASSERT_EQUAL_STRING("", SEND("sc 1\n"));
    TEST_ASSERT_EQUAL_STRING("error: motor idle" EOL, SEND("t 1 5\n"));
    TEST_ASSERT_EQUAL_STRING("", SEND("w axis1.requested_state 8\n"));
    TEST_ASSERT_EQUAL_STRING("", SEND("t 1 5\n"));
}

static void test_save_reaches_the_flash_driver(void)
{
    TEST_ASSERT_EQUAL_STRING("", SEND("ss 1*17\n"));
    TEST_ASSERT_EQUAL_INT64(1, fixture.axis.saved_config_writes);
}

static void test_queries_answer_from_the_property_store(void)
{
    TEST_ASSERT_EQUAL_STRING("24 0" EOL, SEND("g 1\n"));
    TEST_ASSERT_EQUAL_STRING("100 1 0" EOL, SEND("i 1\n"));
    /* a checksummed request gets a checksummed reply, the line end after it */
    TEST_ASSERT_EQUAL_STRING("0 0 *0" EOL, SEND("f 1 *87\n"));
}

static void test_an_instance_of_another_size_is_refused(void)
{
    /* What a caller compiled with other DARAN_* size options would pass. */
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BUILD_MISMATCH,
                            daran_init_checked(&fixture.drive,
                                               DARAN_BUILD_CHECK(daran_drive_t) ^ (uint32_t)sizeof(daran_drive_t) ^
                                                   (uint32_t)(sizeof(daran_drive_t) - 4u),
                                               &port, &fixture));
    TEST_ASSERT_EQUAL_INT64(DARAN_OK,
                            daran_init_checked(&fixture.drive,
                                               DARAN_BUILD_CHECK(daran_drive_t),
                                               &port, &fixture));
}

static void test_a_program_with_another_property_table_is_refused(void)
{
    /* What a caller compiled with another options header (its own rows, an
     * omission, another option) would pass: the same size, another table. */
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BUILD_MISMATCH,
                            daran_init_checked(&fixture.drive,
                                               DARAN_BUILD_CHECK(daran_drive_t) ^ 1u,
                                               &port, &fixture));
    TEST_ASSERT_EQUAL_STRING("build mismatch", daran_result_phrase(DARAN_ERR_BUILD_MISMATCH));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_t_line_reaches_the_control_loop_mailbox);
    RUN_TEST(test_targets_read_back_at_once);
    RUN_TEST(test_estop_blocks_motion_until_cleared_and_closed);
    RUN_TEST(test_save_reaches_the_flash_driver);
    RUN_TEST(test_queries_answer_from_the_property_store);
    RUN_TEST(test_an_instance_of_another_size_is_refused);
    RUN_TEST(test_a_program_with_another_property_table_is_refused);
    return UNITY_END();
}

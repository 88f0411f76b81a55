/* A command added by one protocol row (tests/config/extra_command.h: `ec id
 * value`, a query without a CAN form) and its handler, below. The drive
 * runs it, `h` lists it, the client builds it and knows its reply, and a
 * gateway answers `not bridged` for it when it is addressed to a drive
 * behind it, putting nothing on the bus; so does a port command. */
#include <string.h>

#include "daran_ascii.h"
#include "daran_client.h"
#include "handlers.h"
#include "minimal_hal.h"
#include "reply.h"
#include "unity.h"

/* The handler the row names: answers `ec <value>`. */
daran_result_t daran_cmd_test_echo(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_test_echo(daran_drive_t *drive, const daran_request_t *request)
{
    float value;
    daran_field_t field = daran_field_at(request, 2);
    daran_result_t result = daran_field_f32(&field, &value);
    if (result != DARAN_OK) {
        return result;
    }
    daran_reply_begin(drive);
    daran_reply_text(drive, "ec ", 3);
    daran_reply_f32(drive, value);
    daran_reply_end(drive);
    return DARAN_OK;
}

#if DARAN_ENABLE_CAN_BRIDGE && DARAN_ENABLE_PORT_COMMANDS

typedef struct node {
    minimal_drive_t hal;
    daran_drive_t drive;
    daran_can_t can;
} node_t;

static node_t gateway;
static node_t remote;
static daran_can_bridge_t bridge;
static size_t frames_sent;
static char out[2048];
static size_t out_len;
static uint32_t port_command_runs;

static uint32_t now_ms(void *ctx)
{
    (void)ctx;
    return 1000;
}

static bool bus_send(void *ctx, const daran_can_frame_t *frame)
{
    frames_sent++;
    node_t *other = ctx == &gateway ? &remote : &gateway;
    (void)daran_can_receive(&other->can, frame);
    return true;
}

static void gateway_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    TEST_ASSERT_TRUE(out_len + len < sizeof out);
    memcpy(out + out_len, line, len);
    out_len += len;
    out[out_len] = '\0';
}

static void remote_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
    TEST_FAIL_MESSAGE("the remote drive answered on its ASCII link");
}

/* A node is its ports' context: its first member is the drive minimal's
 * functions take. */
static const daran_hal_t gateway_port = {MINIMAL_HAL_FUNCTIONS, .write = gateway_write,
                                         .now_ms = now_ms, .can_send = bus_send};
static const daran_hal_t remote_port = {MINIMAL_HAL_FUNCTIONS, .write = remote_write,
                                        .now_ms = now_ms, .can_send = bus_send};

/* A port command: `zz id`, counted when it runs. */
static daran_result_t run_zz(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    (void)drive;
    (void)args;
    (void)ctx;
    port_command_runs++;
    return DARAN_OK;
}
static const daran_port_command_t port_commands[] = {{"zz", 0, 0, 0, run_zz, ""}};

static void start(node_t *node, uint32_t id, const daran_hal_t *port)
{
    memset(node, 0, sizeof *node);
    minimal_drive_init(&node->hal);
    node->hal.props[DARAN_PROP_CAN_NODE_ID].u32 = id;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&node->drive, port, node));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&node->can, &node->drive));
}

void setUp(void)
{
    frames_sent = 0;
    out_len = 0;
    out[0] = '\0';
    port_command_runs = 0;
    start(&gateway, 1, &gateway_port);
    start(&remote, 2, &remote_port);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_set_port_commands(&gateway.drive, port_commands, 1));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_bridge_init(&bridge, &gateway.can));
}

void tearDown(void)
{
}

static void line(const char *text)
{
    out_len = 0;
    out[0] = '\0';
    TEST_ASSERT_EQUAL_UINT64(strlen(text), daran_rx_write(&gateway.drive, text, strlen(text)));
    TEST_ASSERT_TRUE(daran_rx_byte(&gateway.drive, '\n'));
    for (int round = 0; round < 4; round++) {
        (void)daran_poll(&gateway.drive);
        (void)daran_can_poll(&gateway.can);
        (void)daran_can_poll(&remote.can);
    }
}

static void test_the_drive_runs_the_added_row(void)
{
    line("ec 1 2.5");
    TEST_ASSERT_EQUAL_STRING("ec 2.5\r\n", out);
    line("ec 0 -1"); /* a query: answered for id 0 too */
    TEST_ASSERT_EQUAL_STRING("ec -1\r\n", out);
    line("ec 1");
    TEST_ASSERT_EQUAL_STRING("error: invalid command format\r\n", out);
    TEST_ASSERT_EQUAL_UINT64(0, frames_sent);
}

static void test_h_lists_the_added_row(void)
{
    line("h 1");
    TEST_ASSERT_NOT_NULL(strstr(out, "\r\nec id value\r\n"));
}

static void test_a_row_without_a_can_form_is_not_bridged_and_sends_nothing(void)
{
    line("ec 2 2.5");
    TEST_ASSERT_EQUAL_STRING("error: not bridged\r\n", out);
    TEST_ASSERT_EQUAL_UINT64(0, frames_sent);
}

static void test_a_port_command_for_another_drive_is_not_bridged_and_sends_nothing(void)
{
    line("zz 2");
    TEST_ASSERT_EQUAL_STRING("error: not bridged\r\n", out);
    TEST_ASSERT_EQUAL_UINT64(0, frames_sent);
    TEST_ASSERT_EQUAL_UINT32(0, port_command_runs);
    line("zz 1");
    TEST_ASSERT_EQUAL_UINT32(1, port_command_runs);
}

static void test_the_client_builds_the_added_row_and_knows_its_reply(void)
{
    TEST_ASSERT_EQUAL_STRING("ec", daran_client_command_word(DARAN_CLIENT_CMD_EC));
    TEST_ASSERT_EQUAL_INT(DARAN_CLIENT_REPLY_ONE_LINE, daran_client_reply_shape(DARAN_CLIENT_CMD_EC));
    TEST_ASSERT_TRUE(daran_client_may_retry(DARAN_CLIENT_CMD_EC));
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_EC, .id = 2, .value_count = 1,
                                      .values = {1.5f}};
    char text[DARAN_CLIENT_LINE_MAX];
    size_t len = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_client_build(&request, false, text, sizeof text, &len));
    TEST_ASSERT_EQUAL_STRING_LEN("ec 2 1.5\n", text, len);
    request.value_count = 0;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_client_build(&request, false, text, sizeof text, &len));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_drive_runs_the_added_row);
    RUN_TEST(test_h_lists_the_added_row);
    RUN_TEST(test_a_row_without_a_can_form_is_not_bridged_and_sends_nothing);
    RUN_TEST(test_a_port_command_for_another_drive_is_not_bridged_and_sends_nothing);
    RUN_TEST(test_the_client_builds_the_added_row_and_knows_its_reply);
    return UNITY_END();
}

#else
void setUp(void)
{
}
void tearDown(void)
{
}
int main(void)
{
    return 77; /* a build without the bridge or the port's commands */
}
#endif

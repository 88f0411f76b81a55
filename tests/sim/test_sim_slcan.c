/* The slcan (Lawicel) codec of daran-sim's --slcan (sim_slcan.h): the
 * command sequences slcand and python-can send, frames both ways, the
 * answers (CR, BEL, z/Z), commands split across reads, and every malformed
 * or refused command answered BEL with no frame sent. */
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_slcan.h"

static daran_sim_slcan_t s;
static char answers[512];
static size_t answers_len;
static daran_can_frame_t sent[8];
static uint32_t sent_count;
static bool bus_takes;

static bool on_send(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    if (!bus_takes) {
        return false;
    }
    if (sent_count < 8u) {
        sent[sent_count++] = *frame;
    }
    return true;
}

static void on_reply(void *ctx, const char *bytes, size_t len)
{
    (void)ctx;
    TEST_ASSERT_TRUE(len < sizeof answers - answers_len);
    memcpy(answers + answers_len, bytes, len);
    answers_len += len;
    answers[answers_len] = '\0';
}

static const daran_sim_slcan_io_t io = {on_send, on_reply, NULL};

void setUp(void)
{
    daran_sim_slcan_init(&s);
    answers_len = 0u;
    answers[0] = '\0';
    sent_count = 0u;
    bus_takes = true;
}

void tearDown(void)
{
}

/* Feed @p text as the host would, returning what the adapter answered;
 * every byte must be taken, one command at a time. */
static const char *host(const char *text)
{
    size_t len = strlen(text);
    size_t pos = 0u;
    answers_len = 0u;
    answers[0] = '\0';
    while (pos < len) {
        size_t n = daran_sim_slcan_take(&s, (const uint8_t *)text + pos, len - pos, &io);
        TEST_ASSERT_TRUE(n > 0u);
        pos += n;
    }
    return answers;
}

/* python-can's slcanBus(bitrate=1000000): C, S8, O. */
static void test_python_cans_opening_sequence_is_answered_and_opens_the_channel(void)
{
    TEST_ASSERT_EQUAL_STRING("\r\r\r", host("C\rS8\rO\r"));
    TEST_ASSERT_TRUE(s.open);
}

static void test_a_standard_frame_from_the_host_goes_to_the_bus(void)
{
    (void)host("O\r");
    TEST_ASSERT_EQUAL_STRING("z\r", host("t01E81979030000000000\r"));
    TEST_ASSERT_EQUAL_UINT32(1u, sent_count);
    TEST_ASSERT_EQUAL_HEX32(0x01Eu, sent[0].id);
    TEST_ASSERT_EQUAL_UINT8(8u, sent[0].dlc);
    TEST_ASSERT_EQUAL_UINT8(0u, sent[0].flags);
    TEST_ASSERT_EQUAL_HEX8(0x19u, sent[0].data[0]);
    TEST_ASSERT_EQUAL_HEX8(0x79u, sent[0].data[1]);
    TEST_ASSERT_EQUAL_HEX8(0x03u, sent[0].data[2]);
}

static void test_extended_remote_and_short_frames_keep_their_shape(void)
{
    (void)host("O\r");
    TEST_ASSERT_EQUAL_STRING("Z\rz\rZ\rz\r", host("T1FFFFFFF2abCD\rr1238\rR000000010\rt0090\r"));
    TEST_ASSERT_EQUAL_UINT32(4u, sent_count);
    TEST_ASSERT_EQUAL_HEX32(0x1FFFFFFFu, sent[0].id);
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_EXTENDED, sent[0].flags);
    TEST_ASSERT_EQUAL_HEX8(0xABu, sent[0].data[0]);
    TEST_ASSERT_EQUAL_HEX8(0xCDu, sent[0].data[1]);
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE, sent[1].flags);
    TEST_ASSERT_EQUAL_UINT8(8u, sent[1].dlc);
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE | DARAN_CAN_FRAME_EXTENDED, sent[2].flags);
    TEST_ASSERT_EQUAL_UINT8(0u, sent[3].dlc); /* the vendor's send_command() default */
}

static void test_malformed_frames_are_refused_and_never_sent(void)
{
    static const char *const bad[] = {
        "t8001\r",            /* id above 7FF */
        "t01E9\r",            /* DLC 9 */
        "t01E2AA\r",          /* fewer digits than the DLC */
        "t01E1AABB\r",        /* more */
        "t01E2GG00\r",        /* not hex */
        "T200000000\r",       /* extended id above 1FFFFFFF */
        "r1238AA\r",          /* a remote frame with data */
        "t01\r",              /* too short */
        "tXYZ0\r",
    };
    size_t k;
    (void)host("O\r");
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        if (strcmp(host(bad[k]), "\a") != 0) {
            FAIL_F("`%s` answered `%s`", bad[k], answers);
        }
    }
    TEST_ASSERT_EQUAL_UINT32(0u, sent_count);
}

static void test_frames_need_an_open_channel_that_is_not_listen_only(void)
{
    TEST_ASSERT_EQUAL_STRING("\a", host("t0010\r"));
    TEST_ASSERT_EQUAL_STRING("\r\a", host("L\rt0010\r"));
    TEST_ASSERT_EQUAL_STRING("\r\r", host("C\rO\r"));
    TEST_ASSERT_EQUAL_STRING("z\r", host("t0010\r"));
    TEST_ASSERT_EQUAL_UINT32(1u, sent_count);
}

static void test_a_frame_the_bus_refuses_is_answered_bel(void)
{
    (void)host("O\r");
    bus_takes = false;
    TEST_ASSERT_EQUAL_STRING("\a", host("t0010\r"));
}

static void test_settings_are_taken_only_while_closed(void)
{
    TEST_ASSERT_EQUAL_STRING("\r\r\r\r", host("S8\rZ1\rX1\rU6\r"));
    TEST_ASSERT_TRUE(s.timestamps);
    /* the bus runs at 1 Mbit/s only; no manual polling; BTR and filters not offered */
    TEST_ASSERT_EQUAL_STRING("\a\a\a\a\a\a\a", host("S6\rS9\rX0\rU7\rs031C\rM00000000\rP\r"));
    (void)host("O\r");
    TEST_ASSERT_EQUAL_STRING("\a\a\a\a", host("S8\rZ0\rO\rL\r"));
    TEST_ASSERT_TRUE(s.timestamps);
}

static void test_identity_and_status_commands(void)
{
    TEST_ASSERT_EQUAL_STRING("V0100\rv0100\rNSIM1\r", host("V\rv\rN\r"));
    TEST_ASSERT_EQUAL_STRING("\a", host("F\r")); /* closed */
    (void)host("O\r");
    s.status = DARAN_SIM_SLCAN_STATUS_OVERRUN | DARAN_SIM_SLCAN_STATUS_BUS_ERROR;
    TEST_ASSERT_EQUAL_STRING("F88\r", host("F\r"));
    TEST_ASSERT_EQUAL_STRING("F80\r", host("F\r")); /* the overrun latch cleared */
}

static void test_bare_carriage_returns_and_line_feeds(void)
{
    TEST_ASSERT_EQUAL_STRING("\r\r\r", host("\r\r\r"));
    TEST_ASSERT_EQUAL_STRING("\r", host("O\r\n"));
    TEST_ASSERT_EQUAL_STRING("z\r", host("\nt0010\r\n"));
}

static void test_a_command_may_arrive_in_pieces(void)
{
    (void)host("O\r");
    TEST_ASSERT_EQUAL_STRING("", host("t01E"));
    TEST_ASSERT_EQUAL_STRING("", host("2AB"));
    TEST_ASSERT_EQUAL_STRING("z\r", host("CD\r"));
    TEST_ASSERT_EQUAL_HEX8(0xCDu, sent[0].data[1]);
}

/* take() stops after each command, so a caller can stop between two. */
static void test_take_stops_after_each_command(void)
{
    const char *two = "O\rt0010\r";
    size_t n = daran_sim_slcan_take(&s, (const uint8_t *)two, strlen(two), &io);
    TEST_ASSERT_EQUAL_UINT32(2u, n);
    TEST_ASSERT_EQUAL_UINT32(0u, sent_count);
}

static void test_an_overlong_command_is_refused_whole(void)
{
    (void)host("O\r");
    TEST_ASSERT_EQUAL_STRING("\a", host("t01E8000000000000000000000000000000000000\r"));
    TEST_ASSERT_EQUAL_STRING("z\r", host("t0010\r"));
}

static void test_frames_to_the_host_are_lines_of_hex(void)
{
    daran_can_frame_t f;
    char line[DARAN_SIM_SLCAN_LINE_MAX];
    size_t n;
    memset(&f, 0, sizeof f);
    f.id = 0x03Eu;
    f.dlc = 8u;
    f.data[0] = 0x19u;
    f.data[1] = 0x79u;
    f.data[2] = 0x03u;
    f.data[4] = 0x01u;
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_slcan_encode(&s, &f, 0u, line)); /* closed */
    (void)host("O\r");
    n = daran_sim_slcan_encode(&s, &f, 0u, line);
    TEST_ASSERT_EQUAL_UINT32(22u, n);
    TEST_ASSERT_EQUAL_MEMORY("t03E81979030001000000\r", line, n);
    f.id = 0x1ABCDEF0u;
    f.flags = DARAN_CAN_FRAME_EXTENDED | DARAN_CAN_FRAME_REMOTE;
    f.dlc = 3u;
    n = daran_sim_slcan_encode(&s, &f, 0u, line);
    TEST_ASSERT_EQUAL_MEMORY("R1ABCDEF03\r", line, n);
    s.timestamps = true; /* milliseconds modulo 60000 */
    f.flags = 0u;
    f.id = 0x7FFu;
    f.dlc = 0u;
    n = daran_sim_slcan_encode(&s, &f, 60000u + 0x1234u, line);
    TEST_ASSERT_EQUAL_MEMORY("t7FF01234\r", line, n);
}

/* Every frame a host can send comes back as the same frame. */
static void test_encode_and_parse_agree(void)
{
    static const uint8_t shapes[4] = {0u, DARAN_CAN_FRAME_EXTENDED, DARAN_CAN_FRAME_REMOTE,
                                      DARAN_CAN_FRAME_EXTENDED | DARAN_CAN_FRAME_REMOTE};
    uint32_t seed = 7u;
    uint32_t k;
    (void)host("O\r");
    for (k = 0; k < 2000u; k++) {
        daran_can_frame_t f;
        daran_can_frame_t back;
        char line[DARAN_SIM_SLCAN_LINE_MAX];
        size_t n;
        uint32_t i;
        memset(&f, 0, sizeof f);
        seed = seed * 1103515245u + 12345u;
        f.flags = shapes[k % 4u];
        f.id = seed & ((f.flags & DARAN_CAN_FRAME_EXTENDED) != 0u ? 0x1FFFFFFFu : 0x7FFu);
        f.dlc = (uint8_t)(k % 9u);
        for (i = 0; (f.flags & DARAN_CAN_FRAME_REMOTE) == 0u && i < f.dlc; i++) {
            f.data[i] = (uint8_t)(seed >> (i + 3u));
        }
        n = daran_sim_slcan_encode(&s, &f, 0u, line);
        TEST_ASSERT_TRUE(n > 1u && line[n - 1u] == '\r');
        TEST_ASSERT_TRUE(daran_sim_slcan_parse_frame(line, n - 1u, &back));
        TEST_ASSERT_EQUAL_HEX32(f.id, back.id);
        TEST_ASSERT_EQUAL_UINT8(f.dlc, back.dlc);
        TEST_ASSERT_EQUAL_UINT8(f.flags, back.flags);
        TEST_ASSERT_EQUAL_MEMORY(f.data, back.data, sizeof f.data);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_python_cans_opening_sequence_is_answered_and_opens_the_channel);
    RUN_TEST(test_a_standard_frame_from_the_host_goes_to_the_bus);
    RUN_TEST(test_extended_remote_and_short_frames_keep_their_shape);
    RUN_TEST(test_malformed_frames_are_refused_and_never_sent);
    RUN_TEST(test_frames_need_an_open_channel_that_is_not_listen_only);
    RUN_TEST(test_a_frame_the_bus_refuses_is_answered_bel);
    RUN_TEST(test_settings_are_taken_only_while_closed);
    RUN_TEST(test_identity_and_status_commands);
    RUN_TEST(test_bare_carriage_returns_and_line_feeds);
    RUN_TEST(test_a_command_may_arrive_in_pieces);
    RUN_TEST(test_take_stops_after_each_command);
    RUN_TEST(test_an_overlong_command_is_refused_whole);
    RUN_TEST(test_frames_to_the_host_are_lines_of_hex);
    RUN_TEST(test_encode_and_parse_agree);
    return UNITY_END();
}

/* The USB-CAN adapter packet codec of daran-sim's --usbcan (sim_usbcan.h):
 * the packets DrEmpower_can.py writes, the packets it accepts back (16
 * bytes, byte 3 = 8, id in bytes 6..7, data in 8..15), packets split across
 * reads, and resynchronisation after noise or a damaged packet. */
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_usbcan.h"

static daran_sim_usbcan_t u;

void setUp(void)
{
    daran_sim_usbcan_init(&u);
}

void tearDown(void)
{
}

/* can_to_uart() of the vendor library for get_id(): send_command(0, 0x1E,
 * [0x19, 0x79, 3, 0, 0, 0, 0, 0]). */
static const uint8_t get_id_packet[16] = {0xAA, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x1E,
                                          0x19, 0x79, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00};

static void test_the_vendor_librarys_packet_is_its_frame(void)
{
    daran_can_frame_t f;
    TEST_ASSERT_TRUE(daran_sim_usbcan_decode(get_id_packet, &f));
    TEST_ASSERT_EQUAL_HEX32(0x01Eu, f.id);
    TEST_ASSERT_EQUAL_UINT8(8u, f.dlc);
    TEST_ASSERT_EQUAL_UINT8(0u, f.flags);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(get_id_packet + 8, f.data, 8);
}

/* What uart_to_can() accepts: 16 bytes, byte 3 = 8, the id in 6..7. */
static void test_a_drives_answer_becomes_the_packet_the_library_reads(void)
{
    daran_can_frame_t f;
    uint8_t packet[16];
    static const uint8_t expected[16] = {0xAA, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x3E,
                                         0x19, 0x79, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00};
    memset(&f, 0, sizeof f);
    f.id = 0x03Eu;
    f.dlc = 8u;
    memcpy(f.data, expected + 8, 8u);
    daran_sim_usbcan_encode(&f, packet);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(expected, packet, 16);
}

static void test_extended_remote_and_short_frames_round_trip(void)
{
    daran_can_frame_t f;
    daran_can_frame_t back;
    uint8_t packet[16];
    memset(&f, 0, sizeof f);
    f.id = 0x1ABCDEF0u;
    f.dlc = 3u;
    f.flags = DARAN_CAN_FRAME_EXTENDED;
    f.data[0] = 1u;
    f.data[1] = 2u;
    f.data[2] = 3u;
    daran_sim_usbcan_encode(&f, packet);
    TEST_ASSERT_EQUAL_HEX8(0x1Au, packet[4]);
    TEST_ASSERT_EQUAL_HEX8(0xF0u, packet[7]);
    TEST_ASSERT_EQUAL_HEX8(0u, packet[11]); /* past the DLC: 0 */
    TEST_ASSERT_TRUE(daran_sim_usbcan_decode(packet, &back));
    TEST_ASSERT_EQUAL_HEX32(f.id, back.id);
    TEST_ASSERT_EQUAL_UINT8(f.flags, back.flags);
    TEST_ASSERT_EQUAL_UINT8(3u, back.dlc);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(f.data, back.data, 8);
    f.flags = DARAN_CAN_FRAME_REMOTE;
    f.id = 0x123u;
    f.dlc = 8u;
    daran_sim_usbcan_encode(&f, packet);
    TEST_ASSERT_EQUAL_HEX8(1u, packet[2]);
    TEST_ASSERT_EQUAL_HEX8(0u, packet[8]); /* a remote frame carries no data */
    TEST_ASSERT_TRUE(daran_sim_usbcan_decode(packet, &back));
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE, back.flags);
    TEST_ASSERT_EQUAL_HEX8(0u, back.data[0]);
}

static void test_invalid_packets_are_refused(void)
{
    daran_can_frame_t f;
    uint8_t p[16];
    size_t k;
    static const struct {
        size_t at;
        uint8_t value;
    } damage[] = {
        {0u, 0xABu}, /* no start byte */
        {1u, 2u},    /* neither standard nor extended */
        {2u, 2u},    /* neither data nor remote */
        {3u, 9u},    /* DLC 9 */
        {6u, 0x08u}, /* standard id 0x81E */
        {4u, 0x20u}, /* (as extended below) id above 1FFFFFFF */
    };
    for (k = 0; k < sizeof damage / sizeof damage[0]; k++) {
        memcpy(p, get_id_packet, 16u);
        if (k == 5u) {
            p[1] = 1u;
        }
        p[damage[k].at] = damage[k].value;
        if (daran_sim_usbcan_decode(p, &f)) {
            FAIL_F("damage %u accepted", (unsigned)k);
        }
    }
}

/* Feed @p bytes in chunks of @p chunk; returns the frames found. */
static uint32_t feed(const uint8_t *bytes, size_t len, size_t chunk, daran_can_frame_t *out,
                     uint32_t max)
{
    uint32_t found = 0u;
    size_t pos = 0u;
    while (pos < len) {
        size_t n = len - pos < chunk ? len - pos : chunk;
        size_t used = 0u;
        while (used < n) {
            daran_can_frame_t f;
            bool got;
            used += daran_sim_usbcan_take(&u, bytes + pos + used, n - used, &f, &got);
            if (got && found < max) {
                out[found++] = f;
            }
        }
        pos += n;
    }
    return found;
}

static void test_packets_in_any_chunks_give_the_same_frames(void)
{
    uint8_t stream[48];
    daran_can_frame_t f[4];
    size_t chunk;
    memcpy(stream, get_id_packet, 16u);
    memcpy(stream + 16, get_id_packet, 16u);
    memcpy(stream + 32, get_id_packet, 16u);
    stream[16 + 7] = 0x3Eu;
    stream[32 + 7] = 0x5Eu;
    for (chunk = 1u; chunk <= sizeof stream; chunk++) {
        daran_sim_usbcan_init(&u);
        TEST_ASSERT_EQUAL_UINT32(3u, feed(stream, sizeof stream, chunk, f, 4u));
        TEST_ASSERT_EQUAL_HEX32(0x01Eu, f[0].id);
        TEST_ASSERT_EQUAL_HEX32(0x03Eu, f[1].id);
        TEST_ASSERT_EQUAL_HEX32(0x05Eu, f[2].id);
    }
}

/* take() stops after each packet, so a caller can stop between two. */
static void test_take_stops_after_each_packet(void)
{
    uint8_t two[32];
    daran_can_frame_t f;
    bool got;
    memcpy(two, get_id_packet, 16u);
    memcpy(two + 16, get_id_packet, 16u);
    TEST_ASSERT_EQUAL_UINT32(16u, daran_sim_usbcan_take(&u, two, sizeof two, &f, &got));
    TEST_ASSERT_TRUE(got);
}

/* Noise before a packet is skipped; a damaged packet is dropped up to the
 * next 0xAA inside it, which starts the real one. */
static void test_noise_and_a_damaged_packet_are_skipped(void)
{
    uint8_t stream[3 + 16 + 16];
    daran_can_frame_t f[4];
    stream[0] = 0x00u;
    stream[1] = 0x55u;
    stream[2] = 0x08u;
    memcpy(stream + 3, get_id_packet, 16u);
    stream[3 + 3] = 0x09u;              /* DLC 9: damaged ... */
    stream[3 + 10] = 0xAAu;             /* ... with a start byte inside it */
    memcpy(stream + 19, get_id_packet, 16u);
    stream[19 + 7] = 0x7Eu;
    TEST_ASSERT_EQUAL_UINT32(1u, feed(stream, sizeof stream, 5u, f, 4u));
    TEST_ASSERT_EQUAL_HEX32(0x07Eu, f[0].id);
    TEST_ASSERT_EQUAL_UINT32(3u + 16u, u.skipped);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_vendor_librarys_packet_is_its_frame);
    RUN_TEST(test_a_drives_answer_becomes_the_packet_the_library_reads);
    RUN_TEST(test_extended_remote_and_short_frames_round_trip);
    RUN_TEST(test_invalid_packets_are_refused);
    RUN_TEST(test_packets_in_any_chunks_give_the_same_frames);
    RUN_TEST(test_take_stops_after_each_packet);
    RUN_TEST(test_noise_and_a_damaged_packet_are_skipped);
    return UNITY_END();
}

/* The firmware update module (docs/update.md, daran_update.h) on a drive
 * whose flash behaves as flash does: the steps and their refusals, a
 * revert, and a power cut at every erase and program step of an update,
 * after each of which the host resumes from the offset the drive names and
 * the image arrives whole, the running slot untouched. */
#include <stdio.h>
#include <string.h>

#include "unity.h"

#include "hash.h"
#include "update_double.h"

#if DARAN_REPLY_CRLF
#define EOL "\r\n"
#else
#define EOL "\n"
#endif

static update_double_t d;
static uint8_t image[DOUBLE_SLOT];
static size_t image_len;

void setUp(void)
{
    double_factory(&d);
    TEST_ASSERT_TRUE(d.bound);
}

void tearDown(void)
{
}

static void put32(uint8_t *at, uint32_t v)
{
    for (unsigned i = 0; i < 4u; i++) {
        at[i] = (uint8_t)(v >> (8u * i));
    }
}

/* An image of @p payload bytes for @p hardware, version @p version. */
static void make_image(uint32_t version, uint32_t hardware, size_t payload)
{
    memset(image, 0, DARAN_UPDATE_HEADER_SIZE);
    uint32_t x = version * 2654435761u;
    for (size_t i = 0; i < payload; i++) {
        x = x * 1664525u + 1013904223u;
        image[DARAN_UPDATE_HEADER_SIZE + i] = (uint8_t)(x >> 24);
    }
    image_len = DARAN_UPDATE_HEADER_SIZE + payload;
    put32(image + DARAN_UPDATE_AT_MAGIC, DARAN_UPDATE_MAGIC);
    image[DARAN_UPDATE_AT_HEADER_VERSION] = DARAN_UPDATE_HEADER_VERSION;
    put32(image + DARAN_UPDATE_AT_PAYLOAD_SIZE, (uint32_t)payload);
    put32(image + DARAN_UPDATE_AT_VERSION, version);
    put32(image + DARAN_UPDATE_AT_HARDWARE_ID, hardware);
    put32(image + DARAN_UPDATE_AT_PAYLOAD_CRC,
          daran_crc32(0u, image + DARAN_UPDATE_HEADER_SIZE, payload));
    daran_sha256_t sha;
    daran_sha256_init(&sha);
    daran_sha256_update(&sha, image + DARAN_UPDATE_HEADER_SIZE, payload);
    daran_sha256_final(&sha, image + DARAN_UPDATE_AT_SHA256);
}

static uint32_t image_crc(void)
{
    return daran_crc32(0u, image, image_len);
}

/* The DATA field of bytes[0..n): base 85 over '!'..'v' without '*'. */
static size_t encode(const uint8_t *bytes, size_t n, char *out)
{
    size_t len = 0;
    for (size_t at = 0; at < n; at += 4u) {
        size_t group = n - at < 4u ? n - at : 4u;
        uint32_t v = 0;
        for (size_t k = 0; k < 4u; k++) {
            v = v << 8 | (k < group ? bytes[at + k] : 0u);
        }
        char digits[5];
        for (int k = 4; k >= 0; k--) {
            unsigned digit = v % 85u;
            v /= 85u;
            digits[k] = (char)('!' + digit + (digit >= 9u ? 1u : 0u));
        }
        memcpy(out + len, digits, group + 1u);
        len += group + 1u;
    }
    out[len] = '\0';
    return len;
}

static void clear_out(void)
{
    d.out_len = 0;
    d.out[0] = '\0';
}

static daran_result_t send(const char *line)
{
    clear_out();
    return double_line(&d, line);
}

static daran_result_t send_begin(uint32_t size, uint32_t crc, uint32_t version, uint32_t hw)
{
    char line[96];
    snprintf(line, sizeof line, "ub 1 %lu %lu %lu %lu", (unsigned long)size, (unsigned long)crc,
             (unsigned long)version, (unsigned long)hw);
    return send(line);
}

static daran_result_t send_chunk(size_t offset, size_t n)
{
    char data[128];
    encode(image + offset, n, data);
    char line[160];
    snprintf(line, sizeof line, "uw 1 %zu %lu %s", offset,
             (unsigned long)daran_crc32(0u, image + offset, n), data);
    return send(line);
}

/* `uq`'s values: state next size running v0 s0 v1 s1. */
static void status(unsigned long v[8])
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("uq 1"));
    TEST_ASSERT_EQUAL_INT(8, sscanf(d.out, "%lu %lu %lu %lu %lu %lu %lu %lu", &v[0], &v[1],
                                    &v[2], &v[3], &v[4], &v[5], &v[6], &v[7]));
}

#define CHUNK 64u

/* The whole image, chunk by chunk from offset 0, then `uv`. */
static void send_all(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE));
    TEST_ASSERT_EQUAL_STRING("0" EOL, d.out);
    for (size_t at = 0; at < image_len; at += CHUNK) {
        size_t n = image_len - at < CHUNK ? image_len - at : CHUNK;
        TEST_ASSERT_EQUAL_INT(DARAN_OK, send_chunk(at, n));
        char want[16];
        snprintf(want, sizeof want, "%zu" EOL, at + n);
        TEST_ASSERT_EQUAL_STRING(want, d.out);
    }
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("uv 1"));
    TEST_ASSERT_EQUAL_STRING("", d.out);
}

static void test_an_update_commits_boots_once_and_is_kept(void)
{
    make_image(2, DOUBLE_HARDWARE, 3000);
    send_all();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("ug 1"));
    TEST_ASSERT_TRUE(d.reset_pending);
    TEST_ASSERT_EQUAL_MEMORY(image, d.slot[1], image_len);
    double_boot(&d);
    TEST_ASSERT_EQUAL_UINT(1, d.running);
    unsigned long v[8];
    status(v);
    /* idle, the new image runs as a test */
    TEST_ASSERT_EQUAL_UINT64(0, v[0]);
    TEST_ASSERT_EQUAL_UINT64(1, v[3]);
    TEST_ASSERT_EQUAL_UINT64(2, v[6]);
    TEST_ASSERT_EQUAL_UINT64(DARAN_SLOT_TESTING, v[7]);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("uy 1"));
    double_boot(&d);
    TEST_ASSERT_EQUAL_UINT(1, d.running);
    TEST_ASSERT_EQUAL_UINT(DARAN_SLOT_CONFIRMED, d.state[1]);
    /* a second `uy` has nothing to keep */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("uy 1"));
}

static void test_a_test_image_not_kept_reverts_at_the_next_boot(void)
{
    make_image(2, DOUBLE_HARDWARE, 1000);
    send_all();
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("ug 1"));
    double_boot(&d);
    TEST_ASSERT_EQUAL_UINT(1, d.running);
    double_boot(&d); /* a watchdog reset or a power cut before `uy` */
    TEST_ASSERT_EQUAL_UINT(0, d.running);
    TEST_ASSERT_EQUAL_UINT(DARAN_SLOT_REVERTED, d.state[1]);
    /* the update is over: motion is taken again */
    TEST_ASSERT_FALSE(daran_update_open(&d.update));
    d.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("t 1 10"));
}

static void test_steps_out_of_order_are_refused_with_no_effect(void)
{
    make_image(2, DOUBLE_HARDWARE, 500);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send_chunk(0, 16));
    TEST_ASSERT_EQUAL_STRING("error: no update" EOL, d.out);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("uv 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("ug 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("uy 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE));
    /* past the next offset, a bad CRC, a character outside the alphabet */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_OUT_OF_RANGE, send_chunk(16, 16));
    char line[160];
    char data[64];
    encode(image, 16, data);
    snprintf(line, sizeof line, "uw 1 0 %lu %s", (unsigned long)(daran_crc32(0u, image, 16) ^ 1u),
             data);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_CHECKSUM_MISMATCH, send(line));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, send("uw 1 0 0 ab~cd"));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("uv 1")); /* not all there */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("ug 1"));
    unsigned long v[8];
    status(v);
    TEST_ASSERT_EQUAL_UINT64(1, v[0]);
    TEST_ASSERT_EQUAL_UINT64(0, v[1]);
    /* another image while this one is open; the same one resumes */
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_UPDATE_OPEN, send_begin((uint32_t)image_len, 7u, 2, DOUBLE_HARDWARE));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_chunk(0, 32));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE));
    TEST_ASSERT_EQUAL_STRING("32" EOL, d.out);
    /* a chunk again is taken as it was; other bytes at its offset are not */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send_chunk(16, 32));
    TEST_ASSERT_EQUAL_STRING("48" EOL, d.out);
    image[20] ^= 1u;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_VALUE, send_chunk(16, 16));
    image[20] ^= 1u;
    /* motion waits for the update's end */
    d.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_UPDATE_OPEN, send("t 1 10"));
    TEST_ASSERT_EQUAL_STRING("error: updating" EOL, d.out);
    d.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("ua 1"));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send("t 1 10") == DARAN_ERR_MOTOR_IDLE ? DARAN_OK : DARAN_ERR_MOTOR_FAULT);
}

static void test_a_foreign_too_big_or_busy_drive_refuses_the_begin(void)
{
    make_image(2, DOUBLE_HARDWARE, 500);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_IMAGE,
                          send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE + 1u));
    TEST_ASSERT_EQUAL_STRING("error: bad image" EOL, d.out);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_IMAGE,
                          send_begin(DOUBLE_SLOT + 1u, image_crc(), 2, DOUBLE_HARDWARE));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_IMAGE, send_begin(10u, image_crc(), 2, DOUBLE_HARDWARE));
    d.props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_NOT_IDLE,
                          send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE));
    TEST_ASSERT_EQUAL_STRING("error: not idle" EOL, d.out);
    TEST_ASSERT_FALSE(daran_update_open(&d.update));
    uint8_t journal[DOUBLE_PAGE];
    memset(journal, 0xff, sizeof journal);
    TEST_ASSERT_EQUAL_MEMORY(journal, d.journal, sizeof journal);
}

static void test_a_corrupt_or_foreign_image_fails_verify_and_is_never_committed(void)
{
    static const size_t spoiled[] = {DARAN_UPDATE_HEADER_SIZE + 7u, DARAN_UPDATE_AT_SHA256,
                                     DARAN_UPDATE_AT_HARDWARE_ID, DARAN_UPDATE_AT_MAGIC};
    for (size_t i = 0; i < sizeof spoiled / sizeof spoiled[0]; i++) {
        setUp();
        make_image(2, DOUBLE_HARDWARE, 700);
        image[spoiled[i]] ^= 0x10u; /* a bit the begin's CRC then covers */
        TEST_ASSERT_EQUAL_INT(DARAN_OK,
                              send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE));
        for (size_t at = 0; at < image_len; at += CHUNK) {
            TEST_ASSERT_EQUAL_INT(DARAN_OK, send_chunk(at, image_len - at < CHUNK ? image_len - at : CHUNK));
        }
        TEST_ASSERT_EQUAL_INT(DARAN_ERR_INVALID_IMAGE, send("uv 1"));
        TEST_ASSERT_EQUAL_INT(DARAN_ERR_NO_UPDATE, send("ug 1"));
        TEST_ASSERT_FALSE(d.reset_pending);
    }
}

static void test_a_broadcast_loads_the_drive_and_answers_nothing(void)
{
    make_image(2, DOUBLE_HARDWARE, 100);
    char line[160];
    snprintf(line, sizeof line, "ub 0 %lu %lu 2 %lu", (unsigned long)image_len,
             (unsigned long)image_crc(), (unsigned long)DOUBLE_HARDWARE);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send(line));
    TEST_ASSERT_EQUAL_STRING("", d.out);
    char data[128];
    encode(image, 64, data);
    snprintf(line, sizeof line, "uw 0 0 %lu %s", (unsigned long)daran_crc32(0u, image, 64), data);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, send(line));
    TEST_ASSERT_EQUAL_STRING("", d.out);
    TEST_ASSERT_TRUE(daran_update_open(&d.update));
    TEST_ASSERT_EQUAL_MEMORY(image, d.slot[1], 64);
    unsigned long v[8];
    status(v);
    TEST_ASSERT_EQUAL_UINT64(image_len, v[2]);
    TEST_ASSERT_EQUAL_UINT64(64, v[1]);
}

/* The number of erase and program steps an update and its verify take. */
static uint32_t steps_of_a_whole_update(void)
{
    setUp();
    make_image(2, DOUBLE_HARDWARE, 2000);
    uint32_t before = d.steps;
    send_all();
    return d.steps - before;
}

/* The host's loop: ask where to go on, go on; true when `uv` took it. */
static bool host_resumes(void)
{
    unsigned long v[8];
    status(v);
    if (v[0] == DARAN_UPDATE_IDLE) {
        if (send_begin((uint32_t)image_len, image_crc(), 2, DOUBLE_HARDWARE) != DARAN_OK) {
            return false;
        }
        v[1] = 0;
    }
    for (size_t at = v[1]; at < image_len; at += CHUNK) {
        size_t n = image_len - at < CHUNK ? image_len - at : CHUNK;
        if (send_chunk(at, n) != DARAN_OK) {
            return false;
        }
    }
    return send("uv 1") == DARAN_OK;
}

static void test_a_power_cut_at_every_step_is_resumed_to_a_whole_image(void)
{
    uint32_t steps = steps_of_a_whole_update();
    TEST_ASSERT_TRUE(steps > 10u);
    printf("power-cut sweep: a cut at each of the %lu erase and program steps of an update\n",
           (unsigned long)steps);
    uint8_t running[DOUBLE_SLOT];
    /* each step cut four ways: the cells it changes left random, as if
     * done, as if not begun, or every other byte done */
    for (uint32_t run = 0; run < 4u * steps; run++) {
        uint32_t cut = run / 4u + 1u;
        setUp();
        memcpy(running, d.slot[0], sizeof running);
        make_image(2, DOUBLE_HARDWARE, 2000);
        d.noise = run % 4u;
        d.noise_state = cut * 7919u;
        d.cut_at = d.steps + cut;
        unsigned attempts = 0;
        bool done = host_resumes();
        while (!done && attempts++ < 3u) {
            TEST_ASSERT_FALSE_MESSAGE(d.powered, "a step failed with the power on");
            d.cut_at = 0;
            double_boot(&d);
            TEST_ASSERT_TRUE(d.bound);
            done = host_resumes();
        }
        char message[64];
        snprintf(message, sizeof message, "power cut at step %lu of %lu, way %lu",
                 (unsigned long)cut, (unsigned long)steps, (unsigned long)(run % 4u));
        TEST_ASSERT_TRUE_MESSAGE(done, message);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(image, d.slot[1], image_len, message);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(running, d.slot[0], sizeof running, message);
        TEST_ASSERT_EQUAL_INT_MESSAGE(DARAN_OK, send("ug 1"), message);
    }
}

static void test_sha256_and_crc32_give_the_standard_answers(void)
{
    static const uint8_t abc_digest[32] = {
        0xba, 0x78, 0x16, 0xbf, 0x8f, 0x01, 0xcf, 0xea, 0x41, 0x41, 0x40, 0xde, 0x5d, 0xae, 0x22,
        0x23, 0xb0, 0x03, 0x61, 0xa3, 0x96, 0x17, 0x7a, 0x9c, 0xb4, 0x10, 0xff, 0x61, 0xf2, 0x00,
        0x15, 0xad};
    static const uint8_t two_block_digest[32] = {
        0x24, 0x8d, 0x6a, 0x61, 0xd2, 0x06, 0x38, 0xb8, 0xe5, 0xc0, 0x26, 0x93, 0x0c, 0x3e, 0x60,
        0x39, 0xa3, 0x3c, 0xe4, 0x59, 0x64, 0xff, 0x21, 0x67, 0xf6, 0xec, 0xed, 0xd4, 0x19, 0xdb,
        0x06, 0xc1};
    uint8_t digest[32];
    daran_sha256_t sha;
    daran_sha256_init(&sha);
    daran_sha256_update(&sha, (const uint8_t *)"abc", 3);
    daran_sha256_final(&sha, digest);
    TEST_ASSERT_EQUAL_MEMORY(abc_digest, digest, 32);
    /* FIPS 180-2's two-block message, fed a byte at a time */
    const char *msg = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    daran_sha256_init(&sha);
    for (size_t i = 0; msg[i] != '\0'; i++) {
        daran_sha256_update(&sha, (const uint8_t *)msg + i, 1);
    }
    daran_sha256_final(&sha, digest);
    TEST_ASSERT_EQUAL_MEMORY(two_block_digest, digest, 32);
    TEST_ASSERT_EQUAL_HEX32(0xcbf43926u, daran_crc32(0u, (const uint8_t *)"123456789", 9));
    /* continued: the same as in one piece */
    uint32_t part = daran_crc32(0u, (const uint8_t *)"1234", 4);
    TEST_ASSERT_EQUAL_HEX32(0xcbf43926u, daran_crc32(part, (const uint8_t *)"56789", 5));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sha256_and_crc32_give_the_standard_answers);
    RUN_TEST(test_an_update_commits_boots_once_and_is_kept);
    RUN_TEST(test_a_test_image_not_kept_reverts_at_the_next_boot);
    RUN_TEST(test_steps_out_of_order_are_refused_with_no_effect);
    RUN_TEST(test_a_foreign_too_big_or_busy_drive_refuses_the_begin);
    RUN_TEST(test_a_corrupt_or_foreign_image_fails_verify_and_is_never_committed);
    RUN_TEST(test_a_broadcast_loads_the_drive_and_answers_nothing);
    RUN_TEST(test_a_power_cut_at_every_step_is_resumed_to_a_whole_image);
    return UNITY_END();
}

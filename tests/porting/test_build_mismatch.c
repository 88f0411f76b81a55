/* A program compiled with another options header, or other options, than
 * the core it links: each instance type it allocates (daran_drive_t,
 * daran_can_t, daran_can_bridge_t) is refused with DARAN_ERR_BUILD_MISMATCH
 * and left untouched, nothing after it written. With the core's own header
 * (EXPECT_REFUSED 0) all three are accepted and the ids mean the same rows
 * on both sides. tests/porting/CMakeLists.txt builds this file once per
 * case, against the core of build_mismatch/library_options.h. */
#include <string.h>

#include "unity.h"

#include "daran_ascii.h"
#include "stub_hal.h"

#ifndef EXPECT_REFUSED
#error "build with EXPECT_REFUSED 1 (another header or option than the core's) or 0"
#endif

/* Room after each instance: a core that took it for an instance of its own
 * layout would write there (8 frames into a 2-slot ring wrote 60 bytes). */
#define GUARD_BYTES 64u
#define FILL 0xA5u

static struct {
    daran_drive_t drive;
    unsigned char guard[GUARD_BYTES];
} drive_box;
static struct {
    daran_can_t can;
    unsigned char guard[GUARD_BYTES];
} can_box;
static struct {
    daran_can_bridge_t bridge;
    unsigned char guard[GUARD_BYTES];
} bridge_box;
static daran_stub_t stub;

static bool take_frame(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    (void)frame;
    return true;
}

static uint32_t clock_ms(void *ctx)
{
    (void)ctx;
    return 0u;
}

static const daran_hal_t stub_with_can = {DARAN_STUB_HAL_FUNCTIONS, .write = daran_stub_drop_reply,
                                          .now_ms = clock_ms, .can_send = take_frame};

static void assert_filled(const void *box, size_t from, size_t size, const char *what)
{
    const unsigned char *bytes = box;
    for (size_t i = from; i < size; i++) {
        if (bytes[i] != FILL) {
            TEST_FAIL_MESSAGE(what);
        }
    }
}

void setUp(void)
{
    memset(&drive_box, FILL, sizeof drive_box);
    memset(&can_box, FILL, sizeof can_box);
    memset(&bridge_box, FILL, sizeof bridge_box);
    daran_stub_init(&stub, 1);
}

void tearDown(void)
{
}

#if EXPECT_REFUSED

static void test_every_instance_is_refused_untouched(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BUILD_MISMATCH,
                          daran_init(&drive_box.drive, &stub_with_can, &stub));
    assert_filled(&drive_box, 0, sizeof drive_box, "the refused drive was written");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BUILD_MISMATCH,
                          daran_can_init(&can_box.can, &drive_box.drive));
    assert_filled(&can_box, 0, sizeof can_box, "the refused CAN front end was written");
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BUILD_MISMATCH,
                          daran_can_bridge_init(&bridge_box.bridge, &can_box.can));
    assert_filled(&bridge_box, 0, sizeof bridge_box, "the refused bridge was written");
    assert_filled(&can_box, 0, sizeof can_box, "the refused bridge wrote its front end");
    /* a static front end whose daran_can_init() was refused is all zeros:
     * the mismatch, not a missing drive, is what the bridge reports */
    memset(&can_box.can, 0, sizeof can_box.can);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BUILD_MISMATCH,
                          daran_can_bridge_init(&bridge_box.bridge, &can_box.can));
    assert_filled(&bridge_box, 0, sizeof bridge_box, "the refused bridge was written");
}

#else

static void test_every_instance_is_accepted_and_ids_agree(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_init(&drive_box.drive, &stub_with_can, &stub));
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_can_init(&can_box.can, &drive_box.drive));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_bridge_init(&bridge_box.bridge, &can_box.can));
    static const char line[] = "w axis1.fan.duty 75";
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_process_line(&drive_box.drive, line, sizeof line - 1u));
    TEST_ASSERT_TRUE(stub.values[DARAN_PROP_FAN_DUTY].f32 == 75.0f);
    TEST_ASSERT_EQUAL_UINT32(0u, stub.values[DARAN_PROP_PUMP_DUTY].u32);
    /* more frames than the ring holds: the rest are dropped, none written past it */
    daran_can_frame_t frame = {1u << 5 | 0x01u, 8u, 0u, {0}};
    for (unsigned i = 0; i < 2u * DARAN_CAN_RX_FRAMES; i++) {
        (void)daran_can_receive(&can_box.can, &frame);
    }
    assert_filled(&drive_box, sizeof drive_box.drive, sizeof drive_box, "written past the drive");
    assert_filled(&can_box, sizeof can_box.can, sizeof can_box, "written past the front end");
    assert_filled(&bridge_box, sizeof bridge_box.bridge, sizeof bridge_box,
                  "written past the bridge");
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if EXPECT_REFUSED
    RUN_TEST(test_every_instance_is_refused_untouched);
#else
    RUN_TEST(test_every_instance_is_accepted_and_ids_agree);
#endif
    return UNITY_END();
}

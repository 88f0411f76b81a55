/* The real-time loop's sleep (sim_wait.h): until the next tick, or until a
 * frame's end is within the spin window, and never a timed sleep inside that
 * window, even when a tick is due before the frame's end (a timed wake-up,
 * tens of microseconds late, would deliver the frame late). */
#include <stdint.h>

#include "unity.h"

#include "sim_wait.h"

#define US 1000u
#define NOW (5000000u * US) /* any time on the clock */

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_without_a_frame_it_sleeps_until_the_tick(void)
{
    TEST_ASSERT_EQUAL_UINT64(700u * US, sim_wait_ns(NOW, NOW + 700u * US, UINT64_MAX));
}

static void test_a_due_tick_or_frame_end_means_no_sleep(void)
{
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW, UINT64_MAX));
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW - 1u, UINT64_MAX));
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW + 700u * US, NOW - 3u * US));
}

/* A timed sleep to the frame's end itself would deliver it late. */
static void test_a_far_frame_end_is_slept_for_until_the_spin_window_opens(void)
{
    uint64_t end = NOW + SIM_SPIN_BEFORE_FRAME_END_NS + 400u * US;
    TEST_ASSERT_EQUAL_UINT64(400u * US, sim_wait_ns(NOW, NOW + 900u * US, end));
}

static void test_a_near_frame_end_is_polled_for(void)
{
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW + 900u * US, NOW + 125u * US));
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW + 900u * US,
                                             NOW + SIM_SPIN_BEFORE_FRAME_END_NS));
}

/* At 8 kHz a tick falls inside nearly every frame: the frame's end must not
 * wait for a timed wake-up at the tick. */
static void test_a_near_frame_end_is_polled_for_with_a_tick_before_it(void)
{
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW + 40u * US, NOW + 125u * US));
    TEST_ASSERT_EQUAL_UINT64(0u, sim_wait_ns(NOW, NOW + 1u * US, NOW + 2u * US));
}

static void test_a_tick_before_the_spin_window_is_slept_for(void)
{
    uint64_t end = NOW + SIM_SPIN_BEFORE_FRAME_END_NS + 400u * US;
    TEST_ASSERT_EQUAL_UINT64(100u * US, sim_wait_ns(NOW, NOW + 100u * US, end));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_without_a_frame_it_sleeps_until_the_tick);
    RUN_TEST(test_a_due_tick_or_frame_end_means_no_sleep);
    RUN_TEST(test_a_far_frame_end_is_slept_for_until_the_spin_window_opens);
    RUN_TEST(test_a_near_frame_end_is_polled_for);
    RUN_TEST(test_a_near_frame_end_is_polled_for_with_a_tick_before_it);
    RUN_TEST(test_a_tick_before_the_spin_window_is_slept_for);
    return UNITY_END();
}

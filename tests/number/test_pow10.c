/* The number module rebuilds its 64-bit powers of ten from a few anchors and
 * stored corrections; every rebuilt entry must equal the exact truncation that
 * the generator computes with rational arithmetic. */
#include <stdint.h>
#include <stdio.h>

#include "unity.h"

#include "number.h"
#include "pow10_expected.h"

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_every_rebuilt_power_of_ten_is_exact(void)
{
    char which[16];
    for (int32_t q = -64; q <= 45; q++) {
        (void)snprintf(which, sizeof which, "10^%d", (int)q);
        TEST_ASSERT_EQUAL_HEX64_MESSAGE(expected_pow10_hi[q + 64], daran_pow10_hi(q), which);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_rebuilt_power_of_ten_is_exact);
    return UNITY_END();
}

/* The number module rebuilds its 64-bit powers of ten from a few anchors and
 * stored corrections; every rebuilt entry must equal the exact truncation that
 * the generator computes with rational arithmetic. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "number.h"
#include "pow10_expected.h"

static void test_every_rebuilt_power_of_ten_is_exact(void **state)
{
    (void)state;
    for (int32_t q = -64; q <= 45; q++) {
        uint64_t want = expected_pow10_hi[q + 64];
        if (daran_pow10_hi(q) != want) {
            fail_msg("10^%d: rebuilt 0x%016llx, exact 0x%016llx", (int)q,
                     (unsigned long long)daran_pow10_hi(q), (unsigned long long)want);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_rebuilt_power_of_ten_is_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

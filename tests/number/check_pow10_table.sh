#!/bin/sh
# The power-of-ten tables in src/text/number.c and the exact list the C test checks
# them against are exactly what the generator makes (which also proves the
# rebuild exact and checks number.c's integer log formulas).
# Usage: check_pow10_table.sh <repository root>
set -eu
root=$1
want=$(python3 "$root/bench/number/gen_pow10_table.py")
have=$(sed -n '/^static const uint64_t daran_pow10_anchor/,/^static const uint8_t daran_pow10_correction/p;/^static const uint8_t daran_pow10_correction/,/^};/p' "$root/src/text/number.c" | uniq)
[ "$want" = "$have" ] || { echo "src/text/number.c tables differ from bench/number/gen_pow10_table.py"; exit 1; }
want=$(python3 "$root/bench/number/gen_pow10_table.py" --expected)
have=$(cat "$root/tests/number/pow10_expected.h")
[ "$want" = "$have" ] || { echo "tests/number/pow10_expected.h differs from the generator's --expected"; exit 1; }
echo "tables and log formulas OK"

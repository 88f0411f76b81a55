#!/bin/sh
# The power-of-ten table in src/number.c is exactly what the generator makes, and
# the generator's exact checks of number.c's integer log formulas pass.
# Usage: check_pow10_table.sh <repository root>
set -eu
root=$1
want=$(python3 "$root/bench/number/gen_pow10_table.py")
have=$(sed -n '/^static const uint64_t daran_pow10_hi/,/^};/p' "$root/src/number.c")
[ "$want" = "$have" ] || { echo "src/number.c table differs from bench/number/gen_pow10_table.py"; exit 1; }
echo "table and log formulas OK"

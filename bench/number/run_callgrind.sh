#!/bin/sh
# Instructions per parse and per print, ours vs glibc, under callgrind.
# Usage: bench/number/run_callgrind.sh [build dir, default build/release]
# Builds number_bench there first (cmake --preset release must have run).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
cmake --build "$build" --target number_bench >/dev/null
bin=$build/bench/number/number_bench
out=$(mktemp -d)
for mode in parse_ours parse_strtof print_ours print_snprintf; do
    valgrind --tool=callgrind --toggle-collect="bench_$mode" \
        --callgrind-out-file="$out/$mode.cg" "$bin" "$mode" "${RECORDINGS:-$root/../shared/recordings}"/*.txt \
        >"$out/$mode.txt" 2>"$out/$mode.err"
    n=$(sed -n 's/^\([0-9]*\) values$/\1/p' "$out/$mode.txt")
    ir=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$out/$mode.cg")
    echo "$mode $n $ir" | awk '{ printf "%-15s %6d values %12d Ir %8.1f Ir/value\n", $1, $2, $3, $3 / $2 }'
done
rm -rf "$out"

#!/bin/sh
# Reproduce every host benchmark figure in docs/performance.md.
#
#   bench/host/run_all.sh               measure everything
#   bench/host/run_all.sh --reference   also refresh bench/host/reference.txt
#
# Needs gcc, valgrind, python3, gnuplot, arm-none-eabi-gcc (clang-14 optional).
# Builds the benchmark driver (gcc and clang-14, -O2, no sanitizers) in
# build/bench/, checks that daran-ascii and the sscanf/printf yardstick make
# the same HAL calls on every stream and that the hand-written yardstick
# makes them up to (proven, counted) float rounding, counts instructions with
# callgrind, measures the hand-written yardstick's rounding, draws the charts,
# links the Cortex-M4 images and rewrites the generated tables of
# docs/performance.md. Results: build/bench/results/{host,rounding,m4}.md,
# charts: docs/bench-host-instructions.png, docs/bench-host-lookup.png. About
# 3 minutes on one core.
set -eu
cd "$(dirname "$0")/../.."
build=build/bench
results=$build/results
mkdir -p "$results"

configure() { # dir compiler
  cmake -S . -B "$1" -G Ninja -DCMAKE_C_COMPILER="$2" -DCMAKE_BUILD_TYPE=Release \
    -DDARAN_BUILD_TESTS=OFF -DDARAN_BUILD_SIM=OFF -DDARAN_BUILD_DEMO=OFF >/dev/null
  cmake --build "$1" --target daran_bench_driver daran_rounding -j2 >/dev/null
}

echo "== build the driver (gcc -O2)"
configure "$build/gcc" gcc
driver=$build/gcc/bench/host/daran_bench_driver
clang_args=""
if command -v clang-14 >/dev/null 2>&1; then
  echo "== build the driver (clang-14 -O2)"
  configure "$build/clang" clang-14
  clang_args="--clang-driver $build/clang/bench/host/daran_bench_driver"
fi

echo "== same HAL calls and replies from the core and both yardsticks"
python3 bench/host/compare_traces.py "$driver" bench/streams/*.txt bench/streams/families/*.txt
if ! python3 bench/host/compare_traces.py --yardstick handwritten "$driver" bench/streams/*.txt \
    bench/streams/families/*.txt >"$results/handwritten-compare.txt"; then
  cat "$results/handwritten-compare.txt"
  exit 1
fi
tail -1 "$results/handwritten-compare.txt"

echo "== callgrind instruction counts"
reference_args=""
if [ "${1:-}" = "--reference" ]; then
  reference_args="--reference bench/host/reference.txt"
fi
# shellcheck disable=SC2086
nice -n 10 python3 bench/host/measure.py --driver "$driver" $clang_args --out "$results" $reference_args \
  --rounding "$build/gcc/bench/host/daran_rounding"

echo "== charts"
gnuplot -e "datafile='$results/families.dat'; outfile='docs/bench-host-instructions.png'" \
  bench/host/families.gp
gnuplot -e "datafile='$results/lookup.dat'; olddata='bench/host/lookup-1a9450a.dat'; outfile='docs/bench-host-lookup.png'" \
  bench/host/lookup.gp

echo "== Cortex-M4 flash and RAM"
sh bench/host/m4_size.sh "$build/m4" | tee "$results/m4.md"

echo "== docs/performance.md (generated blocks only)"
python3 bench/host/update_docs.py docs/performance.md host="$results/host.md" \
  rounding="$results/rounding.md" m4="$results/m4.md"

if [ -f "$results/m4insns.json" ] && [ -f "$results/m0.json" ]; then
  if python3 bench/summary.py "$results" >"$results/summary.md.new"; then
    mv "$results/summary.md.new" "$results/summary.md"
    python3 bench/host/update_docs.py docs/performance.md summary="$results/summary.md"
  else
    echo "summary: not rewritten (the other script's results are missing or older; run it)"
  fi
fi

echo "== done: $results/host.md, $results/rounding.md, $results/m4.md, docs/bench-host-*.png"

#!/bin/sh
# Every target figure of docs/performance.md: the core's flash in the
# cortex-m4 preset (what CTest budget_core_flash measures), instructions per
# protocol line on the Cortex-M4 (QEMU mps2-an386, the cortex-m4 preset's
# tests/target/daran-perf.elf) and, as a report, on a Cortex-M0 (QEMU
# microbit, bench/m0), each with the per-function profile of
# `t 1 10 0 25 *83`. Rewrites the generated blocks m4insns and m0 of
# docs/performance.md (and the summary, from bench/summary.py, once
# bench/host/run_all.sh has left its results); results in
# build/bench/results/{m4insns,m0,m4budgets,summary}.*
#
#   bench/target_insns.sh
#
# Needs arm-none-eabi-gcc, qemu-system-arm (7.2: mps2-an386 and microbit),
# a host C compiler for the plugin, python3. About a minute.
set -eu
cd "$(dirname "$0")/.."
results=build/bench/results
mkdir -p "$results"
commit=$(git rev-parse --short HEAD)
dirty=""
[ -n "$(git status --porcelain -- src include 2>/dev/null)" ] && dirty=" with uncommitted changes in src/ or include/"
qemu=$(qemu-system-arm --version | head -1)
gcc=$(arm-none-eabi-gcc --version | head -1)

# issue 20's instruction budgets, as tests/target/CMakeLists.txt gives them to CTest
budgets="--budget 'e (seven lines)<=2000' --budget 'bytes:r longest path<=12' --report 't with checksum<=600' --report 'blank line<=40' --report 'r longest path<=1200' --report 'f<=350' --budget 'CAN read frame<=400' --report 'CAN t frame<=300'"

echo "== cortex-m4 preset: the library and daran-perf.elf"
cmake --preset cortex-m4 >/dev/null
cmake --build build/cortex-m4 --target daran_ascii daran-perf daran_target_sizeof >/dev/null
# the budgets CTest enforces: flash, RAM of an instance, worst-case stack
ctest --test-dir build/cortex-m4 -R "budget_core_flash|budget_drive_ram|budget_core_stack" -V \
  >"$results/m4budgets.txt" 2>&1 || true
{
  echo "Measured on commit $commit$dirty, $gcc \`-Os\` (the \`cortex-m4\` preset, MinSizeRel),"
  echo "$qemu, machine \`mps2-an386\` (Cortex-M4F)."
  echo
  echo "Core flash (\`arm-none-eabi-size -t build/cortex-m4/src/libdaran_ascii.a\`, text + data"
  echo "of the TOTALS line, as CTest \`budget_core_flash\` counts it):"
  echo
  echo '```'
  arm-none-eabi-size -t build/cortex-m4/src/libdaran_ascii.a | tail -1
  echo '```'
  echo
  echo "\`python3 tools/qemu-insn-count/measure_insns.py --elf build/cortex-m4/tests/target/daran-perf.elf --profile \"t with checksum\" $budgets\`"
  echo "(CTest \`perf_insns_per_line\` runs the same, and fails on a --budget that is over):"
  echo
  # shellcheck disable=SC2086
  eval python3 tools/qemu-insn-count/measure_insns.py --elf build/cortex-m4/tests/target/daran-perf.elf \
    --profile "'t with checksum'" $budgets --json "$results/m4insns.json" || true
} >"$results/m4insns.md"
cat "$results/m4insns.md"

echo "== Cortex-M0 (bench/m0)"
{
  echo "Measured on commit $commit$dirty, $qemu, machine \`microbit\` (nRF51822, Cortex-M0, no FPU);"
  echo "\`bench/m0/measure.sh\` (builds with \`bench/m0/build.sh\`, then runs"
  echo "\`python3 tools/qemu-insn-count/measure_insns.py --elf build/bench/m0/daran-m0.elf --machine microbit --profile \"t with checksum\"\`)."
  echo
  M0_JSON="$results/m0.json" sh bench/m0/measure.sh build/bench/m0
} >"$results/m0.md"
cat "$results/m0.md"

python3 bench/host/update_docs.py docs/performance.md m4insns="$results/m4insns.md" m0="$results/m0.md"
if [ -f "$results/host.json" ]; then
  if python3 bench/summary.py "$results" >"$results/summary.md.new"; then
    mv "$results/summary.md.new" "$results/summary.md"
    python3 bench/host/update_docs.py docs/performance.md summary="$results/summary.md"
  else
    echo "summary: not rewritten (the other script's results are missing or older; run it)"
  fi
fi

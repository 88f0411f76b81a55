#!/bin/sh
# Cortex-M0 report (not a budget): build bench/m0's image and count the
# instructions per protocol line under QEMU's `microbit` machine (nRF51822,
# Cortex-M0, no FPU) with the same plugin as the Cortex-M4 figures
# (tools/qemu-insn-count), with the per-function profile of
# `t 1 10 0 25 *83`.
#
#   bench/m0/measure.sh [OUT_DIR]      (default build/bench/m0)
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench/m0}
sh bench/m0/build.sh "$out"
echo
python3 tools/qemu-insn-count/measure_insns.py --elf "$out/daran-m0.elf" --machine microbit \
  --profile "t with checksum" ${M0_JSON:+--json "$M0_JSON"}

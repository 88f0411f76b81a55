#!/usr/bin/env bash
# Plays a one-drive recording into the example firmware under QEMU with
# tools/replay --target qemu: its UART replies must equal daran-sim's
# reference byte for byte. Skipped (77) until the cortex-m4 preset has built
# the firmware, or without qemu-system-arm.
# usage: qemu_replay.sh TOOLS_REPLAY RECORDING EXPECTED
set -uo pipefail
replay=$1
recording=$2
expected=$3
fw=$(cd "$(dirname "$replay")/.." && pwd)/build/cortex-m4/port/mps2-an386
if [ ! -e "$fw/daran-fw.elf" ] || [ ! -e "$fw/daran-fw-lockstep.elf" ]; then
    echo "SKIP: no firmware in $fw (cmake --workflow --preset cortex-m4)"
    exit 77
fi
if ! command -v qemu-system-arm > /dev/null; then
    echo "SKIP: no qemu-system-arm"
    exit 77
fi
"$replay" --target qemu --drives 1 --tick-hz 1000 --expect "$expected" "$recording"

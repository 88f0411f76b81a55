#!/usr/bin/env bash
# CI step: the recorded one-drive sessions (examples/recordings/pick-and-place
# and tuning) played by tools/replay into the example firmware under QEMU
# must give daran-sim's reference replies (tests/sim/replay/*.expected) byte
# for byte. Runs after 30-cortex-m4, which builds the firmware; the same
# CTest cases of the host presets are skipped when that has not happened yet.
# Budget: 30 seconds.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
start=$SECONDS
fails=0
for name in pick-and-place tuning; do
    bash tests/sim/replay/qemu_replay.sh tools/replay examples/recordings/$name.txt \
        tests/sim/replay/$name.expected
    rc=$?
    if [ "$rc" -ne 0 ]; then
        echo "35-replay-qemu: FAILED: $name (exit status $rc; 77 = firmware or QEMU missing)"
        fails=$((fails + 1))
    fi
done
if [ "$fails" -ne 0 ]; then
    echo "35-replay-qemu: FAILED ($fails of 2 recordings) after $((SECONDS - start)) s"
    exit 1
fi
echo "35-replay-qemu: 2 recordings give the simulator's replies through the firmware, in $((SECONDS - start)) s"

#!/usr/bin/env bash
# ci-weight: 15
# ci-after: 30-cortex-m4.sh
# CI step: recorded sessions played by tools/replay into the example firmware
# under QEMU must give daran-sim's reference replies (tests/sim/replay/) byte
# for byte: the one-drive sessions (pick-and-place, tuning) and the vendor's
# three recordings, whose lines for ids 2 and 3 the one-drive firmware leaves
# unanswered exactly as drive 1 of `daran-sim --drives 1` does (their
# .1drive references). Runs after 30-cortex-m4, which builds the firmware; the
# same CTest cases of the host presets are skipped when that has not happened
# yet. Budget: 60 seconds.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
start=$SECONDS
fails=0
total=0
for entry in pick-and-place:pick-and-place tuning:tuning \
             vendor-python-client:vendor-python-client.1drive \
             vendor-stm32-client:vendor-stm32-client.1drive \
             vendor-python-defaults:vendor-python-defaults.1drive; do
    name=${entry%%:*}
    reference=${entry#*:}
    total=$((total + 1))
    bash tests/sim/replay/qemu_replay.sh tools/replay examples/recordings/$name.txt \
        tests/sim/replay/$reference.expected
    rc=$?
    if [ "$rc" -ne 0 ]; then
        echo "35-replay-qemu: FAILED: $name (exit status $rc; 77 = firmware or QEMU missing)"
        fails=$((fails + 1))
    fi
done
if [ "$fails" -ne 0 ]; then
    echo "35-replay-qemu: FAILED ($fails of $total recordings) after $((SECONDS - start)) s"
    exit 1
fi
echo "35-replay-qemu: $total recordings give the simulator's replies through the firmware, in $((SECONDS - start)) s"

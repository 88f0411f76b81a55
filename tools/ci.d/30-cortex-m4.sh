#!/bin/sh
# ci-weight: 35
# CI step: the Cortex-M4 build (arm-none-eabi-gcc -Os), the example firmware
# and its tests under QEMU mps2-an386: the Unity unit suites of tests/unit and
# tests/number as firmware images (target_unit_*, target_number_*),
# transcripts, budgets. Budget: under 3 minutes on the 2-core CI machine.
set -eu
cd "$(dirname "$0")/../.."

. tools/ci-packages.sh
# shellcheck disable=SC2046
install_packages 30-cortex-m4 $(arm_packages_missing)

# Unity for the target suites: the same copy outside the tree as the host's
# (a no-op when it is there already).
tools/fetch-unity

start=$(date +%s)
status=0
cmake --workflow --preset cortex-m4 || status=$?
# The CAN front end's flash, reported while it is over its budget (the test
# carries the label report-only then, and the workflow leaves it out).
can_flash=$(ctest --test-dir build/cortex-m4 -R '^budget_(can|bridge)_flash$' -V 2>/dev/null |
    sed -n 's/.*members matching [^:]*: \([0-9]* bytes, budget [0-9]*\).*/\1/p' | paste -sd ';' -)
elapsed=$(( $(date +%s) - start ))
if [ "$status" -eq 0 ]; then
    echo "30-cortex-m4: PASS (firmware and test images built, unit suites and transcripts under QEMU, budgets) in ${elapsed}s; CAN front end; bridge flash: ${can_flash:-not measured}"
else
    echo "30-cortex-m4: FAIL (exit $status) in ${elapsed}s: see the CTest output above" \
         "(budget_* tests print the measured figure against the limit)"
fi
exit "$status"

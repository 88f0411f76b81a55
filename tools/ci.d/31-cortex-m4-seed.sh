#!/bin/sh
# ci-weight: 15
# CI step: the seed-only build on the Cortex-M4 (arm-none-eabi-gcc -Os): the
# `cortex-m4-seed` preset, the core built with tests/config/seed_options.h
# (the seed document's protocol: 57 property rows, no discovery, telemetry,
# port commands or S-curve). Its workflow builds the core, the example
# firmware and the number suites' images, and runs the number suites under
# QEMU and the RAM, stack and forbidden-symbol budgets. Then the core's flash
# against its 8,192-byte budget (issue 20): budget_core_flash carries the
# label report-only while the build is over it (DARAN_BUDGET_FLASH_ENFORCED
# OFF in the preset), so this step prints the figure and the bytes over and
# does not fail on it; every other test fails the step. About 15 s.
set -eu
cd "$(dirname "$0")/../.."

. tools/ci-packages.sh
# shellcheck disable=SC2046
install_packages 31-cortex-m4-seed $(arm_packages_missing)

tools/fetch-unity

start=$(date +%s)
status=0
cmake --workflow --preset cortex-m4-seed || status=$?

# The flash figure, enforced or not: the per-object table and the total.
flash_log=build/cortex-m4-seed/seed-flash.log
flash_status=0
ctest --test-dir build/cortex-m4-seed -R '^budget_core_flash$' --output-on-failure \
    >"$flash_log" 2>&1 || flash_status=$?
sed -n '/text.*data.*bss/,/core flash/p' "$flash_log" | sed 's/ (ex .*libdaran_ascii.a)//'
figure=$(sed -n 's/.*core flash (text + data)[^:]*: \([0-9]*\) bytes, budget \([0-9]*\).*/\1 bytes against \2/p' "$flash_log")
if [ -z "$figure" ]; then
    cat "$flash_log"
    echo "31-cortex-m4-seed: FAIL: budget_core_flash printed no figure"
    status=1
elif [ "$flash_status" -ne 0 ]; then
    over=$(sed -n 's/.*OVER BUDGET by \([0-9]*\) bytes.*/\1/p' "$flash_log")
    enforced=$(sed -n 's/^DARAN_BUDGET_FLASH_ENFORCED:BOOL=//p' build/cortex-m4-seed/CMakeCache.txt)
    if [ "$enforced" = "OFF" ]; then
        figure="$figure: OVER by $over bytes (reported, not enforced: docs/performance.md, seed-only build)"
    else
        figure="$figure: OVER by $over bytes"
        status=1
    fi
else
    figure="$figure: within budget"
    enforced=$(sed -n 's/^DARAN_BUDGET_FLASH_ENFORCED:BOOL=//p' build/cortex-m4-seed/CMakeCache.txt)
    [ "$enforced" = "ON" ] ||
        figure="$figure (enforce it: DARAN_BUDGET_FLASH_ENFORCED ON in the cortex-m4-seed preset)"
fi

elapsed=$(( $(date +%s) - start ))
if [ "$status" -eq 0 ]; then
    echo "31-cortex-m4-seed: PASS (number suites under QEMU, RAM/stack/symbol budgets) in ${elapsed}s; core flash $figure"
else
    echo "31-cortex-m4-seed: FAIL (exit $status) in ${elapsed}s: see the CTest output above; core flash ${figure:-not measured}"
fi
exit "$status"

#!/bin/sh
# ci-weight: 150
# CI step: the core's Unity unit suites (tests/unit, tests/number and the
# number sample) as firmware images on four more Cortex-M CPUs under QEMU,
# with the core's flash and the instructions of `t 1 10 0 25 *83` on each:
#   cortex-m0   QEMU microbit     (nRF51822: no FPU, no hardware divide)
#   cortex-m3   QEMU mps2-an385   (no FPU)
#   cortex-m7   QEMU mps2-an500   (FPv5, double precision)
#   cortex-m33  QEMU mps2-an505   (FPv5 single precision, Secure state)
#   big-endian  qemu-ppc          (32-bit PowerPC, glibc; host-style programs)
# One `cmake --workflow --preset <name>` each (port/boards, docs/targets.md),
# then one summary line per target. Exits non-zero if any workflow or
# summary fails. Budget: well under 3 minutes on the 2-core CI machine.
set -eu
cd "$(dirname "$0")/../.."

presets=${MORE_TARGETS:-"cortex-m0 cortex-m3 cortex-m7 cortex-m33 big-endian"}

. tools/ci-packages.sh
missing=$(arm_packages_missing)
[ -e /usr/lib/arm-none-eabi/newlib/thumb/v6-m/nofp/libc.a ] || missing="$missing libnewlib-arm-none-eabi"
command -v cc >/dev/null 2>&1 || missing="$missing gcc" # the counting plugin
command -v powerpc-linux-gnu-gcc >/dev/null 2>&1 || missing="$missing gcc-powerpc-linux-gnu"
[ -e /usr/powerpc-linux-gnu/lib/libm.so.6 ] || missing="$missing libc6-dev-powerpc-cross"
command -v qemu-ppc >/dev/null 2>&1 || missing="$missing qemu-user"
# shellcheck disable=SC2086
install_packages 32-more-targets $(printf '%s\n' $missing | sort -u)

tools/fetch-unity

start=$(date +%s)
status=0
summary=""
for preset in $presets; do
    t0=$(date +%s)
    if cmake --workflow --preset "$preset"; then
        line=$(python3 tests/target/target_summary.py "build/$preset") || {
            status=1
            line="$line (incomplete: see the CTest output above)"
        }
        summary="$summary
  $line, workflow $(( $(date +%s) - t0 ))s"
    else
        status=1
        summary="$summary
  $preset: FAIL (see the output above)"
    fi
done
elapsed=$(( $(date +%s) - start ))
echo
echo "32-more-targets:$summary"
if [ "$status" -eq 0 ]; then
    echo "32-more-targets: PASS ($presets) in ${elapsed}s"
else
    echo "32-more-targets: FAIL in ${elapsed}s"
fi
exit "$status"

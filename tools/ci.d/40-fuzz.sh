#!/bin/sh
# ci-weight: 270
# CI step: build the libFuzzer harnesses (the `fuzz` preset: clang-14, ASan +
# UBSan) and fuzz each for a fixed time from the stored corpus. Any crash,
# sanitizer report, invariant violation, leak or timeout fails the step.
#
# Budget: 8 harnesses, two at a time (the machine has 2 cores): the four
# established ones (stream line number sim) 25 s each, the four newest (port:
# the example port's tables; telemetry: reports between requests; can: CAN
# frames; bridge: lines and frames through a gateway) 40 s each, so 2 min 10 s
# of fuzzing plus the build, beside CI's other steps (shortened from 30 and
# 45 s when the Python and update suites came in: CI stays within 15 min);
# see docs/security.md.
# FUZZ_SECONDS sets one time for every harness (e.g. FUZZ_SECONDS=1800 for
# the long run before a release).
set -u

cd "$(dirname "$0")/../.." || exit 1
# harness:seconds, run in pairs in this order (pair harnesses of equal time)
schedule="stream:25 line:25 number:25 sim:25 telemetry:40 port:40 can:40 bridge:40"
if [ -n "${FUZZ_SECONDS:-}" ]; then
    schedule=$(for e in $schedule; do printf '%s:%s ' "${e%%:*}" "$FUZZ_SECONDS"; done)
    schedule=${schedule% }
fi

need_install=""
command -v clang-14 >/dev/null 2>&1 || need_install="clang-14"
dpkg -s libclang-rt-14-dev >/dev/null 2>&1 || need_install="$need_install libclang-rt-14-dev"
if [ -n "$need_install" ]; then
    echo "40-fuzz: installing $need_install"
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    # shellcheck disable=SC2086  # several package names, split on purpose
    if ! { $SUDO apt-get update -qq && $SUDO apt-get install -y --no-install-recommends $need_install; }; then
        echo "40-fuzz: FAILED to install $need_install"
        exit 1
    fi
fi

harnesses=""
targets=""
for e in $schedule; do
    harnesses="$harnesses ${e%%:*}"
    targets="$targets fuzz_${e%%:*}"
done
harnesses=${harnesses# }

echo "40-fuzz: configuring and building the fuzz preset"
if ! cmake --preset fuzz >/tmp/40-fuzz-configure.log 2>&1; then
    cat /tmp/40-fuzz-configure.log
    echo "40-fuzz: FAILED (configure)"
    exit 1
fi
# shellcheck disable=SC2086
if ! cmake --build --preset fuzz -j2 --target $targets; then
    echo "40-fuzz: FAILED (build)"
    exit 1
fi

bin=build/fuzz/tests/fuzz
work=$(mktemp -d /tmp/40-fuzz.XXXXXX)
trap 'rm -rf "$work"' EXIT

run_one() {
    h=${1%%:*}
    seconds=${1##*:}
    mkdir -p "$work/$h/corpus" "$work/$h/artifacts"
    # Fuzz a copy: new inputs stay out of the repository.
    cp tests/corpus/"$h"/* "$work/$h/corpus/" 2>/dev/null
    dirs="$work/$h/corpus"
    [ -d tests/corpus/regressions/"$h" ] && dirs="$dirs tests/corpus/regressions/$h"
    max_len=2048
    [ "$h" = sim ] && max_len=4096
    # shellcheck disable=SC2086
    nice -n 10 "$bin/fuzz_$h" -max_total_time="$seconds" -max_len=$max_len -timeout=20 \
        -rss_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$work/$h/artifacts/" \
        $dirs >"$work/$h/log" 2>&1
    echo $? >"$work/$h/rc"
}

echo "40-fuzz: fuzzing two at a time (harness:seconds): $schedule"
# shellcheck disable=SC2086  # the list, split on purpose
set -- $schedule
while [ $# -gt 0 ]; do
    run_one "$1" &
    p1=$!
    p2=""
    if [ $# -gt 1 ]; then
        run_one "$2" &
        p2=$!
    fi
    wait $p1
    [ -n "$p2" ] && wait $p2
    shift
    [ $# -gt 0 ] && shift
done

failed=0
for h in $harnesses; do
    rc=$(cat "$work/$h/rc" 2>/dev/null || echo 99)
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/$h/log" | grep -o '[0-9]*$')
    cov=$(grep -o 'cov: [0-9]*' "$work/$h/log" | tail -n 1)
    if [ "$rc" -ne 0 ]; then
        failed=1
        echo "40-fuzz: fuzz_$h FAILED (exit $rc); the end of its log:"
        grep -v '^#' "$work/$h/log" | tail -n 40
        for a in "$work/$h/artifacts"/*; do
            [ -f "$a" ] || continue
            echo "40-fuzz: reproducer $(basename "$a") (base64):"
            base64 "$a" | head -c 4000
            echo
        done
    else
        echo "40-fuzz: fuzz_$h ok: ${execs:-?} executions, $cov"
    fi
done

# An adopter's port through daran_ascii_add_fuzz_target(): port/minimal, 20 s
# from the vendor clients' recordings (tests/adopter-fuzz).
echo "40-fuzz: adopter_fuzz_run (port/minimal through the kit's fuzz targets): 10 s of frames, then 10 s of lines"
if ! nice -n 10 cmake --build --preset fuzz -j2 --target adopter_fuzz_run >"$work/adopter.log" 2>&1; then
    failed=1
    echo "40-fuzz: adopter_fuzz FAILED; the end of its log:"
    grep -v '^#' "$work/adopter.log" | tail -n 40
    ls build/fuzz/tests/adopter-fuzz/adopter_fuzz_findings/
fi

if [ $failed -ne 0 ]; then
    echo "40-fuzz: FAILED: add each reproducer to tests/corpus/regressions/<harness>/<what-it-guards>"
    exit 1
fi
echo "40-fuzz: passed (harness:seconds $schedule; no finding)"

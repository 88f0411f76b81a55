#!/usr/bin/env bash
# ci-weight: 25
# CI step: the benchmark guards (CTest label `bench`) in the `release` build
# (gcc -O2, no sanitizers); only their driver is built, since every other
# suite ran in the `host` workflow and the -O2 build of every target is
# compiled (and its suites run) by 50-package's release step:
#   bench_core_instructions                 the core's callgrind instruction count on
#                                           bench/streams/reference.txt stays within
#                                           +10% of bench/host/reference.txt
#   bench_baseline_makes_the_same_hal_calls the baseline yardstick still agrees with
#                                           daran-ascii on every recorded stream
#   bench_handwritten_same_up_to_rounding   the hand-written yardstick agrees with it
#                                           up to (proven, counted) float rounding
# Installs valgrind when missing (without it the guard would only be skipped).
# Budget: 1 minute.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
start=$SECONDS

if ! command -v valgrind >/dev/null 2>&1; then
  echo "20-bench: installing valgrind"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  if ! { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends valgrind >/dev/null; }; then
    echo "20-bench: FAILED to install valgrind"
    exit 1
  fi
fi

log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! { cmake --preset release && cmake --build --preset release --target daran_bench_driver &&
       ctest --preset release -L '^bench$'; } 2>&1 | tee "$log"; then
  echo "20-bench: FAILED (release build of the bench driver, or a bench test; see the output above) after $((SECONDS - start)) s"
  exit 1
fi
# The guard must have run, not been skipped.
if ! grep -Eq 'bench_core_instructions \.+ +Passed' "$log"; then
  echo "20-bench: FAILED: bench_core_instructions did not run and pass in the release preset"
  exit 1
fi
echo "20-bench: the bench guards passed in the release build, in $((SECONDS - start)) s"

#!/bin/sh
# Runs the core's unit tests under other compile-time options of
# daran_config.h (LF-only replies, ring and line sizes, help text, the
# multi-motor commands, CAN, the bridge, discovery, telemetry, the port's
# commands or S-curves left out, and the last four together), each in its own build directory
# (build/unit-opt-NAME), gcc + ASan + UBSan. Tests of a feature that is
# compiled out skip themselves.
# Usage: tests/unit/run_option_matrix.sh [NAME "FLAGS"]...   (no arguments: the
# default matrix). Exit status: the number of option sets that failed.
set -u
src=$(cd "$(dirname "$0")/../.." && pwd)
# the areas of tests/unit/areas.cmake, so a new suite joins the matrix
areas=$(sed -n '/^set(DARAN_UNIT_AREAS/,/^)/{/^ /p}' "$src/tests/unit/areas.cmake")
[ -n "$areas" ] || { echo "no unit areas found in tests/unit/areas.cmake"; exit 1; }

run_one() {
  name=$1
  flags=$2
  dir=$src/build/unit-opt-$name
  if ! cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_C_COMPILER=gcc -DCMAKE_BUILD_TYPE=Debug \
      -DDARAN_SANITIZE=ON -DDARAN_BUILD_SIM=OFF -DDARAN_BUILD_DEMO=OFF -DCMAKE_C_FLAGS_DEBUG=-O0 \
      -DCMAKE_C_FLAGS="$flags" > "$dir.configure.log" 2>&1; then
    echo "$name: configure failed (see $dir.configure.log)"
    return 1
  fi
  targets=""
  for a in $areas; do targets="$targets tests/unit/unit_$a"; done
  # shellcheck disable=SC2086
  if ! ninja -C "$dir" $targets > "$dir.build.log" 2>&1; then
    echo "$name: build failed (see $dir.build.log)"
    return 1
  fi
  bad=0
  for a in $areas; do
    if ! "$dir/tests/unit/unit_$a" > "$dir.$a.log" 2>&1; then
      echo "$name: unit_$a failed (see $dir.$a.log)"
      bad=1
    fi
  done
  [ $bad -eq 0 ] && echo "$name: all unit tests pass"
  return $bad
}

failed=0
if [ $# -eq 0 ]; then
  set -- lf "-DDARAN_REPLY_CRLF=0" \
         small-ring "-DDARAN_RX_RING_SIZE=16 -DDARAN_LINE_MAX=200" \
         big-ring "-DDARAN_RX_RING_SIZE=1024 -DDARAN_LINE_MAX=96" \
         no-help "-DDARAN_ENABLE_HELP=0" \
         update "-DDARAN_ENABLE_UPDATE=1" \
         no-multi "-DDARAN_ENABLE_MULTI_MOTOR=0" \
         no-can "-DDARAN_ENABLE_CAN=0" \
         no-bridge "-DDARAN_ENABLE_CAN_BRIDGE=0" \
         no-discovery "-DDARAN_ENABLE_DISCOVERY=0" \
         no-telemetry "-DDARAN_ENABLE_TELEMETRY=0" \
         no-port-commands "-DDARAN_ENABLE_PORT_COMMANDS=0" \
         no-s-curve "-DDARAN_ENABLE_S_CURVE=0" \
         no-features "-DDARAN_ENABLE_DISCOVERY=0 -DDARAN_ENABLE_TELEMETRY=0 -DDARAN_ENABLE_PORT_COMMANDS=0 -DDARAN_ENABLE_S_CURVE=0"
fi
# Two option sets at a time: one configures or links while the other
# compiles (each build is -j2 already; a set's lines are printed whole).
out=$(mktemp -d "${TMPDIR:-/tmp}/daran-matrix.XXXXXX")
while [ $# -ge 2 ]; do
  run_one "$1" "$2" >"$out/a" 2>&1 &
  a=$!
  b=""
  if [ $# -ge 4 ]; then
    run_one "$3" "$4" >"$out/b" 2>&1 &
    b=$!
  fi
  wait $a || failed=$((failed + 1))
  cat "$out/a"
  if [ -n "$b" ]; then
    wait $b || failed=$((failed + 1))
    cat "$out/b"
    shift 2
  fi
  shift 2
done
rm -rf "$out"
exit $failed

#!/bin/sh
# CTest guard (label bench): the core's instruction count on the reference
# stream must stay within 10% above the committed figure for this compiler.
#
#   check_reference.sh DRIVER STREAM REFERENCE_FILE COMPILER_KEY
#
# Exit 0: within budget. 1: over budget (or the run failed). 77: skipped
# (no valgrind, or no committed figure for this compiler).
# The count covers daran_process_line() and everything it calls, for every
# line of the stream (callgrind --toggle-collect: deterministic).
set -u
driver=$1 stream=$2 reference=$3 key=$4
if ! command -v valgrind >/dev/null 2>&1; then
  echo "SKIP: valgrind not installed"
  exit 77
fi
expected=$(awk -v key="$key" '$1 == key { print $2 }' "$reference")
if [ -z "$expected" ]; then
  echo "SKIP: no reference figure for compiler $key in $reference"
  exit 77
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
if ! valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect=daran_process_line \
    "$driver" ours "$stream" >/dev/null 2>&1; then
  echo "FAIL: callgrind run of $driver failed"
  exit 1
fi
measured=$(awk '/^totals:/ { print $2 }' "$out")
lines=$(grep -c '' "$stream")
limit=$((expected + expected / 10))
echo "core instructions on $(basename "$stream") ($lines lines, $key): measured $measured," \
  "reference $expected, limit $limit (+10%); per line: $((measured / lines)) vs $((expected / lines))"
if [ "$measured" -gt "$limit" ]; then
  echo "FAIL: the core got more than 10% slower than bench/host/reference.txt"
  echo "      (if that is intended, refresh the figure: bench/host/run_all.sh --reference)"
  exit 1
fi
echo "PASS"

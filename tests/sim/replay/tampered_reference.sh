#!/usr/bin/env bash
# tools/replay must fail (exit 1, a unified diff on stdout) when the replies
# differ from the reference: one digit changed, the last reply line missing,
# an extra line, a lost final newline. The untouched reference passes.
# usage: tampered_reference.sh DARAN_SIM TOOLS_REPLAY RECORDING EXPECTED [REPLAY OPTIONS...]
set -uo pipefail
sim=$1
replay=$2
recording=$3
expected=$4
shift 4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

check() { # NAME: the reference in $tmp/ref must be refused
    "$replay" --sim "$sim" "$@" --expect "$tmp/ref" "$recording" > "$tmp/diff" 2> "$tmp/err"
    local rc=$?
    [ "$rc" -eq 1 ] || { fail "$name: exit status $rc, want 1"; cat "$tmp/err" >&2; }
    grep -q '^@@ ' "$tmp/diff" || fail "$name: no unified diff hunk"
    if ! grep -q '^--- ' "$tmp/diff" || ! grep -q '^+++ ' "$tmp/diff"; then
        fail "$name: no diff header"
    fi
}

"$replay" --sim "$sim" "$@" --expect "$expected" "$recording" > /dev/null 2>&1 ||
    fail "the untouched reference does not pass"

name="one digit changed"
# the first digit of the file, 1 -> 2 or anything else -> 1
awk 'done || !match($0, /[0-9]/) { print; next }
     { d = substr($0, RSTART, 1); print substr($0, 1, RSTART - 1) (d == "1" ? "2" : "1") substr($0, RSTART + 1); done = 1 }' \
    "$expected" > "$tmp/ref"
cmp -s "$expected" "$tmp/ref" && fail "$name: the tampering changed nothing"
check "$@"
if ! grep -q '^-[^-]' "$tmp/diff" || ! grep -q '^+[^+]' "$tmp/diff"; then
    fail "$name: the diff shows no changed line"
fi

name="last line missing"
sed '$d' "$expected" > "$tmp/ref"
check "$@"

name="extra line"
{ cat "$expected"; echo "0 0"; } > "$tmp/ref"
check "$@"

name="final newline lost"
head -c -1 "$expected" > "$tmp/ref"
check "$@"

[ "$fails" -eq 0 ] && echo "tools/replay refuses tampered references: all checks passed"
exit "$fails"

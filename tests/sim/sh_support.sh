# What the daran-sim shell tests share, sourced after `set -uo pipefail`: a
# scratch folder ($tmp) removed at exit, failures counted by fail(), and
# verdict NAME: says "NAME: all checks passed" when none failed, and exits
# 0, or 1 after failures.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
verdict() {
    [ "$fails" -eq 0 ] && echo "$1: all checks passed"
    exit $((fails > 0))
}

#!/usr/bin/env bash
# daran-sim's CAN options and directives at the command line: --help names
# them; `!can` and the can- faults without --can, malformed `!can` frames,
# bad can-lose counts and unknown drives are reported and skipped (the run
# goes on, exit 1); a frame on a bus that is off is said on stderr without
# failing the run; --can leaves the ASCII replies as they were.
# usage: can_cli.sh DARAN_SIM
set -uo pipefail
sim=$1
# shellcheck source=sh_support.sh
. "$(dirname "$0")/sh_support.sh"

"$sim" --help > "$tmp/help" || fail "--help exit status"
for word in --can --slcan --usbcan '!can' can-lose can-mute can-unplug can-bus-off can-recover; do
    grep -q -- "$word" "$tmp/help" || fail "--help does not mention $word"
done

# without --can: every CAN directive is refused, the ASCII line still runs
printf '!can 01E 00\n!fault 1 can-mute\n!fault 0 can-lose 2\nf 1\n' | "$sim" > "$tmp/out" 2> "$tmp/err"
rc=$?
[ "$rc" -eq 1 ] || fail "CAN directives without --can: exit status $rc, want 1"
[ "$(tr -d '\r' < "$tmp/out")" = "0 0" ] || fail "without --can: the run did not go on"
[ "$(grep -c 'needs --can' "$tmp/err")" -eq 3 ] || fail "without --can: want 3 'needs --can' messages"

# with --can: malformed frames and faults, each reported once
printf '%s\n' '!can' '!can 800 00' '!can 1234' '!can 01E 0' '!can 01E 00 00 00 00 00 00 00 00 00' \
    '!can 01E R9' '!fault 1 can-lose 0' '!fault 1 can-lose x' '!fault 1 can-mute 2' \
    '!fault 9 can-unplug' 'f 1' | "$sim" --can > "$tmp/out" 2> "$tmp/err"
rc=$?
[ "$rc" -eq 1 ] || fail "bad CAN directives: exit status $rc, want 1"
[ "$(tr -d '\r' < "$tmp/out")" = "0 0" ] || fail "bad CAN directives: the run did not go on"
[ "$(grep -c 'daran-sim: line' "$tmp/err")" -eq 10 ] || fail "bad CAN directives: want 10 messages"

# a frame on a bus that is off: said on stderr, not a failed run
printf '!fault 0 can-bus-off\n!can 01E 19 79 03 00 00 00 00 00\n!advance 0.01\n' \
    | "$sim" --can > "$tmp/out" 2> "$tmp/err"
rc=$?
[ "$rc" -eq 0 ] || fail "bus off: exit status $rc, want 0"
[ -s "$tmp/out" ] && fail "bus off: a frame crossed it"
grep -q 'the bus is off' "$tmp/err" || fail "bus off: no message"

# 33 frames queued without letting time run: the 33rd does not fit
{ for k in $(seq 33); do echo '!can 7FF'; done; } | "$sim" --can > /dev/null 2> "$tmp/err"
[ $? -eq 1 ] || fail "a full console queue is not an error"
grep -q 'already wait' "$tmp/err" || fail "a full console queue: no message"

# --can changes nothing on the ASCII side
session='r axis1.config.can_node_id\nq 2 30\n!advance 1\nf 2\ni 1\n'
printf "$session" | "$sim" --drives 2 > "$tmp/plain" 2> /dev/null
printf "$session" | "$sim" --drives 2 --can > "$tmp/can" 2> /dev/null
cmp -s "$tmp/plain" "$tmp/can" || fail "--can changed the ASCII replies"

verdict "daran-sim CAN command line"

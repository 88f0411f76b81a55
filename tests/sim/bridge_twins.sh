#!/usr/bin/env bash
# A bridged answer is the line the remote drive prints itself: the same
# session on three drives, once with --bridge (ids 2 and 3 reached through
# drive 1's bridge over CAN) and once on the plain multi-drop line (each
# drive answers its own lines), gives the same ASCII replies: floats,
# integers, signed values, the 64-bit serial number, error registers, a
# value written through the bridge, checksummed answers. Then --help names
# --bridge, and --bridge sends the link's lines to drive 1 alone, and a
# session recorded with --bridge is replayed with it.
# usage: bridge_twins.sh DARAN_SIM
set -uo pipefail
sim=$1
# shellcheck source=sh_support.sh
. "$(dirname "$0")/sh_support.sh"

# drive 3 overheated (its error registers are not 0) and drive 2 moved, so
# the values are not all zeros; then every query kind, for ids 2 and 3
cat > "$tmp/session" <<'SESSION'
!fault 3 overtemp
t 2 -37.5 0 20
!advance 3
w axis2.output_shaft.vel_limit 61.25
w axis3.motor.config.direction -1
f 2
f 3
g 2
i 3
e 3
e 2
r serial_number 2
r axis2.output_shaft.vel_limit
r axis2.output_shaft.pos_setpoint
r axis3.motor.config.direction
r axis3.encoder.config.cpr
r axis3.config.can_node_id
r axis2.config.extra_setting.enable_reply_state
r axis3.error
r axis3.motor.config.pole_pairs
f 2 *84
e 3 *86
r serial_number 3 *61
SESSION
"$sim" --drives 3 --bridge < "$tmp/session" > "$tmp/bridged" 2> "$tmp/bridged.err" ||
    fail "--bridge: exit status $?: $(cat "$tmp/bridged.err")"
"$sim" --drives 3 < "$tmp/session" > "$tmp/plain" 2> "$tmp/plain.err" ||
    fail "plain line: exit status $?: $(cat "$tmp/plain.err")"
grep -v '^can ' "$tmp/bridged" > "$tmp/answers"
if ! cmp -s "$tmp/plain" "$tmp/answers"; then
    fail "bridged answers differ from the drives' own:"
    diff "$tmp/plain" "$tmp/answers" >&2
fi
[ "$(grep -c '^error' "$tmp/plain")" -eq 0 ] || fail "the session has error replies"
# every query crossed the bus: 2 reads for each f g and serial number, 4 for
# i, 7 for each e, 1 for each r (requests and replies both seen)
want=$(( (2 * 4 + 2 + 4 + 7 * 3 + 8 + 2) * 2 + 3 ))
got=$(grep -c '^can ' "$tmp/bridged")
[ "$got" -eq "$want" ] || fail "$got frames on the bus, want $want"

"$sim" --help | grep -q -- '--bridge' || fail "--help does not mention --bridge"
# the link reaches drive 1 alone: a broadcast read is answered once (by
# drive 1) with --bridge, by every drive without
printf 'r axis0.config.can_node_id\n' | "$sim" --drives 3 --bridge > "$tmp/one" 2> /dev/null
[ "$(cat "$tmp/one")" = "$(printf '1\r')" ] || fail "--bridge: a broadcast read answered: $(cat -A "$tmp/one")"

# a session recorded with --bridge replays with --bridge (tools/replay reads
# it from the header): `f 4` (no such drive) is answered `error: no reply`
# by the bridge, and not at all on the plain line
printf 'f 2\nf 4\nr axis3.config.can_node_id\n' |
    "$sim" --drives 3 --bridge --record "$tmp/rec" > "$tmp/rec.out" 2> /dev/null ||
    fail "--bridge --record: exit status $?"
grep -v '^can ' "$tmp/rec.out" > "$tmp/rec.answers"
grep -q 'no reply' "$tmp/rec.answers" || fail "the recorded session has no bridge-only answer"
replay=$(dirname "$0")/../../tools/replay
if "$replay" --sim "$sim" "$tmp/rec" > "$tmp/replayed" 2> "$tmp/replayed.err"; then
    grep -v '^can ' "$tmp/replayed" > "$tmp/replayed.answers"
    cmp -s "$tmp/rec.answers" "$tmp/replayed.answers" ||
        { fail "tools/replay of a --bridge recording answers otherwise:"; diff "$tmp/rec.answers" "$tmp/replayed.answers" >&2; }
else
    fail "tools/replay: $(cat "$tmp/replayed.err")"
fi

verdict "daran-sim --bridge: bridged answers are the remote's own"

#!/usr/bin/env bash
# daran-sim --record, then tools/replay of what it wrote: the recording holds
# exactly the protocol lines received (bytes, times, no directives) and the
# replay gives back the original run's replies byte for byte. Also the
# --record errors and a recording taken on --pty in real time.
# usage: record_roundtrip.sh DARAN_SIM TOOLS_REPLAY
set -uo pipefail
sim=$1
replay=$2
tmp=$(mktemp -d)
sim_pid=
# shellcheck disable=SC2317 # called by the trap
cleanup() {
    [ -n "$sim_pid" ] && kill "$sim_pid" 2> /dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

# A session with what a recording must keep exact: trailing spaces, a tab,
# checksums, an empty line, error replies, times that round to ticks
# (0.0126 s at 8 kHz), drives answering together, and a last line without
# its newline. Only !advance and comments: the other directives are not
# protocol lines and are not recorded.
printf '%s\n' \
    '!# round trip' \
    'r axis0.config.can_node_id ' \
    'f 1 ' \
    'q 1 90 60 60' \
    'ms 2 45 1.5 10' \
    'ms 3 -30 1.5 10' \
    'mq 0 0' \
    '!advance 0.0126' \
    'f 1' \
    '' \
    $'f\t2 ' \
    '!advance 0.25' \
    'f 2 *87' \
    'f 1 *99' \
    'bogus 1' \
    'r axis3.controller.trajectory_done' \
    '!advance 1.5' \
    'r axis2.controller.trajectory_done' \
    'w axis1.controller.config.pos_gain 25' \
    'r axis1.controller.config.pos_gain' \
    '!advance 0.0001' > "$tmp/session"
printf 'g 3' >> "$tmp/session"

"$sim" --drives 3 --tick-hz 8000 --record "$tmp/rec.txt" < "$tmp/session" > "$tmp/out" 2> /dev/null
rc=$?
[ "$rc" -eq 0 ] || fail "recorded run exit status $rc"
[ -s "$tmp/out" ] || fail "the recorded run gave no replies"
grep -q '^error' "$tmp/out" || fail "the session's error replies are missing"

# The format: `#` header lines, then SECONDS<TAB>bytes for every protocol
# line received, in order, and nothing else.
grep -v '^#' "$tmp/rec.txt" | grep -Ev $'^[0-9]+\\.[0-9]+\t' && fail "a line is not SECONDS<TAB>line"
grep -v '^!' "$tmp/session" > "$tmp/sent" # grep ends the last line, as the recording does
grep -v '^#' "$tmp/rec.txt" | cut -f2- > "$tmp/recorded"
cmp -s "$tmp/sent" "$tmp/recorded" || fail "the recorded bytes are not the lines sent"
grep -q '^# daran-sim --drives 3 --tick-hz 8000$' "$tmp/rec.txt" || fail "no header with the options"
# 0.0126 s at 8 kHz is 101 ticks: recorded as 0.012625 (exact)
grep -q $'^0\\.012625\tf 1$' "$tmp/rec.txt" || fail "time of a line after !advance 0.0126"
# !advance 0.0001 is 0.8 tick: rounded to 1
grep -q $'^1\\.762750\tg 3$' "$tmp/rec.txt" || fail "time of the last line"

# Replayed with the options of the header, then given explicitly.
"$replay" --sim "$sim" --expect "$tmp/out" "$tmp/rec.txt" 2> /dev/null ||
    fail "replay (options from the header) differs from the recorded run"
"$replay" --sim "$sim" --drives 3 --tick-hz 8000 --expect "$tmp/out" "$tmp/rec.txt" 2> /dev/null ||
    fail "replay with --drives 3 --tick-hz 8000 differs"
"$replay" --sim "$sim" "$tmp/rec.txt" > "$tmp/again" 2> /dev/null
cmp -s "$tmp/out" "$tmp/again" || fail "replay to stdout differs"
"$replay" --sim "$sim" --drives 1 --expect "$tmp/out" "$tmp/rec.txt" > /dev/null 2>&1
rc=$?
[ "$rc" -eq 1 ] || fail "replay on another bus: exit status $rc, want 1 (differ)"

# Recording the replay gives back the recording: same lines, same times.
"$replay" --session "$tmp/rec.txt" > "$tmp/replayed-session"
"$sim" --drives 3 --tick-hz 8000 --record "$tmp/rec2.txt" < "$tmp/replayed-session" > /dev/null 2>&1
cmp -s "$tmp/rec.txt" "$tmp/rec2.txt" || fail "recording the replay changed the recording"

# --record errors and --help
"$sim" --record /nonexistent/dir/rec.txt < /dev/null > "$tmp/o" 2> "$tmp/e"
rc=$?
[ "$rc" -eq 2 ] || fail "--record to a bad path: exit status $rc, want 2"
grep -q 'daran-sim: --record' "$tmp/e" || fail "--record to a bad path: no message"
"$sim" --record < /dev/null > /dev/null 2>&1
[ $? -eq 2 ] || fail "--record without FILE: want exit status 2"
"$sim" --help | grep -q -- '--record FILE' || fail "--help does not document --record"
printf 'x\n' > "$tmp/bad.txt"
"$replay" --sim "$sim" "$tmp/bad.txt" > /dev/null 2>&1
[ $? -eq 2 ] || fail "replay of a file that is not a recording: want exit status 2"
printf '0.1\t!advance 1\n' > "$tmp/bang.txt"
"$replay" --sim "$sim" "$tmp/bang.txt" > /dev/null 2>&1
[ $? -eq 2 ] || fail "replay of a line starting with '!': want exit status 2"

# --pty: lines arrive in pieces through the pseudo-terminal, and are
# recorded when their newline comes, with the real time since start.
if [ -e /dev/ptmx ]; then
    mkfifo "$tmp/stdin"
    "$sim" --pty --record "$tmp/pty.txt" < "$tmp/stdin" > "$tmp/pty.out" 2>&1 &
    sim_pid=$!
    exec {keep}> "$tmp/stdin" # stdin stays open: the simulator keeps running
    for _ in $(seq 50); do [ -s "$tmp/pty.out" ] && break; sleep 0.1; done
    pts=$(head -1 "$tmp/pty.out")
    if [ -c "$pts" ]; then
        exec {port}<> "$pts"
        printf 'f 1 \n' >&"$port"
        sleep 0.2
        printf 'q 1 ' >&"$port"
        sleep 0.1
        printf '10\nf 1\n' >&"$port"
        echo 'g 1' >&"$keep" # a line on stdin is received too
        if read -r -t 5 reply <&"$port"; then
            [ "${reply%$'\r'}" = "0 0" ] || fail "--pty: reply '$reply' to f 1"
        else
            fail "--pty: no reply"
        fi
        sleep 0.3
        exec {port}>&-
    else
        fail "--pty: no pseudo-terminal path on the first line of stdout"
    fi
    kill -TERM "$sim_pid"
    wait "$sim_pid"
    [ $? -eq 143 ] || fail "--pty run exit status (want 143: ended by SIGTERM)"
    sim_pid=
    exec {keep}>&-
    grep -q '^# daran-sim --drives 1 --tick-hz 1000 --pty' "$tmp/pty.txt" || fail "--pty: header"
    grep -v '^#' "$tmp/pty.txt" | cut -f2- > "$tmp/pty.lines"
    printf 'f 1 \nq 1 10\nf 1\ng 1\n' | cmp -s - "$tmp/pty.lines" ||
        fail "--pty: recorded lines: $(tr '\n' '|' < "$tmp/pty.lines")"
    grep -v '^#' "$tmp/pty.txt" | cut -f1 | awk 'NR == 1 && $1 <= 0 { bad = 1 }
        $1 < prev { bad = 1 } { prev = $1 } END { exit bad }' ||
        fail "--pty: times do not grow from the start"
else
    echo "no /dev/ptmx: the --pty recording is not checked"
fi

[ "$fails" -eq 0 ] && echo "daran-sim --record and tools/replay round trip: all checks passed"
exit "$fails"

#!/usr/bin/env bash
# The daran-sim command-line contract: --help, bad options (message, exit 2),
# bad directives (message, run goes on, exit 1), a last line without its
# newline, stdout flushed after every input line, --trace.
# usage: cli_contract.sh DARAN_SIM
set -uo pipefail
sim=$1
# shellcheck source=sh_support.sh
. "$(dirname "$0")/sh_support.sh"

"$sim" --help > "$tmp/help" || fail "--help exit status"
for word in --drives --nvm --tick-hz --trace --pty --help '!advance' '!power-cycle' '!fault' \
            overtemp undervoltage stall overspeed nvm-corrupt enable_overspeed_error; do
    grep -q -- "$word" "$tmp/help" || fail "--help does not mention $word"
done

for args in "--drives 0" "--drives 17" "--drives x" "--tick-hz 0" "--tick-hz 1e3" \
            "--bogus" "--drives" "extra" "--trace /nonexistent/dir/t.csv" "--nvm /nonexistent/dir"; do
    # shellcheck disable=SC2086
    "$sim" $args < /dev/null > "$tmp/out" 2> "$tmp/err"
    rc=$?
    [ "$rc" -eq 2 ] || fail "'$args' exit status $rc, want 2"
    grep -q 'daran-sim: ' "$tmp/err" || fail "'$args' gave no message"
    [ -s "$tmp/out" ] && fail "'$args' wrote to stdout"
done

printf '!advance -1\n!advance x\n!bogus\n!fault 1 meltdown\n!fault 7 overtemp\n!power-cycle 1 2\n!load 1\nf 1\n' \
    | "$sim" > "$tmp/out" 2> "$tmp/err"
rc=$?
[ "$rc" -eq 1 ] || fail "bad directives: exit status $rc, want 1"
[ "$(tr -d '\r' < "$tmp/out")" = "0 0" ] || fail "bad directives: the run did not go on"
[ "$(grep -c 'daran-sim: line' "$tmp/err")" -eq 7 ] || fail "bad directives: want 7 messages"

printf 'f 1' | "$sim" > "$tmp/out"
[ "$(tr -d '\r' < "$tmp/out")" = "0 0" ] || fail "a last line without newline is not executed"

# Replies must arrive while stdin is still open.
coproc SIM { "$sim" --drives 2; }
# bash unsets SIM_PID once it has reaped the coprocess, which may happen as
# soon as its stdin closes: keep the pid for the wait below
sim_pid=$SIM_PID
echo "f 2" >&"${SIM[1]}"
if read -r -t 5 reply <&"${SIM[0]}"; then
    [ "${reply%$'\r'}" = "0 0" ] || fail "interactive reply '$reply'"
else
    fail "no reply within 5 s: stdout not flushed per line"
fi
exec {SIM[1]}>&-
wait "$sim_pid" || fail "interactive run exit status"

printf 'q 1 90 60 60\n!advance 1\n' | "$sim" --trace "$tmp/t.csv" --tick-hz 2000 > /dev/null
[ "$(head -1 "$tmp/t.csv")" = "time_s,pos_deg_1,vel_rpm_1,torque_nm_1,state_1" ] || fail "trace header"
[ "$(wc -l < "$tmp/t.csv")" -eq 2002 ] || fail "trace: want header + 2001 rows at 2 kHz"
tail -1 "$tmp/t.csv" | grep -q '^1.000000,' || fail "trace: last row is not t = 1 s"
printf '!advance 1\n' | "$sim" --drives 2 --trace "$tmp/t2.csv" --trace-every 100 > /dev/null
[ "$(wc -l < "$tmp/t2.csv")" -eq 12 ] || fail "trace-every 100: want header + 11 rows"
[ "$(head -1 "$tmp/t2.csv" | tr ',' '\n' | wc -l)" -eq 9 ] || fail "trace: 2 drives want 9 columns"

verdict "daran-sim CLI contract"

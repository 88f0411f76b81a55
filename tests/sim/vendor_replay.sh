#!/usr/bin/env bash
# Replays a vendor client recording on a bus of 3 simulated drives: the time
# gaps become `!advance` directives. Not one reply may be an error.
# usage: vendor_replay.sh DARAN_SIM RECORDING.txt
set -euo pipefail
sim=$1
recording=$2
here=$(cd "$(dirname "$0")" && pwd)
session=$(mktemp)
out=$(mktemp)
trap 'rm -f "$session" "$out"' EXIT
awk -f "$here/recording_to_session.awk" "$recording" > "$session"
requests=$(grep -vc '^!' "$session")
"$sim" --drives 3 < "$session" > "$out"
replies=$(wc -l < "$out")
echo "$(basename "$recording"): $requests requests, $replies reply lines"
if grep -n '^error' "$out"; then
    echo "FAIL: error replies to the vendor's requests" >&2
    exit 1
fi

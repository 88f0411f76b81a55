#!/usr/bin/env bash
# Replays a vendor client recording on a bus of simulated drives. Not one
# reply may be an error.
# usage: vendor_replay.sh [--drives N] [--timing real|none] DARAN_SIM RECORDING.txt
#   --drives N     drives on the bus (ids 1..N; default 3)
#   --timing real  the time gaps become `!advance` directives (default)
#   --timing none  no time passes: every line right after the one before, as
#                  a client that never waits sends them (a synchronised move
#                  still runs when the next request comes)
set -euo pipefail
drives=3
timing=real
while [[ $# -gt 0 && $1 == --* ]]; do
    case $1 in
    --drives) drives=${2:-}; shift 2 || true ;;
    --timing) timing=${2:-}; shift 2 || true ;;
    *) echo "vendor_replay.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
if [[ $# -ne 2 || ! $drives =~ ^[1-9][0-9]*$ || ! $timing =~ ^(real|none)$ ]]; then
    echo "usage: vendor_replay.sh [--drives N] [--timing real|none] DARAN_SIM RECORDING.txt" >&2
    exit 2
fi
sim=$1
recording=$2
here=$(cd "$(dirname "$0")" && pwd)
session=$(mktemp)
out=$(mktemp)
trap 'rm -f "$session" "$out"' EXIT
awk -f "$here/recording_to_session.awk" "$recording" > "$session"
if [[ $timing == none ]]; then
    sed -i '/^!advance /d' "$session"
fi
requests=$(grep -vc '^!' "$session")
advances=$(grep -c '^!advance ' "$session" || true)
"$sim" --drives "$drives" < "$session" > "$out"
replies=$(wc -l < "$out")
echo "$(basename "$recording"): $drives drive(s), timing $timing ($advances advances):" \
     "$requests requests, $replies reply lines"
if grep -n '^error' "$out"; then
    echo "FAIL: error replies to the vendor's requests" >&2
    exit 1
fi

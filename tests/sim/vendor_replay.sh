#!/usr/bin/env bash
# Replays a vendor client recording on a bus of simulated drives. Not one
# reply may be an error.
# usage: vendor_replay.sh [--drives N] [--timing real|none] [--bridge [--mute ID]]
#                         DARAN_SIM RECORDING.txt
#   --drives N     drives on the bus (ids 1..N; default 3)
#   --bridge       the recording's link reaches drive 1 alone, ids 2..N through
#                  drive 1's CAN bridge (daran-sim --bridge)
#   --mute ID      with --bridge, drive ID stops answering on CAN: the only
#                  error replies allowed are `error: no reply`, and there must
#                  be some
#   --timing real  the time gaps become `!advance` directives (default)
#   --timing none  no time passes: every line right after the one before, as
#                  a client that never waits sends them (a synchronised move
#                  still runs when the next request comes)
set -euo pipefail
drives=3
timing=real
bridge=()
mute=""
while [[ $# -gt 0 && $1 == --* ]]; do
    case $1 in
    --drives) drives=${2:-}; shift 2 || true ;;
    --timing) timing=${2:-}; shift 2 || true ;;
    --bridge) bridge=(--bridge); shift ;;
    --mute) mute=${2:-}; shift 2 || true ;;
    *) echo "vendor_replay.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
if [[ $# -ne 2 || ! $drives =~ ^[1-9][0-9]*$ || ! $timing =~ ^(real|none)$ ||
      ( -n $mute && ( ${#bridge[@]} -eq 0 || ! $mute =~ ^[1-9][0-9]*$ ) ) ]]; then
    echo "usage: vendor_replay.sh [--drives N] [--timing real|none] [--bridge [--mute ID]]" \
         "DARAN_SIM RECORDING.txt" >&2
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
if [[ -n $mute ]]; then
    sed -i "1i !fault $mute can-mute" "$session"
fi
requests=$(grep -vc '^!' "$session")
advances=$(grep -c '^!advance ' "$session" || true)
"$sim" --drives "$drives" "${bridge[@]}" < "$session" > "$out"
replies=$(grep -vc '^can ' "$out" || true)
echo "$(basename "$recording"): $drives drive(s)${bridge[*]:+, bridged}${mute:+, drive $mute mute}," \
     "timing $timing ($advances advances): $requests requests, $replies reply lines"
if [[ -n $mute ]]; then
    if grep '^error' "$out" | tr -d '\r' | grep -v '^error: no reply$'; then
        echo "FAIL: error replies other than no reply" >&2
        exit 1
    fi
    if ! grep -q '^error: no reply' "$out"; then
        echo "FAIL: drive $mute was mute, yet no line was answered no reply" >&2
        exit 1
    fi
    exit 0
fi
if grep -n '^error' "$out"; then
    echo "FAIL: error replies to the vendor's requests" >&2
    exit 1
fi

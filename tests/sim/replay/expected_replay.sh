#!/usr/bin/env bash
# Replays a recording with tools/replay and compares the replies with the
# committed reference, byte for byte. The reference itself must hold no
# `error` reply: the recordings are sessions a real client ran without one.
# usage: expected_replay.sh DARAN_SIM TOOLS_REPLAY RECORDING EXPECTED [REPLAY OPTIONS...]
set -uo pipefail
sim=$1
replay=$2
recording=$3
expected=$4
shift 4
if grep -n 'error' "$expected"; then
    echo "FAIL: $expected holds error replies" >&2
    exit 1
fi
"$replay" --sim "$sim" "$@" --expect "$expected" "$recording"

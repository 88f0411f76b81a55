#!/usr/bin/env bash
# A config saved with `ss` survives a restart of daran-sim with the same
# --nvm DIR; `se` brings the defaults back; a corrupted store boots with
# defaults and the nvm_corrupt warning.
# usage: nvm_persistence.sh DARAN_SIM
set -euo pipefail
sim=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
check() { # want got what
    if [ "$1" != "$2" ]; then
        echo "FAIL: $3: want '$1', got '$2'" >&2
        exit 1
    fi
}
run() { printf '%b' "$1" | "$sim" --drives 2 --nvm "$dir"; }

run 'w axis2.controller.config.pos_gain 31\nw axis2.config.can_node_id 7\nss 7\nq 7 45 60 120\n!advance 2\nsz 7\nss 7\n' > /dev/null
check $'1\n7' "$(run 'r axis0.config.can_node_id\n' 2> /dev/null)" "ids after restart"
check 31 "$(run 'r axis7.controller.config.pos_gain\n')" "saved gain after restart"
check "0 0" "$(run 'f 7\n')" "saved zero after restart"
check 20 "$(run 'r axis1.controller.config.pos_gain\n')" "the other drive keeps defaults"
run 'se 7\n' > /dev/null
check 20 "$(run 'r axis2.controller.config.pos_gain\n')" "defaults after se"
run 'f 2\n' | grep -q '^45\.0' || { echo "FAIL: zero offset not gone after se" >&2; exit 1; }
run 'ss 2\n!fault 2 nvm-corrupt\n' > /dev/null
check "32 nvm_corrupt" "$(run 'e 2\n')" "corrupt store flagged at boot"
check "" "$(run 'sc 2\nss 2\nt 2 5\n')" "motion with the warning"
check 0 "$(run 'e 2\n')" "a save repairs the store"
echo "NVM persistence across runs: all checks passed"

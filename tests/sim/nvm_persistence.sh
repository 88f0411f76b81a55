#!/usr/bin/env bash
# A config saved with `ss` survives a restart of daran-sim with the same
# --nvm DIR; `se` brings the defaults back; a corrupted store boots with
# defaults and the nvm_corrupt warning (axis0.config_warnings, never an
# error); settings of the vendor's whole table survive too.
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
run() { printf '%b' "$1" | "$sim" --drives 2 --nvm "$dir" | tr -d '\r'; }

run 'w axis2.controller.config.pos_gain 31\nw axis2.config.can_node_id 7\nss 7\nq 7 45 60 120\n!advance 2\nsz 7\nss 7\n' > /dev/null
check $'1\n7' "$(run 'r axis0.config.can_node_id\n' 2> /dev/null)" "ids after restart"
check 31 "$(run 'r axis7.controller.config.pos_gain\n')" "saved gain after restart"
check "0 0" "$(run 'f 7\n')" "saved zero after restart"
check 20 "$(run 'r axis1.controller.config.pos_gain\n')" "the other drive keeps defaults"
run 'se 7\n' > /dev/null
check 20 "$(run 'r axis2.controller.config.pos_gain\n')" "defaults after se"
run 'f 2\n' | grep -q '^45\.0' || { echo "FAIL: zero offset not gone after se" >&2; exit 1; }
run 'w axis2.trap_traj.config.traj_mode 2\nw axis2.motor.config.pole_pairs 14\nw axis2.config.extra_setting.gear_ratio 8\nw axis2.controller.config.vel_limit_tolerance 1.5\nw config.dc_bus_undervoltage_trip_level 12 2\nw axis2.motor.config.direction -1\nss 2\n' > /dev/null
check $'2\n14\n8\n1.5\n12\n-1' "$(run 'r axis2.trap_traj.config.traj_mode\nr axis2.motor.config.pole_pairs\nr axis2.config.extra_setting.gear_ratio\nr axis2.controller.config.vel_limit_tolerance\nr config.dc_bus_undervoltage_trip_level 2\nr axis2.motor.config.direction\n')" "new settings after restart"
run 'ss 2\n!fault 2 nvm-corrupt\n' > /dev/null
check $'1\n0\n8' "$(run 'r axis2.config_warnings\nr axis2.error\nr axis2.current_state\n')" "corrupt store: a warning at boot"
check "1" "$(run 'r axis2.trap_traj.config.traj_mode\n')" "corrupt store: defaults"
check "" "$(run 'sc 2\nss 2\nt 2 5\n')" "motion with the warning"
check $'0\n0' "$(run 'r axis2.config_warnings\nr axis2.error\n')" "a save repairs the store"
echo "NVM persistence across runs: all checks passed"

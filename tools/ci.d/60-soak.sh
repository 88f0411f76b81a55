#!/usr/bin/env bash
# ci-light
# ci-after: 05-host.sh
# CI step: the soak (tools/soak, docs/reliability.md) in its short form,
# about 60 s of wall time:
#   1. 46 s of the three clients against daran-sim --nvm under bus faults,
#      power cycles and one kill -9 during a save: must pass;
#   2. 8 s with three defects made on purpose (a wrong value, a relative
#      move sent twice, a damaged NVM): must fail, naming each of them, so
#      that the checks of step 1 are known to bite.
# Uses build/host's daran-sim (05-host.sh builds it), building it only when
# it is missing. SOAK_SEED picks the seed
# (default 1).
set -euo pipefail
cd "$(dirname "$0")/../.."

sim=build/host/port/sim/daran-sim
if [ ! -x "$sim" ]; then
  cmake --preset host >/dev/null
  cmake --build --preset host --target daran-sim -j 2 >/dev/null
fi
if [ ! -e /dev/ptmx ] || ! /usr/bin/python3 -c 'import can, serial' 2>/dev/null; then
  echo "60-soak: SKIPPED: needs pseudo-terminals and python3-can, python3-serial (tools/install-deps test)"
  exit 0
fi
seed=${SOAK_SEED:-1}
log=$(mktemp "${TMPDIR:-/tmp}/daran-soak.XXXXXX")
trap 'rm -f "$log"' EXIT

echo "60-soak: 46 s, seed $seed"
if ! tools/soak --duration 46 --seed "$seed" --sim "$sim" >"$log" 2>&1; then
  cat "$log"
  echo "60-soak: FAILED (tools/soak --duration 46 --seed $seed)"
  exit 1
fi
sed -n '/^client /,/^all /p' "$log"
grep -E '^(defects|soak):' "$log"

echo "60-soak: 8 s with defects made on purpose: each must be found"
status=0
tools/soak --duration 8 --seed "$seed" --sim "$sim" \
  --inject wrong-value,double-move,nvm-loss >"$log" 2>&1 || status=$?
missing=()
grep -q 'DEFECT: ascii: drive 1: w .* then r gave' "$log" || missing+=("the wrong value")
grep -q 'DEFECT: can: drive 4 ran a relative move twice' "$log" || missing+=("the double move")
grep -q 'DEFECT: ascii: drive 1 lost its NVM' "$log" || missing+=("the NVM loss")
if [ "$status" -ne 1 ] || [ ${#missing[@]} -gt 0 ]; then
  cat "$log"
  echo "60-soak: FAILED: the run with defects made on purpose exited $status;" \
    "not found: ${missing[*]:-nothing missing}"
  exit 1
fi
echo "60-soak: the wrong value, the double move and the NVM loss were each found (exit 1)"

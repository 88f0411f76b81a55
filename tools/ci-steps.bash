# Sourced by the CI steps that run a list of named sub-steps
# (tools/ci.d/50-package.sh, 55-adopter.sh): each sub-step runs quietly into
# a log; the first failure prints that log, the summary so far, and stops.
# Not a step itself (tools/test runs tools/ci.d/*.sh only).
#
#   ci_steps_begin NAME     NAME prefixes the messages; makes $work (removed
#                           on exit) and sets jobs=(-j 2) and Ninja
#   step TITLE COMMAND...   one sub-step
#   ci_steps_end            the summary and the time taken

ci_steps_begin() {
  ci_steps_name=$1
  ci_steps_start=$SECONDS
  ci_steps_summary=()
  work=$(mktemp -d "${TMPDIR:-/tmp}/daran-$ci_steps_name.XXXXXX")
  # shellcheck disable=SC2064  # expand $work now: it is this run's folder
  trap "rm -rf '$work'" EXIT
  export CMAKE_GENERATOR=Ninja
  jobs=(-j 2)
}

step() {
  local title=$1
  shift
  local t0=$SECONDS
  if "$@" >"$work/step.log" 2>&1; then
    ci_steps_summary+=("PASS  $title ($((SECONDS - t0)) s)")
  else
    echo "$ci_steps_name: FAIL $title; its output:"
    sed 's/^/    /' "$work/step.log"
    printf '%s\n' "${ci_steps_summary[@]}" "FAIL  $title"
    echo "$ci_steps_name: FAILED after $((SECONDS - ci_steps_start)) s"
    exit 1
  fi
}

ci_steps_end() {
  printf '%s\n' "${ci_steps_summary[@]}"
  echo "$ci_steps_name: ${#ci_steps_summary[@]} steps passed in $((SECONDS - ci_steps_start)) s"
}

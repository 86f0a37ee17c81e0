#!/usr/bin/env bash
# The whole check of a change, as CI is to run it once its time on an idle machine is measured
# (doc/hardening.md, "CI"; .ci/run runs the first stage only for now). Three stages, each run
# even if one before failed:
#   make test           the README's test command (installs what it needs, builds, every test)
#   make test-sanitize  the gtest suite under ASan + UBSan (clang 14, build-asan/)
#   make fuzz           each libFuzzer target for FUZZ_SECONDS (60), in the same build-asan/
# Each stage prints its own "...: N passed, N failed" line; the closing line adds them up,
# "N passed, N failed" (the sanitizer stage counts its test cases, the fuzz stage one case per
# target; a stage that fails without a count, e.g. a build error, counts one failure).
# Exit 1 if any stage failed.
set -uo pipefail
cd "$(dirname "$0")/.."
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
total_passed=0 total_failed=0 status=0

run_stage() {
  local name=$1
  shift
  local start=$SECONDS
  "$@" 2>&1 | tee "$logs/$name.log"
  local stage_status=${PIPESTATUS[0]}
  local counts passed=0 failed=0
  counts=$(grep -Eo '[0-9]+ passed, [0-9]+ failed' "$logs/$name.log" | tail -1)
  if [[ -n "$counts" ]]; then
    passed=${counts%% passed*}
    failed=${counts#*passed, }
    failed=${failed%% failed*}
  fi
  if [[ $stage_status -ne 0 && $failed -eq 0 ]]; then failed=1; fi
  [[ $stage_status -ne 0 ]] && status=1
  total_passed=$((total_passed + passed))
  total_failed=$((total_failed + failed))
  echo "ci: $name: exit $stage_status, $passed passed, $failed failed, $((SECONDS - start)) s"
}

run_stage "make test" make test
run_stage "make test-sanitize" make test-sanitize
run_stage "make fuzz" make fuzz FUZZ_SECONDS=60
echo "$total_passed passed, $total_failed failed"
exit $status

#!/usr/bin/env bash
# Builds the gtest suite (the core modules', the ROS shell's conversion tests, the vdc CLI tests)
# with clang under ASan + UBSan in the sanitizer build (scripts/sanitized_build.sh, default
# build-asan) and runs each binary. The first sanitizer report ends its binary (halt_on_error), so
# a binary is clean or it fails. Prints the failed cases and "sanitizers: N passed, N failed" as
# its last line; exit 1 if anything failed.
#   scripts/test_sanitize.sh [binary...]   (default: every binary of $tests below)
set -uo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/sanitizer_results.sh
source scripts/sanitizer_results.sh
build_dir=${SANITIZE_BUILD_DIR:-build-asan}
export PATH=/usr/bin:/bin:$PATH

# Not here (doc/hardening.md): the rostests (most of `make test`'s 13-15 minutes: a second run
# under ASan does not fit CI's 40; the shell code they run is covered by vdc_ros_tests and the
# server_requests fuzz target), vdc_findings_tests (trains a 42-direction model, over 3 min even without sanitizers;
# the training tests run the same code) and vdc_install_tests (installs and builds a dependent
# package: a check of the install, not of memory).
tests=(vdc_common_tests vdc_geometry_tests vdc_features_tests vdc_learning_tests
  vdc_informativeness_tests vdc_training_tests vdc_bingham_tests vdc_refinement_tests
  vdc_estimation_tests vdc_planning_tests vdc_evaluation_tests vdc_visualisation_tests
  vdc_ros_tests vdc_cli_tests vdc_evaluation_report_tests)
[[ $# -gt 0 ]] && tests=("$@")

SANITIZE_BUILD_DIR=$build_dir scripts/sanitized_build.sh "${tests[@]}" || exit 1

# detect_leaks: a leak fails the binary at exit. The suppressions name leaks of the libraries
# underneath (not this package's code), each with its reason.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/test/sanitizer/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# Two shards share the two cores: libomp's idle threads would otherwise spin for 200 ms after every
# parallel region on the core the other shard needs (two quick trainings at once: 63 s, 59 s
# passive).
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}

# The quick mug model the estimation and evaluation tests share: trained once under ASan (about
# 50 s) instead of once per shard of each binary.
use_quick_model_cache "$build_dir"

results="$build_dir/test_results_sanitize"
rm -rf "$results"
mkdir -p "$results"
for name in "${tests[@]}"; do
  run_gtest sanitizers "$build_dir" "$results" "$name"
  status=$?
  [[ $status -eq 127 ]] && continue  # not built: recorded
  if [[ $status -ne 0 ]]; then
    grep -E -A40 '^==[0-9]+==ERROR|runtime error|^\[  FAILED' "$results/$name.log" | head -60
    if ! has_failed_case "$results" "$name"; then
      record_failure "$results" "$name" sanitizer_report_or_crash
    fi
  fi
done
summary=$(/usr/bin/python3 scripts/summarize_test_results.py "$results")
status=$?
echo "$summary" | sed '$d'
echo "sanitizers: $(echo "$summary" | tail -1)"
exit $status

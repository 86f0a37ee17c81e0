#!/usr/bin/env bash
# Builds with clang under ThreadSanitizer (SANITIZE=thread scripts/sanitized_build.sh: build-tsan/,
# its own build: TSan cannot share one with ASan) and runs what has threads of its own
# (doc/hardening.md, "Threads (TSan)"):
#   - the gtest binaries whose code runs threads: refinement (its starts aligned on 2
#     std::threads), estimation (the estimator refines by default) and the ROS shell's tests;
#   - the node rostests (the estimator's worker thread, its timers and mutexes, tf2's listener,
#     the nodelets in one manager), the nodes and test nodes built under TSan and run from
#     build-tsan's devel space. Skipped with --gtests-only.
# A binary or node with a TSan report fails (reports in libraries underneath are suppressed by
# test/sanitizer/tsan.supp, each with its reason). Prints the failed cases and
# "tsan: N passed, N failed" as its last line; exit 1 if anything failed. Not in CI (.ci/run):
# the build and the run take too long for its budget (doc/hardening.md has the figures).
#   scripts/test_tsan.sh [--gtests-only] [binary-or-rostest...]
set -uo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/sanitizer_results.sh
source scripts/sanitizer_results.sh
build_dir=${TSAN_BUILD_DIR:-build-tsan}
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

gtests=(vdc_refinement_tests vdc_estimation_tests vdc_ros_tests)
# Every node rostest but rviz_screenshot (rviz is not built under TSan: it only draws).
rostests=(estimator_stream estimator_bad_input estimator_reconfigure estimator_convergence
  estimator_startup server_startup server_bad_requests server_reconfigure camera_startup
  simulated_camera nodelets_closed_loop)
# What the rostests run: the nodes, the nodelet library, the C++ test nodes and the tool that
# trains the quick mug model (the target vdc_test_model).
rostest_targets=(orientation_estimator simulated_depth_camera informativeness_server
  view_direction_classification_nodelets estimator_bad_input_test estimator_convergence_test
  nodelets_closed_loop_test vdc_test_model view_direction_classification_generate_messages_py
  view_direction_classification_gencfg)
if [[ ${1:-} == --gtests-only ]]; then
  rostests=()
  shift
fi
if [[ $# -gt 0 ]]; then
  gtests=()
  rostests=()
  for name in "$@"; do
    if [[ -f test/ros/$name.test ]]; then rostests+=("$name"); else gtests+=("$name"); fi
  done
fi
# vdc_test_model also for the gtests: the real-scan test of vdc_estimation_tests needs the model.
targets=("${gtests[@]}" vdc_test_model)
[[ ${#rostests[@]} -gt 0 ]] && targets+=("${rostest_targets[@]}")

# OpenMP: libomp is not instrumented, so TSan alone does not see how it orders its threads (its
# barriers and hand-overs are its own spin flags, not pthread calls) and reports the work before
# and after every parallel region as racing. Archer, LLVM's OpenMP tool for TSan (libarcher.so,
# in libomp-14-dev), tells TSan about OpenMP's forks, joins, barriers, reductions, critical
# sections and tasks, so the OpenMP loops run on 2 threads and are checked too. PCL's precompiled
# OpenMP code (built by gcc for libgomp) runs on libomp as well: libomp, linked first, provides
# the GOMP_* entry points. Without Archer, OpenMP must run on one thread:
#   OMP_TOOL_LIBRARIES= OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 scripts/test_tsan.sh
# (OMP_THREAD_LIMIT too: PCL's NormalEstimationOMP asks for one thread per core with
# num_threads(), which OMP_NUM_THREADS does not cap.)
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
export OMP_TOOL_LIBRARIES=${OMP_TOOL_LIBRARIES-/usr/lib/llvm-14/lib/libarcher.so}
# libomp warns at every region it cannot give the threads asked for (under OMP_THREAD_LIMIT).
export KMP_WARNINGS=0
# halt_on_error=0: every report of a run is printed (a binary with one still exits 66, a failure).
# second_deadlock_stack: both stacks of a lock-order inversion. ignore_noninstrumented_modules:
# intercepted calls (close, send, memcmp) made by uninstrumented libraries are not checked as
# memory accesses (tsan.supp says why). Set before the build: it runs the instrumented `vdc` to
# train the rostests' model.
default_options=halt_on_error=0:second_deadlock_stack=1:ignore_noninstrumented_modules=1
export TSAN_OPTIONS=${TSAN_OPTIONS:-$default_options:suppressions=$PWD/test/sanitizer/tsan.supp}

start=$(date +%s)
SANITIZE=thread SANITIZE_BUILD_DIR=$build_dir scripts/sanitized_build.sh "${targets[@]}" || exit 1
echo "tsan: build in $(( $(date +%s) - start )) s"
# The estimation tests' quick mug model: trained once, not once per shard.
use_quick_model_cache "$build_dir"
results="$build_dir/test_results_tsan"
rm -rf "$results"
mkdir -p "$results"

for name in "${gtests[@]}"; do
  run_gtest tsan "$build_dir" "$results" "$name"
  status=$?
  [[ $status -eq 127 ]] && continue  # not built: recorded
  if grep -q '^WARNING: ThreadSanitizer' "$results/$name.log"; then
    grep -E -A30 '^WARNING: ThreadSanitizer' "$results/$name.log" | head -80
    record_failure "$results" "$name" tsan_report
  elif [[ $status -ne 0 ]] && ! has_failed_case "$results" "$name"; then
    tail -20 "$results/$name.log"
    record_failure "$results" "$name" exit_status
  fi
done

if [[ ${#rostests[@]} -gt 0 ]]; then
  # The rostests run the nodes of build-tsan's devel space (rosrun and nodelet find them there).
  # catkin's setup scripts read unset variables.
  set +u
  # shellcheck disable=SC1091
  source "$build_dir/devel/setup.bash"
  set -u
  data="$build_dir/test_data"
  for name in "${rostests[@]}"; do
    # Each instrumented process writes its reports to its own file: log_path.<pid>.
    mkdir -p "$results/$name"
    start=$(date +%s)
    TSAN_OPTIONS="$TSAN_OPTIONS:log_path=$PWD/$results/$name/tsan" \
      rostest --pkgdir="$PWD" --package=view_direction_classification \
      --results-filename "$name.xml" --results-base-dir "$PWD/$results/$name" \
      "test/ros/$name.test" "model:=$PWD/$data/mug_quick.h5" "mesh:=$PWD/$data/mug.ply" \
      > "$results/$name.log" 2>&1
    status=$?
    echo "tsan: rostest $name exit $status in $(( $(date +%s) - start )) s"
    reports=("$results/$name"/tsan.*)
    if [[ -e ${reports[0]} ]]; then
      for report in "${reports[@]}"; do
        echo "tsan: $name: $(grep -c '^WARNING: ThreadSanitizer' "$report") report(s) in $report"
        grep -E -A30 '^WARNING: ThreadSanitizer' "$report" | head -60
      done
      record_failure "$results" "$name" tsan_report
    fi
    if [[ $status -ne 0 ]] && ! find "$results/$name" -name '*.xml' | grep -q .; then
      tail -20 "$results/$name.log"
      record_failure "$results" "$name" exit_status
    fi
  done
fi

summary=$(/usr/bin/python3 scripts/summarize_test_results.py "$results")
status=$?
echo "$summary" | sed '$d'
echo "tsan: $(echo "$summary" | tail -1)"
exit $status

#!/usr/bin/env bash
# Runs every test of the package (gtests and rostests, through catkin's run_tests) and prints
# one closing line "N passed, N failed" counting each test case once. Exit 1 if any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

rm -rf "$build_dir/test_results"
# catkin's run_tests, in two steps: the gtest binaries TEST_JOBS (default 2, one per core) at a
# time (most run on one thread, and each writes only its own files), then the rostests one at a
# time (their nodes keep camera rate and time out: they get the machine to themselves).
# Neither target builds or cleans anything (scripts/build.sh built `tests`; the results were
# removed above). They exit 0 even when tests fail; the XML results are the verdict.
package=view_direction_classification
{
  cmake --build "$build_dir" -- -j"${TEST_JOBS:-2}" "run_tests_${package}_gtest"
  cmake --build "$build_dir" -- "run_tests_${package}_rostest"
} 2>&1 | tee "$build_dir/run_tests.log" \
  | grep -E '^\[( +OK|  FAILED|  PASSED|==========)|^\[ROSTEST\]|FAILURE|Error' || true
/usr/bin/python3 scripts/summarize_test_results.py "$build_dir/test_results"

#!/usr/bin/env bash
# Runs every test of the package (gtests and rostests, through catkin's run_tests) and prints
# one closing line "N passed, N failed" counting each test case once. Exit 1 if any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

rm -rf "$build_dir/test_results"
# run_tests exits 0 even when tests fail; the XML results are the verdict.
cmake --build "$build_dir" -- run_tests 2>&1 | tee "$build_dir/run_tests.log" \
  | grep -E '^\[( +OK|  FAILED|  PASSED|==========)|^\[ROSTEST\]|FAILURE|Error' || true
/usr/bin/python3 scripts/summarize_test_results.py "$build_dir/test_results"

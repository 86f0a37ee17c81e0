#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (ASan + UBSan, coverage) in the clang sanitizer build
# $SANITIZE_BUILD_DIR (default build-asan, scripts/sanitized_build.sh) and runs each for
# $FUZZ_SECONDS (default 60) on its committed seed corpus (fuzz/corpus/<name>/, read only) with
# its dictionary (fuzz/dictionaries/<name>.dict, if any); what a run adds goes to
# $SANITIZE_BUILD_DIR/corpus/<name>/ and a crash's input to $SANITIZE_BUILD_DIR/artifacts/<name>/.
# Only the fuzz targets and the libraries they link are built.
#   scripts/fuzz.sh [name...]   (names: mesh model_bundle cloud_conversion bingham_conversion
#                                server_requests; default all)
# FUZZ_JOBS (default 2) targets run at once.
# Exit 1 if any target crashed, leaked, ran out of memory or timed out on an input. The closing
# line is "fuzz: N passed, N failed (targets...)".
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${SANITIZE_BUILD_DIR:-build-asan}
seconds=${FUZZ_SECONDS:-60}
export PATH=/usr/bin:/bin:$PATH
all_targets=(mesh model_bundle cloud_conversion bingham_conversion server_requests)
targets=("${@:-${all_targets[@]}}")

build_targets=()
for name in "${targets[@]}"; do build_targets+=("vdc_${name}_fuzzer"); done
SANITIZE_BUILD_DIR=$build_dir scripts/sanitized_build.sh "${build_targets[@]}" || exit 1

export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# Leaks inside the libraries underneath, each with its reason (test/sanitizer/lsan.supp).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/test/sanitizer/lsan.supp:print_suppressions=0}
# Runs target $1 for $seconds; its exit status goes to $build_dir/fuzz_$1.status.
run_target() {
  local name=$1 corpus="$build_dir/corpus/$1" artifacts="$build_dir/artifacts/$1/"
  mkdir -p "$corpus" "$artifacts"
  local dictionary=()
  [[ -f "fuzz/dictionaries/$name.dict" ]] && dictionary=(-dict="fuzz/dictionaries/$name.dict")
  # -timeout: an input that takes 10 s is a hang (a request or file that stalls a node).
  "$build_dir/fuzz/vdc_${name}_fuzzer" "$corpus" "fuzz/corpus/$name" "${dictionary[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$artifacts" > "$build_dir/fuzz_$name.log" 2>&1
  echo $? > "$build_dir/fuzz_$name.status"
}

# FUZZ_JOBS targets at once (default 2, one per core): a libFuzzer run is one thread, so one
# target at a time would leave a core idle for the whole stage.
jobs_at_once=${FUZZ_JOBS:-2}
rm -f "$build_dir"/fuzz_*.status
running=0
for name in "${targets[@]}"; do
  echo "fuzz: $name for ${seconds} s"
  run_target "$name" &
  if (( ++running >= jobs_at_once )); then
    wait -n
    running=$((running - 1))
  fi
done
wait

failed=()
for name in "${targets[@]}"; do
  status=$(cat "$build_dir/fuzz_$name.status" 2>/dev/null || echo 1)
  artifacts="$build_dir/artifacts/$name/"
  echo -n "fuzz: $name: "
  grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb)|^#[0-9]+.*DONE' \
    "$build_dir/fuzz_$name.log" | tr '\n' ' '
  echo
  if [[ $status -ne 0 ]]; then
    failed+=("$name")
    grep -E -A30 '^==[0-9]+==ERROR|runtime error|deadly signal|ALARM|out-of-memory' \
      "$build_dir/fuzz_$name.log" | head -60
    echo "fuzz: $name FAILED (exit $status): input in $artifacts, log $build_dir/fuzz_$name.log"
  fi
done
# The closing line counts targets as test cases (.ci/run adds it to the other stages').
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: failed: ${failed[*]}"
  echo "fuzz: $(( ${#targets[@]} - ${#failed[@]} )) passed, ${#failed[@]} failed (targets, ${seconds} s each)"
  exit 1
fi
echo "fuzz: ${#targets[@]} passed, 0 failed (targets, ${seconds} s each, no crash)"

#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (ASan + UBSan, coverage) in the clang sanitizer build
# $SANITIZE_BUILD_DIR (default build-asan, scripts/sanitized_build.sh) and runs each for
# $FUZZ_SECONDS (default 60) on its committed seed corpus (fuzz/corpus/<name>/, read only) with
# its dictionary (fuzz/dictionaries/<name>.dict, if any); what a run adds goes to
# $SANITIZE_BUILD_DIR/corpus/<name>/ and a crash's input to $SANITIZE_BUILD_DIR/artifacts/<name>/.
# Only the fuzz targets and the libraries they link are built.
#   scripts/fuzz.sh [name...]   (names: mesh model_bundle cloud_conversion bingham_conversion
#                                label_image_conversion server_requests scene_segmentation
#                                scene_memory;
#                                default all)
# FUZZ_JOBS (default 2) lanes of targets run at once (below).
# Exit 1 if any target crashed, leaked, ran out of memory or timed out on an input. The closing
# line is "fuzz: N passed, N failed (targets...)".
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${SANITIZE_BUILD_DIR:-build-asan}
seconds=${FUZZ_SECONDS:-60}
export PATH=/usr/bin:/bin:$PATH
all_targets=(mesh model_bundle cloud_conversion bingham_conversion label_image_conversion
  server_requests scene_segmentation scene_memory bop_json)
targets=("${@:-${all_targets[@]}}")

build_targets=()
for name in "${targets[@]}"; do build_targets+=("vdc_${name}_fuzzer"); done
SANITIZE_BUILD_DIR=$build_dir scripts/sanitized_build.sh "${build_targets[@]}" || exit 1

# alloc_dealloc_mismatch=0: PCL's supervoxels (scene segmentation) release a PointCloud that
# its precompiled library allocated with the class's aligned operator new (malloc underneath)
# through the shared_ptr deleter our clang build instantiated, which calls the global operator
# delete (free underneath): ASan reports the pair, glibc frees it correctly.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:alloc_dealloc_mismatch=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# Leaks inside the libraries underneath, each with its reason (test/sanitizer/lsan.supp).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/test/sanitizer/lsan.supp:print_suppressions=0}
# Runs target $1 for $2 seconds as its part $3; its exit status goes to
# $build_dir/fuzz_$1.$3.status, its output to fuzz_$1.$3.log.
run_target() {
  local name=$1 part_seconds=$2 part=$3 corpus="$build_dir/corpus/$1"
  local artifacts="$build_dir/artifacts/$1/"
  mkdir -p "$corpus" "$artifacts"
  local dictionary=()
  [[ -f "fuzz/dictionaries/$name.dict" ]] && dictionary=(-dict="fuzz/dictionaries/$name.dict")
  # -timeout: an input that takes 10 s is a hang (a request or file that stalls a node).
  "$build_dir/fuzz/vdc_${name}_fuzzer" "$corpus" "fuzz/corpus/$name" "${dictionary[@]}" \
      -max_total_time="$part_seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$artifacts" > "$build_dir/fuzz_$name.$part.log" 2>&1
  echo $? > "$build_dir/fuzz_$name.$part.status"
}

# FUZZ_JOBS lanes at once (default 2, one per core; a libFuzzer run is one thread). The targets'
# $seconds each are laid end to end and cut into equal lanes, so a target may run as two parts,
# one in each lane, on the same corpus: five targets take two and a half minutes on two lanes,
# not three rounds of a minute with a core idle in the last.
jobs_at_once=${FUZZ_JOBS:-2}
lane_seconds=$(( (${#targets[@]} * seconds + jobs_at_once - 1) / jobs_at_once ))
lanes=()  # per lane, its "name:seconds:part" runs in order
lane=0 left=$lane_seconds
for name in "${targets[@]}"; do
  need=$seconds part=0
  while (( need > 0 )); do
    take=$(( need < left ? need : left ))
    lanes[lane]+="$name:$take:$part "
    need=$((need - take)) left=$((left - take)) part=$((part + 1))
    if (( left == 0 )); then lane=$((lane + 1)) left=$lane_seconds; fi
  done
done
rm -f "$build_dir"/fuzz_*.status "$build_dir"/fuzz_*.log
for runs in "${lanes[@]}"; do
  (
    for run in $runs; do
      IFS=: read -r name part_seconds part <<< "$run"
      echo "fuzz: $name for ${part_seconds} s (part $part)"
      run_target "$name" "$part_seconds" "$part"
    done
  ) &
done
wait

failed=()
for name in "${targets[@]}"; do
  artifacts="$build_dir/artifacts/$name/"
  status=0
  for log in "$build_dir/fuzz_$name".*.log; do
    part_status=$(cat "${log%.log}.status" 2>/dev/null || echo 1)
    part=${log%.log}
    echo -n "fuzz: $name, part ${part##*.}: "
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb)|^#[0-9]+.*DONE' "$log" \
      | tr '\n' ' '
    echo
    if [[ $part_status -ne 0 ]]; then
      status=$part_status
      grep -E -A30 '^==[0-9]+==ERROR|runtime error|deadly signal|ALARM|out-of-memory' "$log" \
        | head -60
      echo "fuzz: $name FAILED (exit $part_status): input in $artifacts, log $log"
    fi
  done
  [[ -e "$build_dir/fuzz_$name.0.log" ]] || status=1  # never ran
  [[ $status -ne 0 ]] && failed+=("$name")
done
# The closing line counts targets as test cases (.ci/run adds it to the other stages').
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: failed: ${failed[*]}"
  echo "fuzz: $(( ${#targets[@]} - ${#failed[@]} )) passed, ${#failed[@]} failed (targets, ${seconds} s each)"
  exit 1
fi
echo "fuzz: ${#targets[@]} passed, 0 failed (targets, ${seconds} s each, no crash)"

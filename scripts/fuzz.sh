#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan, coverage) in $FUZZ_BUILD_DIR
# (default build-fuzz) and runs each for $FUZZ_SECONDS (default 60) on its committed seed corpus
# (fuzz/corpus/<name>/, read only); what a run adds goes to $FUZZ_BUILD_DIR/corpus/<name>/ and a
# crash's input to $FUZZ_BUILD_DIR/artifacts/<name>/. Only the fuzz targets and the libraries they
# link are built, not the nodes or the tests.
#   scripts/fuzz.sh [name...]   (names: mesh model_bundle cloud_conversion bingham_conversion
#                                server_requests; default all)
# Exit 1 if any target crashed, leaked, ran out of memory or timed out on an input.
set -uo pipefail
cd "$(dirname "$0")/.."
build_dir=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${FUZZ_SECONDS:-60}
jobs=${JOBS:-2}
export PATH=/usr/bin:/bin:$PATH
all_targets=(mesh model_bundle cloud_conversion bingham_conversion server_requests)
targets=("${@:-${all_targets[@]}}")

if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  # -O1: the sanitizers' usual level (fast to build, stacks still readable).
  if ! cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
      -DVDC_SANITIZE=address,undefined -DVDC_BUILD_FUZZERS=ON -DCATKIN_ENABLE_TESTING=OFF \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 \
      > "$build_dir.configure.log" 2>&1; then
    cat "$build_dir.configure.log" >&2
    rm -rf "$build_dir"
    echo "fuzz: configuring failed (log above)" >&2
    exit 1
  fi
fi
build_targets=()
for name in "${targets[@]}"; do build_targets+=("vdc_${name}_fuzzer"); done
cmake --build "$build_dir" -- -j"$jobs" "${build_targets[@]}" || exit 1

export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
failed=()
for name in "${targets[@]}"; do
  corpus="$build_dir/corpus/$name" artifacts="$build_dir/artifacts/$name/"
  mkdir -p "$corpus" "$artifacts"
  dictionary=()
  [[ -f "fuzz/dictionaries/$name.dict" ]] && dictionary=(-dict="fuzz/dictionaries/$name.dict")
  echo "fuzz: $name for ${seconds} s"
  # -timeout: an input that takes 10 s is a hang (a request or file that stalls a node).
  "$build_dir/fuzz/vdc_${name}_fuzzer" "$corpus" "fuzz/corpus/$name" "${dictionary[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$artifacts" > "$build_dir/fuzz_$name.log" 2>&1
  status=$?
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
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: ${#failed[@]} of ${#targets[@]} targets failed: ${failed[*]}"
  exit 1
fi
echo "fuzz: ${#targets[@]} targets, ${seconds} s each, no crash"

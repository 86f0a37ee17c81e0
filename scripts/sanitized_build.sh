#!/usr/bin/env bash
# Configures (once) and builds targets of the one clang build that both scripts/fuzz.sh and
# scripts/test_sanitize.sh use, in $SANITIZE_BUILD_DIR (default build-asan): clang-14, ASan +
# UBSan (VDC_SANITIZE=address,undefined), libFuzzer coverage on every target
# (VDC_BUILD_FUZZERS=ON, -fsanitize=fuzzer-no-link) and the gtests configured. Sharing it means
# the fuzz targets and the sanitizer test suite compile the core once, not twice (CI time,
# doc/hardening.md); the coverage instrumentation does not change what the tests check.
# SANITIZE=thread builds instead a ThreadSanitizer build in build-tsan (scripts/test_tsan.sh):
# TSan cannot be combined with ASan in one binary, and it gets no fuzzer coverage (the fuzz
# targets are ASan's; the coverage would only slow the threads down).
#   scripts/sanitized_build.sh <target...>
#   SANITIZE=thread scripts/sanitized_build.sh <target...>
set -uo pipefail
cd "$(dirname "$0")/.."
sanitize=${SANITIZE:-address,undefined}
case "$sanitize" in
  address,undefined) default_dir=build-asan fuzzers=ON ;;
  thread) default_dir=build-tsan fuzzers=OFF ;;
  *) echo "sanitized build: SANITIZE must be address,undefined or thread" >&2; exit 2 ;;
esac
build_dir=${SANITIZE_BUILD_DIR:-$default_dir}
jobs=${JOBS:-2}
export PATH=/usr/bin:/bin:$PATH

if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  # -O1: the sanitizers' usual level (fast to build, stacks still readable).
  # -gline-tables-only: the file, line and inlined function of every frame of a sanitizer report
  # and nothing a report does not use; it builds about a sixth faster than -g (doc/hardening.md,
  # "Build time"). A failed configure caches bad values: start clean.
  if ! cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DVDC_SANITIZE="$sanitize" -DVDC_BUILD_FUZZERS=$fuzzers -DCATKIN_ENABLE_TESTING=ON \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 \
      > "$build_dir.configure.log" 2>&1; then
    cat "$build_dir.configure.log" >&2
    rm -rf "$build_dir"
    echo "sanitized build: configuring failed (log above)" >&2
    exit 1
  fi
fi
cmake --build "$build_dir" -- -j"$jobs" "$@"

# Helpers of the sanitizer test scripts (test_sanitize.sh, test_tsan.sh), sourced by both.

# record_failure RESULTS NAME CASE: a result file with one failed case NAME.CASE in RESULTS, for
# a binary that wrote none (not built, or stopped by a sanitizer report before gtest wrote its
# results) or whose run a sanitizer report fails although gtest's cases passed.
record_failure() {
  echo "<testsuites><testsuite><testcase classname=\"$2\" name=\"$3\"><failure/></testcase>" \
    "</testsuite></testsuites>" > "$1/$2.$3.xml"
}

# find_test_binary BUILD NAME: the path of the executable NAME in the build tree BUILD, or
# nothing when it was not built.
find_test_binary() {
  find "$1/devel/lib" "$1" -maxdepth 4 -type f -name "$2" -perm -u+x | head -1
}

# run_gtest PREFIX BUILD RESULTS NAME: runs the gtest binary NAME of the build tree BUILD, its
# results in RESULTS/NAME*.xml and its output in RESULTS/NAME.log, and prints "PREFIX: NAME exit S
# in T s". Returns the binary's exit status (the worst of its shards'), or 127 after recording a
# failed case when NAME was not built.
# The cases run as TEST_SHARDS (default 2, one per core) gtest shards at once: most cases run on
# one thread, and a sanitized binary is mostly run time, so one process at a time leaves a core
# idle (doc/hardening.md, "Sanitizer test suite"). Each shard is its own process, so each ends
# with its own leak check and halts at its own first report.
run_gtest() {
  local prefix=$1 build=$2 results=$3 name=$4 binary start status=0 shards=${TEST_SHARDS:-2}
  local shard shard_status pids=()
  binary=$(find_test_binary "$build" "$name")
  if [[ -z "$binary" ]]; then
    echo "$prefix: $name was not built"
    record_failure "$results" "$name" built
    return 127
  fi
  start=$(date +%s)
  for (( shard = 0; shard < shards; ++shard )); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
      "$binary" --gtest_output="xml:$results/$name.shard$shard.xml" \
      > "$results/$name.shard$shard.log" 2>&1 &
    pids+=($!)
  done
  for (( shard = 0; shard < shards; ++shard )); do
    wait "${pids[$shard]}"
    shard_status=$?
    (( shard_status > status )) && status=$shard_status
    { echo "=== $name, shard $shard of $shards: exit $shard_status"
      cat "$results/$name.shard$shard.log"; } >> "$results/$name.log"
    rm -f "$results/$name.shard$shard.log"
  done
  echo "$prefix: $name exit $status in $(( $(date +%s) - start )) s"
  return $status
}

# has_failed_case RESULTS NAME: whether a result file of NAME's shards records a failed case.
has_failed_case() {
  grep -q '<failure' "$1/$2".*xml 2>/dev/null
}

# use_quick_model_cache BUILD: exports VDC_QUICK_MODEL_CACHE, a folder of BUILD where the first
# process that needs the quick mug model (test/support/quick_mug_model.h) trains and saves it and
# every other process loads it. Emptied when a library that trains the model, or its recipe,
# is newer than the cache's stamp.
use_quick_model_cache() {
  local cache=$1/quick_model_cache
  local stamp=$cache/libraries_older_than_this
  if [[ -f "$stamp" && -n "$(find "$1/devel/lib" -maxdepth 1 -newer "$stamp" \
      \( -name 'libvdc_common.so' -o -name 'libvdc_geometry.so' -o -name 'libvdc_features.so' \
      -o -name 'libvdc_learning.so' -o -name 'libvdc_informativeness.so' \
      -o -name 'libvdc_training.so' \); find test/support/quick_mug_model.h -newer "$stamp")" ]]; then
    rm -rf "$cache"
  fi
  mkdir -p "$cache"
  [[ -f "$stamp" ]] || touch "$stamp"
  export VDC_QUICK_MODEL_CACHE=$PWD/$cache
}

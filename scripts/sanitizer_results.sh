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

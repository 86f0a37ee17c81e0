# Sanitizer and fuzzer builds, in a build directory of their own so the ordinary build is
# untouched (doc/hardening.md). scripts/sanitized_build.sh sets both in build-asan/, which
# `make fuzz` and `make test-sanitize` share:
#   VDC_SANITIZE=address,undefined   every target built and linked with these sanitizers
#   VDC_BUILD_FUZZERS=ON             the libFuzzer targets of fuzz/ (clang only), every target
#                                    instrumented for coverage (harmless for the gtests)
set(VDC_SANITIZE "" CACHE STRING
  "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(VDC_BUILD_FUZZERS "Build the libFuzzer targets of fuzz/ (needs clang)" OFF)

if(VDC_SANITIZE)
  # No recovery: the first report ends the test (halt_on_error), so a run is clean or it fails.
  add_compile_options(-fsanitize=${VDC_SANITIZE} -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${VDC_SANITIZE})
endif()

if(VDC_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "VDC_BUILD_FUZZERS needs clang (libFuzzer): configure with "
      "-DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 (scripts/fuzz.sh does)")
  endif()
  if(NOT VDC_SANITIZE)
    message(FATAL_ERROR "VDC_BUILD_FUZZERS needs VDC_SANITIZE (e.g. address,undefined)")
  endif()
  # The libraries record coverage for libFuzzer; only the fuzz targets link its main().
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

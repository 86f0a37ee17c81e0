# The two commands of the README's quick start, and a few helpers around them.
#   make demo   install what is missing, build, run the demo on the built-in mug
#   make test   install what is missing (with rviz and Xvfb for the rviz screenshot test), build,
#               run every test; ends with "N passed, N failed"
#   make fuzz           run each libFuzzer target of fuzz/ for FUZZ_SECONDS (default 60) under
#                       ASan + UBSan (clang 14, build-asan/; doc/hardening.md)
#   make test-sanitize  the gtest suite under ASan + UBSan (clang 14, build-asan/)
#   make test-tsan      the threaded gtests and the node rostests under ThreadSanitizer (clang 14,
#                       build-tsan/; not in CI: doc/hardening.md)
#   make ci             what CI runs (.ci/run): make test, then fuzzing and the sanitizer suite
#                       within a 39-minute budget (scripts/ci_all_stages.sh)
BUILD_DIR ?= build
JOBS ?= 2
FUZZ_SECONDS ?= 60
export BUILD_DIR JOBS FUZZ_SECONDS
# Debian's catkin needs Debian's python3 (a pyenv python3 lacks catkin_pkg).
export PATH := /usr/bin:/bin:$(PATH)

.PHONY: all deps deps-gui deps-sanitize build test ci fuzz test-sanitize test-tsan demo bench \
	format clean

all: build

deps:
	@scripts/install_deps.sh

deps-gui:
	@scripts/install_deps.sh --gui

deps-sanitize:
	@scripts/install_deps.sh --sanitize

build: deps
	@scripts/build.sh

test: deps-gui build
	@scripts/run_tests.sh

ci:
	@scripts/ci_all_stages.sh

fuzz: deps-sanitize
	@scripts/fuzz.sh

test-sanitize: deps-sanitize
	@scripts/test_sanitize.sh

test-tsan: deps-sanitize
	@scripts/test_tsan.sh

demo: build
	@scripts/demo.sh

bench: build
	@scripts/run_benchmarks.sh

format:
	@find src include test bench -name '*.cpp' -o -name '*.h' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)

#!/usr/bin/env bash
# Configures (once) and builds the package with plain CMake into $BUILD_DIR (default: build).
# The devel space is $BUILD_DIR/devel: `source $BUILD_DIR/devel/setup.bash` for rosrun/roslaunch.
# DEBUG_INFO (default -g1) is the debug-information flag of the optimised build: -g1 keeps
# function names and line numbers for backtraces, perf and crash reports, and compiles about a
# third faster than -g (doc/hardening.md, "Build time"); DEBUG_INFO=-g adds the variables a
# debugger shows. It never changes the generated code. Read when the build directory is
# configured, i.e. on its first build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
jobs=${JOBS:-2}
debug_info=${DEBUG_INFO:--g1}
export PATH=/usr/bin:/bin:$PATH

# The install space is inside the build directory, as catkin_make's is inside its workspace, but
# in a hidden folder: roslaunch and rosrun search the whole package folder for a launch file or a
# node by name, and a second copy of launch/ (an install in build/install) makes every
# `roslaunch view_direction_classification X.launch` fail with "multiple files named". ROS's
# resource search skips folders whose name starts with a dot. The install test (test/install)
# installs there and builds a dependent package against it.
install_prefix="$(realpath -m "$build_dir")/.install"
if [[ -f "$build_dir/CMakeCache.txt" ]] &&
    ! grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$install_prefix" "$build_dir/CMakeCache.txt"; then
  # A build directory configured before the install space moved: move it, and remove the old
  # install tree that shadows the package's launch files.
  if grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$(realpath -m "$build_dir")/install" \
      "$build_dir/CMakeCache.txt"; then
    echo "build: moving the install space to $install_prefix (was $build_dir/install)"
    rm -rf "$build_dir/install"
    cmake "$build_dir" -DCMAKE_INSTALL_PREFIX="$install_prefix" > "$build_dir.configure.log" 2>&1 ||
      { cat "$build_dir.configure.log" >&2; exit 1; }
  fi
fi
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  # A failed configure caches bad values (e.g. a python without catkin_pkg): start clean.
  if ! cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 $debug_info -DNDEBUG" \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 $debug_info -DNDEBUG" \
      -DCMAKE_INSTALL_PREFIX="$install_prefix" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 \
      -DCATKIN_ENABLE_TESTING=ON > "$build_dir.configure.log" 2>&1; then
    cat "$build_dir.configure.log" >&2
    rm -rf "$build_dir"
    echo "build: configuring failed (log above)" >&2
    exit 1
  fi
fi
# `all` builds the libraries, tools and nodes; `tests` the gtest binaries (not part of `all`).
cmake --build "$build_dir" -- -j"$jobs" all
cmake --build "$build_dir" -- -j"$jobs" tests

#!/usr/bin/env bash
# Installs the Debian packages this package builds, tests and runs with.
# Idempotent: does nothing (and needs no network) when everything is already installed.
# Usage: scripts/install_deps.sh [--gui] [--sanitize]
#   --gui       rviz, Xvfb, ImageMagick and PIL: the rviz screenshot test, which `make test` runs
#   --sanitize  clang 14 with its sanitizer and libFuzzer runtimes and LLVM's OpenMP: `make fuzz`,
#               `make test-sanitize` and `make test-tsan`
set -euo pipefail

packages=(
  # toolchain and catkin
  build-essential cmake catkin python3-catkin-pkg python3-empy
  # ROS 1 C++ libraries and their message definitions
  libroscpp-dev libnodeletlib-dev libnodeletlib-tools pluginlib-dev libpcl-ros-dev libpcl-conversions-dev
  libtf2-ros-dev libtf2-eigen-dev libtf2-geometry-msgs-dev libtf2-sensor-msgs-dev
  libsensor-msgs-dev libgeometry-msgs-dev libvisualization-msgs-dev libstd-srvs-dev
  libstd-msgs-dev libdiagnostic-updater-dev libdiagnostic-msgs-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  ros-std-msgs ros-geometry-msgs ros-sensor-msgs ros-std-srvs ros-visualization-msgs
  ros-diagnostic-msgs ros-message-generation ros-message-runtime
  # rospy side: rostest, rostopic, rosservice and the test scripts
  librostest-dev python3-rostest python3-rospy python3-sensor-msgs python3-geometry-msgs
  python3-std-srvs python3-visualization-msgs python3-tf2-ros python3-numpy
  python3-diagnostic-msgs
  rosbash python3-roslaunch python3-rosnode python3-rosservice python3-rostopic rosout
  # the core's libraries
  libpcl-dev libflann-dev libnanoflann-dev libeigen3-dev liblbfgspp-dev libhdf5-dev hdf5-tools python3-h5py
  libboost-dev libassimp-dev libcli11-dev nlohmann-json3-dev libpng-dev
  # tests, benchmarks and plots
  libgtest-dev libbenchmark-dev python3-matplotlib
  # the node reference test reads config/*.yaml
  libyaml-cpp-dev
  # the single-view baseline of `vdc evaluate` (OpenCV surface_matching PPF detector)
  libopencv-contrib-dev libopencv-dev
)
for option in "$@"; do
  case "$option" in
    --gui) packages+=(rviz xvfb xauth imagemagick python3-pil) ;;
    --sanitize) packages+=(clang-14 libclang-rt-14-dev libomp-14-dev) ;;
    *) echo "install_deps: unknown option $option" >&2; exit 2 ;;
  esac
done

# PCL's real scans (BSD-3), out of Debian's python3-pcl, unpacked into a cache (not installed):
# the stereo scan of a mug on a table, the input of the real-scan test
# (test/estimation/real_scan_test.cpp), and the Kinect scene of a milk carton among other objects
# with the carton cut out of it, the input of the scene segmentation test
# (test/scene/scene_segmentation_test.cpp). The tests' CMakeLists look there; without the archive
# those tests are skipped, with a message saying so.
real_scans=(
  table_scene_mug_stereo_textured.pcd
  correspondence_grouping/milk_cartoon_all_small_clorox.pcd
  correspondence_grouping/milk.pcd
)
fetch_real_scan() {
  local cache=${XDG_CACHE_HOME:-$HOME/.cache}/view_direction_classification
  local tutorials=usr/share/doc/python3-pcl/examples/pcldata/tutorials
  local wanted=()
  for name in "${real_scans[@]}"; do
    [[ -s "$cache/$(basename "$name")" ]] || wanted+=("$name")
  done
  [[ ${#wanted[@]} -eq 0 ]] && return 0
  local work
  work=$(mktemp -d)
  if (cd "$work" && apt-get download -qq python3-pcl >/dev/null 2>&1) &&
      dpkg-deb -x "$work"/python3-pcl_*.deb "$work/root"; then
    mkdir -p "$cache"
    for name in "${wanted[@]}"; do
      if [[ -s "$work/root/$tutorials/$name" ]]; then
        cp "$work/root/$tutorials/$name" "$cache/$(basename "$name")"
        echo "install_deps: PCL's real scan is in $cache/$(basename "$name")"
      else
        echo "install_deps: python3-pcl has no $name: its test will be skipped" >&2
      fi
    done
  else
    echo "install_deps: could not fetch python3-pcl (apt-get download): the real-scan tests" \
      "will be skipped" >&2
  fi
  rm -rf "$work"
}

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install_deps: all ${#packages[@]} packages present"
  fetch_real_scan
  exit 0
fi

echo "install_deps: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fetch_real_scan
echo "install_deps: done"

#!/usr/bin/env bash
# Soak run (not a CI test; doc/performance.md has the recorded figures): the three nodes, each in
# its own process, the simulated camera streaming 640x480 clouds (307 200 points, NaN where
# nothing is hit) at 30 Hz into the estimator while it circles the mug, and the server answering
# next-best-view and heatmap requests spread over the stream, every fifth one malformed. Each
# node's resident memory is sampled once a second; the end prints peak and end RSS, requests per
# second and latency, clouds fused and dropped, crashes. Exit 1 if a node died or a request was not answered
# as it should be.
#   SOAK_SECONDS   length of the cloud stream (default 600; it runs on until every request is
#                  answered)
#   SOAK_REQUESTS  requests to the server (default 10000)
#   SOAK_RATE      camera rate [Hz] (default 30)
#   SOAK_SAMPLES   candidates sampled per next-best-view request (default 50)
#   SOAK_MODEL     model bundle (default: the test model build/test_data/mug_quick.h5, trained
#                  with `cmake --build build --target vdc_test_model` if missing)
#   SOAK_OUT       directory for rss.csv (one row per node and second) and the nodes' logs
#                  (default soak_output)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
seconds=${SOAK_SECONDS:-600}
requests=${SOAK_REQUESTS:-10000}
rate=${SOAK_RATE:-30}
samples=${SOAK_SAMPLES:-50}
model=${SOAK_MODEL:-$build_dir/test_data/mug_quick.h5}
out=$(realpath -m "${SOAK_OUT:-soak_output}")
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

if [[ -z "${SOAK_MODEL:-}" && ! -f "$model" ]]; then
  cmake --build "$build_dir" --target vdc_test_model
fi
model=$(realpath "$model")
mkdir -p "$out"
set +u
# shellcheck disable=SC1091
source "$build_dir/devel/setup.bash"
set -u
# A master of our own on a free port, and the nodes' logs in $out.
export ROS_MASTER_URI=http://localhost:$(/usr/bin/python3 -c \
  'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
export ROS_LOG_DIR=$out/logs

launch_file=$out/soak.launch
cat > "$launch_file" <<EOF
<launch>
  <include file="\$(find view_direction_classification)/launch/simulated_depth_camera.launch">
    <arg name="rate" value="$rate"/>
    <arg name="output" value="log"/>
  </include>
  <include file="\$(find view_direction_classification)/launch/estimator.launch">
    <arg name="model" value="$model"/>
    <arg name="cloud" value="simulated_depth_camera/cloud"/>
    <arg name="output" value="log"/>
  </include>
  <include file="\$(find view_direction_classification)/launch/informativeness_server.launch">
    <arg name="model" value="$model"/>
    <arg name="output" value="log"/>
  </include>
</launch>
EOF

echo "== soak: ${seconds} s of ${rate} Hz clouds, ${requests} requests (every fifth malformed)," \
  "model $model, master $ROS_MASTER_URI"
roslaunch --wait "$launch_file" > "$out/roslaunch.log" 2>&1 &
launch_pid=$!
roscore_pid=""
roscore -p "${ROS_MASTER_URI##*:}" > "$out/roscore.log" 2>&1 &
roscore_pid=$!
stop() {
  kill -INT "$launch_pid" 2> /dev/null || true
  wait "$launch_pid" 2> /dev/null || true
  kill -INT "$roscore_pid" 2> /dev/null || true
  wait "$roscore_pid" 2> /dev/null || true
}
trap stop EXIT
# The nodes are up when the server offers its service (it loads the model last).
for _ in $(seq 120); do
  rosservice list 2> /dev/null | grep -q informativeness_server/next_best_view && break
  sleep 1
done
status=0
scripts/soak_client.py --seconds "$seconds" --requests "$requests" --samples "$samples" \
  --rss-csv "$out/rss.csv" || status=$?
echo "== memory samples: $out/rss.csv, logs: $out/logs"
exit "$status"

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
#   SOAK_PATROL    1: the patrol soak instead (scripts/patrol_soak_client.py): the estimator with
#                  segmentation scene and the library {mug: SOAK_MODEL} on a 30 Hz stream of a
#                  table with two mugs, a box and a cylinder; the camera passes along the table,
#                  looks away, and between passes two of them are moved, turned, taken away or
#                  put back (~place_part). Writes patrol_samples.csv (RSS and CPU time per node
#                  and second, and the estimator's heap in use and held from its /diagnostics)
#                  and patrol_passes.csv (the memory scored after each pass). No server and no
#                  requests. SOAK_SEED seeds the changes (default 1).
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
if [[ "${SOAK_PATROL:-0}" == 1 ]]; then
  # The built-in mug as a mesh file, for the second mug (a distractor's description is a file).
  "$build_dir/devel/lib/view_direction_classification/vdc" mesh mug --out "$out/mug.ply" \
    > /dev/null
  # The mug's origin is its centre, 4.75 cm above its bottom: the table top is at -0.0475.
  cat > "$launch_file" <<EOF
<launch>
  <node pkg="view_direction_classification" type="simulated_depth_camera"
        name="simulated_depth_camera" output="log" required="true">
    <rosparam command="load"
              file="\$(find view_direction_classification)/config/simulated_depth_camera.yaml"/>
    <param name="rate" value="$rate"/>
    <rosparam>
      table_size: [1.0, 0.8]
      object_pose: [0.0, 0.0, 0.0, 0.0, 0.0, 0.5]
      distractors: "$out/mug.ply; box 0.09 0.08 0.10; cylinder 0.03 0.25"
      distractor_poses: [0.2, 0.15, 0.0, 0.0, 0.0, -1.0,  -0.2, 0.1, -0.0475, 0.0, 0.0, 0.3,
                         0.1, -0.2, -0.0475, 0.0, 0.0, 0.0]
    </rosparam>
  </node>
  <include file="\$(find view_direction_classification)/launch/estimator.launch">
    <arg name="models" value="{mug: $model}"/>
    <arg name="segmentation" value="scene"/>
    <arg name="cloud" value="simulated_depth_camera/cloud"/>
    <arg name="output" value="log"/>
  </include>
</launch>
EOF
else
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
fi

if [[ "${SOAK_PATROL:-0}" == 1 ]]; then
  echo "== patrol soak: ${seconds} s of ${rate} Hz clouds, model $model, master $ROS_MASTER_URI"
else
  echo "== soak: ${seconds} s of ${rate} Hz clouds, ${requests} requests (every fifth malformed)," \
    "model $model, master $ROS_MASTER_URI"
fi
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
status=0
if [[ "${SOAK_PATROL:-0}" == 1 ]]; then
  # Parts as NAME:MODEL:X,Y,YAW:LIFT in the camera's order (the object, then the distractors).
  scripts/patrol_soak_client.py --seconds "$seconds" --table-top -0.0475 \
    --part mug_a:mug:0,0,0.5:0.0475 --part mug_b:mug:0.2,0.15,-1.0:0.0475 \
    --part box:-:-0.2,0.1,0.3:0 --part cylinder:-:0.1,-0.2,0:0 --max-instances 6 \
    --seed "${SOAK_SEED:-1}" --samples-csv "$out/patrol_samples.csv" \
    --passes-csv "$out/patrol_passes.csv" || status=$?
  echo "== samples: $out/patrol_samples.csv, passes: $out/patrol_passes.csv, logs: $out/logs"
  exit "$status"
fi
# The nodes are up when the server offers its service (it loads the model last).
for _ in $(seq 120); do
  rosservice list 2> /dev/null | grep -q informativeness_server/next_best_view && break
  sleep 1
done
scripts/soak_client.py --seconds "$seconds" --requests "$requests" --samples "$samples" \
  --rss-csv "$out/rss.csv" || status=$?
echo "== memory samples: $out/rss.csv, logs: $out/logs"
exit "$status"

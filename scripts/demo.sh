#!/usr/bin/env bash
# `make demo`: the closed loop of launch/demo.launch on the built-in mug, headless. A simulated
# camera streams a table-top scene at 15 Hz to the orientation estimator; the informativeness
# server and the planner loop move the camera until it has been at $DEMO_VIEWS views; then the
# error after each view is printed beside the belief's own 90 % cone.
#   DEMO_MODEL    model bundle (default: the default mug model, trained into ~/.ros/vdc on the
#                 first run and again whenever vdc was rebuilt since)
#   DEMO_VIEWS    views (default 8)        DEMO_UTILITY  informativeness | information_gain
#   DEMO_OUT      output directory (default demo_output)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
model=${DEMO_MODEL:-$HOME/.ros/vdc/mug_default.h5}
views=${DEMO_VIEWS:-8}
utility=${DEMO_UTILITY:-information_gain}
out=$(realpath -m "${DEMO_OUT:-demo_output}")
vdc="$build_dir/devel/lib/view_direction_classification/vdc"
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

if [[ -z "${DEMO_MODEL:-}" && ( ! -f "$model" || "$vdc" -nt "$model" ) ]]; then
  # The default model (42 directions x 20 clouds, ~3 min on 2 cores). Retrained when vdc is newer
  # than the cached file: a rebuilt tool may compute features differently. DEMO_MODEL=any.h5
  # uses a given model as it is.
  echo "== training the default mug model into $model (about 3 minutes, once)"
  mkdir -p "$(dirname "$model")"
  "$vdc" mesh mug --out "$(dirname "$model")/mug.ply"
  "$vdc" train --mesh "$(dirname "$model")/mug.ply" --out "$model"
fi

echo "== closed loop: $views views, utility $utility, model $model"
mkdir -p "$out"
rm -f "$out/errors.csv"
# setup.bash reads unset variables: relax -u while sourcing it.
set +u
# shellcheck disable=SC1091
source "$build_dir/devel/setup.bash"
set -u
# The planner node is required: when it has written its results the launch shuts down.
# roslaunch's whole output goes to $out/roslaunch.log; the terminal shows the progress lines.
log="$out/roslaunch.log"
set +e
roslaunch view_direction_classification demo.launch model:="$model" views:="$views" \
  utility:="$utility" output_dir:="$out" gui:=false output:=log 2>&1 | tee "$log" \
  | grep --line-buffered -E 'planner: |view [0-9]+: |FATAL|ERROR'
launch_status=${PIPESTATUS[0]}
set -e

if [[ ! -f "$out/errors.csv" ]]; then
  # Say why: roslaunch's own error (a launch file it cannot resolve, a missing argument, a node
  # that cannot start) is only in its output, which the filter above hides.
  {
    echo "demo: the planner wrote no $out/errors.csv; roslaunch exited with status" \
      "$launch_status. The end of its output ($log):"
    tail -n 40 "$log" | sed -e 's/\x1b\[[0-9;]*m//g' -e 's/^/  | /'
    echo "demo: each node's own output is in ~/.ros/log/latest/"
  } >&2
  exit 1
fi
echo
echo "== orientation error after each view (MAP vs ground truth) and the belief's 90 % cone"
/usr/bin/python3 - "$out/errors.csv" <<'EOF'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print("view %2s: error %6.1f deg, cone90 %6.1f deg, %2s views fused, entropy %6.2f nats"
          % (row["view"], float(row["error_deg"]), float(row["cone90_deg"]), row["views_fused"],
             float(row["entropy_nats"])))
EOF
echo "results: $out/errors.csv, plot: $out/errors.png"

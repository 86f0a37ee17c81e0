#!/usr/bin/env bash
# `make demo`: the closed loop of launch/demo.launch on the built-in mug, headless. A simulated
# camera, the orientation estimator, the informativeness server and the planner loop run until
# the planner has taken $DEMO_VIEWS views; then the error after each view is printed.
#   DEMO_MODEL    model bundle (default: the quick mug model, trained once into ~/.ros/vdc)
#   DEMO_VIEWS    views (default 8)        DEMO_UTILITY  informativeness | information_gain
#   DEMO_OUT      output directory (default demo_output)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
model=${DEMO_MODEL:-$HOME/.ros/vdc/mug_quick.h5}
views=${DEMO_VIEWS:-8}
utility=${DEMO_UTILITY:-informativeness}
out=$(realpath -m "${DEMO_OUT:-demo_output}")
vdc="$build_dir/devel/lib/view_direction_classification/vdc"
export PATH=/usr/bin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

if [[ ! -f "$model" ]]; then
  # The quick model (12 directions x 4 clouds, about a minute): enough to watch the loop work.
  # A full model (`vdc train --mesh mug.ply --out mug.h5`, 42 x 20, ~20 min) estimates better:
  # DEMO_MODEL=mug.h5 make demo.
  echo "== training the quick mug model once into $model"
  mkdir -p "$(dirname "$model")"
  "$vdc" mesh mug --out "$(dirname "$model")/mug.ply"
  "$vdc" train --quick --mesh "$(dirname "$model")/mug.ply" --out "$model"
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
roslaunch view_direction_classification demo.launch model:="$model" views:="$views" \
  utility:="$utility" output_dir:="$out" gui:=false output:=log 2>&1 \
  | grep --line-buffered -E 'planner: |view [0-9]+: |FATAL|ERROR' || true

if [[ ! -f "$out/errors.csv" ]]; then
  echo "demo: the planner wrote no $out/errors.csv (see the log above and ~/.ros/log/latest)" >&2
  exit 1
fi
echo
echo "== orientation error after each view (MAP vs ground truth)"
/usr/bin/python3 - "$out/errors.csv" <<'EOF'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print("view %2s: error %6.1f deg, entropy %6.2f nats"
          % (row["view"], float(row["error_deg"]), float(row["entropy_nats"])))
EOF
echo "results: $out/errors.csv, plot: $out/errors.png"

#!/usr/bin/env bash
# `make demo`: the main job on the built-in mug. Writes into demo_output/ (or $DEMO_OUT).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
out=${DEMO_OUT:-demo_output}
vdc="$build_dir/devel/lib/view_direction_classification/vdc"
mkdir -p "$out"

echo "== the built-in mug"
"$vdc" mesh mug --out "$out/mug.ply"
echo
echo "== one rendered depth cloud and its FPFH features per viewing direction"
"$vdc" views --mesh "$out/mug.ply" --views 42

#!/usr/bin/env bash
# `make bench`: the Google Benchmark binaries and the feature-stage throughput on the mug.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${BUILD_DIR:-build}/devel/lib/view_direction_classification"
for benchmark in vdc_renderer_benchmark vdc_bingham_benchmark; do
  if [[ -x "$bin/$benchmark" ]]; then
    echo "== $benchmark"
    "$bin/$benchmark" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
  fi
done
echo "== feature stage on the built-in mug"
out=$(mktemp -d)
"$bin/vdc" mesh mug --out "$out/mug.ply" >/dev/null
"$bin/vdc" views --mesh "$out/mug.ply" | tail -4
rm -rf "$out"

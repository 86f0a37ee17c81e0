// Renders per second of the default mug at the training distance (0.6 m), the figure that
// bounds training-set generation and the simulated camera's frame rate.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace {

// A few directions: side, handle, top (inside visible), bottom, two oblique.
std::vector<Eigen::Isometry3d> mugPoses() {
  const std::vector<Eigen::Vector3d> directions = {{1, 0, 0},  {0, 1, 0}, {0, 0, 1},
                                                   {0, 0, -1}, {1, 1, 1}, {-1, 0.5, -0.3}};
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    poses.push_back(vdc::cameraFromObject(directions[i], 0.6, 0.5 * static_cast<double>(i)));
  }
  return poses;
}

void BM_RenderMugCloud(benchmark::State& state) {
  const bool noisy = state.range(0) != 0;
  const vdc::DepthRenderer renderer(vdc::makeMug());
  const std::vector<Eigen::Isometry3d> poses = mugPoses();
  const vdc::DepthNoiseModel noise{noisy};
  std::mt19937 rng(1);
  std::size_t i = 0;
  for (auto _ : state) {
    auto cloud = renderer.render(poses[i++ % poses.size()], noise, &rng);
    benchmark::DoNotOptimize(cloud.points.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(noisy ? "noise on" : "noise off");
}
BENCHMARK(BM_RenderMugCloud)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_RenderMugDepthImage(benchmark::State& state) {
  const vdc::DepthRenderer renderer(vdc::makeMug());
  const std::vector<Eigen::Isometry3d> poses = mugPoses();
  std::size_t i = 0;
  for (auto _ : state) {
    auto depth = renderer.renderDepth(poses[i++ % poses.size()]);
    benchmark::DoNotOptimize(depth.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RenderMugDepthImage)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// Time to rank 100 candidate camera poses with each next-best-view utility on a synthetic
// bundle of the default size (M = 42 directions, ~10k surface points): the figure behind the
// informativeness server's "answers fast".
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/estimation/view_measurement.h"
#include "view_direction_classification/geometry/view_sphere.h"
#include "view_direction_classification/planning/next_best_view.h"

namespace {

// Surface points on a 5 cm sphere (a stand-in for the mug's 2 mm sampling), a score for every
// (point, direction) pair the point faces, random confusion rows.
std::shared_ptr<const vdc::ModelBundle> syntheticBundle() {
  constexpr int kViews = 42, kPoints = 10000;
  auto bundle = std::make_shared<vdc::ModelBundle>();
  const vdc::ViewSphere views(kViews);
  bundle->view_directions = views.directions();
  const vdc::ViewSphere points(kPoints);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> score(0.5f, 4.0f);
  bundle->score_matrix.resize(kPoints, kViews);
  for (int i = 0; i < kPoints; ++i) {
    const Eigen::Vector3f normal = points.direction(i).cast<float>();
    bundle->surface_points.push_back(0.05f * normal);
    bundle->surface_normals.push_back(normal);
    for (int m = 0; m < kViews; ++m) {
      const bool seen = normal.dot(views.direction(m).cast<float>()) > 0.2f;
      bundle->score_matrix(i, m) = seen ? score(rng) : -1.0f;
    }
  }
  std::uniform_real_distribution<double> probability(0.0, 1.0);
  auto& informativeness = bundle->view_informativeness;
  informativeness.confusion = Eigen::MatrixXd::NullaryExpr(
      kViews, kViews, [&](Eigen::Index, Eigen::Index) { return probability(rng); });
  informativeness.confusion += 5.0 * Eigen::MatrixXd::Identity(kViews, kViews);
  for (int m = 0; m < kViews; ++m) {
    informativeness.confusion.row(m) /= informativeness.confusion.row(m).sum();
  }
  informativeness.view_scores = Eigen::VectorXd::Constant(kViews, 2.0);
  return bundle;
}

std::vector<Eigen::Vector3d> candidatePositions() {
  std::vector<Eigen::Vector3d> positions;
  for (const auto& pose : vdc::sampleCandidatePoses(100, 0.6, Eigen::Vector3d(0.5, 0, 0.2))) {
    positions.push_back(pose.translation());
  }
  return positions;
}

// A belief after one view: the measurement mixture of a view's p_sum over all 42 directions.
vdc::BinghamMixture oneViewBelief(const vdc::ModelBundle& bundle) {
  Eigen::VectorXd p_sum = bundle.view_informativeness.confusion.row(0).transpose();
  return vdc::viewMeasurement(p_sum, bundle.view_directions, 37.0);
}

void BM_RankInformativeness(benchmark::State& state) {
  const vdc::ViewUtilityScorer scorer(syntheticBundle());
  const auto candidates = candidatePositions();
  vdc::PlanningScene scene;
  scene.object_position = Eigen::Vector3d(0.5, 0, 0.2);
  // state.range(0) occluder points in a 10 cm cube between the object and one side.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> box(-0.05, 0.05);
  for (int i = 0; i < state.range(0); ++i) {
    scene.occluder_world.emplace_back(0.65 + box(rng), box(rng), 0.2 + box(rng));
  }
  for (auto _ : state) {
    auto ranked =
        vdc::rankCandidates(scorer, candidates, vdc::ViewUtility::kInformativeness, scene);
    benchmark::DoNotOptimize(ranked.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(candidates.size()));
  state.SetLabel("100 candidates, " + std::to_string(state.range(0)) + " occluder points");
}
BENCHMARK(BM_RankInformativeness)->Arg(0)->Arg(2000)->Unit(benchmark::kMillisecond);

void BM_RankInformationGain(benchmark::State& state) {
  const auto bundle = syntheticBundle();
  const vdc::ViewUtilityScorer scorer(bundle);
  const auto candidates = candidatePositions();
  vdc::PlanningScene scene;
  scene.object_position = Eigen::Vector3d(0.5, 0, 0.2);
  scene.belief = oneViewBelief(*bundle);
  vdc::NextBestViewOptions options;
  options.samples_per_component = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto ranked =
        vdc::rankCandidates(scorer, candidates, vdc::ViewUtility::kInformationGain, scene, options);
    benchmark::DoNotOptimize(ranked.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(candidates.size()));
  state.SetLabel("100 candidates, " + std::to_string(scene.belief.size()) + " components x " +
                 std::to_string(1 + state.range(0)) + " hypotheses");
}
BENCHMARK(BM_RankInformationGain)->Arg(0)->Arg(8)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

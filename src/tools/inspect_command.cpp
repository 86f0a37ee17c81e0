// `vdc inspect B.h5 [--json]`: what a model bundle holds and how good it is.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "sensor_option.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc::tools {

namespace {

double meanOfValid(const Eigen::Ref<const Eigen::VectorXd>& values) {
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (values(i) >= 0.0) sum += values(i), ++count;
  }
  return count > 0 ? sum / count : -1.0;
}

nlohmann::json describe(const ModelBundle& bundle, const std::string& path) {
  const auto& v = bundle.view_informativeness;
  const Eigen::VectorXd global = bundle.global_scores.cast<double>();
  int observable = 0;
  for (Eigen::Index i = 0; i < global.size(); ++i) observable += global(i) >= 0.0 ? 1 : 0;
  nlohmann::json ranking = nlohmann::json::array();
  for (int m : v.ranking) {
    const Eigen::Vector3d& d = bundle.view_directions[static_cast<std::size_t>(m)];
    ranking.push_back(
        {{"view", m}, {"score", v.view_scores(m)}, {"direction", {d.x(), d.y(), d.z()}}});
  }
  const double mean_global = meanOfValid(global);
  return {
      {"file", path},
      {"format_version", ModelBundle::kFormatVersion},
      {"mesh", bundle.parameters.mesh_name},
      {"views", static_cast<int>(bundle.view_directions.size())},
      {"clouds_per_view", bundle.parameters.clouds_per_view},
      {"seed", bundle.parameters.seed},
      {"distance_range_m",
       {bundle.parameters.distance * (1.0 - bundle.parameters.distance_jitter),
        bundle.parameters.distance * (1.0 + bundle.parameters.distance_jitter)}},
      {"sensor", selectionName(bundle.parameters.noise, bundle.parameters.sensor)},
      {"classifier_clusters", bundle.parameters.clusters},
      {"surface_points", static_cast<int>(bundle.surface_points.size())},
      {"extent_m",
       {bundle.bounds.sizes().x(), bundle.bounds.sizes().y(), bundle.bounds.sizes().z()}},
      {"observable_surface_points", observable},
      {"held_out_accuracy", bundle.held_out.accuracy},
      {"held_out_log_loss", bundle.held_out.log_loss},
      {"held_out_features", bundle.held_out.features},
      {"mean_view_score", meanOfValid(v.view_scores)},
      {"mean_global_score", mean_global},
      // The paper's reading of a mean score: the average weight on the correct view, e^-score.
      {"mean_correct_view_weight", mean_global >= 0.0 ? std::exp(-mean_global) : -1.0},
      {"view_ranking", ranking},
  };
}

void printText(const nlohmann::json& j) {
  std::printf("%s\n", j["file"].get<std::string>().c_str());
  std::printf("  format version      %d\n", j["format_version"].get<int>());
  std::printf("  mesh                %s\n", j["mesh"].get<std::string>().c_str());
  std::printf("  views               %d (x %d training clouds, seed %u)\n", j["views"].get<int>(),
              j["clouds_per_view"].get<int>(), j["seed"].get<unsigned>());
  const auto& distances = j["distance_range_m"];
  std::printf("  camera distances    %.2f-%.2f m (training clouds)\n", distances[0].get<double>(),
              distances[1].get<double>());
  std::printf("  depth sensor        %s (training clouds)\n",
              j["sensor"].get<std::string>().c_str());
  std::printf("  surface points      %d (%d observable)\n", j["surface_points"].get<int>(),
              j["observable_surface_points"].get<int>());
  const auto& extent = j["extent_m"];
  std::printf("  extent              %.1f x %.1f x %.1f cm (bounding box, object frame)\n",
              100.0 * extent[0].get<double>(), 100.0 * extent[1].get<double>(),
              100.0 * extent[2].get<double>());
  std::printf("  held-out accuracy   %.3f (chance %.3f) on %zu features\n",
              j["held_out_accuracy"].get<double>(), 1.0 / j["views"].get<int>(),
              j["held_out_features"].get<std::size_t>());
  std::printf("  held-out log-loss   %.3f\n", j["held_out_log_loss"].get<double>());
  std::printf("  mean view score     %.3f\n", j["mean_view_score"].get<double>());
  std::printf(
      "  mean global score   %.3f (mean weight on the correct view %.1f %%; the paper's "
      "mug: 2.15, 11.6 %%)\n",
      j["mean_global_score"].get<double>(), 100.0 * j["mean_correct_view_weight"].get<double>());
  std::printf("  view ranking (most informative first):\n");
  std::printf("    %4s %5s %8s  %s\n", "rank", "view", "score", "direction (object frame)");
  int rank = 1;
  for (const auto& entry : j["view_ranking"]) {
    const auto& d = entry["direction"];
    std::printf("    %4d %5d %8.3f  (%6.3f %6.3f %6.3f)\n", rank++, entry["view"].get<int>(),
                entry["score"].get<double>(), d[0].get<double>(), d[1].get<double>(),
                d[2].get<double>());
  }
}

}  // namespace

void addInspectCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto* inspect = app.add_subcommand("inspect", "describe a model bundle");
  inspect->add_option("bundle", *path, "model bundle (HDF5)")->required();
  inspect->add_flag("--json", *json, "machine-readable output");
  inspect->callback([path, json] {
    const nlohmann::json description = describe(loadModelBundle(*path), *path);
    if (*json) {
      std::cout << description.dump(2) << "\n";
    } else {
      printText(description);
    }
  });
}

}  // namespace vdc::tools

// `vdc heatmap --model B.h5 --out DIR`: pictures of the surface scores in the paper's colour
// scale. The panels are rendered here (exact occlusion); scripts/plot_heatmaps.py only lays them
// out with titles and colour bars.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "commands.h"
#include "python_script.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/visualisation/heatmap_colours.h"
#include "view_direction_classification/visualisation/surface_splat_renderer.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

struct HeatmapOptions {
  std::string model_path;
  std::string out_dir;
  int size = 360;
  int views = 3;
  bool no_figure = false;
};

std::vector<Rgb> colour(const Eigen::VectorXf& values, double black_at) {
  std::vector<Rgb> colours(static_cast<std::size_t>(values.size()));
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    colours[static_cast<std::size_t>(i)] = heatmapColour(values(i), black_at);
  }
  return colours;
}

void runHeatmap(const HeatmapOptions& options) {
  const ModelBundle bundle = loadModelBundle(options.model_path);
  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error)
    throw Error("cannot create output directory " + options.out_dir + ": " + error.message());

  SplatView view;
  view.size = options.size;
  view.point_spacing = bundle.parameters.surface_spacing;
  nlohmann::json panels = nlohmann::json::array();
  auto draw = [&](const Eigen::VectorXf& values, double black_at, const Eigen::Vector3d& direction,
                  const std::string& name, const std::string& title, const std::string& row) {
    view.direction = direction;
    const RgbImage image =
        renderSplats(bundle.surface_points, bundle.surface_normals, colour(values, black_at), view);
    const std::string file = name + ".png";
    writePng(image, (fs::path(options.out_dir) / file).string());
    panels.push_back({{"file", file}, {"title", title}, {"row", row}, {"black_at", black_at}});
  };

  // Global score g (paper figure 3): along x, y, z; median scale and maximum scale.
  const Eigen::VectorXf& g = bundle.global_scores;
  const double g_median = medianOfValid(g);
  const double g_max = g.size() > 0 ? std::max(0.0, static_cast<double>(g.maxCoeff())) : 0.0;
  const std::pair<const char*, Eigen::Vector3d> axes[] = {{"x", Eigen::Vector3d::UnitX()},
                                                          {"y", Eigen::Vector3d::UnitY()},
                                                          {"z", Eigen::Vector3d::UnitZ()}};
  for (const auto& [axis, direction] : axes) {
    draw(g, g_median, direction, std::string("global_median_") + axis,
         std::string("global score, seen from +") + axis, "global score\n(black = median)");
  }
  for (const auto& [axis, direction] : axes) {
    draw(g, g_max, direction, std::string("global_max_") + axis,
         std::string("global score, seen from +") + axis, "global score\n(black = maximum)");
  }

  // View-conditional scores (paper figure 2): columns of K for the best and worst ranked views,
  // each seen from its own direction, one scale for all (the median of all valid entries of K).
  const auto& ranking = bundle.view_informativeness.ranking;
  const Eigen::MatrixXf& K = bundle.score_matrix;
  const Eigen::VectorXf all_scores = Eigen::Map<const Eigen::VectorXf>(K.data(), K.size());
  const double k_median = medianOfValid(all_scores);
  const int shown = std::min<int>(options.views, static_cast<int>(ranking.size()) / 2);
  for (int r = 0; r < shown; ++r) {
    for (const bool best : {true, false}) {
      const int rank = best ? r : static_cast<int>(ranking.size()) - shown + r;
      const int m = ranking[static_cast<std::size_t>(rank)];
      char title[128];
      std::snprintf(title, sizeof(title), "view %d, rank %d/%zu, v = %.2f", m, rank + 1,
                    ranking.size(), bundle.view_informativeness.view_scores(m));
      draw(K.col(m), k_median, bundle.view_directions[static_cast<std::size_t>(m)],
           (best ? "view_best_" : "view_worst_") + std::to_string(r + 1), title,
           best ? "most informative views\n(black = median of K)"
                : "least informative views\n(black = median of K)");
    }
  }

  const Rgb invalid = heatmapColour(-1.0, 1.0);
  const nlohmann::json manifest = {{"model", fs::path(options.model_path).filename().string()},
                                   {"mean_global_score", g.size() ? g.cwiseMax(0.0f).mean() : 0.0f},
                                   {"unobservable_colour", {invalid[0], invalid[1], invalid[2]}},
                                   {"panels", panels}};
  const fs::path manifest_path = fs::path(options.out_dir) / "heatmaps.json";
  std::ofstream(manifest_path) << manifest.dump(2) << "\n";
  std::printf("wrote %zu panels to %s\n", panels.size(), options.out_dir.c_str());

  if (options.no_figure) return;
  const fs::path figure = fs::path(options.out_dir) / "heatmaps.png";
  runPythonScript("plot_heatmaps.py", {manifest_path.string(), figure.string()},
                  "composing the figure", "the single panels are in " + options.out_dir);
  std::printf("wrote %s\n", figure.c_str());
}

}  // namespace

void addHeatmapCommand(CLI::App& app) {
  auto options = std::make_shared<HeatmapOptions>();
  auto* heatmap = app.add_subcommand("heatmap", "PNG pictures of the surface informativeness");
  heatmap->add_option("--model", options->model_path, "model bundle (HDF5)")->required();
  heatmap->add_option("--out", options->out_dir, "output directory")->required();
  heatmap->add_option("--size", options->size, "panel size [px]")
      ->capture_default_str()
      ->check(CLI::Range(64, 4096));
  heatmap->add_option("--views", options->views, "best and worst views to show")
      ->capture_default_str()
      ->check(CLI::Range(0, 20));
  heatmap->add_flag("--no-figure", options->no_figure,
                    "only the single panels, no composed figure (no matplotlib needed)");
  heatmap->callback([options] { runHeatmap(*options); });
}

}  // namespace vdc::tools

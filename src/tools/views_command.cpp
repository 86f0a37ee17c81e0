// `vdc views`: renders the object once from every grid direction, computes its features and
// prints what each view yields, with the renderer's and the feature stage's throughput. It is
// the quickest check that a mesh, the camera model and the feature settings fit together.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "commands.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc::tools {

namespace {

struct ViewsOptions {
  std::string mesh_path;  // empty: the built-in mug
  int views = 42;
  double distance = 0.6;
  bool no_noise = false;
  unsigned seed = 1;
  int repeat = 5;
};

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

template <typename T>
T median(std::vector<T> values) {
  if (values.empty()) return T{};
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

void runViews(const ViewsOptions& options) {
  const TriangleMesh mesh = options.mesh_path.empty() ? makeMug() : loadMesh(options.mesh_path);
  const std::string name = options.mesh_path.empty() ? "built-in mug" : options.mesh_path;
  for (const auto& warning : validateObjectMesh(mesh, name)) {
    std::cerr << "warning: " << warning << "\n";
  }
  const ViewSphere sphere(options.views);
  const DepthRenderer renderer(mesh);
  const DepthNoiseModel noise{!options.no_noise};
  std::mt19937 rng(options.seed);

  std::printf("object: %s, %zu triangles, %.1f cm^2\n", name.c_str(), mesh.triangles.size(),
              mesh.area() * 1e4);
  std::printf("camera: %dx%d, fx %.0f, distance %.2f m, noise %s; %d views\n",
              renderer.intrinsics().width, renderer.intrinsics().height, renderer.intrinsics().fx,
              options.distance, noise.enabled ? "on" : "off", sphere.size());
  std::printf("%5s  %-22s %8s %9s\n", "view", "direction (object)", "points", "features");

  std::vector<std::size_t> points, features;
  double render_seconds = 0.0, feature_seconds = 0.0;
  std::size_t feature_total = 0;
  for (int m = 0; m < sphere.size(); ++m) {
    const Eigen::Isometry3d pose = cameraFromObject(sphere.direction(m), options.distance, 0.0);
    auto start = std::chrono::steady_clock::now();
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (int r = 0; r < options.repeat; ++r) cloud = renderer.render(pose, noise, &rng);
    render_seconds += seconds(std::chrono::steady_clock::now() - start) / options.repeat;
    start = std::chrono::steady_clock::now();
    const FeatureSet f = computeFeatures(cloud);
    feature_seconds += seconds(std::chrono::steady_clock::now() - start);
    points.push_back(countValidPoints(cloud));
    features.push_back(f.size());
    feature_total += f.size();
    const Eigen::Vector3d& d = sphere.direction(m);
    std::printf("%5d  (%6.3f %6.3f %6.3f)  %8zu %9zu\n", m, d.x(), d.y(), d.z(), points.back(),
                features.back());
  }
  const auto [min_points, max_points] = std::minmax_element(points.begin(), points.end());
  const auto [min_features, max_features] = std::minmax_element(features.begin(), features.end());
  std::printf("points per view: min %zu, median %zu, max %zu\n", *min_points, median(points),
              *max_points);
  std::printf("features per view: min %zu, median %zu, max %zu (total %zu)\n", *min_features,
              median(features), *max_features, feature_total);
  std::printf("renderer: %.0f renders/s (%.2f ms per %dx%d view, 1 thread, mean of %d)\n",
              sphere.size() / render_seconds, 1e3 * render_seconds / sphere.size(),
              renderer.intrinsics().width, renderer.intrinsics().height, options.repeat);
  std::printf("features: %.1f clouds/s, %.0f features/s (%.1f ms per view, %d threads)\n",
              sphere.size() / feature_seconds, feature_total / feature_seconds,
              1e3 * feature_seconds / sphere.size(), omp_get_max_threads());
}

}  // namespace

void addViewsCommand(CLI::App& app) {
  auto options = std::make_shared<ViewsOptions>();
  auto* views = app.add_subcommand(
      "views", "render every grid view, compute features, print a summary and throughput");
  views->add_option("--mesh", options->mesh_path, "mesh file (default: the built-in mug)");
  views->add_option("--views", options->views, "number of viewing directions")
      ->check(CLI::Range(2, 10000));
  views->add_option("--distance", options->distance, "camera distance [m]")
      ->check(CLI::Range(0.05, 20.0));
  views->add_flag("--no-noise", options->no_noise, "render without sensor noise");
  views->add_option("--seed", options->seed, "noise seed");
  views->add_option("--repeat", options->repeat, "renders per view for the timing")
      ->check(CLI::Range(1, 1000));
  views->callback([options] { runViews(*options); });
}

}  // namespace vdc::tools

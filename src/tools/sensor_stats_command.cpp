// `vdc sensor-stats [--cloud SCAN.pcd ...]`: which depth sensor model (geometry/sensor_model.h)
// a real scan looks like. Prints the figures of evaluation/depth_statistics.h for each scan and
// for renders of a comparable scene (the built-in mug on a table, seen from `--elevation` at
// `--distance`) with each sensor model, in one table (doc/evaluation.md, "Depth sensor models").
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "commands.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/depth_statistics.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc::tools {

namespace {

struct SensorStatsOptions {
  std::vector<std::string> clouds;
  double distance = 1.0;    // [m] camera to mug
  double elevation = 40.0;  // [deg] of the camera above the table
  unsigned seed = 1;
};

// PCL's reader crashes on some files that are not PCD at all: read the header alone first and
// require x, y and z fields.
void checkScanHeader(const std::string& path) {
  pcl::PCLPointCloud2 header;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0, data_type = 0;
  unsigned int data_offset = 0;
  if (pcl::PCDReader().readHeader(path, header, origin, orientation, version, data_type,
                                  data_offset) != 0) {
    throw Error("cannot read the point cloud " + path + ": not a PCD file");
  }
  for (const char* axis : {"x", "y", "z"}) {
    const bool found = std::any_of(header.fields.begin(), header.fields.end(),
                                   [axis](const pcl::PCLPointField& f) { return f.name == axis; });
    if (!found) throw Error("the point cloud " + path + " has no " + axis + " field");
  }
}

pcl::PointCloud<pcl::PointXYZ> loadScan(const std::string& path) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  // PCL prints its own complaint before returning an error; the one line below says it all.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  checkScanHeader(path);
  if (pcl::io::loadPCDFile(path, cloud) != 0) {
    throw Error("cannot read the point cloud " + path + " (a PCD file with x y z fields)");
  }
  return cloud;
}

// The mug standing upright on a 1.2 x 0.8 m table, its handle towards the camera's side.
TriangleMesh mugOnTable() {
  Scene scene;
  scene.object.mesh = makeMug();
  scene.table_size = Eigen::Vector2d(1.2, 0.8);
  return sceneMesh(scene);
}

Eigen::Isometry3d cameraOverTable(const SensorStatsOptions& options) {
  const double elevation = options.elevation * M_PI / 180.0;
  // From the -y side, so that the handle (+x) shows in profile, as on the PCL scan.
  const Eigen::Vector3d direction(0.0, -std::cos(elevation), std::sin(elevation));
  return cameraFromObject(direction, options.distance, 0.0);
}

void printHeader() {
  std::printf("%-44s %7s %6s %9s %9s %6s %8s %8s %8s\n", "source", "points", "z [m]", "levels/cm",
              "step [px]", "edges", "edge gap", "flat gap", "flying");
}

void printRow(const std::string& source, const DepthStatistics& s) {
  std::printf("%-44s %7zu %6.3f %9.1f %9.4f %6zu %8.3f %8.3f %8.3f\n", source.c_str(), s.points,
              s.median_depth, s.levels_per_cm, s.disparity_step_px, s.depth_edges,
              s.edge_gap_fraction, s.flat_gap_fraction, s.flying_fraction);
}

void checkOptions(const SensorStatsOptions& options) {
  if (!(options.distance > 0.1 && options.distance < 10.0)) {
    throw Error("--distance must be between 0.1 and 10 m, got " + std::to_string(options.distance));
  }
  if (!(options.elevation >= 5.0 && options.elevation <= 90.0)) {
    throw Error("--elevation must be between 5 and 90 degrees, got " +
                std::to_string(options.elevation));
  }
}

void runSensorStats(const SensorStatsOptions& options) {
  checkOptions(options);
  // Every scan read before the table starts: a bad file ends the run with its one-line error.
  std::vector<DepthStatistics> scans;
  for (const std::string& path : options.clouds) scans.push_back(depthStatistics(loadScan(path)));
  printHeader();
  for (std::size_t i = 0; i < scans.size(); ++i) printRow(options.clouds[i], scans[i]);
  const DepthRenderer renderer(mugOnTable());
  const Eigen::Isometry3d camera = cameraOverTable(options);
  std::mt19937 rng(options.seed);
  printRow("render: none (exact depth)", depthStatistics(renderer.render(camera, {false})));
  for (DepthSensor kind : {DepthSensor::kKinectGaussian, DepthSensor::kStructuredLight,
                           DepthSensor::kActiveStereo, DepthSensor::kTimeOfFlight}) {
    const pcl::PointCloud<pcl::PointXYZ> cloud =
        renderer.render(camera, DepthNoiseModel{true, sensorModel(kind)}, &rng);
    printRow(std::string("render: ") + sensorName(kind), depthStatistics(cloud));
  }
}

}  // namespace

void addSensorStatsCommand(CLI::App& app) {
  auto options = std::make_shared<SensorStatsOptions>();
  auto* command = app.add_subcommand(
      "sensor-stats",
      "depth figures (quantisation, dropouts and flying pixels at depth edges) of real scans and "
      "of renders of the mug on a table with each sensor model");
  command->add_option("--cloud", options->clouds, "a real scan (PCD; organised for the edges)")
      ->check(CLI::ExistingFile);
  command->add_option("--distance", options->distance, "[m] render camera to mug")
      ->capture_default_str();
  command->add_option("--elevation", options->elevation, "[deg] render camera above the table")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the renders' noise")->capture_default_str();
  command->callback([options] { runSensorStats(*options); });
}

}  // namespace vdc::tools

#include "estimator_ros_parameters.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

const char* typeName(const std::string&) { return "string"; }
const char* typeName(bool) { return "boolean"; }
const char* typeName(int) { return "integer"; }
const char* typeName(double) { return "number"; }
const char* typeName(const std::vector<double>&) { return "list of numbers"; }

// The parameter's value, `fallback` when it is not set; a value of the wrong type is an error
// (roscpp's getParam would silently keep the default).
template <typename T>
T read(const ros::NodeHandle& node, const std::string& name, T fallback) {
  if (!node.hasParam(name)) return fallback;
  T value{};
  if (!node.getParam(name, value)) {
    throw Error("Parameter ~" + name + " must be a " + typeName(value) + ".");
  }
  return value;
}

template <typename T>
void require(bool condition, const std::string& name, const std::string& rule, const T& value) {
  if (condition) return;
  std::ostringstream message;
  message << "Parameter ~" << name << " must be " << rule << ", got " << value << ".";
  throw Error(message.str());
}

void requireName(const std::string& value, const std::string& name) {
  require(!value.empty() && value.find(' ') == std::string::npos, name,
          "a non-empty name without spaces", "'" + value + "'");
}

}  // namespace

EstimatorRosParameters readEstimatorRosParameters(const ros::NodeHandle& node) {
  EstimatorRosParameters p;
  p.model_path = read<std::string>(node, "model", "");
  if (p.model_path.empty()) {
    throw Error(
        "Parameter ~model (the model bundle's path) is required; train one with `vdc "
        "train` and pass it as model:=<file.h5>.");
  }
  p.fixed_frame = read(node, "fixed_frame", p.fixed_frame);
  requireName(p.fixed_frame, "fixed_frame");
  p.object_id = read(node, "object_id", p.object_id);
  p.object_frame = read(node, "object_frame", p.object_frame);
  requireName(p.object_frame, "object_frame");
  require(p.object_frame != p.fixed_frame, "object_frame", "different from ~fixed_frame",
          p.object_frame);
  p.publish_tf = read(node, "publish_tf", p.publish_tf);
  p.tf_rate = read(node, "tf_rate", p.tf_rate);
  require(std::isfinite(p.tf_rate) && p.tf_rate >= 0.0, "tf_rate",
          "a finite number >= 0 (0: only on each estimate)", p.tf_rate);
  p.tf_timeout = read(node, "tf_timeout", p.tf_timeout);
  require(std::isfinite(p.tf_timeout) && p.tf_timeout >= 0.0, "tf_timeout", "a finite number >= 0",
          p.tf_timeout);
  p.max_points = read(node, "max_points", p.max_points);
  require(p.max_points >= 1, "max_points", ">= 1", p.max_points);
  p.position_variance = read(node, "position_variance", p.position_variance);
  require(std::isfinite(p.position_variance) && p.position_variance > 0.0, "position_variance",
          "a finite number > 0", p.position_variance);
  p.marker_samples = read(node, "marker_samples", p.marker_samples);
  require(p.marker_samples >= 0 && p.marker_samples <= 1000, "marker_samples", "between 0 and 1000",
          p.marker_samples);
  p.marker_length = read(node, "marker_length", p.marker_length);
  require(std::isfinite(p.marker_length) && p.marker_length > 0.0, "marker_length",
          "a finite number > 0", p.marker_length);

  EstimatorParameters& core = p.core;
  core.n_feat = read(node, "n_feat", core.n_feat);
  require(core.n_feat >= 0, "n_feat", ">= 0 (0: the model's value)", core.n_feat);
  core.kappa = read(node, "kappa", core.kappa);
  require(std::isfinite(core.kappa) && core.kappa >= 0.0, "kappa",
          "a finite number >= 0 (0: from the model's view spacing)", core.kappa);
  core.max_components = read(node, "max_components", core.max_components);
  require(core.max_components >= 1, "max_components", ">= 1", core.max_components);
  core.min_features = read(node, "min_features", core.min_features);
  require(core.min_features >= 1, "min_features", ">= 1", core.min_features);
  core.min_weight = read(node, "min_weight", core.min_weight);
  require(core.min_weight >= 0.0 && core.min_weight < 1.0, "min_weight", "in [0, 1)",
          core.min_weight);

  SegmentationParameters& s = core.segmentation;
  const std::string mode = read<std::string>(node, "segmentation", "none");
  if (mode == "none") {
    s.mode = SegmentationMode::kNone;
  } else if (mode == "region_of_interest") {
    s.mode = SegmentationMode::kRegionOfInterest;
  } else {
    require(false, "segmentation", "\"none\" or \"region_of_interest\"", "\"" + mode + "\"");
  }
  const std::vector<double> centre = read(node, "roi_centre", std::vector<double>{0.0, 0.0, 0.0});
  require(centre.size() == 3, "roi_centre", "a list [x, y, z] in the fixed frame",
          std::to_string(centre.size()) + " numbers");
  s.roi_centre = Eigen::Vector3d(centre[0], centre[1], centre[2]);
  require(s.roi_centre.allFinite(), "roi_centre", "finite", s.roi_centre.transpose());
  s.roi_radius = read(node, "roi_radius", s.roi_radius);
  require(std::isfinite(s.roi_radius) && s.roi_radius > 0.0, "roi_radius", "a finite number > 0",
          s.roi_radius);
  s.plane_distance = read(node, "plane_distance", s.plane_distance);
  require(std::isfinite(s.plane_distance) && s.plane_distance > 0.0, "plane_distance",
          "a finite number > 0", s.plane_distance);
  s.min_plane_fraction = read(node, "min_plane_fraction", s.min_plane_fraction);
  require(s.min_plane_fraction >= 0.0 && s.min_plane_fraction <= 1.0, "min_plane_fraction",
          "in [0, 1]", s.min_plane_fraction);
  s.cluster_tolerance = read(node, "cluster_tolerance", s.cluster_tolerance);
  require(std::isfinite(s.cluster_tolerance) && s.cluster_tolerance > 0.0, "cluster_tolerance",
          "a finite number > 0", s.cluster_tolerance);
  s.min_cluster_points = read(node, "min_cluster_points", s.min_cluster_points);
  require(s.min_cluster_points >= 1, "min_cluster_points", ">= 1", s.min_cluster_points);
  return p;
}

}  // namespace vdc

#include "view_direction_classification/evaluation/ppf_baseline.h"

#include <pcl/features/normal_3d.h>
#include <pcl/features/ppf.h>
#include <pcl/filters/uniform_sampling.h>
#include <pcl/registration/ppf_registration.h>
#include <pcl/search/kdtree.h>

#include <chrono>
#include <cmath>
#include <string>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/ppf_angle_step.h"
#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {

struct PpfBaseline::Detector {
  pcl::PointCloud<pcl::PointNormal>::Ptr model{new pcl::PointCloud<pcl::PointNormal>};
  pcl::PPFHashMapSearch::Ptr hash_map;
};

namespace {

constexpr double kDegrees = M_PI / 180.0;

void checkPositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("the PPF baseline's ") + name + " must be positive and finite, got " +
                std::to_string(value));
  }
}

void checkParameters(const PpfParameters& p) {
  checkPositive(p.model_spacing, "model spacing");
  checkPositive(p.angle_step_deg, "angle step");
  checkPositive(p.distance_step, "distance step");
  checkPositive(p.normal_radius, "normal radius");
  checkPositive(p.scene_spacing, "scene spacing");
  checkPositive(p.cluster_position, "position clustering threshold");
  checkPositive(p.cluster_rotation_deg, "rotation clustering threshold");
  if (p.angle_step_deg > 90.0) {
    throw Error("the PPF baseline's angle step must be at most 90 degrees, got " +
                std::to_string(p.angle_step_deg));
  }
  if (p.reference_sampling_rate < 1) {
    throw Error("the PPF baseline's reference sampling rate must be at least 1, got " +
                std::to_string(p.reference_sampling_rate));
  }
  if (p.min_scene_points < 3) {
    throw Error("the PPF baseline needs at least 3 scene points to match, got min_scene_points " +
                std::to_string(p.min_scene_points));
  }
}

// One point per scene_spacing cell: the points keep their own normals, no averaging across the
// mug's thin wall.
pcl::PointCloud<pcl::PointNormal>::Ptr sampledScene(
    const pcl::PointCloud<pcl::PointNormal>::ConstPtr& scene, const PpfParameters& parameters) {
  pcl::PointCloud<pcl::PointNormal>::Ptr sampled(new pcl::PointCloud<pcl::PointNormal>);
  if (!scene || scene->empty()) return sampled;
  pcl::UniformSampling<pcl::PointNormal> sampling;
  sampling.setInputCloud(scene);
  sampling.setRadiusSearch(parameters.scene_spacing);
  sampling.filter(*sampled);
  return sampled;
}

}  // namespace

PpfBaseline::PpfBaseline(const TriangleMesh& mesh, const PpfParameters& parameters)
    : parameters_(parameters), detector_(std::make_unique<Detector>()) {
  checkParameters(parameters_);
  if (mesh.empty()) throw Error("the PPF baseline cannot be trained on a mesh without triangles");
  const SurfaceSamples samples =
      sampleSurface(mesh, parameters_.model_spacing, parameters_.model_seed);
  if (samples.size() < 3) {
    throw Error("the PPF baseline's model has fewer than 3 surface samples; use a smaller spacing");
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    pcl::PointNormal point;
    point.getVector3fMap() = samples.points[i];
    point.getNormalVector3fMap() = samples.normals[i];
    detector_->model->push_back(point);
  }
  model_points_ = samples.size();

  // Every ordered pair of model points, hashed by its quantised feature.
  pcl::PointCloud<pcl::PPFSignature>::Ptr features(new pcl::PointCloud<pcl::PPFSignature>);
  pcl::PPFEstimation<pcl::PointNormal, pcl::PointNormal, pcl::PPFSignature> estimation;
  estimation.setInputCloud(detector_->model);
  estimation.setInputNormals(detector_->model);
  estimation.compute(*features);
  // A step that keeps PCL's votes inside its accumulator (ppf_angle_step.h).
  angle_step_rad_ = safePpfAngleStep(parameters_.angle_step_deg * kDegrees);
  detector_->hash_map.reset(
      new pcl::PPFHashMapSearch(angle_step_rad_, static_cast<float>(parameters_.distance_step)));
  detector_->hash_map->setInputFeatureCloud(features);
}

PpfBaseline::~PpfBaseline() = default;
PpfBaseline::PpfBaseline(PpfBaseline&&) noexcept = default;
PpfBaseline& PpfBaseline::operator=(PpfBaseline&&) noexcept = default;

pcl::PointCloud<pcl::PointNormal>::Ptr PpfBaseline::sceneWithNormals(
    const pcl::PointCloud<pcl::PointXYZ>& camera_cloud) const {
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : camera_cloud.points) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) points->push_back(p);
  }
  pcl::PointCloud<pcl::PointNormal>::Ptr with_normals(new pcl::PointCloud<pcl::PointNormal>);
  if (static_cast<int>(points->size()) < parameters_.min_scene_points) return with_normals;

  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(points);
  estimation.setSearchMethod(
      pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
  estimation.setRadiusSearch(parameters_.normal_radius);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  for (std::size_t i = 0; i < points->size(); ++i) {
    if (!normals[i].getNormalVector3fMap().allFinite()) continue;
    pcl::PointNormal point;
    point.getVector3fMap() = (*points)[i].getVector3fMap();
    point.getNormalVector3fMap() = normals[i].getNormalVector3fMap();
    with_normals->push_back(point);
  }
  return with_normals;
}

double PpfBaseline::angleStepDeg() const { return angle_step_rad_ / kDegrees; }

PpfMatch PpfBaseline::match(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud) {
  const auto start = std::chrono::steady_clock::now();
  PpfMatch result = matchScene(sceneWithNormals(camera_cloud));
  result.milliseconds = millisecondsSince(start);
  return result;
}

PpfMatch PpfBaseline::matchScene(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& full_scene) {
  const auto start = std::chrono::steady_clock::now();
  PpfMatch result;
  const auto scene = sampledScene(full_scene, parameters_);
  if (static_cast<int>(scene->size()) >= parameters_.min_scene_points) {
    pcl::PPFRegistration<pcl::PointNormal, pcl::PointNormal> registration;
    registration.setSceneReferencePointSamplingRate(
        static_cast<unsigned>(parameters_.reference_sampling_rate));
    registration.setPositionClusteringThreshold(static_cast<float>(parameters_.cluster_position));
    registration.setRotationClusteringThreshold(
        static_cast<float>(parameters_.cluster_rotation_deg * kDegrees));
    registration.setSearchMethod(detector_->hash_map);
    registration.setInputSource(detector_->model);
    registration.setInputTarget(scene);
    pcl::PointCloud<pcl::PointNormal> aligned;
    registration.align(aligned);
    // The final transformation maps the model (object frame) onto the scene (camera frame).
    const Eigen::Matrix4d pose = registration.getFinalTransformation().cast<double>();
    if (pose.allFinite()) {
      result.found = true;
      // Re-orthonormalise: the clustered pose averages rotations in single precision.
      const Eigen::Quaterniond rotation(Eigen::Matrix3d(pose.topLeftCorner<3, 3>()));
      result.camera_from_object.linear() = rotation.normalized().toRotationMatrix();
      result.camera_from_object.translation() = pose.topRightCorner<3, 1>();
    }
  }
  result.milliseconds = millisecondsSince(start);
  return result;
}

}  // namespace vdc

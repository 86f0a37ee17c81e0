#include "view_direction_classification/evaluation/baseline_icp.h"

#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void checkParameters(const BaselineIcpParameters& p) {
  if (!(p.model_spacing > 0.0) || !std::isfinite(p.model_spacing)) {
    throw Error("the baseline ICP's model spacing must be positive and finite, got " +
                std::to_string(p.model_spacing));
  }
  if (!(p.max_correspondence_distance > 0.0) || !std::isfinite(p.max_correspondence_distance)) {
    throw Error("the baseline ICP's max correspondence distance must be positive and finite, got " +
                std::to_string(p.max_correspondence_distance));
  }
  if (p.max_iterations < 1) {
    throw Error("the baseline ICP needs at least 1 iteration, got " +
                std::to_string(p.max_iterations));
  }
  if (p.min_correspondences < 3) {
    throw Error("the baseline ICP needs at least 3 correspondences, got min_correspondences " +
                std::to_string(p.min_correspondences));
  }
}

// The model samples (object frame) whose mesh normal faces the camera at the origin under the
// pose: n_C . p_C < 0.
pcl::PointCloud<pcl::PointNormal>::Ptr cameraFacingSamples(const SurfaceSamples& model,
                                                           const Eigen::Isometry3d& pose) {
  pcl::PointCloud<pcl::PointNormal>::Ptr facing(new pcl::PointCloud<pcl::PointNormal>);
  const Eigen::Isometry3f camera_from_object = pose.cast<float>();
  for (std::size_t i = 0; i < model.size(); ++i) {
    const Eigen::Vector3f point = camera_from_object * model.points[i];
    const Eigen::Vector3f normal = camera_from_object.linear() * model.normals[i];
    if (normal.dot(point) >= 0.0f) continue;
    pcl::PointNormal sample;
    sample.getVector3fMap() = model.points[i];
    sample.getNormalVector3fMap() = model.normals[i];
    facing->push_back(sample);
  }
  return facing;
}

// PCL's point-to-plane step solves a 6 x 6 system with a plain inverse: with fewer than six
// pairs, or pairs that constrain fewer than six degrees of freedom, it returns inf/NaN, and the
// next iteration hands NaN points to the k-d tree, which aborts on an assertion in Debian's PCL.
// This step keeps a non-finite estimate out (the identity: no move, so ICP stops) and remembers
// that it happened, so the caller keeps its starting pose.
class FinitePointToPlane
    : public pcl::registration::TransformationEstimationPointToPlaneLLS<pcl::PointNormal,
                                                                        pcl::PointNormal> {
 public:
  using TransformationEstimationPointToPlaneLLS::estimateRigidTransformation;
  void estimateRigidTransformation(const pcl::PointCloud<pcl::PointNormal>& source,
                                   const pcl::PointCloud<pcl::PointNormal>& target,
                                   const pcl::Correspondences& correspondences,
                                   Matrix4& transformation) const override {
    TransformationEstimationPointToPlaneLLS::estimateRigidTransformation(
        source, target, correspondences, transformation);
    if (!transformation.allFinite()) {
      transformation.setIdentity();
      degenerate_ = true;
    }
  }
  bool degenerate() const { return degenerate_; }

 private:
  mutable bool degenerate_ = false;
};

// PCL's point-to-plane ICP with a minimum number of pairs per iteration (PCL's own is 3, too few
// for six unknowns) and the finite step above.
class PointToPlaneIcp
    : public pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> {
 public:
  PointToPlaneIcp(int min_correspondences) : step_(std::make_shared<FinitePointToPlane>()) {
    min_number_correspondences_ = static_cast<unsigned>(std::max(6, min_correspondences));
    setTransformationEstimation(step_);
  }
  bool degenerate() const { return step_->degenerate(); }

 private:
  std::shared_ptr<FinitePointToPlane> step_;
};

}  // namespace

BaselineIcp::BaselineIcp(const TriangleMesh& mesh, const BaselineIcpParameters& parameters)
    : parameters_(parameters) {
  checkParameters(parameters_);
  if (mesh.empty()) throw Error("the baseline ICP cannot use a mesh without triangles");
  model_ = sampleSurface(mesh, parameters_.model_spacing, parameters_.model_seed);
}

BaselineIcpResult BaselineIcp::align(
    const pcl::PointCloud<pcl::PointNormal>::ConstPtr& camera_scene,
    const Eigen::Isometry3d& camera_from_object) const {
  const auto start = std::chrono::steady_clock::now();
  BaselineIcpResult result;
  result.camera_from_object = camera_from_object;
  const auto facing = cameraFacingSamples(model_, camera_from_object);
  const auto minimum = static_cast<std::size_t>(parameters_.min_correspondences);
  if (camera_scene && camera_scene->size() >= minimum && facing->size() >= minimum &&
      camera_from_object.matrix().allFinite()) {
    // The scene is the source: every point of it was seen, so every pair within the distance is
    // real, whereas model samples can face the camera and still be hidden (behind the handle,
    // the far inner wall). The camera-facing samples are the target: point-to-plane uses their
    // exact mesh normals, and culling keeps the inner wall behind the outer one out of reach.
    // ICP thus finds T_OC, starting from the inverse of the PPF pose.
    PointToPlaneIcp icp(parameters_.min_correspondences);
    icp.setInputSource(camera_scene);
    icp.setInputTarget(facing);
    icp.setMaxCorrespondenceDistance(parameters_.max_correspondence_distance);
    icp.setMaximumIterations(parameters_.max_iterations);
    icp.setTransformationEpsilon(1e-10);
    icp.setEuclideanFitnessEpsilon(1e-12);
    pcl::PointCloud<pcl::PointNormal> aligned;
    icp.align(aligned, camera_from_object.inverse().matrix().cast<float>());
    const Eigen::Matrix4d object_from_camera = icp.getFinalTransformation().cast<double>();
    if (icp.hasConverged() && !icp.degenerate() && object_from_camera.allFinite()) {
      result.converged = true;
      // Re-orthonormalise the single-precision rotation, then invert.
      const Eigen::Quaterniond rotation(Eigen::Matrix3d(object_from_camera.topLeftCorner<3, 3>()));
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = rotation.normalized().toRotationMatrix();
      pose.translation() = object_from_camera.topRightCorner<3, 1>();
      result.camera_from_object = pose.inverse();
      // PCL compares the squared distances with its argument.
      result.fitness_m2 = icp.getFitnessScore(std::pow(parameters_.max_correspondence_distance, 2));
    }
  }
  result.milliseconds = millisecondsSince(start);
  return result;
}

std::optional<Eigen::Isometry3d> PpfIcpMatch::pose() const {
  if (!ppf.found) return std::nullopt;
  if (icp && icp->converged) return icp->camera_from_object;
  return ppf.camera_from_object;
}

PpfIcpMatch matchPpfIcp(PpfBaseline& ppf, const BaselineIcp& icp,
                        const pcl::PointCloud<pcl::PointXYZ>& camera_cloud) {
  PpfIcpMatch result;
  const pcl::PointCloud<pcl::PointNormal>::ConstPtr scene = ppf.sceneWithNormals(camera_cloud);
  result.ppf = ppf.matchScene(scene);
  if (result.ppf.found) result.icp = icp.align(scene, result.ppf.camera_from_object);
  return result;
}

}  // namespace vdc

#include "view_direction_classification/refinement/pose_verification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ray_footprint.h"
#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

// [1] The largest |x / z| or |y / z| of an observed point the verifier looks at.
constexpr float kMaxRayTangent = 1e6f;
// An observed point is explained only by a sample whose normal makes at most 120 degrees
// with the direction to the camera: the side the camera looks at, with slack for the
// silhouette, where a small pose error turns a visible sample edge-on.
constexpr float kMinObservedFacingCosine = -0.5f;

void checkNonNegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(std::string("refinement's ") + name + " must be >= 0 and finite, got " +
                std::to_string(value));
  }
}

}  // namespace

void checkVerificationParameters(const VerificationParameters& parameters) {
  checkNonNegative(parameters.inlier_distance, "inlier_distance");
  checkNonNegative(parameters.free_space_tolerance, "free_space_tolerance");
  checkNonNegative(parameters.min_facing_cosine, "min_facing_cosine");
  checkNonNegative(parameters.depth_noise_at_1m, "depth_noise_at_1m");
  checkNonNegative(parameters.inlier_sigmas, "inlier_sigmas");
  checkNonNegative(parameters.free_space_sigmas, "free_space_sigmas");
}

double inlierTolerance(const VerificationParameters& parameters, double z) {
  return std::max(parameters.inlier_distance,
                  parameters.inlier_sigmas * parameters.depth_noise_at_1m * z * z);
}

double freeSpaceTolerance(const VerificationParameters& parameters, double z) {
  return std::max(parameters.free_space_tolerance,
                  parameters.free_space_sigmas * parameters.depth_noise_at_1m * z * z);
}

PoseVerifier::PoseVerifier(std::shared_ptr<const ModelSurface> surface,
                           const std::vector<RefinementView>& views,
                           VerificationParameters parameters)
    : surface_(std::move(surface)), parameters_(parameters) {
  checkVerificationParameters(parameters_);
  neighbour_radius_ = std::max(0.004, 2.0 * surface_->spacing());
  for (const RefinementView& view : views) {
    if (auto indexed = indexView(view)) views_.push_back(std::move(indexed));
  }
}

namespace {

// A point at no depth, or 89.99994 degrees or more off the optical axis, is in no camera's
// image; its ray would be infinite or near a float's maximum, where a k-d tree's split overflows
// (doc/hardening.md).
bool hasRay(const pcl::PointXYZ& p) {
  return p.z > 0.0f && std::abs(p.x / p.z) <= kMaxRayTangent &&
         std::abs(p.y / p.z) <= kMaxRayTangent;
}

std::unique_ptr<const NearestPoints> rayIndexOf(const pcl::PointCloud<pcl::PointXYZ>& points) {
  std::vector<Eigen::Vector3f> rays;
  rays.reserve(points.size());
  for (const auto& p : points.points) rays.emplace_back(p.x / p.z, p.y / p.z, 0.0f);
  return std::make_unique<const NearestPoints>(std::move(rays));
}

// The points of `cloud` with a ray, and their ray index (null for no cloud or no such point).
std::pair<pcl::PointCloud<pcl::PointXYZ>::ConstPtr, std::shared_ptr<const NearestPoints>> withRays(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud) {
  if (!cloud) return {};
  auto kept = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  kept->reserve(cloud->size());
  for (const auto& p : cloud->points) {
    if (hasRay(p)) kept->push_back(p);
  }
  if (kept->empty()) return {};
  std::shared_ptr<const NearestPoints> rays = rayIndexOf(*kept);
  return {kept, rays};
}

}  // namespace

SceneDepth indexRays(const SceneDepth& scene) {
  SceneDepth indexed;
  std::tie(indexed.occluders, indexed.occluder_rays) = withRays(scene.occluders);
  std::tie(indexed.supports, indexed.support_rays) = withRays(scene.supports);
  return indexed;
}

std::unique_ptr<PoseVerifier::IndexedView> PoseVerifier::indexView(
    const RefinementView& view) const {
  if (!view.points || view.points->empty()) return nullptr;
  auto indexed = std::make_unique<IndexedView>();
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::vector<Eigen::Vector2f> flat;  // the rays in the image plane, for the footprint
  points->reserve(view.points->size());
  flat.reserve(view.points->size());
  for (const auto& p : view.points->points) {
    if (!hasRay(p)) continue;
    points->push_back(p);
    flat.emplace_back(p.x / p.z, p.y / p.z);
  }
  if (points->empty()) return nullptr;
  indexed->object = {points, rayIndexOf(*points)};
  indexed->footprint = convexHull(std::move(flat));
  indexed->camera_from_world = view.world_from_camera.inverse();
  if (view.scene.support_plane) indexed->support_plane = view.scene.support_plane->cast<float>();
  if (view.scene.occluders) {
    indexed->scene = view.scene.occluder_rays
                         ? RayIndex{view.scene.occluders, view.scene.occluder_rays}
                         : indexScene(*view.scene.occluders, *points);
  }
  if (view.scene.supports) {
    indexed->supports = view.scene.support_rays
                            ? RayIndex{view.scene.supports, view.scene.support_rays}
                            : indexScene(*view.scene.supports, *points);
  }
  return indexed;
}

// Only the scene's points whose rays can meet a pose of the model near the object's points: the
// object's ray box grown by the model's diagonal at the object's nearest depth. A whole VGA cloud
// would cost a k-d tree of 300 000 rays per view; this keeps the cost to the object's surroundings.
PoseVerifier::RayIndex PoseVerifier::indexScene(
    const pcl::PointCloud<pcl::PointXYZ>& scene,
    const pcl::PointCloud<pcl::PointXYZ>& object) const {
  Eigen::AlignedBox2f box;
  float nearest_z = std::numeric_limits<float>::infinity();
  for (const auto& p : object.points) {
    box.extend(Eigen::Vector2f(p.x / p.z, p.y / p.z));
    nearest_z = std::min(nearest_z, p.z);
  }
  const float margin = static_cast<float>(surface_->diagonal() + neighbour_radius_) / nearest_z;
  box.min().array() -= margin;
  box.max().array() += margin;
  auto near = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : scene.points) {
    if (hasRay(p) && box.contains(Eigen::Vector2f(p.x / p.z, p.y / p.z))) near->push_back(p);
  }
  if (near->empty()) return {};
  RayIndex index{near, rayIndexOf(*near)};
  return index;
}

VerificationScore PoseVerifier::score(const Eigen::Isometry3d& world_from_object) const {
  VerificationScore result;
  Counts counts;
  for (const auto& view : views_) addViewScore(*view, world_from_object, &counts, &result);
  if (result.observed > 0) {
    result.inlier_fraction = double(counts.inliers) / result.observed;
    result.facing_inlier_fraction = double(counts.facing_inliers) / result.observed;
    result.facing_close_fraction = double(counts.facing_close) / result.observed;
  }
  if (result.predicted > 0)
    result.violation_fraction = double(counts.violations) / result.predicted;
  if (counts.below_judged > 0) result.sunk_fraction = double(counts.sunk) / counts.below_judged;
  return result;
}

void PoseVerifier::countFacingRematches(const std::vector<Eigen::Vector3f>& matched,
                                        const std::vector<float>& z, const Eigen::Vector3f& camera,
                                        Counts* counts) const {
  if (matched.empty()) return;
  std::vector<Eigen::Vector3f> towards_camera;
  towards_camera.reserve(matched.size());
  for (const Eigen::Vector3f& q : matched) towards_camera.push_back((camera - q).normalized());
  const NearestPoints::FacingFilter facing{&towards_camera, kMinObservedFacingCosine};
  std::vector<int> index;
  std::vector<float> squared;
  surface_->nearest().search(matched, &index, &squared, neighbour_radius_, &facing);
  const auto& model = *surface_->cloud();
  for (std::size_t i = 0; i < matched.size(); ++i) {
    if (index[i] < 0) continue;
    const auto& sample = model[index[i]];
    const float offset = sample.getNormalVector3fMap().dot(matched[i] - sample.getVector3fMap());
    const double tolerance = inlierTolerance(parameters_, z[i]);
    if (std::abs(offset) > tolerance) continue;
    ++counts->facing_inliers;
    if (std::abs(offset) <= 0.5 * tolerance) ++counts->facing_close;
  }
}

void PoseVerifier::addViewScore(const IndexedView& view, const Eigen::Isometry3d& world_from_object,
                                Counts* counts, VerificationScore* score) const {
  const Eigen::Isometry3d camera_from_object = view.camera_from_world * world_from_object;
  const Eigen::Isometry3f object_from_camera = camera_from_object.inverse().cast<float>();
  const float radius_sq = static_cast<float>(neighbour_radius_ * neighbour_radius_);
  std::vector<int> index;
  std::vector<float> squared;

  // The observed half: is each point on the model's surface? And on the side of it the camera
  // sees (VerificationScore::facing_inlier_fraction)? Only the few inliers matched to a sample
  // facing away are searched again, among the facing samples.
  const auto& model = *surface_->cloud();
  std::vector<Eigen::Vector3f> queries;
  const auto& observed = *view.object.points;
  queries.reserve(observed.size());
  for (const auto& p : observed.points) {
    queries.push_back(object_from_camera * p.getVector3fMap());
  }
  surface_->nearest().search(queries, &index, &squared, neighbour_radius_);
  score->observed += static_cast<int>(queries.size());
  const Eigen::Vector3f camera = object_from_camera.translation();
  std::vector<Eigen::Vector3f> facing_away;
  std::vector<float> facing_away_z;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (index[i] < 0 || squared[i] > radius_sq) continue;
    const auto& sample = model[index[i]];
    const float offset = sample.getNormalVector3fMap().dot(queries[i] - sample.getVector3fMap());
    const double tolerance = inlierTolerance(parameters_, observed[i].z);
    if (std::abs(offset) > tolerance) continue;
    ++counts->inliers;
    const Eigen::Vector3f towards_camera = camera - queries[i];
    if (sample.getNormalVector3fMap().dot(towards_camera) >=
        kMinObservedFacingCosine * towards_camera.norm()) {
      ++counts->facing_inliers;
      if (std::abs(offset) <= 0.5 * tolerance) ++counts->facing_close;
    } else {
      facing_away.push_back(queries[i]);
      facing_away_z.push_back(observed[i].z);
    }
  }
  countFacingRematches(facing_away, facing_away_z, camera, counts);

  // The predicted half: is each camera-facing sample where the camera saw a surface?
  const Eigen::Isometry3f transform = camera_from_object.cast<float>();
  const Eigen::Matrix3f rotation = transform.linear();
  std::vector<Eigen::Vector3f> predicted, rays;
  float nearest_z = std::numeric_limits<float>::infinity();  // bounds every ray's radius below
  if (view.support_plane) counts->below_judged += static_cast<int>(model.size());
  for (const auto& sample : model.points) {
    const Eigen::Vector3f m = transform * sample.getVector3fMap();
    if (view.support_plane && view.support_plane->head<3>().dot(m) + (*view.support_plane)[3] <
                                  -freeSpaceTolerance(parameters_, m.z())) {
      ++counts->sunk;
    }
    if (!(m.z() > 0.0f)) continue;
    const Eigen::Vector3f n = rotation * sample.getNormalVector3fMap();
    if (-n.dot(m) / m.norm() < parameters_.min_facing_cosine) continue;
    predicted.push_back(m);
    rays.emplace_back(m.x() / m.z(), m.y() / m.z(), 0.0f);
    nearest_z = std::min(nearest_z, m.z());
  }
  score->predicted += static_cast<int>(predicted.size());
  // Against the scene's depth where it is given, else against the object's points.
  const RayIndex& seen = view.scene.rays ? view.scene : view.object;
  seen.rays->search(rays, &index, &squared, neighbour_radius_ / nearest_z);
  std::vector<int> support_index;
  std::vector<float> support_squared;
  if (view.supports.rays) {
    view.supports.rays->search(rays, &support_index, &support_squared,
                               neighbour_radius_ / nearest_z);
  }
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    const float ray_radius = static_cast<float>(neighbour_radius_) / predicted[i].z();
    if (index[i] < 0 || squared[i] > ray_radius * ray_radius) {
      if (!support_index.empty() && support_index[i] >= 0 &&
          support_squared[i] <= ray_radius * ray_radius) {
        // The ray meets the table: the sample must lie on it.
        const float support_z = (*view.supports.points)[support_index[i]].z;
        if (std::abs(predicted[i].z() - support_z) > freeSpaceTolerance(parameters_, support_z)) {
          ++counts->violations;
        }
        continue;
      }
      // Nothing seen on this ray (no return, or a point left out of the scene): a contradiction
      // inside the object's footprint; outside it hidden or cropped away, for all we know.
      if (parameters_.judge_only_within_footprint &&
          !insideConvexPolygon(view.footprint, rays[i].head<2>(), ray_radius)) {
        --score->predicted;
        continue;
      }
      ++counts->violations;  // predicted where nothing was seen
      continue;
    }
    const float observed_z = (*seen.points)[index[i]].z;
    if (predicted[i].z() < observed_z - freeSpaceTolerance(parameters_, observed_z)) {
      ++counts->violations;
    }
  }
}

}  // namespace vdc

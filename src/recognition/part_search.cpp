#include "view_direction_classification/recognition/part_search.h"

#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"

namespace vdc {

namespace {

void checkIn(double value, double low, double high, const char* name) {
  if (!(value >= low && value <= high)) {
    throw Error(std::string("part search ") + name + " must be in [" + std::to_string(low) + ", " +
                std::to_string(high) + "], got " + std::to_string(value));
  }
}

void checkAtLeast(int value, int low, const char* name) {
  if (value < low) {
    throw Error(std::string("part search ") + name + " must be >= " + std::to_string(low) +
                ", got " + std::to_string(value));
  }
}

void checkPositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("part search ") + name + " must be a finite number > 0, got " +
                std::to_string(value));
  }
}

}  // namespace

void checkPartSearchParameters(const PartSearchParameters& p) {
  checkAtLeast(p.max_candidates, 0, "max_candidates");
  checkAtLeast(p.max_crops, 1, "max_crops");
  checkPositive(p.part_tolerance, "part_tolerance");
  checkIn(p.min_normal_cosine, -1.0, 1.0, "min_normal_cosine");
  checkAtLeast(p.min_points, 1, "min_points");
  checkAtLeast(p.max_parts, 1, "max_parts");
  checkIn(p.min_fitted_score, -1.0, 1.0, "min_fitted_score");
  checkIn(p.min_shape_gain, 0.0, 1.0, "min_shape_gain");
  checkIn(p.min_rest_shape_fraction, -1.0, 1.0, "min_rest_shape_fraction");
}

std::vector<int> spreadSeeds(const pcl::PointCloud<pcl::PointXYZ>& points, int count,
                             double min_distance) {
  std::vector<int> seeds;
  if (points.empty() || count < 1) return seeds;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const auto& p : points) centroid += p.getVector3fMap();
  centroid /= static_cast<float>(points.size());
  // Each point's squared distance to the nearest chosen seed (to the centroid before the first).
  std::vector<float> nearest(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    nearest[i] = (points[i].getVector3fMap() - centroid).squaredNorm();
  }
  const auto min_squared = static_cast<float>(min_distance * min_distance);
  while (static_cast<int>(seeds.size()) < count) {
    const auto farthest = std::max_element(nearest.begin(), nearest.end());
    if (!seeds.empty() && *farthest < min_squared) break;
    const auto seed = static_cast<int>(farthest - nearest.begin());
    seeds.push_back(seed);
    const Eigen::Vector3f at = points[seed].getVector3fMap();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const float squared = (points[i].getVector3fMap() - at).squaredNorm();
      // The centroid chose the first seed only; from then on, the distance to the seeds.
      nearest[i] = seeds.size() == 1 ? squared : std::min(nearest[i], squared);
    }
  }
  return seeds;
}

namespace {

// The points within `radius` [m] of points[seed].
pcl::PointCloud<pcl::PointXYZ> crop(const pcl::PointCloud<pcl::PointXYZ>& points, int seed,
                                    double radius) {
  pcl::PointCloud<pcl::PointXYZ> cropped;
  const Eigen::Vector3f at = points[seed].getVector3fMap();
  const auto squared = static_cast<float>(radius * radius);
  for (const auto& p : points) {
    if ((p.getVector3fMap() - at).squaredNorm() <= squared) cropped.push_back(p);
  }
  return cropped;
}

// [m] Normals are estimated over this radius: a few millimetres of depth noise tilt a smaller one.
constexpr double kNormalRadius = 0.01;

// The points' normals (PCL's, facing the camera at the origin) turned into the fixed frame.
std::vector<Eigen::Vector3f> worldNormals(const pcl::PointCloud<pcl::PointXYZ>& points,
                                          const Eigen::Isometry3d& world_from_camera) {
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(points));
  estimation.setSearchMethod(pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  estimation.setRadiusSearch(kNormalRadius);
  estimation.setViewPoint(0.0f, 0.0f, 0.0f);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  const Eigen::Matrix3f rotation = world_from_camera.linear().cast<float>();
  std::vector<Eigen::Vector3f> world;
  world.reserve(normals.size());
  for (const pcl::Normal& n : normals) world.push_back(rotation * n.getNormalVector3fMap());
  return world;
}

}  // namespace

void PartSearch::fitCrop(const std::shared_ptr<const ModelBundle>& model, const SceneDepth& scene,
                         const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                         CropFit* fit) const {
  OrientationEstimator estimator(model, instance_parameters_);
  const ViewUpdate update = estimator.update(fit->points, world_from_camera, time,
                                             {scene, BeliefSearch::kWhenDue, nullptr});
  fit->score = update.fitted_identity_score;
  if (update.fitted_pose && update.fitted_identity_score) {
    fit->world_from_object = *update.fitted_pose;
  } else {
    fit->score.reset();
  }
}

PartSearch::PartSearch(EstimatorParameters instance_parameters, PartSearchParameters parameters,
                       int threads)
    : instance_parameters_(std::move(instance_parameters)),
      parameters_(parameters),
      threads_(std::max(1, threads)) {
  checkPartSearchParameters(parameters_);
}

std::vector<PartSearch::CropFit> PartSearch::fittedCrops(
    const ModelLibrary& library, const pcl::PointCloud<pcl::PointXYZ>& points,
    const Eigen::Vector3d& sides, const SceneDepth& scene,
    const Eigen::Isometry3d& world_from_camera, std::optional<double> time) const {
  const auto min_points = static_cast<std::size_t>(parameters_.min_points);
  std::vector<CropFit> fits;
  for (int m = 0; m < library.size(); ++m) {
    // A model whose smallest side exceeds the candidate's largest is no part of it.
    const ObjectExtent& extent = library.models()[m].extent;
    if (extent.sizes.minCoeff() > sides.maxCoeff()) continue;
    const double radius = 0.5 * extent.diagonal();
    for (const int seed : spreadSeeds(points, parameters_.max_crops, radius)) {
      CropFit fit;
      fit.model = m;
      fit.points = crop(points, seed, radius);
      // A crop of (nearly) the whole candidate was tried already: the candidate itself.
      if (fit.points.size() >= min_points && fit.points.size() + min_points <= points.size()) {
        fits.push_back(std::move(fit));
      }
    }
  }
  parallelFor(fits.size(), threads_, [&](int, std::size_t k) {
    fitCrop(library.models()[fits[k].model].bundle, scene, world_from_camera, time, &fits[k]);
  });
  // Per model its best fitted crop, the best models first.
  std::vector<CropFit> best;
  for (CropFit& fit : fits) {
    if (!fit.score) continue;
    const auto kept = std::find_if(best.begin(), best.end(),
                                   [&](const CropFit& b) { return b.model == fit.model; });
    if (kept == best.end()) {
      best.push_back(std::move(fit));
    } else if (*fit.score > *kept->score) {
      *kept = std::move(fit);
    }
  }
  std::stable_sort(best.begin(), best.end(),
                   [](const CropFit& a, const CropFit& b) { return *a.score > *b.score; });
  return best;
}

std::vector<PartSearch::CropFit> PartSearch::refittedParts(
    const std::vector<CropFit>& best, const ModelLibrary& library, const Explanations& explanations,
    const CandidatePoints& candidate, const SceneDepth& scene,
    const Eigen::Isometry3d& world_from_camera, std::optional<double> time) const {
  std::vector<CropFit> refits;
  for (const CropFit& fit : best) {
    if (*fit.score < parameters_.min_fitted_score) break;
    if (static_cast<int>(refits.size()) == parameters_.max_parts) break;
    // The crop's pose sorts the candidate's points; the model is fitted again to those it
    // explains, whose centroid is the object's (the crop's was off by the other object's points).
    CropFit refit = fit;
    refit.points.clear();
    const std::vector<bool> member = explanations[fit.model]->explainedPoints(
        *candidate.world, fit.world_from_object, parameters_.part_tolerance,
        candidate.normals_world, parameters_.min_normal_cosine);
    for (std::size_t i = 0; i < member.size(); ++i) {
      if (member[i]) refit.points.push_back((*candidate.camera)[i]);
    }
    if (refit.points.size() >= static_cast<std::size_t>(parameters_.min_points)) {
      refits.push_back(std::move(refit));
    }
  }
  parallelFor(refits.size(), threads_, [&](int, std::size_t k) {
    const CropFit crop_fit = refits[k];
    fitCrop(library.models()[refits[k].model].bundle, scene, world_from_camera, time, &refits[k]);
    if (!refits[k].score) refits[k] = crop_fit;  // nothing fitted the part: the crop's pose
  });
  return refits;
}

std::vector<CandidatePart> PartSearch::find(const ModelLibrary& library,
                                            const Explanations& explanations,
                                            const pcl::PointCloud<pcl::PointXYZ>& points,
                                            const std::vector<Eigen::Vector3f>& points_world,
                                            const Eigen::Vector3d& sides, const SceneDepth& scene,
                                            const Eigen::Isometry3d& world_from_camera,
                                            std::optional<double> time) const {
  if (points.size() != points_world.size()) {
    throw Error("part search needs the candidate's points in both frames");
  }
  const auto min_points = static_cast<std::size_t>(parameters_.min_points);
  if (points.size() < 2 * min_points) return {};
  const std::vector<CropFit> best =
      fittedCrops(library, points, sides, scene, world_from_camera, time);
  // Most searched candidates end here (nothing fitted well enough): no normals needed then.
  if (best.empty() || *best.front().score < parameters_.min_fitted_score) return {};
  const std::vector<Eigen::Vector3f> normals_world = worldNormals(points, world_from_camera);
  const CandidatePoints candidate{&points, &points_world, &normals_world};
  std::vector<CandidatePart> parts;
  for (const CropFit& refit :
       refittedParts(best, library, explanations, candidate, scene, world_from_camera, time)) {
    CandidatePart part;
    part.model = refit.model;
    part.world_from_object = refit.world_from_object;
    part.fitted_score = *refit.score;
    part.member = explanations[refit.model]->explainedPoints(
        points_world, refit.world_from_object, parameters_.part_tolerance, &normals_world,
        parameters_.min_normal_cosine);
    part.points = static_cast<int>(std::count(part.member.begin(), part.member.end(), true));
    const auto members = static_cast<std::size_t>(part.points);
    if (members >= min_points && members + min_points <= points.size()) {
      parts.push_back(std::move(part));
    }
  }
  std::stable_sort(parts.begin(), parts.end(), [](const CandidatePart& a, const CandidatePart& b) {
    return a.fitted_score > b.fitted_score;
  });
  return parts;
}

}  // namespace vdc

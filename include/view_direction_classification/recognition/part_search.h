#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <vector>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/recognition/instance_explanation.h"
#include "view_direction_classification/recognition/model_library.h"

namespace vdc {

struct PartSearchParameters {
  // Candidates a frame searches for a known object in part of them, at most: those that every
  // identification left unknown, most points first. 0: none. Each costs up to max_crops fresh
  // estimators per model that could be part of it.
  int max_candidates = 2;
  // Crops per model and candidate: the candidate's points within half the model's diagonal of
  // points spread through it (the farthest from each other first).
  int max_crops = 3;
  // [m] A candidate point within this of the model's surface at its best fitted pose, facing
  // the way that surface does (the cosine of their normals at least min_normal_cosine), is the
  // part's: a box's face pressed against a mug lies within millimetres of its side, facing it.
  double part_tolerance = 0.01;
  double min_normal_cosine = 0.5;
  // A part is proposed only when it holds at least this many points and leaves at least as many
  // of the candidate to something else (else the whole candidate, which failed already).
  int min_points = 50;
  // The parts proposed per candidate at most: the models whose best crop fitted best, each
  // fitting at least min_fitted_score (ViewUpdate::fitted_identity_score; 0.6 is well below
  // identification's unknown_score, since the crop holds the other object's points too).
  int max_parts = 2;
  double min_fitted_score = 0.6;
  // A part is identified only when the model and a simple shape on the rest explain at least
  // min_shape_gain more of the candidate than one simple shape explains of it whole
  // (ShapeAlternative::fraction): a model fitted into one box or can (a mug's side on a can's)
  // explains nothing the box or can does not.
  double min_shape_gain = 0.2;
  // The rest of the candidate must be something too: where one simple shape explains at least
  // min_rest_shape_fraction of it, a box or a can the object touches; else it must be identified
  // as a known object, before the part is (a cow's body fitted into a camel's leaves the camel's
  // neck and head, which nothing explains).
  double min_rest_shape_fraction = 0.8;
};

// Throws vdc::Error naming the first bad parameter.
void checkPartSearchParameters(const PartSearchParameters& parameters);

// One model's best fit to part of a candidate.
struct CandidatePart {
  int model = -1;
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  // That pose's identity score on the points fitted (ViewUpdate::fitted_identity_score).
  double fitted_score = 0.0;
  // Per candidate point: within part_tolerance of that pose's surface and facing its way.
  std::vector<bool> member;
  int points = 0;  // its members
};

// A known object in part of a candidate that no model explains whole: an object in one cluster
// with another it touches where the split at concave edges did not cut them (an elephant pressed
// against a box). Identifying the whole fails, since the other object's points are no model's;
// the part the model explains must be found first. Each model that could be part of the
// candidate is fitted by a fresh estimator to crops of it the model's size, so that the other
// object's points are few and the fit's start (the crop's centroid) is near; the candidate's
// points the best fitted pose explains are the part, to which the model is fitted once more.
// A part is proposed, not taken: the caller judges whether the part and the rest can be two
// objects and identifies the part like any candidate (SceneEstimator::identifyPart).
class PartSearch {
 public:
  using Explanations = std::vector<std::unique_ptr<InstanceExplanation>>;  // per library model

  // Throws vdc::Error for bad parameters.
  PartSearch(EstimatorParameters instance_parameters, PartSearchParameters parameters, int threads);

  // points: the candidate in the camera frame, points_world the same in the fixed frame; sides
  // its extent (largest first). Up to max_parts parts, one per model, each holding between
  // min_points and all but min_points of the candidate, the best fitted first.
  std::vector<CandidatePart> find(const ModelLibrary& library, const Explanations& explanations,
                                  const pcl::PointCloud<pcl::PointXYZ>& points,
                                  const std::vector<Eigen::Vector3f>& points_world,
                                  const Eigen::Vector3d& sides, const SceneDepth& scene,
                                  const Eigen::Isometry3d& world_from_camera,
                                  std::optional<double> time) const;
  const PartSearchParameters& parameters() const { return parameters_; }

 private:
  // One crop or part a model is fitted to, and the best fitted pose (no score: none fitted).
  struct CropFit {
    int model = -1;
    pcl::PointCloud<pcl::PointXYZ> points;
    std::optional<double> score;
    Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  };
  // The candidate's points in both frames and their normals (fixed frame).
  struct CandidatePoints {
    const pcl::PointCloud<pcl::PointXYZ>* camera;
    const std::vector<Eigen::Vector3f>* world;
    const std::vector<Eigen::Vector3f>* normals_world;
  };
  // A fresh estimator of `model` fuses fit->points; its best fitted pose and score.
  void fitCrop(const std::shared_ptr<const ModelBundle>& model, const SceneDepth& scene,
               const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
               CropFit* fit) const;
  // Every model that could be part of the candidate fitted to its crops: per model its best
  // fitted crop, the best first.
  std::vector<CropFit> fittedCrops(const ModelLibrary& library,
                                   const pcl::PointCloud<pcl::PointXYZ>& points,
                                   const Eigen::Vector3d& sides, const SceneDepth& scene,
                                   const Eigen::Isometry3d& world_from_camera,
                                   std::optional<double> time) const;
  // The best of them (max_parts, each at least min_fitted_score) fitted again to the candidate's
  // points their crop's pose explains.
  std::vector<CropFit> refittedParts(const std::vector<CropFit>& best, const ModelLibrary& library,
                                     const Explanations& explanations,
                                     const CandidatePoints& candidate, const SceneDepth& scene,
                                     const Eigen::Isometry3d& world_from_camera,
                                     std::optional<double> time) const;

  EstimatorParameters instance_parameters_;
  PartSearchParameters parameters_;
  int threads_;
};

// About `count` of the points (their indices) spread through them: the first the farthest from
// their centroid, each next the farthest from those chosen; stops early when the farthest left is
// nearer than min_distance [m] to one chosen. None for no points.
std::vector<int> spreadSeeds(const pcl::PointCloud<pcl::PointXYZ>& points, int count,
                             double min_distance);

}  // namespace vdc

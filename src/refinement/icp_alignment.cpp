#include "icp_alignment.h"

#include <pcl/registration/correspondence_estimation.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls_weighted.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

// PCL's linearised point-to-plane step solves a 6 x 6 system by inversion: where the matched
// surface leaves a motion unconstrained (a cylinder's roll and slide, a plane's drift) it is
// singular, the step is NaN and the next correspondence search aborts. Such a step becomes no
// step, and the alignment is refused as degenerate. Each pair is weighted by its observed point's
// weight (PCL's weighted step scales each row by the square root of it).
class FiniteStepPointToPlane
    : public pcl::registration::TransformationEstimationPointToPlaneLLSWeighted<pcl::PointNormal,
                                                                                pcl::PointNormal> {
 public:
  using Base = pcl::registration::TransformationEstimationPointToPlaneLLSWeighted<pcl::PointNormal,
                                                                                  pcl::PointNormal>;
  using Base::estimateRigidTransformation;

  explicit FiniteStepPointToPlane(std::vector<float> point_weights) {
    for (float& weight : point_weights) weight = std::sqrt(weight);
    row_scales_ = std::move(point_weights);
  }

  // PCL's own overload would read each pair's weight from pcl::Correspondence, whose weight
  // shares its storage with the distance the convergence test reads: the weights come from the
  // observed points instead.
  void estimateRigidTransformation(const pcl::PointCloud<pcl::PointNormal>& source,
                                   const pcl::PointCloud<pcl::PointNormal>& target,
                                   const pcl::Correspondences& correspondences,
                                   Matrix4& transform) const override {
    // PCL's ICP would stop before this step and print an error for every such alignment (to
    // stderr, unthrottled: a node's terminal filled with it); it is told to ask for every step
    // (CountingIcp), and the check is here, where a start without pairs is the usual case of a
    // search, not an error.
    if (correspondences.size() < kMinPairs) {
      transform.setIdentity();
      too_few_pairs = true;
      return;
    }
    std::vector<float> scales(correspondences.size(), 1.0f);
    if (!row_scales_.empty()) {
      for (std::size_t i = 0; i < correspondences.size(); ++i) {
        scales[i] = row_scales_[static_cast<std::size_t>(correspondences[i].index_query)];
      }
    }
    pcl::ConstCloudIterator<pcl::PointNormal> source_it(source, correspondences, true);
    pcl::ConstCloudIterator<pcl::PointNormal> target_it(target, correspondences, false);
    std::vector<float>::const_iterator scale_it = scales.begin();
    Base::estimateRigidTransformation(source_it, target_it, scale_it, transform);
    if (!transform.allFinite()) {
      transform.setIdentity();
      degenerate = true;
    }
  }

  // The fewest pairs PCL's ICP takes a step from (its min_number_correspondences_ default).
  static constexpr std::size_t kMinPairs = 3;
  mutable bool degenerate = false;
  mutable bool too_few_pairs = false;  // fewer than kMinPairs: no step

 private:
  std::vector<float> row_scales_;  // per observed point: the square root of its weight
};

// PCL's correspondence search asks the k-d tree one point at a time, which costs FLANN's per-call
// set-up each time (nearest_points.h); this one asks the model surface's batched search for all
// source points at once. The same correspondences: each source point's nearest model sample
// within the maximum distance, its squared distance as PCL records it.
class BatchedCorrespondences
    : public pcl::registration::CorrespondenceEstimation<pcl::PointNormal, pcl::PointNormal> {
 public:
  explicit BatchedCorrespondences(std::shared_ptr<const ModelSurface> surface)
      : surface_(std::move(surface)) {}

  void determineCorrespondences(pcl::Correspondences& correspondences,
                                double max_distance) override {
    correspondences.clear();
    if (!input_) return;
    std::vector<Eigen::Vector3f> queries;
    std::vector<int> sources;
    const std::size_t count = indices_ ? indices_->size() : input_->size();
    queries.reserve(count);
    sources.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const int source = indices_ ? (*indices_)[i] : static_cast<int>(i);
      queries.push_back((*input_)[source].getVector3fMap());
      sources.push_back(source);
    }
    std::vector<int> matches;
    std::vector<float> squared;
    surface_->nearest().search(queries, &matches, &squared, max_distance);
    const double max_squared = max_distance * max_distance;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (matches[i] < 0 || squared[i] > max_squared) continue;
      correspondences.emplace_back(sources[i], matches[i], squared[i]);
    }
  }

  pcl::registration::CorrespondenceEstimationBase<pcl::PointNormal, pcl::PointNormal>::Ptr clone()
      const override {
    return pcl::make_shared<BatchedCorrespondences>(*this);
  }

 private:
  std::shared_ptr<const ModelSurface> surface_;
};

// PCL's ICP, telling how many iterations its last alignment took, and taking every step to
// FiniteStepPointToPlane, which judges whether there are pairs enough for one.
class CountingIcp
    : public pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> {
 public:
  CountingIcp() { min_number_correspondences_ = 0; }
  int iterations() const { return nr_iterations_; }
};

// PCL's fitness score (the mean squared distance of the points within max_distance of the model
// to their nearest sample), from one batched search.
double meanSquaredDistance(const ModelSurface& surface,
                           const pcl::PointCloud<pcl::PointNormal>& observed,
                           const Eigen::Isometry3f& object_from_world, double max_distance) {
  const std::vector<Eigen::Vector3f> queries = objectFramePoints(observed, object_from_world);
  std::vector<int> matches;
  std::vector<float> squared;
  surface.nearest().search(queries, &matches, &squared, max_distance);
  double sum = 0.0;
  int inside = 0;
  for (const float d2 : squared) {
    if (d2 > max_distance * max_distance) continue;
    sum += d2;
    ++inside;
  }
  return inside > 0 ? sum / inside : std::numeric_limits<double>::max();
}

}  // namespace

struct IcpAlignment::Registration {
  CountingIcp icp;
  std::shared_ptr<FiniteStepPointToPlane> step;
  std::shared_ptr<const ModelSurface> surface;
  pcl::PointCloud<pcl::PointNormal>::Ptr observed;
  IcpSettings settings;
};

IcpAlignment::IcpAlignment(std::shared_ptr<const ModelSurface> surface,
                           pcl::PointCloud<pcl::PointNormal>::Ptr observed_world,
                           IcpSettings settings, std::vector<float> point_weights)
    : registration_(std::make_unique<Registration>()) {
  if (!point_weights.empty() && point_weights.size() != observed_world->size()) {
    throw Error("ICP needs one weight per observed point or none");
  }
  registration_->step = std::make_shared<FiniteStepPointToPlane>(std::move(point_weights));
  auto& icp = registration_->icp;
  // The observed points are the source and the model the target: point-to-plane uses the
  // target's normals, which the model has exactly (the mesh's), so the scene needs none.
  icp.setInputSource(observed_world);
  icp.setInputTarget(surface->cloud());
  // PCL's ICP must hold a search tree for its target, but BatchedCorrespondences answers every
  // nearest-sample question from the surface's one index: an empty tree PCL is told never to
  // build (it would otherwise build one per alignment).
  icp.setSearchMethodTarget(pcl::make_shared<pcl::search::KdTree<pcl::PointNormal>>(), true);
  icp.setTransformationEstimation(registration_->step);
  icp.setCorrespondenceEstimation(pcl::make_shared<BatchedCorrespondences>(surface));
  registration_->surface = surface;
  registration_->observed = observed_world;
  registration_->settings = settings;
  icp.setMaxCorrespondenceDistance(settings.max_correspondence_distance);
  // Converged when a step moves the pose by less than the settings' translation and rotation, or
  // the mean squared distance changes by less than 0.01 % (PCL's "Euclidean fitness epsilon" is
  // relative; its transformation epsilon is the squared translation).
  icp.setTransformationEpsilon(settings.convergence_translation * settings.convergence_translation);
  icp.setTransformationRotationEpsilon(std::cos(settings.convergence_rotation_deg * M_PI / 180.0));
  icp.setEuclideanFitnessEpsilon(1e-4);
  // Running out of iterations is not convergence.
  icp.getConvergeCriteria()->setFailureAfterMaximumIterations(true);
}

IcpAlignment::~IcpAlignment() = default;

IcpOutcome IcpAlignment::align(const Eigen::Isometry3d& start_object_from_world) {
  return align(start_object_from_world, registration_->settings.max_iterations);
}

IcpOutcome IcpAlignment::align(const Eigen::Isometry3d& start_object_from_world,
                               int max_iterations) {
  const IcpSettings& settings = registration_->settings;
  IcpOutcome outcome;
  outcome.object_from_world = start_object_from_world;
  // In chunks of settle_iterations: on noisy data PCL's criteria can miss a minimum that ICP
  // circles (the steps alternate by a degree or two about a near-symmetric body's axis); a full
  // chunk that ends where it began has settled there.
  while (outcome.iterations < max_iterations) {
    const int chunk = std::min(settings.settle_iterations, max_iterations - outcome.iterations);
    const Eigen::Isometry3d before = outcome.object_from_world;
    const IcpOutcome part = alignOnce(before, chunk);
    outcome.iterations += part.iterations;
    if (part.degenerate) {
      outcome.degenerate = true;
      return outcome;
    }
    outcome.object_from_world = part.object_from_world;
    if (part.too_few_pairs) {
      outcome.too_few_pairs = true;
      return outcome;
    }
    const Eigen::Isometry3d moved = before.inverse() * part.object_from_world;
    const bool settled =
        chunk == settings.settle_iterations &&
        moved.translation().norm() < settings.settle_translation &&
        Eigen::AngleAxisd(moved.linear()).angle() < settings.settle_rotation_deg * M_PI / 180.0;
    if (part.converged || settled) {
      outcome.converged = true;
      break;
    }
  }
  if (!outcome.converged) return outcome;
  outcome.fitness = meanSquaredDistance(*registration_->surface, *registration_->observed,
                                        outcome.object_from_world.cast<float>(),
                                        registration_->icp.getMaxCorrespondenceDistance());
  return outcome;
}

IcpOutcome IcpAlignment::alignOnce(const Eigen::Isometry3d& start_object_from_world,
                                   int max_iterations) {
  auto& icp = registration_->icp;
  icp.setMaximumIterations(max_iterations);
  pcl::PointCloud<pcl::PointNormal> aligned;
  registration_->step->degenerate = false;
  registration_->step->too_few_pairs = false;
  icp.align(aligned, start_object_from_world.matrix().cast<float>());
  IcpOutcome outcome;
  outcome.iterations = icp.iterations();
  const Eigen::Matrix4d transform = icp.getFinalTransformation().cast<double>();
  outcome.degenerate = registration_->step->degenerate || !transform.allFinite();
  if (outcome.degenerate) return outcome;
  // The no-step a lack of pairs gave ends PCL's loop as converged: it is not.
  outcome.too_few_pairs =
      registration_->step->too_few_pairs || icp.getConvergeCriteria()->getConvergenceState() ==
                                                pcl::registration::DefaultConvergenceCriteria<
                                                    float>::CONVERGENCE_CRITERIA_NO_CORRESPONDENCES;
  outcome.converged = icp.hasConverged() && !outcome.too_few_pairs;
  // Re-orthonormalise: ICP composes its steps in single precision.
  const Eigen::Quaterniond rotation(Eigen::Matrix3d(transform.topLeftCorner<3, 3>()));
  outcome.object_from_world.linear() = rotation.normalized().toRotationMatrix();
  outcome.object_from_world.translation() = transform.topRightCorner<3, 1>();
  return outcome;
}

}  // namespace vdc

#include "view_direction_classification/recognition/instance_collision.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "view_direction_classification/recognition/instance_overlap.h"
#include "view_direction_classification/recognition/instance_presence.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/refinement/nearest_points.h"

namespace vdc {
namespace {

// Samples of each model probed against the other: a tenth of a surface inside another is told
// from a twentieth within a few percent, and one comparison stays around a millisecond.
constexpr std::size_t kProbes = 400;
// A point counts as inside a body only within about 37 degrees of its nearest sample's inward
// normal (cosine 0.8).
constexpr float kAlongNormal = 0.8f;

}  // namespace

InstanceCollision::InstanceCollision(const ModelLibrary& library) {
  for (const LibraryModel& model : library.models()) {
    const ModelBundle& bundle = *model.bundle;
    ModelBody body;
    body.surface = std::make_unique<const NearestPoints>(bundle.surface_points);
    body.points = bundle.surface_points;
    body.normals = bundle.surface_normals;
    const std::size_t stride = std::max<std::size_t>(1, bundle.surface_points.size() / kProbes);
    for (std::size_t i = 0; i < bundle.surface_points.size(); i += stride) {
      body.probes.push_back(bundle.surface_points[i]);
    }
    body.radius = 0.5 * bundle.bounds.diagonal().norm();
    bodies_.push_back(std::move(body));
  }
}

InstanceCollision::~InstanceCollision() = default;

double InstanceCollision::insideShare(int samples_model, const Eigen::Isometry3d& samples_pose,
                                      int body_model, const Eigen::Isometry3d& body_pose,
                                      double depth) const {
  const ModelBody& probed = bodies_.at(static_cast<std::size_t>(samples_model));
  const ModelBody& body = bodies_.at(static_cast<std::size_t>(body_model));
  if (probed.probes.empty() || body.normals.size() != body.points.size()) return 0.0;
  const Eigen::Isometry3f body_from_samples = (body_pose.inverse() * samples_pose).cast<float>();
  std::vector<Eigen::Vector3f> queries;
  queries.reserve(probed.probes.size());
  for (const Eigen::Vector3f& p : probed.probes) queries.push_back(body_from_samples * p);
  std::vector<int> nearest;
  std::vector<float> squared;
  // No point of a body lies farther inside it than its half diagonal.
  body.surface->search(queries, &nearest, &squared, body.radius);
  int inside = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (nearest[q] < 0) continue;
    const Eigen::Vector3f& sample = body.points[nearest[q]];
    // Inside: behind the nearest sample along its inward normal. Off that line the nearest
    // sample is an edge's or a tip's (a hoof's rim, an ear's), whose normal says nothing of a
    // point beside it.
    const float outward = body.normals[nearest[q]].dot(queries[q] - sample);
    if (outward < -static_cast<float>(depth) && -outward >= kAlongNormal * std::sqrt(squared[q])) {
      ++inside;
    }
  }
  return static_cast<double>(inside) / static_cast<double>(queries.size());
}

double InstanceCollision::penetration(int model_a, const Eigen::Isometry3d& a, int model_b,
                                      const Eigen::Isometry3d& b, double depth) const {
  const double reach = bodies_.at(static_cast<std::size_t>(model_a)).radius +
                       bodies_.at(static_cast<std::size_t>(model_b)).radius;
  if ((a.translation() - b.translation()).norm() > reach) return 0.0;
  return std::max(insideShare(model_a, a, model_b, b, depth),
                  insideShare(model_b, b, model_a, a, depth));
}

int InstanceCollision::collidingInstance(const std::vector<ObjectInstance>& instances, int model,
                                         const Eigen::Isometry3d& world_from_object, double depth,
                                         double min_penetration) const {
  int most = -1;
  double most_penetration = min_penetration;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const ObjectInstance& instance = instances[i];
    if (instance.model == model || instance.presence.state == InstanceState::kGone ||
        instance.presence.last_check.evidence == PresenceEvidence::kAbsent) {
      continue;
    }
    const std::optional<Eigen::Isometry3d> pose = believedPose(*instance.estimator);
    if (!pose) continue;
    const double shared = penetration(model, world_from_object, instance.model, *pose, depth);
    if (shared > most_penetration) most = static_cast<int>(i), most_penetration = shared;
  }
  return most;
}

}  // namespace vdc

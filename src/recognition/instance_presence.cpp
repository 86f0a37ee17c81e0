#include "view_direction_classification/recognition/instance_presence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/recognition/instance_overlap.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {
namespace {

// [m] The model's samples are thinned to refinement's spacing: a few hundred camera-facing
// samples per object are plenty to tell a surface from free space, and the check runs for every
// instance out of place on every segmented frame.
constexpr double kSampleSpacing = 0.004;
// A frame is evidence only when the depth judged (seen or free) at least this fraction of the
// camera-facing samples: a place mostly hidden or mostly outside the image tells nothing, and a
// few rays past an occluder's edge must not decide.
constexpr double kMinJudgedFraction = 0.5;
// Nor may a handful of judged samples decide, when the support explains nearly all the others.
constexpr int kMinJudgedSamples = 20;
// Of the judged samples, this fraction free makes the frame one of absence. Not all of a removed
// object's samples come out free: near its foot the table lies within the tolerance of where the
// surface should be (about the lowest centimetre of a mug seen from 40 degrees up). And an object
// moved 5 cm sideways still covers part of its old rays at nearly the old depth.
constexpr double kMinFreeFraction = 0.6;
// Of the judged samples, at most this fraction free makes it a frame that saw the surface (and
// restarts the count); between the two the frame says nothing. A place seen half free is not
// seen occupied: on a patrolled table a removed mug's place next to another mug came out 263
// seen, 266 free from one side, and wiped the absence its other views had counted, pass after
// pass. The mug in place has none free.
constexpr double kMaxFreeFractionSeen = 0.25;
// Samples nearer the camera than this [m] have no usable ray (DepthRenderer's near plane).
constexpr float kMinDepth = 0.01f;

// The nearest depth seen on each ray (within ray_radius / z of it) in one ray-indexed cloud, or
// infinity where it has no point there.
void nearestDepths(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points,
                   const std::shared_ptr<const NearestPoints>& rays_index,
                   const std::vector<Eigen::Vector3f>& samples,
                   const std::vector<Eigen::Vector3f>& rays, double ray_radius, float nearest_z,
                   std::vector<float>* depths) {
  if (!points || !rays_index || samples.empty()) return;
  std::vector<int> index;
  std::vector<float> squared;
  rays_index->search(rays, &index, &squared, ray_radius / nearest_z);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const float radius = static_cast<float>(ray_radius) / samples[i].z();
    if (index[i] < 0 || squared[i] > radius * radius) continue;
    (*depths)[i] = std::min((*depths)[i], (*points)[index[i]].z);
  }
}

}  // namespace

PresenceEvidence presenceEvidence(const PresenceCheck& check) {
  const int judged = check.seen + check.free;
  const int telling = check.predicted - check.on_support;
  if (judged < kMinJudgedSamples || judged < kMinJudgedFraction * telling) {
    return PresenceEvidence::kNone;
  }
  if (check.free >= kMinFreeFraction * judged) return PresenceEvidence::kAbsent;
  if (check.free <= kMaxFreeFractionSeen * judged) return PresenceEvidence::kSeen;
  return PresenceEvidence::kNone;
}

InstancePresence::InstancePresence(const ModelLibrary& library,
                                   const VerificationParameters& verification, int absent_views,
                                   double forget_gone_after)
    : verification_(verification),
      absent_views_(absent_views),
      forget_gone_after_(forget_gone_after) {
  checkVerificationParameters(verification_);
  if (absent_views_ < 1) {
    throw Error("instance presence: absent_views must be >= 1, got " +
                std::to_string(absent_views_));
  }
  for (const LibraryModel& model : library.models()) {
    const ModelBundle& bundle = *model.bundle;
    surfaces_.push_back(std::make_unique<const ModelSurface>(
        bundle.surface_points, bundle.surface_normals, bundle.bounds,
        bundle.parameters.surface_spacing, kSampleSpacing));
  }
}

InstancePresence::~InstancePresence() = default;

PresenceCheck InstancePresence::check(int model, const Eigen::Isometry3d& world_from_object,
                                      const SceneDepth& scene,
                                      const Eigen::Isometry3d& world_from_camera) const {
  PresenceCheck result;
  const ModelSurface& surface = *surfaces_.at(static_cast<std::size_t>(model));
  const Eigen::Isometry3f camera_from_object =
      (world_from_camera.inverse() * world_from_object).cast<float>();
  std::vector<Eigen::Vector3f> samples, rays;
  float nearest_z = std::numeric_limits<float>::infinity();
  for (const auto& sample : surface.cloud()->points) {
    const Eigen::Vector3f m = camera_from_object * sample.getVector3fMap();
    if (!(m.z() > kMinDepth)) continue;
    const Eigen::Vector3f n = camera_from_object.linear() * sample.getNormalVector3fMap();
    if (-n.dot(m) / m.norm() < verification_.min_facing_cosine) continue;
    samples.push_back(m);
    rays.emplace_back(m.x() / m.z(), m.y() / m.z(), 0.0f);
    nearest_z = std::min(nearest_z, m.z());
  }
  result.predicted = static_cast<int>(samples.size());
  // The frame's scene is ray-indexed once for all its verifiers; a caller's may not be.
  const bool indexed =
      (!scene.occluders || scene.occluder_rays) && (!scene.supports || scene.support_rays);
  const SceneDepth depth = indexed ? scene : indexRays(scene);
  // The ray radius of verification's predicted half: the samples' neighbourhood.
  const double ray_radius = std::max(0.004, 2.0 * surface.spacing());
  const float none = std::numeric_limits<float>::infinity();
  std::vector<float> off_support(samples.size(), none), support(samples.size(), none);
  nearestDepths(depth.occluders, depth.occluder_rays, samples, rays, ray_radius, nearest_z,
                &off_support);
  nearestDepths(depth.supports, depth.support_rays, samples, rays, ray_radius, nearest_z, &support);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    // What the camera saw on a ray is the nearest of the two: an object or the table.
    const bool table_nearest = support[i] < off_support[i];
    const float observed = std::min(off_support[i], support[i]);
    if (!std::isfinite(observed)) continue;
    const double tolerance = freeSpaceTolerance(verification_, observed);
    if (observed < samples[i].z() - tolerance) {
      ++result.hidden;
    } else if (observed > samples[i].z() + tolerance) {
      ++result.free;
    } else if (table_nearest) {
      ++result.on_support;
    } else {
      ++result.seen;
    }
  }
  result.evidence = presenceEvidence(result);
  return result;
}

void InstancePresence::checkPlaces(std::vector<ObjectInstance>& instances, const SceneDepth& scene,
                                   const Eigen::Isometry3d& world_from_camera) const {
  for (ObjectInstance& instance : instances) {
    if (instance.presence.state == InstanceState::kGone) continue;
    const std::optional<Eigen::Isometry3d> pose = believedPose(*instance.estimator);
    if (pose) {
      instance.presence.last_check = check(instance.model, *pose, scene, world_from_camera);
    }
  }
}

void InstancePresence::record(const PresenceCheck& check, std::optional<double> time,
                              Presence* presence) const {
  presence->last_check = check;
  if (check.evidence == PresenceEvidence::kSeen) presence->absent_frames = 0;
  if (check.evidence != PresenceEvidence::kAbsent) return;
  ++presence->absent_frames;
  if (presence->absent_frames >= absent_views_) {
    presence->state = InstanceState::kGone;
    presence->gone_since = time;
  }
}

std::vector<int> InstancePresence::observe(std::vector<ObjectInstance>& instances,
                                           const std::vector<int>& associated,
                                           const SceneDepth& scene,
                                           const Eigen::Isometry3d& world_from_camera,
                                           std::optional<double> time) const {
  std::vector<int> marked_gone;
  for (ObjectInstance& instance : instances) {
    Presence& presence = instance.presence;
    const bool candidate_there =
        std::find(associated.begin(), associated.end(), instance.id) != associated.end();
    // A gone instance stays gone until it is found moved (or put back): the scene estimator
    // associates no candidate with it.
    if (presence.state == InstanceState::kGone) continue;
    const std::optional<Eigen::Isometry3d> pose = believedPose(*instance.estimator);
    const PresenceCheck place =
        pose ? check(instance.model, *pose, scene, world_from_camera) : PresenceCheck{};
    if (candidate_there && place.evidence != PresenceEvidence::kAbsent) {
      presence = Presence{};  // seen: present, whatever the frames before said
      presence.last_check = place;
      continue;
    }
    // A candidate near an instance whose place the depth shows free is a piece of something
    // else (a neighbour cut by the touching split, what stands there now): it neither keeps
    // the instance present nor brings a gone one back. With a camera that passes along the same
    // path, such an instance is not refined again (no new view) and nothing else would notice.
    if (!pose) continue;
    record(place, time, &presence);
    if (presence.state == InstanceState::kGone) marked_gone.push_back(instance.id);
  }
  return marked_gone;
}

int InstancePresence::movedInstance(const std::vector<ObjectInstance>& instances, int model,
                                    const Eigen::Vector3d& centroid_world) const {
  int nearest = -1;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const ObjectInstance& instance = instances[i];
    const bool out_of_place =
        instance.presence.state == InstanceState::kGone || instance.presence.absent_frames > 0;
    if (instance.model != model || !out_of_place) continue;
    const double distance = (instance.centroid_world - centroid_world).norm();
    if (distance < nearest_distance) {
      nearest = static_cast<int>(i);
      nearest_distance = distance;
    }
  }
  return nearest;
}

std::vector<int> InstancePresence::forgetGone(std::vector<ObjectInstance>& instances,
                                              std::optional<double> time) const {
  std::vector<int> forgotten;
  if (forget_gone_after_ <= 0.0 || !time) return forgotten;
  const auto expired = [&](const ObjectInstance& instance) {
    const Presence& presence = instance.presence;
    return presence.state == InstanceState::kGone && presence.gone_since &&
           *time - *presence.gone_since > forget_gone_after_;
  };
  for (const ObjectInstance& instance : instances) {
    if (expired(instance)) forgotten.push_back(instance.id);
  }
  instances.erase(std::remove_if(instances.begin(), instances.end(), expired), instances.end());
  return forgotten;
}

}  // namespace vdc

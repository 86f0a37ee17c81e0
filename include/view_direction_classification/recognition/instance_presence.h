#pragma once

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <vector>

#include "view_direction_classification/recognition/model_library.h"
#include "view_direction_classification/refinement/model_surface.h"
#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

struct ObjectInstance;

// What one segmented frame says about a known instance that no candidate of the frame was
// associated with (doc/method.md section 13, "Change").
enum class PresenceEvidence {
  kNone,    // its place was hidden, out of the image or without depth: no evidence either way
  kSeen,    // the camera saw a surface where the instance's should be
  kAbsent,  // the camera saw through its place: the scene lies clearly behind its surface
};

// The camera-facing samples of the instance's surface at its believed pose, by what the frame's
// depth shows on each one's ray.
struct PresenceCheck {
  PresenceEvidence evidence = PresenceEvidence::kNone;
  int predicted = 0;  // samples in front of the camera that face it
  int seen = 0;       // a scene point within the free-space tolerance of the sample's depth
  int free = 0;       // the nearest scene point on the ray lies clearly behind the sample
  int hidden = 0;     // ... clearly in front of it: something hides the place
  // The nearest point on the ray is the support's, within the tolerance of the sample's depth: the
  // table looks the same whether the object stands there or not (its foot; a mug's inside floor
  // seen from above), so these say nothing.
  int on_support = 0;
  // predicted - seen - free - hidden - on_support: no scene point near the ray (outside the
  // image, NaN, out of the sensor's range).
  int noData() const { return predicted - seen - free - hidden - on_support; }
};

// What the check's counts say: no evidence when under half the samples that could tell (those
// not on the support) were judged (seen or free), or fewer than a few; absence when at least 60 %
// of the judged were free, the surface seen when at most 25 % were; in between nothing (a place
// half free is not seen occupied).
PresenceEvidence presenceEvidence(const PresenceCheck& check);

enum class InstanceState {
  kPresent,
  kGone,  // its place was seen free in absent_views frames: taken away, or moved unseen
};

// An instance's presence in the scene, kept on the instance (ObjectInstance::presence).
struct Presence {
  InstanceState state = InstanceState::kPresent;
  // Frames in a row whose depth showed its place free (reset by a frame that saw it there).
  int absent_frames = 0;
  std::optional<double> gone_since;  // the time of the frame that marked it gone, if stamped
  PresenceCheck last_check;          // of the latest frame it was not associated on
};

// Decides from the scene's depth whether known instances that are out of their place are gone,
// and which one a newly identified object probably is (moved). Owned by the SceneEstimator, which
// calls it on every segmented frame; it holds only each model's surface.
class InstancePresence {
 public:
  // verification: the instances' (its free-space tolerance and facing cosine are used);
  // absent_views >= 1; forget_gone_after [s] >= 0, 0: gone instances are kept.
  InstancePresence(const ModelLibrary& library, const VerificationParameters& verification,
                   int absent_views, double forget_gone_after);
  ~InstancePresence();

  // What the frame (`scene`: its depth off and on the supports, ray-indexed by indexRays) shows
  // where the model's surface at world_from_object would be.
  PresenceCheck check(int model, const Eigen::Isometry3d& world_from_object,
                      const SceneDepth& scene, const Eigen::Isometry3d& world_from_camera) const;

  // Before a segmented frame's association: each instance that is not gone and has a pose gets
  // this frame's check as its last_check (counting nothing). The scene estimator associates no
  // candidate with an instance whose place the frame shows free: its pose is out of date.
  void checkPlaces(std::vector<ObjectInstance>& instances, const SceneDepth& scene,
                   const Eigen::Isometry3d& world_from_camera) const;

  // After a segmented frame's association: the instances whose ids are in `associated` were seen
  // (present again, their count reset); every other one with a position is checked against the
  // frame and marked gone after absent_views frames of absence in a row. Returns the ids it
  // marked gone on this frame.
  std::vector<int> observe(std::vector<ObjectInstance>& instances,
                           const std::vector<int>& associated, const SceneDepth& scene,
                           const Eigen::Isometry3d& world_from_camera,
                           std::optional<double> time) const;

  // The index of the instance a new object identified as `model` at centroid_world (fixed frame)
  // most probably is, or -1: the nearest instance of that model that is gone or whose place this
  // or an earlier frame showed free. An instance out of view or hidden is not taken: a second
  // object of the same model may well stand elsewhere.
  int movedInstance(const std::vector<ObjectInstance>& instances, int model,
                    const Eigen::Vector3d& centroid_world) const;

  // Erases the instances gone for more than forget_gone_after at `time` (none when it is 0 or
  // the frame has no time). Returns their ids.
  std::vector<int> forgetGone(std::vector<ObjectInstance>& instances,
                              std::optional<double> time) const;

 private:
  // Counts one frame's check into the instance's presence.
  void record(const PresenceCheck& check, std::optional<double> time, Presence* presence) const;

  std::vector<std::unique_ptr<const ModelSurface>> surfaces_;  // per library model
  VerificationParameters verification_;
  int absent_views_;
  double forget_gone_after_;
};

}  // namespace vdc

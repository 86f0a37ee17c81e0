#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/recognition/candidate_identification.h"
#include "view_direction_classification/recognition/instance_collision.h"
#include "view_direction_classification/recognition/instance_explanation.h"
#include "view_direction_classification/recognition/instance_overlap.h"
#include "view_direction_classification/recognition/instance_presence.h"
#include "view_direction_classification/recognition/model_library.h"
#include "view_direction_classification/recognition/part_search.h"
#include "view_direction_classification/recognition/scene_memory.h"
#include "view_direction_classification/recognition/shape_alternative.h"
#include "view_direction_classification/recognition/unknown_objects.h"
#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc {

struct SceneEstimatorParameters {
  SceneSegmentationParameters segmentation;
  // Each instance's estimator. Its segmentation is `none` (the candidate is the object); its
  // refinement verifies against the whole scene.
  EstimatorParameters instance;
  IdentificationParameters identification;
  // [m] A candidate whose centroid (fixed frame) is this close to where an instance was last
  // seen is that instance.
  double association_distance = 0.05;
  // Candidates identified per frame at most (the largest first): identification runs an
  // estimator per fitting model, the frame's main cost. What a first view leaves untried waits
  // for the next segmented frame; 20 rather than 10 found 96 % of the known objects after one
  // view instead of 92 % (67 % to 81 % with 5 models) for the same CPU over three views
  // (doc/evaluation.md), a slower first frame.
  int max_identifications = 20;
  // Unions tried per frame at most of an instance identified on one candidate alone with a piece
  // beside it that nothing explains (growNewInstances), after the groups; their own bound, not
  // max_identifications, which a first view of a crowded table spends before them. 0: none.
  int max_growth_tries = 4;
  // A known object in part of a candidate left unknown (part_search.h), searched after every
  // other identification of the frame; its own bound (max_candidates), not max_identifications.
  PartSearchParameters part_search;
  // When a candidate found unknown is tried again (unknown_objects.h).
  UnknownRetryParameters unknown_retry;
  // A frame is segmented only when the camera moved at least this far [m] or turned this much
  // [rad] since the last segmented frame: a still camera shows nothing new, and a frame that is
  // not segmented costs next to nothing.
  double min_camera_translation = 0.02;
  double min_camera_rotation = 0.05;
  // A candidate of which at least min_explained_fraction of the points lie within part_tolerance
  // [m] of a known instance's surface (at its MAP orientation and position) is a part of that
  // instance that segmentation cut off (a mug's handle), not an object of its own.
  double part_tolerance = 0.01;
  double min_explained_fraction = 0.7;
  // Candidates of a detector's label image (segmentLabels) carry the detector's class. When this
  // maps classes to model names of the library, a candidate is identified only against its
  // class's model, and one of a class without an entry is ignored (a detector sees chairs and
  // people too); when empty, every model whose size fits is tried, as for geometric candidates.
  std::map<std::int64_t, std::string> label_models;
  // Change (InstancePresence): an instance no candidate was associated with is marked gone after
  // this many segmented frames in a row (each taken after the camera moved) showed free space
  // where its surface should be; hidden or out of view is no evidence. >= 1.
  int absent_views = 2;
  // [s] A gone instance is forgotten this long after it was marked gone (frames with a time);
  // 0: kept, so that the object is known again, under its id, wherever it comes back.
  double forget_gone_after = 0.0;
};

// Throws vdc::Error naming the first bad parameter.
void checkSceneEstimatorParameters(const SceneEstimatorParameters& parameters);

// One known object in the scene: a model and its own estimator (belief, refinement, trust).
struct ObjectInstance {
  int id = 0;        // stable for the instance's life, unique in the scene
  int model = -1;    // index into the library
  std::string name;  // "<model name>_<n>", n counting each model's instances from 1
  std::unique_ptr<OrientationEstimator> estimator;
  std::vector<double> identity;  // probabilities per model, "unknown" last, at identification
  // Its model against "unknown": the identification's probability, then each fused view's
  // evidence added in log-odds (identityEvidence).
  double identity_probability = 0.0;
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();  // of its points when last seen
  std::optional<double> last_seen;                           // that frame's time
  int frames_seen = 0;
  Presence presence;  // present, or gone: its place was seen free (InstancePresence)
};

// What became of one candidate of a frame.
struct CandidateOutcome {
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d sides = Eigen::Vector3d::Zero();
  int points = 0;
  int instance = -1;  // the instance's id (-1: unknown, or not tried)
  bool new_instance = false;
  bool moved = false;        // identified as a known instance that was out of place: moved here
  bool dropped = false;      // its instance's identity fell below drop_probability: forgotten
  double probability = 0.0;  // of the instance's model at this identification (0 if associated)
  std::string note;          // why it is unknown or was not tried
  ViewUpdate update;         // its instance's estimator update (when it has one)
};

// Where a segmented frame's time went [ms], stage by stage, in the order they run (the
// frame's total_ms is their sum and the little between them).
struct SceneStageTimes {
  double preparation = 0;     // the verification's ray index and the frame's candidates
  double instances = 0;       // association and the associated instances' updates
  double identification = 0;  // whole clusters and single candidates against the library
  double groups = 0;          // groups of pieces beside each other
  double parts = 0;           // the part search (part_search_candidates)
};

struct SceneUpdate {
  bool segmented = false;
  std::string skip_reason;  // why the frame was not segmented
  int planes = 0;
  // Clusters the segmentation dropped (too large, over max_candidates) and why (SceneSegments).
  int dropped_clusters = 0;
  std::string segmentation_note;
  std::vector<CandidateOutcome> candidates;
  // Instances marked gone on this frame, and gone ones forgotten (forget_gone_after): their ids.
  std::vector<int> gone, forgotten;
  double segmentation_ms = 0, total_ms = 0;
  SceneStageTimes stage_ms;  // segmented frames only
};

// The scene layer (doc/method.md section 13): every frame's candidates are found, each is
// associated with a known instance or identified against the library, and each instance's own
// estimator fuses its view. Instances out of view keep their beliefs; one whose place the camera
// sees free is marked gone after absent_views such frames, and a new object of its model is
// taken for it moved (InstancePresence, "Change").
class SceneEstimator {
 public:
  // Throws vdc::Error for invalid parameters (its own, the segmentation's, an instance's) and
  // for a label_models entry naming no model of the library (naming it).
  SceneEstimator(ModelLibrary library, SceneEstimatorParameters parameters);

  // cloud: camera frame, organised or not, NaN allowed; world_from_camera: the camera's pose in
  // the fixed frame; time [s]. Segments the cloud (segmentScene) when the camera moved enough.
  // Never throws for cloud content; throws vdc::Error for a non-finite pose.
  SceneUpdate update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                     const Eigen::Isometry3d& world_from_camera,
                     std::optional<double> time = std::nullopt);
  // The same with the cloud's segments computed by the caller (segmentLabels: a detector's
  // masks); they are used only when the camera moved enough (willSegment).
  SceneUpdate update(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
                     const Eigen::Isometry3d& world_from_camera,
                     std::optional<double> time = std::nullopt);
  // Whether update would segment a frame taken from this pose (the camera moved enough since
  // the last segmented frame): a caller that segments itself need not when it would not.
  bool willSegment(const Eigen::Isometry3d& world_from_camera) const {
    return cameraMoved(world_from_camera);
  }

  const std::vector<ObjectInstance>& instances() const { return instances_; }
  const ObjectInstance* instance(int id) const;
  // Whether the views support the instance's model well enough to report it: its identity
  // probability is at least min_probability (below, it is kept until it recovers or is dropped).
  bool identified(const ObjectInstance& instance) const {
    return instance.identity_probability >= parameters_.identification.min_probability;
  }
  // Whether its pose is reported: identified and present (a gone one is not where it was).
  bool confirmed(const ObjectInstance& instance) const {
    return identified(instance) && instance.presence.state == InstanceState::kPresent;
  }
  const ModelLibrary& library() const { return library_; }
  // Forgets every instance (and every unknown object).
  void reset();
  // Forgets one instance; false if there is none with that id.
  bool resetInstance(int id);
  // The instances and id counters a restart needs back (scene_memory_file.h saves them), and
  // the estimator set to them: restoreMemory throws vdc::Error (changing nothing) for an
  // instance whose model is not in the library, a repeated id or name, a next_id that would
  // reuse one, or an estimator snapshot the instance's estimator refuses. Unknown objects and
  // the last segmented camera pose are forgotten.
  SceneMemory memory() const;
  void restoreMemory(const SceneMemory& memory);

 private:
  // One candidate of the frame being processed.
  struct FrameCandidate {
    pcl::PointCloud<pcl::PointXYZ> points;  // camera frame
    std::vector<Eigen::Vector3f> points_world;
    Eigen::Vector3f up = Eigen::Vector3f::Zero();  // its support's normal (camera frame), if any
    std::optional<Eigen::Vector4d> support;        // the plane it stands on (camera frame)
    int instance = -1;                             // index into instances_ once assigned
    // The models it may be (label_models); empty: any. ignored: its class has no model.
    std::vector<bool> allowed;
    bool ignored = false;
  };
  bool cameraMoved(const Eigen::Isometry3d& world_from_camera) const;
  std::vector<FrameCandidate> frameCandidates(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                              const SceneSegments& segments,
                                              const Eigen::Isometry3d& world_from_camera,
                                              SceneUpdate* result) const;
  // The models a candidate of this class may be (label_models), and whether it is ignored.
  void restrictToClass(std::int64_t class_id, FrameCandidate* candidate,
                       CandidateOutcome* outcome) const;
  // Each candidate's known instance: the nearest by centroid, else the one it is a part of.
  void associate(std::vector<FrameCandidate>& candidates, const SceneUpdate& result) const;
  // Whether an instance is out of its believed place on this frame (gone, or its place seen free).
  static bool outOfPlace(const ObjectInstance& instance);
  // The index of the instance whose pose explains the candidate (a part of it), or -1.
  int explainingInstance(const FrameCandidate& candidate) const;
  // Each instance fuses the union of its candidates' points.
  void updateAssignedInstances(std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                               const Eigen::Isometry3d& world_from_camera,
                               std::optional<double> time, SceneUpdate* result);
  // Adds a fused view's evidence to the instance's identity (identityEvidence).
  // penalty: ShapeAlternative's for the instance's model on this view's points.
  void weighIdentity(ObjectInstance& instance, const ViewUpdate& update, double penalty,
                     const Eigen::Isometry3d& world_from_camera);
  // Forgets the instances whose identity fell below drop_probability.
  void dropUnlikelyInstances(SceneUpdate* result);
  // Segmentation splits objects at concave edges, and some objects are cut by their own (an
  // elephant at its legs, a mug at its handle): the pieces of one cluster that no instance has
  // are first tried together, and become one instance if a model explains them so; else each is
  // tried alone. Returns the unions tried (candidate indices, ascending).
  std::set<std::vector<std::size_t>> identifyWholeClusters(
      const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
      std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
      const Eigen::Isometry3d& world_from_camera, std::optional<double> time, int* identifications,
      SceneUpdate* result);
  // After each candidate was tried alone: the candidates no instance explains, each with those
  // beside it in the image (adjacentCandidateGroups), are tried as one object, but for the
  // unions tried already.
  void identifyAdjacentGroups(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                              const SceneSegments& segments,
                              std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                              const Eigen::Isometry3d& world_from_camera,
                              std::optional<double> time,
                              const std::set<std::vector<std::size_t>>& tried, int* identifications,
                              SceneUpdate* result);
  // Segmentation also cuts an object into pieces one of which alone fits wrongly (a helmet's dome
  // apart from its brim): after the groups, each instance identified on one candidate alone on
  // this frame is tried with each piece beside it that nothing explains and whose union fits the
  // instance's model in size (max_growth_tries per frame). The union takes the instance's place
  // where it is identified at least as surely (identify's same-object rule), or as another
  // model, which then owns the piece; else nothing changes.
  void growNewInstances(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
                        std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                        const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                        SceneUpdate* result);
  // Identifies the union of members (candidates of one cluster, or beside each other, most
  // points first) as one object. Identified: it became an instance, whose largest piece reports
  // it and the others are its parts. Not tried: no model fits its size, it is a known unknown, or
  // max_identifications was reached. union_outcome (optional): the union's outcome. must_fit
  // (optional): a model index the union's size must fit, or it is not tried. budget: the bound
  // of *identifications (max_identifications when none).
  enum class UnionOutcome { kNotTried, kUnknown, kIdentified };
  UnionOutcome identifyPieces(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                              const SceneSegments& segments,
                              const std::vector<std::size_t>& members,
                              std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                              const Eigen::Isometry3d& world_from_camera,
                              std::optional<double> time, int* identifications, SceneUpdate* result,
                              CandidateOutcome* union_outcome = nullptr, int must_fit = -1,
                              std::optional<int> budget = std::nullopt);
  // After every other identification: the candidates that were identified alone and found
  // unknown (unknown_alone), most points first, searched for a known object in part of them
  // (PartSearch); a part identified becomes an instance that the candidate reports.
  void identifyParts(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
                     std::vector<FrameCandidate>& candidates,
                     const std::vector<bool>& unknown_alone, const SceneDepth& scene,
                     const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                     SceneUpdate* result);
  // Identifies a part of candidate c (PartSearch) when it and the rest could be two objects
  // (PartSearchParameters: min_shape_gain against `whole`, what one simple shape explains of the
  // candidate; a rest that no simple shape explains must be identified first). Whether the part
  // became an instance, which the candidate then reports.
  bool identifyPart(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
                    std::size_t c, const CandidatePart& part, double whole,
                    std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                    const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                    SceneUpdate* result);
  // Identifies the points of candidate c marked in `subset` as a candidate of their own (not
  // remembered when unknown): identify's result, its outcome in *outcome.
  int identifySubset(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
                     std::size_t c, const std::vector<bool>& subset, const SceneDepth& scene,
                     const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                     CandidateOutcome* outcome);
  // remember_unknown: an unknown outcome is remembered (unknowns_) for its centroid.
  // Returns the index of the candidate's instance (a new one, or a known one that moved), or -1.
  // `others`: the frame's candidates without an instance besides this one; those the identified
  // pose explains are its pieces (judgeShapesOnExplainedPieces).
  int identify(const FrameCandidate& candidate, const SceneDepth& scene,
               const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
               CandidateOutcome* outcome, bool remember_unknown = true,
               const std::vector<const FrameCandidate*>& others = {});
  static std::vector<const FrameCandidate*> unassignedBesides(
      const std::vector<FrameCandidate>& candidates, std::size_t candidate);
  // The shape alternative judged on the candidate with those of `others` the identified pose
  // explains (explained_pieces.h): the lower penalties stand (lowerPenalties).
  void judgeShapesOnExplainedPieces(const FrameCandidate& candidate,
                                    const std::vector<const FrameCandidate*>& others,
                                    const SceneDepth& scene, const std::vector<double>& penalties,
                                    Identification* identification) const;
  // The index of the instance of its model the identified object is because the two would
  // share their volume (InstanceOverlap), or -1; the outcome says it moved.
  int sameObject(const Identification& identification, CandidateOutcome* outcome) const;
  // Whether the instance was first identified on the frame of `time` (never without a time).
  static bool newOnThisFrame(const ObjectInstance& instance, std::optional<double> time);
  // Whether the identified object would stand inside an instance of another model
  // (InstanceCollision) that is at least as probable: then it stays unknown. A less probable
  // such instance yields instead: its probability is set to 0, to be dropped at the end of the
  // frame. The outcome's note says which happened.
  bool collidesWithLikelierInstance(const Identification& identification,
                                    CandidateOutcome* outcome);
  // The instance a candidate identified as `model` is (its index): a known one of the model that
  // is out of place (InstancePresence::movedInstance: it moved here), else a new one.
  int instanceFor(int model, CandidateOutcome* outcome);

  ModelLibrary library_;
  SceneEstimatorParameters parameters_;
  std::vector<std::unique_ptr<InstanceExplanation>> explanations_;  // per library model
  std::unique_ptr<ShapeAlternative> shapes_;
  std::unique_ptr<InstancePresence> presence_;
  std::unique_ptr<InstanceOverlap> overlap_;
  std::unique_ptr<InstanceCollision> collision_;  // identifications of two models in one space
  std::unique_ptr<PartSearch> part_search_;
  // Per library model: an estimator that fuses nothing and holds its model's surfaces alive.
  std::vector<std::unique_ptr<const OrientationEstimator>> surface_holders_;
  std::vector<ObjectInstance> instances_;
  UnknownObjects unknowns_;
  std::vector<int> instances_named_;  // per model: instances named so far
  int next_id_ = 1;
  std::optional<Eigen::Isometry3d> last_segmented_camera_;
  std::map<std::int64_t, int> label_model_index_;  // label_models' classes -> library index
};

}  // namespace vdc

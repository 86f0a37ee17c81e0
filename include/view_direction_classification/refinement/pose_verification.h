#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <vector>

#include "view_direction_classification/refinement/model_surface.h"
#include "view_direction_classification/refinement/nearest_points.h"

namespace vdc {

// What the camera saw besides the object, for verification (camera frame; NaN and points behind
// the camera are ignored).
struct SceneDepth {
  // The points off the supports, the object's own among them: what can hide the object. A
  // predicted sample behind one is hidden by it (an occluder explains it), a sample in front of
  // one is a surface the camera saw through. So an object partly hidden by another keeps its
  // right pose.
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr occluders;
  // The points of the surfaces the objects stand on (the table). Nothing stands hidden under a
  // table, so a predicted sample on a ray that meets one must lie at its depth: in front of it is
  // free space (a mug's handle over the table where the camera saw the table), behind it is sunk
  // into the table.
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr supports;
  // Optional: both indexed by their rays (x/z, y/z, 0) once for every verifier of the frame
  // (indexRays). Without them each verifier indexes the points around its own object, which for
  // a scene of many candidates and models costs more than the verification itself.
  std::shared_ptr<const NearestPoints> occluder_rays, support_rays;
  // Optional: the plane the object stands on (n . x + d = 0, unit n towards the camera). The
  // table is solid: a model sample below it by more than the free-space tolerance is sunk into
  // it, whether or not the camera could see there. The rays alone miss this where another object
  // hides the part under the table: a cow sunk 5 cm into the table at the foot of a box explained
  // the box's lowest strip with its back at 0.83-0.97.
  std::optional<Eigen::Vector4d> support_plane;
  bool empty() const { return !occluders && !supports && !support_plane; }
};

// The scene's points with a ray (in front of the camera, not 90 degrees off its axis) and their
// ray indices: what PoseVerifier would otherwise build per verifier.
SceneDepth indexRays(const SceneDepth& scene);

// One observation of the object: its points in the camera frame (finite; the segmented object)
// and where the camera was in the fixed frame.
struct RefinementView {
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr points;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  // Optional: the scene around the object. When given, the model's predicted surface is judged
  // against the scene's depth rather than the object's points alone; on a ray that meets no scene
  // point the footprint rule below applies, as without a scene.
  SceneDepth scene;
};

struct VerificationParameters {
  // [m] An observed point is explained by the model when a model sample lies within twice the
  // samples' spacing (at least 4 mm) and the point is within inlier_distance of its tangent plane
  // (or inlier_sigmas depth noise sigmas at its depth, when that is more).
  double inlier_distance = 0.003;
  // [m] A model sample that faces the camera and lies this much (or free_space_sigmas depth noise
  // sigmas at its depth, when that is more) in front of the observed surface along its ray
  // occupies space the camera saw through.
  double free_space_tolerance = 0.008;
  // [m] The sensor's depth noise (standard deviation) at 1 m; it grows with the square of the
  // depth, as a stereo or structured-light camera's does. 5 mm covers a stereo head of 0.1 m
  // baseline at a fifth of a pixel and is above a Kinect's (1.3 mm at 0.6 m, depth_noise.h): on
  // PCL's real stereo scan of a mug at 0.77 m (doc/evaluation.md, "Real scan") the fixed
  // 3 / 8 mm tolerances leave the right pose at 0.74, below min_score, wrong ones at 0.60-0.67.
  double depth_noise_at_1m = 0.005;
  double inlier_sigmas = 2.0;
  double free_space_sigmas = 4.0;
  // Samples facing the camera at a cosine below this (grazing, near the silhouette) are not
  // predicted: their visibility depends on sub-pixel geometry.
  double min_facing_cosine = 0.3;
  // A predicted sample where nothing was observed contradicts the view only inside the view's
  // footprint (the convex hull of its points' rays, grown by the neighbour radius): outside it
  // the sample may be hidden by an occluder the segmentation removed or lie beyond a crop, so it
  // is not judged. false: judged everywhere (a segmented object whose whole silhouette is seen).
  bool judge_only_within_footprint = true;
};

// Throws vdc::Error for negative or non-finite parameters.
void checkVerificationParameters(const VerificationParameters& parameters);

// [m] The tolerances at depth z [m] (camera frame): an observed point within inlierTolerance of
// a model sample's tangent plane is explained; a predicted sample freeSpaceTolerance in front of
// the observed surface is one the camera saw through. Every judge of the scene's depth (the
// verifier, the presence check, the simple-shape alternative) uses these, so all judge alike.
double inlierTolerance(const VerificationParameters& parameters, double z);
double freeSpaceTolerance(const VerificationParameters& parameters, double z);

// The render-and-compare score of one pose (doc/method.md, "Refinement"), computed on points: the
// model's camera-facing samples are its predicted depth, the observed points the measured one.
struct VerificationScore {
  double inlier_fraction = 0.0;  // observed points the model explains
  // Observed points the model explains with a sample on the side the camera sees. A thin wall's
  // inner side lies a wall's thickness behind its outer one, so inlier_fraction lets a mug's
  // inside explain the front of a slightly narrower can; refinement keeps that leniency (its
  // coarse ICP may settle a wall's thickness off before the polish), identification does not.
  double facing_inlier_fraction = 0.0;
  // Of those, the ones within half the inlier tolerance. A model a few millimetres off the true
  // shape (a mug on a slightly narrower can) still explains nearly every point within the
  // tolerance, which must allow for depth noise, but far fewer within half of it; the true shape
  // explains nearly as many there, since the tolerance is at least two noise sigmas.
  double facing_close_fraction = 0.0;
  // Predicted samples the observation contradicts: in front of the observed surface (the camera
  // saw through them), or where nothing was observed at all (the object's points are segmented,
  // so a prediction outside them is a surface that is not there). Samples behind the observed
  // surface are occluded, which is no contradiction.
  double violation_fraction = 0.0;
  // Of the model's samples (all of them, seen or not), those sunk into the support plane
  // (SceneDepth::support_plane); 0 without one. No part of an object lies inside its table.
  double sunk_fraction = 0.0;
  int observed = 0, predicted = 0;
  // inlier_fraction - violation_fraction, in [-1, 1]: both halves matter, a pose that explains
  // the points with a model part sticking out into free space is as wrong as one that leaves
  // points unexplained. It leaves out sunk_fraction: refinement turns a pose sunk into the table
  // by its restarts into the right one (a helmet 3 cm low and tilted, whose restarts found the
  // truth), which it only tries from a pose it accepted.
  double score() const { return inlier_fraction - violation_fraction; }
  // How well the model, and no other object, explains the view: facing inliers weighted by their
  // residual (1 within half the tolerance, 1/2 up to it), a coarse residual likelihood, minus the
  // contradicted predictions and the share sunk into the table. The simple-shape alternative
  // (shape_alternative.h) is weighed alike.
  double identityScore() const {
    return 0.5 * (facing_inlier_fraction + facing_close_fraction) - violation_fraction -
           sunk_fraction;
  }
};

// Scores poses of the model against a fixed set of views. Building one indexes each view's
// points by their ray (x/z, y/z), once for all poses. Scoring is const and thread-safe.
class PoseVerifier {
 public:
  // Throws vdc::Error for negative or non-finite parameters.
  PoseVerifier(std::shared_ptr<const ModelSurface> surface,
               const std::vector<RefinementView>& views, VerificationParameters parameters = {});

  // world_from_object: the pose to score. Views without points count for nothing.
  VerificationScore score(const Eigen::Isometry3d& world_from_object) const;

 private:
  // Points indexed by their rays (x/z, y/z, 0).
  struct RayIndex {
    pcl::PointCloud<pcl::PointXYZ>::ConstPtr points;
    std::shared_ptr<const NearestPoints> rays;
  };
  struct IndexedView {
    RayIndex object;
    // The scene's points near the object's rays (empty: verified against the object alone).
    RayIndex scene, supports;
    Eigen::Isometry3d camera_from_world;
    std::vector<Eigen::Vector2f> footprint;  // convex hull of the object's rays, counter-clockwise
    std::optional<Eigen::Vector4f> support_plane;  // camera frame
  };
  std::unique_ptr<IndexedView> indexView(const RefinementView& view) const;
  RayIndex indexScene(const pcl::PointCloud<pcl::PointXYZ>& scene,
                      const pcl::PointCloud<pcl::PointXYZ>& object) const;
  // Counts of one pose over the views.
  struct Counts {
    int inliers = 0, facing_inliers = 0, facing_close = 0, violations = 0;
    int sunk = 0, below_judged = 0;  // samples sunk into the support plane, of those judged
  };
  void addViewScore(const IndexedView& view, const Eigen::Isometry3d& world_from_object,
                    Counts* counts, VerificationScore* score) const;
  // Of the inliers `matched` (object frame, each matched to `index`'s sample) whose sample faces
  // away from the camera at `camera` (object frame): the ones a sample facing it explains,
  // counted into counts->facing_inliers and (within half the tolerance) counts->facing_close.
  void countFacingRematches(const std::vector<Eigen::Vector3f>& matched,
                            const std::vector<float>& z, const Eigen::Vector3f& camera,
                            Counts* counts) const;

  std::shared_ptr<const ModelSurface> surface_;
  std::vector<std::unique_ptr<IndexedView>> views_;

  VerificationParameters parameters_;
  double neighbour_radius_;
};

}  // namespace vdc

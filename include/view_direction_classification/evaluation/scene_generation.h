#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_noise.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/scene.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Cluttered table scenes for the evaluation of recognising every known object in a scene: several
// known objects and unknown distractors standing on a table, seen by a camera moving on an arc.
//
// Fixed frame: z up (REP 103), the table top is the plane z = 0, centred on the origin. Every
// object stands upright as in its mesh's own frame (+z up), turned by a random yaw about z, with
// its lowest vertex on the table; objects that only rest stably on another face need a mesh
// frame that puts that face down.

// A known object: the model's name (what an estimate names) and its mesh in the object frame [m].
struct KnownModel {
  std::string name;
  TriangleMesh mesh;
};

struct SceneGenerationSettings {
  int known_objects = 5;  // drawn from the models in turn (shuffled), so each appears when it can
  int distractors = 5;    // drawn from the distractor meshes in turn (shuffled)
  Eigen::Vector2d table_size{1.2, 0.8};  // [m] along x and y
  // Objects not placed against a neighbour have their origin uniform in this disc about the table
  // centre [m]; a small disc crowds the scene, so objects hide each other. An object that finds
  // no free place in half its attempts goes anywhere on the table.
  double scatter_radius = 0.15;
  // Fraction of the objects after the first placed in contact with one already placed, at
  // contact_gap [m] between their footprints (a gap, so noise cannot make them interpenetrate).
  double contact_fraction = 0.4;
  double contact_gap = 0.002;
  // Fraction of the distractors placed in front of a known object as the first view sees it, so
  // that known objects are partly hidden: occluder_gap_min..max [m] from it, in a direction
  // turned from the first view's (horizontal) by occluder_bearing_min..max [deg] to either side,
  // so the occluder covers one side of the object rather than all of it.
  double occluder_fraction = 0.8;
  double occluder_gap_min = 0.01, occluder_gap_max = 0.05;
  double occluder_bearing_min_deg = 15.0, occluder_bearing_max_deg = 45.0;
  // The camera path: `views` poses on an arc about the scene's centre.
  int views = 3;
  double min_camera_distance = 0.5, max_camera_distance = 1.2;  // [m] to the scene's centre
  double min_elevation_deg = 40.0, max_elevation_deg = 65.0;    // above the table plane
  double arc_deg = 90.0;  // azimuth covered from the first view to the last
  int attempts_per_object = 500;
};

// Throws vdc::Error naming the first bad setting.
void checkSceneGenerationSettings(const SceneGenerationSettings& settings);

struct PlacedKnownObject {
  std::string model;
  ScenePart part;
};

struct TableScene {
  Eigen::Vector2d table_size = Eigen::Vector2d(1.2, 0.8);
  std::vector<PlacedKnownObject> known;
  std::vector<ScenePart> distractors;
  // Pairs placed in contact, as indices into known followed by distractors (known.size() + d).
  std::vector<std::pair<int, int>> touching;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // of all objects' bounds: what views look at
  std::vector<Eigen::Isometry3d> world_from_camera;  // optical frame (z forward, x right, y down)
};

// A scene with the known models and distractor meshes (need not be closed: any mesh in metres,
// standing on z = 0 or not). Deterministic in (inputs, settings, seed). Throws vdc::Error for bad
// settings, no known models, distractors requested without meshes, an empty mesh, or when an
// object finds no free place on the table (table too small for the objects).
TableScene generateTableScene(const std::vector<KnownModel>& models,
                              const std::vector<TriangleMesh>& distractor_meshes,
                              const SceneGenerationSettings& settings, std::uint32_t seed);

// The table, known objects and distractors as one vdc::Scene (the table is its `object`, the
// objects its distractors), e.g. for sceneMesh.
Scene asScene(const TableScene& scene);

// One view of a table scene.
struct SceneView {
  pcl::PointCloud<pcl::PointXYZ> cloud;  // organised, in the camera's optical frame
  // Per object (known, then distractors): of the pixels it covers when rendered alone, the
  // fraction where the scene's (noise-free) depth is its own; 0 for an object outside the image.
  std::vector<double> known_visible_fraction;
  std::vector<double> distractor_visible_fraction;
};

// Renders views of one scene: holds a renderer for the whole scene and one per object.
class TableSceneRenderer {
 public:
  explicit TableSceneRenderer(const TableScene& scene, const CameraIntrinsics& intrinsics = {});

  // The cloud gets the noise of `noise` drawn from *rng (see DepthRenderer::render).
  SceneView render(const Eigen::Isometry3d& world_from_camera, const DepthNoiseModel& noise = {},
                   std::mt19937* rng = nullptr) const;

 private:
  DepthRenderer whole_scene_;
  std::vector<DepthRenderer> known_, distractors_;
  std::vector<Eigen::Isometry3d> world_from_known_, world_from_distractor_;
};

}  // namespace vdc

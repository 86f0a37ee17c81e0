#include <cmath>

#include "view_direction_classification/evaluation/scene_generation.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

// A pixel shows an object when the scene's depth there is the object's own. Both come from the
// same triangles transformed along different (float) paths, so they may differ by rounding.
constexpr double kSameDepthRelativeTolerance = 1e-4;

std::vector<DepthRenderer> renderersOf(const std::vector<const TriangleMesh*>& meshes,
                                       const CameraIntrinsics& intrinsics) {
  std::vector<DepthRenderer> renderers;
  for (const TriangleMesh* mesh : meshes) renderers.emplace_back(*mesh, intrinsics);
  return renderers;
}

std::vector<const TriangleMesh*> knownMeshes(const TableScene& scene) {
  std::vector<const TriangleMesh*> meshes;
  for (const PlacedKnownObject& object : scene.known) meshes.push_back(&object.part.mesh);
  return meshes;
}

std::vector<const TriangleMesh*> distractorMeshes(const TableScene& scene) {
  std::vector<const TriangleMesh*> meshes;
  for (const ScenePart& part : scene.distractors) meshes.push_back(&part.mesh);
  return meshes;
}

double visibleFraction(const std::vector<float>& alone, const std::vector<float>& scene) {
  long covered = 0, visible = 0;
  for (std::size_t i = 0; i < alone.size(); ++i) {
    if (alone[i] <= 0.0f) continue;
    ++covered;
    if (std::abs(scene[i] - alone[i]) <= kSameDepthRelativeTolerance * alone[i]) ++visible;
  }
  return covered > 0 ? static_cast<double>(visible) / static_cast<double>(covered) : 0.0;
}

// Per object, its visible fraction in the scene's depth image.
std::vector<double> visibleFractions(const std::vector<DepthRenderer>& objects,
                                     const std::vector<Eigen::Isometry3d>& world_from_object,
                                     const Eigen::Isometry3d& camera_from_world,
                                     const std::vector<float>& scene_depth) {
  std::vector<double> fractions;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::vector<float> alone =
        objects[i].renderDepth(camera_from_world * world_from_object[i]);
    fractions.push_back(visibleFraction(alone, scene_depth));
  }
  return fractions;
}

}  // namespace

Scene asScene(const TableScene& table_scene) {
  Scene scene;
  scene.object = {makeRectangleMesh(table_scene.table_size), Eigen::Isometry3d::Identity()};
  for (const PlacedKnownObject& object : table_scene.known) {
    scene.distractors.push_back(object.part);
  }
  for (const ScenePart& part : table_scene.distractors) scene.distractors.push_back(part);
  return scene;
}

TableSceneRenderer::TableSceneRenderer(const TableScene& scene, const CameraIntrinsics& intrinsics)
    : whole_scene_(sceneMesh(asScene(scene)), intrinsics),
      known_(renderersOf(knownMeshes(scene), intrinsics)),
      distractors_(renderersOf(distractorMeshes(scene), intrinsics)) {
  for (const PlacedKnownObject& object : scene.known) {
    world_from_known_.push_back(object.part.world_from_part);
  }
  for (const ScenePart& part : scene.distractors) {
    world_from_distractor_.push_back(part.world_from_part);
  }
}

SceneView TableSceneRenderer::render(const Eigen::Isometry3d& world_from_camera,
                                     const DepthNoiseModel& noise, std::mt19937* rng) const {
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  const std::vector<float> scene_depth = whole_scene_.renderDepth(camera_from_world);
  SceneView view;
  view.cloud = whole_scene_.render(camera_from_world, noise, rng);
  view.known_visible_fraction =
      visibleFractions(known_, world_from_known_, camera_from_world, scene_depth);
  view.distractor_visible_fraction =
      visibleFractions(distractors_, world_from_distractor_, camera_from_world, scene_depth);
  return view;
}

}  // namespace vdc

#include "view_direction_classification/evaluation/patrol_truth.h"

#include <utility>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Depths of the same triangles along different float paths may differ by rounding.
constexpr double kSameDepthRelativeTolerance = 1e-4;

const TriangleMesh& meshOf(const PatrolScene& scene, int id) {
  for (const PatrolObject& object : scene.objects) {
    if (object.id == id) return object.placed.part.mesh;
  }
  throw Error("patrol truth: no object with id " + std::to_string(id));
}

// Of the pixels the place's object covers alone, the fraction where the scene shows nothing
// nearer: there the camera would see the object, so it sees the place (free or not).
double placeVisibleFraction(const std::vector<float>& alone, const std::vector<float>& scene) {
  long covered = 0, visible = 0;
  for (std::size_t i = 0; i < alone.size(); ++i) {
    if (alone[i] <= 0.0f) continue;
    ++covered;
    if (scene[i] <= 0.0f || scene[i] >= alone[i] * (1.0 - kSameDepthRelativeTolerance)) ++visible;
  }
  return covered > 0 ? static_cast<double>(visible) / static_cast<double>(covered) : 0.0;
}

}  // namespace

PatrolTruthRenderer::PatrolTruthRenderer(const PatrolScene& scene, const TableScene& present,
                                         std::vector<int> ids, std::vector<VacatedPlace> vacated,
                                         const CameraIntrinsics& intrinsics)
    : present_(present),
      ids_(std::move(ids)),
      vacated_(std::move(vacated)),
      whole_scene_(sceneMesh(asScene(present)), intrinsics) {
  for (const VacatedPlace& place : vacated_)
    places_.emplace_back(meshOf(scene, place.object), intrinsics);
}

PatrolTruth PatrolTruthRenderer::truth(const SceneView& view,
                                       const Eigen::Isometry3d& world_from_camera) const {
  PatrolTruth truth;
  truth.present = viewTruth(present_, view).known;
  truth.ids = ids_;
  truth.vacated = vacated_;
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  const std::vector<float> scene_depth = whole_scene_.renderDepth(camera_from_world);
  for (std::size_t p = 0; p < vacated_.size(); ++p) {
    const std::vector<float> alone =
        places_[p].renderDepth(camera_from_world * vacated_[p].world_from_object);
    truth.vacated[p].visible_fraction = placeVisibleFraction(alone, scene_depth);
  }
  return truth;
}

}  // namespace vdc

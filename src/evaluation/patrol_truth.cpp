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

// The camera's image grown by its own size on every side (the same focal lengths): an object
// rendered into it covers the pixels it would cover were the image that large, so the part of it
// beyond the real image's border counts as out of sight.
CameraIntrinsics paddedIntrinsics(const CameraIntrinsics& intrinsics) {
  CameraIntrinsics padded = intrinsics;
  padded.width = 3 * intrinsics.width;
  padded.height = 3 * intrinsics.height;
  padded.cx += intrinsics.width;
  padded.cy += intrinsics.height;
  return padded;
}

// Of the pixels the place's object covers alone (in the padded image), the fraction inside the
// real image where the scene shows a surface at or behind the place: there a depth camera shows
// the place free (or taken). A ray that meets nothing returns no depth, which tells free space
// from a dropout no better than a hidden place does, so it does not count as seen; nor does the
// part of the place beyond the image's border.
double placeVisibleFraction(const std::vector<float>& alone_padded, const std::vector<float>& scene,
                            const CameraIntrinsics& intrinsics) {
  const int padded_width = 3 * intrinsics.width;
  long covered = 0, visible = 0;
  for (std::size_t i = 0; i < alone_padded.size(); ++i) {
    const float alone = alone_padded[i];
    if (alone <= 0.0f) continue;
    ++covered;
    const int u = static_cast<int>(i % padded_width) - intrinsics.width;
    const int v = static_cast<int>(i / padded_width) - intrinsics.height;
    if (u < 0 || u >= intrinsics.width || v < 0 || v >= intrinsics.height) continue;
    const float behind = scene[static_cast<std::size_t>(v) * intrinsics.width + u];
    if (behind > 0.0f && behind >= alone * (1.0 - kSameDepthRelativeTolerance)) ++visible;
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
      intrinsics_(intrinsics),
      whole_scene_(sceneMesh(asScene(present)), intrinsics) {
  for (const VacatedPlace& place : vacated_)
    places_.emplace_back(meshOf(scene, place.object), paddedIntrinsics(intrinsics));
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
    truth.vacated[p].visible_fraction = placeVisibleFraction(alone, scene_depth, intrinsics_);
  }
  return truth;
}

}  // namespace vdc

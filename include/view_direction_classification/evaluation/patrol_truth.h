#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/evaluation/patrol_changes.h"
#include "view_direction_classification/evaluation/patrol_metrics.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {

// The truth of each view of one patrol pass: the present objects as the view shows them, and
// the places objects left, with how much of each place the view sees free (a place counts as
// seen where the object, were it still there, would be in sight, inside the image, and the depth
// shows a surface at or behind it), for the time to notice a removal in views of its place.
class PatrolTruthRenderer {
 public:
  // present: presentScene(scene, &ids); vacated: places of objects of `scene`.
  PatrolTruthRenderer(const PatrolScene& scene, const TableScene& present, std::vector<int> ids,
                      std::vector<VacatedPlace> vacated, const CameraIntrinsics& intrinsics = {});

  // view: the present scene's, rendered from world_from_camera.
  PatrolTruth truth(const SceneView& view, const Eigen::Isometry3d& world_from_camera) const;

 private:
  TableScene present_;
  std::vector<int> ids_;
  std::vector<VacatedPlace> vacated_;
  CameraIntrinsics intrinsics_;
  DepthRenderer whole_scene_;
  std::vector<DepthRenderer> places_;  // per vacated: its object's mesh, in a padded image
};

}  // namespace vdc

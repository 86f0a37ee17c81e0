#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/visualisation/rgb_image.h"

namespace vdc {

// Draws a coloured surface point set (the set S with per-point colours) as seen from a viewing
// direction: orthographic, each point a disc, a z-buffer for occlusion and back-facing points
// skipped, fitted into the image with a margin. This is what the heatmap pictures are made of.
struct SplatView {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // object frame, object -> viewer
  int size = 400;                                        // square image edge [px]
  double point_spacing = 0.002;                          // spacing of S [m] (sets disc size)
  Rgb background{235, 235, 235};
};

RgbImage renderSplats(const std::vector<Eigen::Vector3f>& points,
                      const std::vector<Eigen::Vector3f>& normals, const std::vector<Rgb>& colours,
                      const SplatView& view);

}  // namespace vdc

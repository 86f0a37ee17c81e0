#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace vdc {

// Figures of one depth cloud that tell the depth sensor models apart (geometry/sensor_model.h;
// doc/evaluation.md, "Depth sensor models"), computed the same way for a real scan and a render.
// Depth levels need any cloud; the edge figures need an organised one (NaN otherwise). Edges are
// looked for along image rows between consecutive measured pixels at most kMaxEdgeGap apart.
struct DepthStatistics {
  static constexpr int kMaxEdgeGap = 8;           // [px] wider holes are not edges
  static constexpr double kEdgeJumpRatio = 0.02;  // a depth edge: depths differ by > 2 % of z
  // Kinect v1's focal length times baseline [px m]: a step in 1/z times this is its step in
  // disparity, 1/8 px on the device's grid.
  static constexpr double kKinectFocalBaseline = 580.0 * 0.075;

  std::size_t points = 0;     // measured (finite) points
  double median_depth = 0.0;  // [m]
  // Distinct depths per cm within +-5 % of the median depth: continuous noise gives hundreds,
  // a quantised sensor a few.
  double levels_per_cm = 0.0;
  // Median step between adjacent distinct depths there, in 1/z, times kKinectFocalBaseline [px]:
  // 0.125 on a Kinect's disparity grid, near 0 for continuous depth.
  double disparity_step_px = 0.0;
  std::size_t depth_edges = 0;     // pairs of consecutive measured pixels across a depth edge
  double edge_gap_fraction = 0.0;  // of those edges: with a missing pixel between the two sides
  double flat_gap_fraction = 0.0;  // of the pairs on one surface: with a missing pixel between
  // Of the edge sites along rows (five measured pixels, a depth jump of more than 5 % of z across
  // the middle one, a flat surface on either side), those whose middle pixel lies between the
  // two surfaces (more than 15 % of the jump from either): 0 for sharp edges, up to 1 when every
  // edge flies. Only a few hundred sites on the mug renders: a figure to a few hundredths.
  double flying_fraction = 0.0;
};

// The figures of `cloud` (any frame whose z axis is the optical axis, either way: depth is |z|;
// an organised cloud for the edge figures). A cloud without points gives zeros and NaN.
DepthStatistics depthStatistics(const pcl::PointCloud<pcl::PointXYZ>& cloud);

}  // namespace vdc

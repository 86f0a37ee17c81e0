#pragma once

// The model surface's truncated distance field (private to refinement): the distance from any
// point of the object frame to the nearest surface sample, up to a truncation, on a grid. The
// screening of refinement's starts asks the mean truncated distance of a few hundred points for
// every start; on a piece, whose starts are placed five times over, a k-d tree search per point
// was 45 % of a scene's first view (doc/performance.md). Interpolated from a grid, a look-up costs
// a few memory reads.

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace vdc {

class TruncatedDistanceField {
 public:
  // samples (object frame) inside `bounds`; truncation [m] > 0; cell [m] > 0. The grid covers
  // the bounds grown by the truncation.
  TruncatedDistanceField(const std::vector<Eigen::Vector3f>& samples,
                         const Eigen::AlignedBox3d& bounds, double truncation, double cell);

  // [m] The distance from p (object frame) to the nearest sample, trilinearly interpolated
  // between the grid's nodes (the distance changes by at most a cell's diagonal across a cell,
  // so the error stays below that: up to 1.5 mm next to a sample), and `truncation` where
  // it is farther or p off the grid.
  double distance(const Eigen::Vector3f& p) const;
  double truncation() const { return truncation_; }

 private:
  double node(int x, int y, int z) const;

  double truncation_, cell_;
  Eigen::Vector3d origin_;  // the node (0, 0, 0)
  Eigen::Vector3i size_;    // nodes per axis
  // Per node, the distance in units of truncation / 65535: a quarter of a float's memory, and a
  // hundredth of a millimetre's resolution at ICP's 15 mm.
  std::vector<std::uint16_t> nodes_;
};

}  // namespace vdc

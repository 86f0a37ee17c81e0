#pragma once

#include <Eigen/Core>

#include <random>
#include <vector>

namespace vdc {

// The unit icosphere of subdivision level >= 0: the icosahedron's 12 vertices and 20 faces, each
// level splitting every triangle into four at its edge midpoints pushed onto the sphere
// (10 * 4^level + 2 vertices). Faces are counter-clockwise seen from outside.
struct Icosphere {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
};
// Throws vdc::Error for a level outside [0, 6].
Icosphere makeIcosphere(int level);

// The M training viewing directions (doc/method.md section 2): near-uniform, deterministic unit
// vectors. 12, 42, 162 and 642 give the vertices of the icosphere of subdivision level 0..3
// (42 = level 1, the default); any other count gives a Fibonacci lattice. A direction's cell is
// its Voronoi cell on the sphere (the directions nearer to it than to any other).
class ViewSphere {
 public:
  // Throws vdc::Error for count < 2 or count > 10000.
  explicit ViewSphere(int count = 42);

  int size() const { return static_cast<int>(directions_.size()); }
  const Eigen::Vector3d& direction(int m) const;  // vdc::Error for m out of range
  const std::vector<Eigen::Vector3d>& directions() const { return directions_; }

  // Index of the cell containing `direction` (any non-zero vector; it is normalised). Ties go to
  // the lower index. vdc::Error for a zero or non-finite vector.
  int nearest(const Eigen::Vector3d& direction) const;
  // Mean angle [rad] between a direction and its nearest neighbour.
  double neighbourAngle() const { return neighbour_angle_; }
  // Angular radius [rad] of a spherical cap around direction(m) that contains the whole cell.
  double cellRadius(int m) const;
  // A direction drawn uniformly from the sphere restricted to cell m (rejection sampling from
  // the cell's bounding cap). vdc::Error for m out of range.
  Eigen::Vector3d sampleInCell(int m, std::mt19937& rng) const;

 private:
  void checkIndex(int m) const;

  std::vector<Eigen::Vector3d> directions_;
  std::vector<double> cell_radius_;
  double neighbour_angle_ = 0.0;
};

}  // namespace vdc

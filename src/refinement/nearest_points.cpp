#include "view_direction_classification/refinement/nearest_points.h"

#include <nanoflann.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace vdc {

namespace {

// The points as nanoflann reads them.
struct PointsAdaptor {
  const std::vector<Eigen::Vector3f>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  float kdtree_get_pt(std::uint32_t index, std::size_t dimension) const {
    return points[index][static_cast<Eigen::Index>(dimension)];
  }
  template <typename Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;  // nanoflann computes the box itself
  }
};

// nanoflann's search result: the nearest point strictly nearer than a bound, which prunes the
// tree from the start (nanoflann skips every cell farther than worstDist()).
class NearestWithin {
 public:
  explicit NearestWithin(float squared_bound) : squared_distance_(squared_bound) {}
  bool full() const { return true; }
  float worstDist() const { return squared_distance_; }
  bool addPoint(float squared_distance, std::uint32_t index) {
    if (squared_distance < squared_distance_) {
      squared_distance_ = squared_distance;
      index_ = static_cast<int>(index);
    }
    return true;  // search on: a nearer point may follow
  }
  int index() const { return index_; }
  float squaredDistance() const { return squared_distance_; }

 private:
  float squared_distance_;
  int index_ = -1;
};

}  // namespace

struct NearestPoints::Index {
  using Tree =
      nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointsAdaptor>,
                                          PointsAdaptor, 3, std::uint32_t>;
  explicit Index(const std::vector<Eigen::Vector3f>& points)
      : adaptor{points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
  PointsAdaptor adaptor;
  Tree tree;
};

NearestPoints::NearestPoints(std::vector<Eigen::Vector3f> points) : points_(std::move(points)) {
  if (!points_.empty()) index_ = std::make_unique<Index>(points_);
}

NearestPoints::~NearestPoints() = default;

void NearestPoints::search(const std::vector<Eigen::Vector3f>& queries, std::vector<int>* indices,
                           std::vector<float>* squared_distances, double max_distance) const {
  const std::size_t count = queries.size();
  indices->assign(count, -1);
  squared_distances->assign(count, std::numeric_limits<float>::infinity());
  if (count == 0 || !index_) return;
  // Widened by a part in a million: the search keeps only points strictly inside the bound, and
  // a point at exactly max_distance must still be reported.
  const double max_squared = max_distance * max_distance * (1.0 + 1e-6);
  const float bound = std::isfinite(max_squared) && max_squared < std::numeric_limits<float>::max()
                          ? static_cast<float>(max_squared)
                          : std::numeric_limits<float>::infinity();
  const nanoflann::SearchParams exact(32, 0.0f, false);  // eps 0: the exact nearest
  for (std::size_t i = 0; i < count; ++i) {
    NearestWithin nearest(bound);
    index_->tree.findNeighbors(nearest, queries[i].data(), exact);
    if (nearest.index() < 0) continue;
    (*indices)[i] = nearest.index();
    (*squared_distances)[i] = nearest.squaredDistance();
  }
}

}  // namespace vdc

#include "view_direction_classification/refinement/nearest_points.h"

#include <nanoflann.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"

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

// nanoflann's search result: the nearest allowed point strictly nearer than a bound, which prunes
// the tree from the start (nanoflann skips every cell farther than worstDist()).
class NearestWithin {
 public:
  // normals and towards_camera: both null (every point), or the points' normals and the query's
  // unit direction to its camera (only points facing it).
  NearestWithin(float squared_bound, const std::vector<Eigen::Vector3f>* normals,
                const Eigen::Vector3f* towards_camera, float min_cosine)
      : squared_distance_(squared_bound),
        normals_(normals),
        towards_camera_(towards_camera),
        min_cosine_(min_cosine) {}
  bool full() const { return true; }
  float worstDist() const { return squared_distance_; }
  bool addPoint(float squared_distance, std::uint32_t index) {
    if (squared_distance < squared_distance_ && faces(index)) {
      squared_distance_ = squared_distance;
      index_ = static_cast<int>(index);
    }
    return true;  // search on: a nearer point may follow
  }
  int index() const { return index_; }
  float squaredDistance() const { return squared_distance_; }

 private:
  bool faces(std::uint32_t index) const {
    return !normals_ || (*normals_)[index].dot(*towards_camera_) >= min_cosine_;
  }

  float squared_distance_;
  const std::vector<Eigen::Vector3f>* normals_;
  const Eigen::Vector3f* towards_camera_;
  float min_cosine_;
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

NearestPoints::NearestPoints(std::vector<Eigen::Vector3f> points,
                             std::vector<Eigen::Vector3f> normals)
    : NearestPoints(std::move(points)) {
  if (normals.size() != points_.size()) {
    throw Error("NearestPoints: " + std::to_string(normals.size()) + " normals for " +
                std::to_string(points_.size()) + " points");
  }
  normals_ = std::move(normals);
}

NearestPoints::~NearestPoints() = default;

void NearestPoints::search(const std::vector<Eigen::Vector3f>& queries, std::vector<int>* indices,
                           std::vector<float>* squared_distances, double max_distance,
                           const FacingFilter* facing) const {
  const std::size_t count = queries.size();
  indices->assign(count, -1);
  squared_distances->assign(count, std::numeric_limits<float>::infinity());
  if (count == 0 || !index_) return;
  if (facing &&
      (normals_.empty() || !facing->towards_camera || facing->towards_camera->size() != count)) {
    throw Error(
        "NearestPoints::search: a facing filter needs the points' normals and one camera "
        "direction per query");
  }
  // Widened by a part in a million: the search keeps only points strictly inside the bound, and
  // a point at exactly max_distance must still be reported.
  const double max_squared = max_distance * max_distance * (1.0 + 1e-6);
  const float bound = std::isfinite(max_squared) && max_squared < std::numeric_limits<float>::max()
                          ? static_cast<float>(max_squared)
                          : std::numeric_limits<float>::infinity();
  const nanoflann::SearchParams exact(32, 0.0f, false);  // eps 0: the exact nearest
  for (std::size_t i = 0; i < count; ++i) {
    NearestWithin nearest(bound, facing ? &normals_ : nullptr,
                          facing ? &(*facing->towards_camera)[i] : nullptr,
                          facing ? facing->min_cosine : 0.0f);
    index_->tree.findNeighbors(nearest, queries[i].data(), exact);
    if (nearest.index() < 0) continue;
    (*indices)[i] = nearest.index();
    (*squared_distances)[i] = nearest.squaredDistance();
  }
}

}  // namespace vdc

#include "view_direction_classification/refinement/nearest_points.h"

#include <flann/flann.hpp>

#include <limits>
#include <utility>

namespace vdc {

struct NearestPoints::Index {
  explicit Index(std::vector<Eigen::Vector3f>& points)
      : index(flann::Matrix<float>(points.front().data(), points.size(), 3),
              flann::KDTreeSingleIndexParams(15)) {
    index.buildIndex();
  }
  flann::Index<flann::L2_Simple<float>> index;
};

NearestPoints::NearestPoints(std::vector<Eigen::Vector3f> points) : points_(std::move(points)) {
  if (!points_.empty()) index_ = std::make_unique<Index>(points_);
}

NearestPoints::~NearestPoints() = default;

void NearestPoints::search(const std::vector<Eigen::Vector3f>& queries, std::vector<int>* indices,
                           std::vector<float>* squared_distances) const {
  const std::size_t count = queries.size();
  indices->assign(count, -1);
  squared_distances->assign(count, std::numeric_limits<float>::infinity());
  if (count == 0 || !index_) return;
  // FLANN reads the queries without changing them; its Matrix type is not const-correct.
  flann::Matrix<float> query_matrix(const_cast<float*>(queries.front().data()), count, 3);
  std::vector<std::size_t> found(count);
  flann::Matrix<std::size_t> index_matrix(found.data(), count, 1);
  flann::Matrix<float> distance_matrix(squared_distances->data(), count, 1);
  flann::SearchParams parameters(-1, 0.0f, false);  // exact (single k-d tree), unsorted
  parameters.cores = 1;                             // callers already run in parallel
  index_->index.knnSearch(query_matrix, index_matrix, distance_matrix, 1, parameters);
  for (std::size_t i = 0; i < count; ++i) (*indices)[i] = static_cast<int>(found[i]);
}

}  // namespace vdc

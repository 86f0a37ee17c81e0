#include "distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

constexpr double kLevels = 65535.0;

}  // namespace

TruncatedDistanceField::TruncatedDistanceField(const std::vector<Eigen::Vector3f>& samples,
                                               const Eigen::AlignedBox3d& bounds, double truncation,
                                               double cell)
    : truncation_(truncation), cell_(cell) {
  if (!(truncation > 0.0) || !std::isfinite(truncation) || !(cell > 0.0) || !std::isfinite(cell)) {
    throw Error("a distance field needs a positive, finite truncation and cell");
  }
  origin_ = bounds.min() - Eigen::Vector3d::Constant(truncation + cell);
  const Eigen::Vector3d extent =
      bounds.sizes() + Eigen::Vector3d::Constant(2.0 * (truncation + cell));
  for (int a = 0; a < 3; ++a) size_[a] = static_cast<int>(std::ceil(extent[a] / cell)) + 1;
  // Squared distances first, then quantised: each sample lowers the nodes within the truncation.
  std::vector<float> squared(static_cast<std::size_t>(size_.prod()),
                             static_cast<float>(truncation * truncation));
  const int reach = static_cast<int>(std::ceil(truncation / cell));
  for (const Eigen::Vector3f& sample : samples) {
    const Eigen::Vector3d s = sample.cast<double>();
    const Eigen::Vector3d g = (s - origin_) / cell;
    Eigen::Vector3i low, high;
    for (int a = 0; a < 3; ++a) {
      low[a] = std::max(0, static_cast<int>(std::floor(g[a])) - reach);
      high[a] = std::min(size_[a] - 1, static_cast<int>(std::ceil(g[a])) + reach);
    }
    for (int z = low.z(); z <= high.z(); ++z) {
      for (int y = low.y(); y <= high.y(); ++y) {
        for (int x = low.x(); x <= high.x(); ++x) {
          const Eigen::Vector3d n = origin_ + cell * Eigen::Vector3d(x, y, z);
          const auto d2 = static_cast<float>((n - s).squaredNorm());
          float& kept = squared[(static_cast<std::size_t>(z) * size_.y() + y) * size_.x() + x];
          kept = std::min(kept, d2);
        }
      }
    }
  }
  nodes_.resize(squared.size());
  for (std::size_t i = 0; i < squared.size(); ++i) {
    const double d = std::min(truncation, std::sqrt(static_cast<double>(squared[i])));
    nodes_[i] = static_cast<std::uint16_t>(std::lround(d / truncation * kLevels));
  }
}

double TruncatedDistanceField::node(int x, int y, int z) const {
  return nodes_[(static_cast<std::size_t>(z) * size_.y() + y) * size_.x() + x] * truncation_ /
         kLevels;
}

double TruncatedDistanceField::distance(const Eigen::Vector3f& p) const {
  const Eigen::Vector3d g = (p.cast<double>() - origin_) / cell_;
  if (!g.allFinite()) return truncation_;
  Eigen::Vector3i i;
  Eigen::Vector3d f;
  for (int a = 0; a < 3; ++a) {
    if (!(g[a] >= 0.0) || g[a] >= size_[a] - 1) return truncation_;  // off the grid
    i[a] = static_cast<int>(g[a]);
    f[a] = g[a] - i[a];
  }
  const auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double c00 = lerp(node(i.x(), i.y(), i.z()), node(i.x() + 1, i.y(), i.z()), f.x());
  const double c10 = lerp(node(i.x(), i.y() + 1, i.z()), node(i.x() + 1, i.y() + 1, i.z()), f.x());
  const double c01 = lerp(node(i.x(), i.y(), i.z() + 1), node(i.x() + 1, i.y(), i.z() + 1), f.x());
  const double c11 =
      lerp(node(i.x(), i.y() + 1, i.z() + 1), node(i.x() + 1, i.y() + 1, i.z() + 1), f.x());
  return lerp(lerp(c00, c10, f.y()), lerp(c01, c11, f.y()), f.z());
}

}  // namespace vdc

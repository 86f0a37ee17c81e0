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
    : truncation_(truncation), cell_(cell), samples_(samples) {
  if (!(truncation > 0.0) || !std::isfinite(truncation) || !(cell > 0.0) || !std::isfinite(cell)) {
    throw Error("a distance field needs a positive, finite truncation and cell");
  }
  if (samples.size() >= kNoSample) throw Error("a distance field takes fewer than 2^32 samples");
  origin_ = bounds.min() - Eigen::Vector3d::Constant(truncation + cell);
  const Eigen::Vector3d extent =
      bounds.sizes() + Eigen::Vector3d::Constant(2.0 * (truncation + cell));
  for (int a = 0; a < 3; ++a) size_[a] = static_cast<int>(std::ceil(extent[a] / cell)) + 1;
  // Squared distances first, then quantised: each sample lowers the nodes within its reach.
  const double reach_distance = truncation + cell * std::sqrt(3.0);
  std::vector<float> squared(static_cast<std::size_t>(size_.prod()),
                             static_cast<float>(reach_distance * reach_distance));
  nearest_.assign(squared.size(), kNoSample);
  const int reach = static_cast<int>(std::ceil(reach_distance / cell));
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Eigen::Vector3d s = samples[k].cast<double>();
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
          const std::size_t i = nodeIndex(x, y, z);
          if (d2 < squared[i]) {  // strictly: of equally near samples the first is kept
            squared[i] = d2;
            nearest_[i] = static_cast<std::uint32_t>(k);
          }
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

void TruncatedDistanceField::nearest(const std::vector<Eigen::Vector3f>& queries,
                                     std::vector<int>* indices,
                                     std::vector<float>* squared_distances,
                                     double max_distance) const {
  if (!(max_distance <= truncation_)) {
    throw Error("a distance field answers nearest-sample questions within its truncation only");
  }
  indices->assign(queries.size(), -1);
  squared_distances->assign(queries.size(), std::numeric_limits<float>::infinity());
  const auto max_squared = static_cast<float>(max_distance * max_distance);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const Eigen::Vector3d g = (queries[q].cast<double>() - origin_) / cell_;
    Eigen::Vector3i i;
    bool on_grid = true;
    for (int a = 0; a < 3 && on_grid; ++a) {
      on_grid = g[a] >= 0.0 && g[a] < size_[a] - 1;  // false for NaN too
      if (on_grid) i[a] = static_cast<int>(g[a]);
    }
    if (!on_grid) continue;  // farther than the truncation from every sample
    std::uint32_t best = kNoSample, last = kNoSample;
    float best_squared = max_squared;
    for (int corner = 0; corner < 8; ++corner) {
      const std::uint32_t sample = nearest_[nodeIndex(
          i.x() + (corner & 1), i.y() + ((corner >> 1) & 1), i.z() + ((corner >> 2) & 1))];
      if (sample == kNoSample || sample == last) continue;
      last = sample;
      const float d2 = (samples_[sample] - queries[q]).squaredNorm();
      if (d2 < best_squared || (d2 == best_squared && best != kNoSample && sample < best)) {
        best = sample;
        best_squared = d2;
      }
    }
    if (best == kNoSample) continue;
    (*indices)[q] = static_cast<int>(best);
    (*squared_distances)[q] = best_squared;
  }
}

double TruncatedDistanceField::node(int x, int y, int z) const {
  return nodes_[nodeIndex(x, y, z)] * truncation_ / kLevels;
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

#include "view_direction_classification/evaluation/depth_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vdc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kLevelWindow = 0.05;   // +- relative to the median depth
constexpr double kFlyingMargin = 0.15;  // of the jump, from either side
// An edge site's jump [relative to z]: larger than the edges', so that 15 % of it stays above
// the stereo model's depth noise (2.7 mm at 0.85 m) and noise alone makes no flying pixel.
constexpr double kSiteJumpRatio = 0.05;

bool measured(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.z != 0.0f;
}

// The depth along the optical axis. |z|: PCL's Kinect scans of the milk carton look along -z.
float depthOf(const pcl::PointXYZ& p) { return std::abs(p.z); }

double median(std::vector<double> values) {
  if (values.empty()) return kNaN;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Distinct depths near the median and their median step in 1/z.
void depthLevels(const std::vector<float>& depths, DepthStatistics* s) {
  std::vector<float> window;
  for (float z : depths) {
    if (std::abs(z - s->median_depth) <= kLevelWindow * s->median_depth) window.push_back(z);
  }
  std::sort(window.begin(), window.end());
  window.erase(std::unique(window.begin(), window.end()), window.end());
  const double range_cm = 2.0 * kLevelWindow * s->median_depth * 100.0;
  s->levels_per_cm = static_cast<double>(window.size()) / range_cm;
  std::vector<double> steps;
  for (std::size_t i = 1; i < window.size(); ++i) {
    steps.push_back((1.0 / window[i - 1] - 1.0 / window[i]) *
                    DepthStatistics::kKinectFocalBaseline);
  }
  s->disparity_step_px = median(std::move(steps));
}

bool isJump(float a, float b) {
  return std::abs(a - b) > DepthStatistics::kEdgeJumpRatio * std::min(a, b);
}

// Depths of five consecutive pixels of a row, the middle one the candidate.
struct RowWindow {
  float outer_left, left, middle, right, outer_right;
};

// An edge site: a depth jump across the middle pixel with a flat surface on either side. The flat
// sides tell an edge from a steep slope (a surface seen at a grazing angle), whose depths step
// evenly. A sharp edge gives two sites (the middle on either side of it), a flying pixel one.
bool isEdgeSite(const RowWindow& w) {
  if (std::abs(w.left - w.right) <= kSiteJumpRatio * std::min(w.left, w.right)) return false;
  const float margin = static_cast<float>(kFlyingMargin) * std::abs(w.right - w.left);
  return std::abs(w.outer_left - w.left) < margin && std::abs(w.outer_right - w.right) < margin;
}

// At an edge site: the middle pixel lies between the two surfaces, a mixture of both.
bool isFlying(const RowWindow& w) {
  const float margin = static_cast<float>(kFlyingMargin) * std::abs(w.right - w.left);
  return w.middle > std::min(w.left, w.right) + margin &&
         w.middle < std::max(w.left, w.right) - margin;
}

// Row counts of the edge figures.
struct EdgeCounts {
  std::size_t edges = 0, edges_with_gap = 0, flat = 0, flat_with_gap = 0, sites = 0, flying = 0;
};

void countRow(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::uint32_t row, EdgeCounts* c) {
  int previous = -1;
  const int width = static_cast<int>(cloud.width);
  const auto at = [&](int col) { return cloud.at(static_cast<std::uint32_t>(col), row); };
  const auto z = [&](int col) { return depthOf(at(col)); };
  const auto allMeasured = [&](int first, int last) {
    for (int col = first; col <= last; ++col) {
      if (!measured(at(col))) return false;
    }
    return true;
  };
  for (int col = 0; col < width; ++col) {
    if (!measured(at(col))) continue;
    if (previous >= 0 && col - previous - 1 <= DepthStatistics::kMaxEdgeGap) {
      const bool gap = col - previous > 1;
      if (isJump(z(previous), z(col))) {
        ++c->edges;
        c->edges_with_gap += gap;
      } else {
        ++c->flat;
        c->flat_with_gap += gap;
      }
    }
    if (col >= 2 && col + 2 < width && allMeasured(col - 2, col + 2)) {
      const RowWindow window{z(col - 2), z(col - 1), z(col), z(col + 1), z(col + 2)};
      if (isEdgeSite(window)) {
        ++c->sites;
        c->flying += isFlying(window);
      }
    }
    previous = col;
  }
}

double ratio(std::size_t part, std::size_t whole) {
  return whole == 0 ? kNaN : static_cast<double>(part) / static_cast<double>(whole);
}

void edgeFigures(const pcl::PointCloud<pcl::PointXYZ>& cloud, DepthStatistics* s) {
  if (!cloud.isOrganized()) {
    s->edge_gap_fraction = s->flat_gap_fraction = s->flying_fraction = kNaN;
    return;
  }
  EdgeCounts counts;
  for (std::uint32_t row = 0; row < cloud.height; ++row) countRow(cloud, row, &counts);
  s->depth_edges = counts.edges;
  s->edge_gap_fraction = ratio(counts.edges_with_gap, counts.edges);
  s->flat_gap_fraction = ratio(counts.flat_with_gap, counts.flat);
  s->flying_fraction = ratio(counts.flying, counts.sites);
}

}  // namespace

DepthStatistics depthStatistics(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  DepthStatistics s;
  std::vector<float> depths;
  for (const pcl::PointXYZ& p : cloud) {
    if (measured(p)) depths.push_back(depthOf(p));
  }
  s.points = depths.size();
  if (depths.empty()) {
    s.median_depth = s.levels_per_cm = s.disparity_step_px = kNaN;
    s.edge_gap_fraction = s.flat_gap_fraction = s.flying_fraction = kNaN;
    return s;
  }
  s.median_depth = median(std::vector<double>(depths.begin(), depths.end()));
  depthLevels(depths, &s);
  edgeFigures(cloud, &s);
  return s;
}

}  // namespace vdc

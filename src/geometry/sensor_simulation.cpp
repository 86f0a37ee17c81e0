#include "view_direction_classification/geometry/sensor_simulation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// A depth image with its size; 0 = no depth.
class DepthImage {
 public:
  DepthImage(const std::vector<float>& depth, int width, int height)
      : depth_(depth), width_(width), height_(height) {}

  float at(int col, int row) const { return depth_[static_cast<std::size_t>(row) * width_ + col]; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const std::vector<float>& depth_;
  int width_, height_;
};

// Nearest and farthest depth within `band` pixels of (col, row); `empty` is set when that
// window holds a pixel without depth (inside the image).
struct Neighbourhood {
  float nearest, farthest;
  bool empty;
};

Neighbourhood neighbourhood(const DepthImage& image, int col, int row, int band) {
  Neighbourhood n{image.at(col, row), image.at(col, row), false};
  for (int r = std::max(0, row - band); r <= std::min(image.height() - 1, row + band); ++r) {
    for (int c = std::max(0, col - band); c <= std::min(image.width() - 1, col + band); ++c) {
      const float z = image.at(c, r);
      if (!(z > 0.0f)) {
        n.empty = true;
        continue;
      }
      n.nearest = std::min(n.nearest, z);
      n.farthest = std::max(n.farthest, z);
    }
  }
  return n;
}

// A pixel is on a depth edge when its window has an empty pixel or a depth jump beyond
// edge_jump_ratio * z: a structured-light or stereo matcher loses such pixels (its correlation
// window straddles two surfaces), a time-of-flight pixel mixes them.
bool onEdge(const Neighbourhood& n, float z, const SensorModel& model) {
  const float jump = static_cast<float>(model.edge_jump_ratio) * z;
  return n.empty || z - n.nearest > jump || n.farthest - z > jump;
}

// True when the projector at (baseline, 0, 0) sees something closer than the pixel's own point
// along its ray. The projector shares the camera's rows (a pure x offset), so only the column
// moves; both columns around the projection must be closer, so that rounding at the point's
// own silhouette does not count as a shadow.
bool inShadow(const DepthImage& projector, const CameraIntrinsics& c, const SensorModel& model,
              int col, int row, float z) {
  const double x = (col - c.cx) * z / c.fx;
  const double u = c.fx * (x - model.baseline) / z + c.cx;
  const int left = static_cast<int>(std::floor(u));
  if (left < 0 || left + 1 >= projector.width()) return false;  // outside: cannot tell
  const float tolerance = static_cast<float>(model.edge_jump_ratio) * z;
  for (int column : {left, left + 1}) {
    const float seen = projector.at(column, row);
    if (!(seen > 0.0f) || seen > z - tolerance) return false;
  }
  return true;
}

// Depth measured through a disparity d = f b / z with Gaussian noise, quantised to the device's
// subpixel step; 0 when the disparity is not positive.
float disparityDepth(const SensorModel& m, float z, std::mt19937& rng) {
  const double fb = m.disparity_focal_px * m.baseline;
  double d = fb / z;
  if (m.disparity_sigma_px > 0.0) {
    d += m.disparity_sigma_px * std::normal_distribution<double>(0.0, 1.0)(rng);
  }
  if (m.disparity_step_px > 0.0) d = std::round(d / m.disparity_step_px) * m.disparity_step_px;
  return d > 0.0 ? static_cast<float>(fb / d) : 0.0f;
}

float axialDepth(const SensorModel& m, float z, std::mt19937& rng) {
  const double sigma = m.axial_sigma_m + m.axial_sigma_per_m2 * z * z;
  return static_cast<float>(z + sigma * std::normal_distribution<double>(0.0, 1.0)(rng));
}

// The edge effects of one pixel on edge: lost, mixed with its background, or kept.
float edgeDepth(const SensorModel& m, const Neighbourhood& n, float z, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (m.edge_dropout > 0.0 && uniform(rng) < m.edge_dropout) return 0.0f;
  if (m.flying_pixel > 0.0 && uniform(rng) < m.flying_pixel) {
    if (n.empty) return 0.0f;  // mixed with nothing: too dim a return
    return static_cast<float>(n.nearest + uniform(rng) * (n.farthest - n.nearest));
  }
  return z;
}

void checkImage(const std::vector<float>& image, const CameraIntrinsics& c, const char* name) {
  const std::size_t expected = static_cast<std::size_t>(c.width) * c.height;
  if (image.size() != expected) {
    throw Error(std::string("sensor simulation: the ") + name + " image has " +
                std::to_string(image.size()) + " pixels, the camera " + std::to_string(expected));
  }
}

}  // namespace

std::vector<float> simulateSensor(const SensorModel& model, const CameraIntrinsics& intrinsics,
                                  const std::vector<float>& depth,
                                  const std::vector<float>& projector_depth, std::mt19937& rng) {
  checkSensorModel(model);
  checkIntrinsics(intrinsics);
  checkImage(depth, intrinsics, "depth");
  if (model.shadows) checkImage(projector_depth, intrinsics, "projector depth");
  const DepthImage image(depth, intrinsics.width, intrinsics.height);
  const DepthImage projector(projector_depth, model.shadows ? intrinsics.width : 0,
                             model.shadows ? intrinsics.height : 0);
  const bool disparity = model.disparity_sigma_px > 0.0 || model.disparity_step_px > 0.0;
  const bool axial = model.axial_sigma_m > 0.0 || model.axial_sigma_per_m2 > 0.0;
  const bool edges = model.edge_dropout > 0.0 || model.flying_pixel > 0.0;

  std::vector<float> measured(depth.size(), 0.0f);
  for (int row = 0; row < intrinsics.height; ++row) {
    for (int col = 0; col < intrinsics.width; ++col) {
      float z = image.at(col, row);
      if (!(z > 0.0f)) continue;
      if (model.shadows && inShadow(projector, intrinsics, model, col, row, z)) continue;
      if (edges) {
        const Neighbourhood n = neighbourhood(image, col, row, model.edge_band_px);
        if (onEdge(n, z, model)) z = edgeDepth(model, n, z, rng);
        if (!(z > 0.0f)) continue;
      }
      if (disparity) z = disparityDepth(model, z, rng);
      if (axial) z = axialDepth(model, z, rng);
      measured[static_cast<std::size_t>(row) * intrinsics.width + col] = std::max(z, 0.0f);
    }
  }
  return measured;
}

}  // namespace vdc

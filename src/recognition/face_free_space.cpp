#include "face_free_space.h"

#include <algorithm>
#include <cmath>

#include "seen_through.h"

namespace vdc {
namespace {

// The q-quantile (0..1) of `values` (not empty); reorders them.
float quantile(std::vector<float>* values, double q) {
  const std::size_t k = static_cast<std::size_t>(q * static_cast<double>(values->size() - 1));
  std::nth_element(values->begin(), values->begin() + k, values->end());
  return (*values)[k];
}

// [fit units] No finer than this: the scene's rays are matched within 4 mm (seenThrough).
constexpr float kMinCellMetres = 0.004f;
// The extent's ends are the 1st and 99th percentiles: one stray inlier does not widen the face.
constexpr double kExtentQuantile = 0.01;

}  // namespace

FaceJudgement judgeFaceRectangle(const std::vector<Eigen::Vector3f>& face_points,
                                 const Eigen::Vector3f& normal, const Eigen::Vector3f& up,
                                 float scale, const SceneDepth& scene, double free_space_tolerance,
                                 int max_samples) {
  FaceJudgement judgement;
  if (face_points.size() < 3 || scene.empty() || max_samples <= 0 || !(scale > 0.0f)) {
    return judgement;
  }
  // An orthonormal frame: RANSAC's normal may lean a few degrees off square to up.
  const Eigen::Vector3f square = (normal - normal.dot(up) * up).normalized();
  if (!square.allFinite()) return judgement;
  const Eigen::Vector3f across = up.cross(square);
  std::vector<float> offsets, widths, heights;
  for (const Eigen::Vector3f& p : face_points) {
    offsets.push_back(square.dot(p));
    widths.push_back(across.dot(p));
    heights.push_back(up.dot(p));
  }
  const float left = quantile(&widths, kExtentQuantile);
  const float right = quantile(&widths, 1.0 - kExtentQuantile);
  const float bottom = quantile(&heights, kExtentQuantile);
  const float top = quantile(&heights, 1.0 - kExtentQuantile);
  const float width = right - left, height = top - bottom;
  if (!(width > 0.0f) || !(height > 0.0f)) return judgement;
  const float cell =
      std::max(kMinCellMetres * scale, std::sqrt(width * height / static_cast<float>(max_samples)));
  const int columns = std::max(1, static_cast<int>(width / cell));
  const int rows = std::max(1, static_cast<int>(height / cell));
  // The face's plane through the origin of the (across, up) coordinates.
  const Eigen::Vector3f origin = quantile(&offsets, 0.5) * square;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const float u = left + (static_cast<float>(column) + 0.5f) * width / columns;
      const float v = bottom + (static_cast<float>(row) + 0.5f) * height / rows;
      const Eigen::Vector3f sample = (origin + u * across + v * up) / scale;
      ++judgement.samples;
      if (seenThrough(scene, sample, free_space_tolerance)) ++judgement.seen_through;
    }
  }
  return judgement;
}

}  // namespace vdc

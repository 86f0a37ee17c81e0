#include "view_direction_classification/bop/bop_vsd.h"

#include <cmath>
#include <string>

#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// The rendering's depth [mm] per pixel, 0 where the model is not seen.
std::vector<double> renderedDepthMm(const DepthRenderer& renderer, const BopPose& pose) {
  const std::vector<float> depth_m = renderer.renderDepth(isometryOf(pose));
  std::vector<double> depth_mm(depth_m.size());
  for (std::size_t i = 0; i < depth_m.size(); ++i) depth_mm[i] = depth_m[i] * kMillimetresPerMetre;
  return depth_mm;
}

// Visible: rendered, and the image's surface is not more than delta in front of it (a missing
// measurement hides nothing).
bool visible(double rendered, double measured, double delta) {
  return rendered > 0.0 && (measured <= 0.0 || measured - rendered >= -delta);
}

}  // namespace

std::vector<double> visibleSurfaceDiscrepancy(const BopPose& estimate, const BopPose& truth,
                                              const DepthRenderer& renderer,
                                              const BopDepthImage& image, double depth_scale,
                                              const std::vector<double>& taus, double delta) {
  const CameraIntrinsics& k = renderer.intrinsics();
  if (image.width != k.width || image.height != k.height) {
    throw Error("VSD: the depth image is " + std::to_string(image.width) + " x " +
                std::to_string(image.height) + ", the renderer's camera " +
                std::to_string(k.width) + " x " + std::to_string(k.height));
  }
  const std::vector<double> d_est = renderedDepthMm(renderer, estimate);
  const std::vector<double> d_gt = renderedDepthMm(renderer, truth);
  std::vector<int> union_count(taus.size(), 0), cost(taus.size(), 0);
  for (std::size_t i = 0; i < d_gt.size(); ++i) {
    const double measured = image.values[i] * depth_scale;
    const bool gt_visible = visible(d_gt[i], measured, delta);
    const bool est_visible = visible(d_est[i], measured, delta) || (gt_visible && d_est[i] > 0.0);
    if (!gt_visible && !est_visible) continue;
    for (std::size_t t = 0; t < taus.size(); ++t) {
      ++union_count[t];
      const bool both = gt_visible && est_visible;
      if (!both || std::abs(d_est[i] - d_gt[i]) >= taus[t]) ++cost[t];
    }
  }
  std::vector<double> errors;
  for (std::size_t t = 0; t < taus.size(); ++t) {
    errors.push_back(union_count[t] == 0 ? 1.0 : static_cast<double>(cost[t]) / union_count[t]);
  }
  return errors;
}

std::vector<double> vsdTaus(double diameter) {
  std::vector<double> taus;
  for (int i = 1; i <= 10; ++i) taus.push_back(0.05 * i * diameter);
  return taus;
}

std::vector<double> vsdCorrectThresholds() {
  std::vector<double> thresholds;
  for (int i = 1; i <= 10; ++i) thresholds.push_back(0.05 * i);
  return thresholds;
}

}  // namespace vdc

#pragma once

// Where on the model's visible part an observed centroid may lie (private to refinement;
// doc/method.md, "Refinement"): a start is placed by putting the centroid of what the camera
// would see of the model onto the observed centroid. That is right for a whole view, but a piece
// of an object (cut off by the segmentation at a concave edge, or the rest hidden) has its
// centroid somewhere on the visible part, up to half the object's size from its centroid: more
// than ICP reaches. So a piece's starts are also placed at patches of the visible part.

#include <Eigen/Geometry>

#include <utility>
#include <vector>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

// The samples (object frame) a camera at `camera` (object frame) sees: a z-buffer of the samples
// facing it over angular cells about two sample spacings wide, the nearest sample per cell.
std::vector<Eigen::Vector3d> visibleSamples(const ModelSurface& surface,
                                            const Eigen::Vector3d& camera);

// The root mean square distance of the points from their centroid (0 for none).
double rmsRadius(const std::vector<Eigen::Vector3d>& points);

// Where an observation of RMS radius observed_rms [m] may be centred on the visible samples:
// first the centroid of them all; then, when the observation spreads less than partial_ratio of
// the visible part's RMS radius, the centroids of up to max_patches patches of the visible part
// as large as the observation (samples within sqrt(2) observed_rms of a seed: a flat patch's
// radius), seeded by farthest-point sampling so that they cover it. Empty without samples.
std::vector<Eigen::Vector3d> placementAnchors(const std::vector<Eigen::Vector3d>& visible,
                                              double observed_rms, double partial_ratio,
                                              int max_patches);

// placementAnchors() remembered per camera position: the starts along a girdle differ by a roll
// about the line of sight, which leaves the camera (nearly) where it was in the object frame, so
// a girdle's starts share one z-buffer instead of each paying for its own.
class VisibleParts {
 public:
  VisibleParts(const ModelSurface& surface, double observed_rms, double partial_ratio,
               int max_patches);
  // The anchors (object frame) for a camera at `camera` (object frame).
  const std::vector<Eigen::Vector3d>& anchors(const Eigen::Vector3d& camera);

 private:
  const ModelSurface& surface_;
  double observed_rms_, partial_ratio_;
  int max_patches_;
  std::vector<std::pair<Eigen::Vector3d, std::vector<Eigen::Vector3d>>> known_;
};

}  // namespace vdc

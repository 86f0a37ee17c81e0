#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/recognition/instance_explanation.h"

namespace vdc {

// Segmentation cuts a concave object at its creases (a spool lying on its side: the near
// flange, the core behind it), and a piece alone can be a simple shape that the object is not: a
// flange's face is a disc, a can's top. Judged on that piece, the shape alternative
// (shape_alternative.h) takes nearly all the evidence from the right model. Once a piece is
// identified, the pieces beside it that the identified pose explains are the object too, and
// the alternative is judged on them together (SceneEstimator::identify).

// A candidate's points as the scene layer holds them: camera frame, and the same in the fixed
// frame.
struct PieceView {
  const pcl::PointCloud<pcl::PointXYZ>* points = nullptr;
  const std::vector<Eigen::Vector3f>* points_world = nullptr;
};

// `piece`'s points joined by those of each of `others` that the model placed at
// world_from_object explains as a part: at least min_fraction of its points within tolerance [m]
// of the model's surface (InstanceExplanation). *joined counts the pieces that joined.
pcl::PointCloud<pcl::PointXYZ> withExplainedPieces(const pcl::PointCloud<pcl::PointXYZ>& piece,
                                                   const std::vector<PieceView>& others,
                                                   const InstanceExplanation& explanation,
                                                   const Eigen::Isometry3d& world_from_object,
                                                   double tolerance, double min_fraction,
                                                   int* joined);

}  // namespace vdc

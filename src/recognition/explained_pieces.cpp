#include "explained_pieces.h"

namespace vdc {

pcl::PointCloud<pcl::PointXYZ> withExplainedPieces(const pcl::PointCloud<pcl::PointXYZ>& piece,
                                                   const std::vector<PieceView>& others,
                                                   const InstanceExplanation& explanation,
                                                   const Eigen::Isometry3d& world_from_object,
                                                   double tolerance, double min_fraction,
                                                   int* joined) {
  pcl::PointCloud<pcl::PointXYZ> points = piece;
  *joined = 0;
  for (const PieceView& other : others) {
    if (!explanation.explainsPart(*other.points_world, world_from_object, tolerance,
                                  min_fraction)) {
      continue;
    }
    points += *other.points;
    ++*joined;
  }
  return points;
}

}  // namespace vdc

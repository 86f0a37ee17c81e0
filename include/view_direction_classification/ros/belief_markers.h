#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vdc {

// rviz markers of an orientation belief at `position` (in header.frame_id):
// - namespace "<ns>/map": three ARROW markers (ids 0, 1, 2), the MAP orientation's x, y, z axes
//   in red, green, blue, `length` long;
// - namespace "<ns>/samples": one LINE_LIST (id 0) with an axes triad per sampled orientation,
//   0.8 * length long, thin and translucent, so the spread of the triads shows the uncertainty
//   (omitted when there are no samples).
// Orientations are unit quaternions (w, x, y, z). Fixed ids: each array replaces the previous one.
visualization_msgs::MarkerArray makeBeliefMarkers(const std_msgs::Header& header,
                                                  const std::string& ns,
                                                  const Eigen::Vector3d& position,
                                                  const Eigen::Vector4d& map_orientation,
                                                  const std::vector<Eigen::Vector4d>& samples,
                                                  double length);

// One DELETEALL marker: clears what makeBeliefMarkers drew (after a reset).
visualization_msgs::MarkerArray makeClearMarkers(const std_msgs::Header& header);

}  // namespace vdc

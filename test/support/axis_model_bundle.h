#pragma once

#include <Eigen/Core>

#include <memory>

#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc::test {

// Six training directions +x, -x, +y, -y, +z, -z (indices 0..5) and four surface points:
// two on the +x face, one on the -x face, one on the +z face. Only +x and -x have valid scores
// for their own points; +z (view 4) observed nothing; view 5 (-z) has no training data.
inline std::shared_ptr<ModelBundle> makeAxisBundle() {
  auto bundle = std::make_shared<ModelBundle>();
  bundle->view_directions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  bundle->surface_points = {{0.05f, 0.01f, 0}, {0.05f, -0.01f, 0}, {-0.05f, 0, 0}, {0, 0, 0.05f}};
  bundle->surface_normals = {{1, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}};
  bundle->score_matrix = Eigen::MatrixXf::Constant(4, 6, -1.0f);
  bundle->score_matrix(0, 0) = 1.0f;
  bundle->score_matrix(1, 0) = 3.0f;
  bundle->score_matrix(2, 1) = 0.5f;
  bundle->view_informativeness.view_scores = Eigen::VectorXd::Constant(6, 2.0);
  bundle->view_informativeness.view_scores(4) = 1.25;
  bundle->view_informativeness.view_scores(5) = -1.0;
  bundle->view_informativeness.confusion = Eigen::MatrixXd::Identity(6, 6);
  return bundle;
}

// A concentrated Bingham distribution whose mode is q.
inline BinghamDistribution sharpAround(const Eigen::Vector4d& q) {
  BinghamDistribution::Axes axes;  // rows w, x, y, z: the mode (identity) is the fourth direction
  axes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return BinghamDistribution(Eigen::Vector3d::Constant(-100), axes).rotated(q);
}

}  // namespace vdc::test

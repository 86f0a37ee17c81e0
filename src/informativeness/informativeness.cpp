#include "view_direction_classification/informativeness/informativeness.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
double viewKlDivergence(const Eigen::VectorXd& p_sum, int true_view) {
  if (true_view < 0 || true_view >= p_sum.size()) {
    throw Error("view informativeness: true view " + std::to_string(true_view) +
                " is outside the summed distribution of " + std::to_string(p_sum.size()) +
                " views");
  }
  const double p = p_sum(true_view);
  if (!std::isfinite(p) || p < 0.0) {
    throw Error("view informativeness: the summed distribution has an invalid probability " +
                std::to_string(p) + " at view " + std::to_string(true_view));
  }
  return flooredNegativeLog(p);
}

ViewInformativeness computeViewInformativeness(const std::vector<CloudPrediction>& clouds,
                                               int num_views) {
  if (num_views < 1) {
    throw Error("view informativeness: the number of views must be at least 1, got " +
                std::to_string(num_views));
  }
  Eigen::VectorXd score_sum = Eigen::VectorXd::Zero(num_views);
  Eigen::VectorXi count = Eigen::VectorXi::Zero(num_views);
  Eigen::MatrixXd confusion_sum = Eigen::MatrixXd::Zero(num_views, num_views);
  for (std::size_t c = 0; c < clouds.size(); ++c) {
    const CloudPrediction& cloud = clouds[c];
    if (cloud.p_sum.size() != num_views) {
      throw Error("view informativeness: cloud " + std::to_string(c) + " has a distribution over " +
                  std::to_string(cloud.p_sum.size()) + " views, expected " +
                  std::to_string(num_views));
    }
    if (!cloud.p_sum.allFinite()) {
      throw Error("view informativeness: cloud " + std::to_string(c) +
                  " has a non-finite summed distribution");
    }
    const double kl = viewKlDivergence(cloud.p_sum, cloud.true_view);  // also checks true_view
    score_sum(cloud.true_view) += kl;
    ++count(cloud.true_view);
    confusion_sum.row(cloud.true_view) += cloud.p_sum.transpose();
  }

  ViewInformativeness result;
  result.view_scores = Eigen::VectorXd::Constant(num_views, -1.0);
  result.confusion = Eigen::MatrixXd::Constant(num_views, num_views, 1.0 / num_views);
  for (int m = 0; m < num_views; ++m) {
    if (count(m) == 0) continue;
    result.view_scores(m) = score_sum(m) / count(m);
    result.confusion.row(m) = confusion_sum.row(m) / count(m);
    result.ranking.push_back(m);
  }
  std::stable_sort(result.ranking.begin(), result.ranking.end(),
                   [&](int a, int b) { return result.view_scores(a) < result.view_scores(b); });
  return result;
}

Eigen::MatrixXf computeScoreMatrix(const std::vector<Eigen::Vector3f>& surface_points,
                                   const LabelledFeatureScores& features, int num_views,
                                   double radius) {
  if (num_views < 1) {
    throw Error("surface informativeness: the number of views must be at least 1, got " +
                std::to_string(num_views));
  }
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw Error("surface informativeness: the score radius must be a positive length, got " +
                std::to_string(radius));
  }
  const std::size_t count = features.positions.size();
  if (static_cast<std::size_t>(features.views.size()) != count ||
      static_cast<std::size_t>(features.kl.size()) != count) {
    throw Error("surface informativeness: " + std::to_string(count) + " feature positions but " +
                std::to_string(features.views.size()) + " views and " +
                std::to_string(features.kl.size()) + " scores");
  }
  for (std::size_t f = 0; f < count; ++f) {
    const int view = features.views(static_cast<Eigen::Index>(f));
    const float kl = features.kl(static_cast<Eigen::Index>(f));
    if (view < 0 || view >= num_views) {
      throw Error("surface informativeness: feature " + std::to_string(f) + " has view " +
                  std::to_string(view) + ", outside [0, " + std::to_string(num_views) + ")");
    }
    if (!std::isfinite(kl) || kl < 0.0f || !features.positions[f].allFinite()) {
      throw Error("surface informativeness: feature " + std::to_string(f) +
                  " has a non-finite position or an invalid score");
    }
  }
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    if (!surface_points[i].allFinite()) {
      throw Error("surface informativeness: surface point " + std::to_string(i) + " is not finite");
    }
  }

  const Eigen::Index n = static_cast<Eigen::Index>(surface_points.size());
  Eigen::MatrixXf K = Eigen::MatrixXf::Constant(n, num_views, -1.0f);
  if (count == 0 || n == 0) return K;

  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(count);
  for (const auto& p : features.positions) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);

  // FLANN's radius test is strict and in float; search slightly wider and decide membership here
  // in double, so "within radius" means distance <= radius exactly.
  const double radius_squared = radius * radius;
  const double search_radius = radius * (1.0 + 1e-4);
#pragma omp parallel
  {
    std::vector<int> indices;
    std::vector<float> squared_distances;
    Eigen::VectorXd sums(num_views);
    Eigen::VectorXi counts(num_views);
#pragma omp for schedule(dynamic, 64)
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3f& s = surface_points[static_cast<std::size_t>(i)];
      tree.radiusSearch(pcl::PointXYZ(s.x(), s.y(), s.z()), search_radius, indices,
                        squared_distances);
      sums.setZero();
      counts.setZero();
      for (int f : indices) {
        const double d2 =
            (features.positions[static_cast<std::size_t>(f)].cast<double>() - s.cast<double>())
                .squaredNorm();
        if (d2 > radius_squared) continue;
        sums(features.views(f)) += features.kl(f);
        ++counts(features.views(f));
      }
      for (int m = 0; m < num_views; ++m) {
        if (counts(m) > 0) K(i, m) = static_cast<float>(sums(m) / counts(m));
      }
    }
  }
  return K;
}

Eigen::VectorXf globalScores(const Eigen::MatrixXf& K) {
  Eigen::VectorXf g = Eigen::VectorXf::Constant(K.rows(), -1.0f);
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    double sum = 0.0;
    int valid = 0;
    for (Eigen::Index m = 0; m < K.cols(); ++m) {
      if (K(i, m) >= 0.0f) {
        sum += K(i, m);
        ++valid;
      }
    }
    if (valid > 0) g(i) = static_cast<float>(sum / valid);
  }
  return g;
}

}  // namespace vdc

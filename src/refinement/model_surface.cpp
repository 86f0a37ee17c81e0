#include "view_direction_classification/refinement/model_surface.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "distance_field.h"
#include "half_turn_axes.h"
#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

// The point c that puts the line (c, d) closest to being the surface's axis of revolution: on a
// surface of revolution about it, every normal n at p meets the line, n . (d x (p - c)) = 0, i.e.
// (p - c) . w = 0 with w = n x d; least squares in c across d (the part along d is the
// centroid's, which the condition leaves free).
Eigen::Vector3d axisPoint(const pcl::PointCloud<pcl::PointNormal>& samples,
                          const Eigen::Vector3d& centroid, const Eigen::Vector3d& d) {
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (const auto& sample : samples.points) {
    const Eigen::Vector3d p = sample.getVector3fMap().cast<double>() - centroid;
    const Eigen::Vector3d w = sample.getNormalVector3fMap().cast<double>().cross(d);
    normal_matrix += w * w.transpose();
    right += w * p.dot(w);
  }
  // w is orthogonal to d, so the system is singular along d: regularise it there.
  normal_matrix += d * d.transpose() * (normal_matrix.trace() + 1e-12);
  return centroid + normal_matrix.ldlt().solve(right);
}

// The axes of (near) rotational symmetry: a surface of revolution about direction d through c
// has every (p - c) x n orthogonal to d, so d is the eigenvector of the smallest eigenvalue of
// the sum of their outer products; the other two eigenvectors are the next best. Unlike the
// samples' principal axes, which a mug's handle tilts by 10 degrees off the body's axis, the
// body's normals fix this one, and it is placed through its best point; the other two only
// start the search for the half turns' axes that replace them (symmetryAxes()), so they are left
// through the centroid.
std::vector<Eigen::ParametrizedLine<double, 3>> nearSymmetryAxes(
    const pcl::PointCloud<pcl::PointNormal>& samples) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& sample : samples.points) centroid += sample.getVector3fMap().cast<double>();
  centroid /= static_cast<double>(samples.size());
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (const auto& sample : samples.points) {
    const Eigen::Vector3d m = (sample.getVector3fMap().cast<double>() - centroid)
                                  .cross(sample.getNormalVector3fMap().cast<double>());
    moments += m * m.transpose();
  }
  const Eigen::Matrix3d directions =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moments).eigenvectors();
  std::vector<Eigen::ParametrizedLine<double, 3>> axes;
  axes.emplace_back(axisPoint(samples, centroid, directions.col(0)), directions.col(0));
  for (int i = 1; i < 3; ++i) axes.emplace_back(centroid, directions.col(i));
  return axes;
}

}  // namespace

ModelSurface::ModelSurface(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<Eigen::Vector3f>& normals,
                           const Eigen::AlignedBox3d& bounds, double source_spacing, double spacing)
    : cloud_(new pcl::PointCloud<pcl::PointNormal>), bounds_(bounds) {
  if (points.size() != normals.size()) {
    throw Error("the model surface has " + std::to_string(points.size()) + " points but " +
                std::to_string(normals.size()) + " normals");
  }
  if (points.size() < 10) {
    throw Error("the model surface needs at least 10 samples to refine against, got " +
                std::to_string(points.size()));
  }
  if (bounds.isEmpty() || !bounds.min().allFinite() || !bounds.max().allFinite()) {
    throw Error("the model surface needs a non-empty, finite extent");
  }
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(source_spacing > 0.0) ||
      !std::isfinite(source_spacing)) {
    throw Error("the model surface's spacings must be positive and finite, got " +
                std::to_string(source_spacing) + " and " + std::to_string(spacing));
  }
  // The stratified set's k-th samples follow the surface in a spatially coherent order, so
  // keeping every stride-th one thins it evenly.
  const double ratio = spacing / source_spacing;
  const std::size_t stride = std::max<std::size_t>(1, static_cast<std::size_t>(ratio * ratio));
  spacing_ = source_spacing * std::sqrt(static_cast<double>(stride));
  for (std::size_t i = 0; i < points.size(); i += stride) {
    if (!points[i].allFinite() || !normals[i].allFinite()) {
      throw Error("the model surface has a non-finite sample (index " + std::to_string(i) + ")");
    }
    pcl::PointNormal point;
    point.getVector3fMap() = points[i];
    point.getNormalVector3fMap() = normals[i].normalized();
    cloud_->push_back(point);
  }
  std::vector<Eigen::Vector3f> samples, sample_normals;
  samples.reserve(cloud_->size());
  sample_normals.reserve(cloud_->size());
  for (const auto& point : cloud_->points) {
    samples.push_back(point.getVector3fMap());
    sample_normals.push_back(point.getNormalVector3fMap());
  }
  nearest_ = std::make_unique<const NearestPoints>(std::move(samples), std::move(sample_normals));
}

const std::vector<Eigen::ParametrizedLine<double, 3>>& ModelSurface::symmetryAxes() const {
  std::call_once(symmetry_axes_once_, [this] {
    symmetry_axes_ = nearSymmetryAxes(*cloud_);
    // The other two eigenvectors say nothing about half turns (a mug's are 9 degrees off the
    // line through its handle): the axes of the half turns are searched for.
    const auto half_turns =
        halfTurnAxes(*cloud_, *nearest_, symmetry_axes_[0], symmetry_axes_[1].direction());
    symmetry_axes_[1] = half_turns[0];
    symmetry_axes_[2] = half_turns[1];
  });
  return symmetry_axes_;
}

const TruncatedDistanceField& ModelSurface::distanceField(double truncation) const {
  const std::lock_guard<std::mutex> lock(fields_mutex_);
  for (const auto& field : fields_) {
    if (field->truncation() == truncation) return *field;
  }
  std::vector<Eigen::Vector3f> samples;
  samples.reserve(cloud_->size());
  for (const auto& point : cloud_->points) samples.push_back(point.getVector3fMap());
  // Half the samples' spacing: the interpolation's error stays well below the screening's
  // millimetres; at least 2 mm, which bounds the grid (a 25 cm object: 5 MB).
  fields_.push_back(std::make_shared<const TruncatedDistanceField>(
      samples, bounds_, truncation, std::max(0.002, 0.5 * spacing_)));
  return *fields_.back();
}

}  // namespace vdc

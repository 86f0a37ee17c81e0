#include "view_direction_classification/planning/next_best_view.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>

#include "view_direction_classification/bingham/bingham_sampler.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/informativeness/informativeness.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc {
namespace {

// Distance from p to the segment [a, b].
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double t = length_sq > 0.0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// An orthonormal frame whose third axis is `axis` (unit).
Eigen::Matrix3d frameAround(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = axis.cross(helper).normalized();
  Eigen::Matrix3d frame;
  frame << e1, axis.cross(e1), axis;
  return frame;
}

void checkFinitePosition(const Eigen::Vector3d& p, const char* what) {
  if (!p.allFinite()) throw Error(std::string("The ") + what + " is not finite.");
}

}  // namespace

ViewUtility parseViewUtility(const std::string& name) {
  if (name == "informativeness") return ViewUtility::kInformativeness;
  if (name == "information_gain") return ViewUtility::kInformationGain;
  throw Error("Unknown next-best-view utility \"" + name +
              "\": use \"informativeness\" or \"information_gain\".");
}

std::string viewUtilityName(ViewUtility utility) {
  return utility == ViewUtility::kInformativeness ? "informativeness" : "information_gain";
}

std::vector<OrientationHypothesis> beliefHypotheses(const BinghamMixture& belief,
                                                    int samples_per_component, std::uint64_t seed) {
  if (samples_per_component < 0) {
    throw Error("The number of hypothesis samples per belief component must be >= 0, got " +
                std::to_string(samples_per_component) + ".");
  }
  std::mt19937_64 generator(seed);
  std::vector<OrientationHypothesis> hypotheses;
  hypotheses.reserve(belief.size() * static_cast<std::size_t>(1 + samples_per_component));
  const double share = 1.0 / (1.0 + samples_per_component);
  for (std::size_t k = 0; k < belief.size(); ++k) {
    const double weight = belief.weight(k) * share;
    hypotheses.push_back({belief.component(k).mode(), weight});
    if (samples_per_component == 0) continue;
    const BinghamSampler sampler(belief.component(k));
    for (int s = 0; s < samples_per_component; ++s) {
      hypotheses.push_back({sampler(generator).normalized(), weight});
    }
  }
  return hypotheses;
}

double mutualInformation(const Eigen::MatrixXd& confusion, const std::vector<int>& predicted_views,
                         const std::vector<double>& weights) {
  if (predicted_views.empty()) throw Error("The information gain needs at least one hypothesis.");
  if (predicted_views.size() != weights.size()) {
    throw Error("The information gain got " + std::to_string(predicted_views.size()) +
                " predicted views but " + std::to_string(weights.size()) + " weights.");
  }
  if (confusion.rows() != confusion.cols() || confusion.rows() == 0) {
    throw Error("The confusion matrix must be square and non-empty.");
  }
  const int views = static_cast<int>(confusion.rows());
  double weight_sum = 0.0;
  for (double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) {
      throw Error("A hypothesis weight is negative or not finite (" + std::to_string(w) + ").");
    }
    weight_sum += w;
  }
  if (!(weight_sum > 0.0)) throw Error("The hypothesis weights sum to zero.");

  // Normalised measurement distribution of each hypothesis, and their mixture p(m).
  Eigen::MatrixXd rows(predicted_views.size(), views);
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    const int v = predicted_views[h];
    if (v < 0 || v >= views) {
      throw Error("Predicted view " + std::to_string(v) + " is outside the " +
                  std::to_string(views) + " training views.");
    }
    const Eigen::RowVectorXd row = confusion.row(v);
    if (!row.allFinite() || (row.array() < 0.0).any() || !(row.sum() > 0.0)) {
      throw Error("Row " + std::to_string(v) +
                  " of the confusion matrix is negative, non-finite or all zero.");
    }
    rows.row(h) = row / row.sum();
  }
  Eigen::RowVectorXd marginal = Eigen::RowVectorXd::Zero(views);
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    marginal += (weights[h] / weight_sum) * rows.row(h);
  }
  double information = 0.0;
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    const double w = weights[h] / weight_sum;
    if (w == 0.0) continue;
    for (int m = 0; m < views; ++m) {
      const double p = rows(h, m);
      // p > 0 implies marginal(m) >= w p > 0.
      if (p > 0.0) information += w * p * std::log(p / marginal(m));
    }
  }
  // Rounding can leave a tiny negative sum for identical predictions; I >= 0 exactly.
  return std::max(0.0, information);
}

OccluderCloud::OccluderCloud(std::vector<Eigen::Vector3d> points_object, double radius)
    : points_(std::move(points_object)), radius_(radius) {
  if (points_.empty()) throw Error("The occluder cloud is empty.");
  for (const auto& p : points_) {
    if (!p.allFinite()) throw Error("The occluder cloud contains a non-finite point.");
  }
  if (!(radius_ > 0.0) || !std::isfinite(radius_)) {
    throw Error("The occluder radius must be positive and finite, got " + std::to_string(radius_) +
                " m.");
  }
}

std::vector<bool> OccluderCloud::hidden(const Eigen::Vector3d& camera_object,
                                        const std::vector<Eigen::Vector3d>& surface_points) const {
  checkFinitePosition(camera_object, "camera position");
  std::vector<bool> result(surface_points.size(), false);
  if (surface_points.empty()) return result;
  // Image plane of a camera at c looking at the object origin (or along -z if c is the origin).
  const Eigen::Vector3d axis = camera_object.norm() > 0.0
                                   ? Eigen::Vector3d(-camera_object.normalized())
                                   : Eigen::Vector3d(0, 0, -1);
  const Eigen::Matrix3d camera_frame = frameAround(axis).transpose();  // rows e1, e2, axis

  // The query points' image coordinates (x/z, y/z); points behind the camera are never hidden.
  std::vector<Eigen::Vector2d> surface_image(surface_points.size());
  std::vector<bool> in_front(surface_points.size(), false);
  double max_image_radius = 0.0, max_surface_depth = 0.0;
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    const Eigen::Vector3d u = camera_frame * (surface_points[i] - camera_object);
    if (u.z() <= 0.0) continue;
    in_front[i] = true;
    surface_image[i] = u.head<2>() / u.z();
    max_image_radius = std::max(max_image_radius, surface_image[i].norm());
    max_surface_depth = std::max(max_surface_depth, u.z());
  }
  // Occluder points at least 2 radii in front of the camera (points nearer the camera plane are
  // left out: an occluder touching the lens) and not beyond every query point (those cannot
  // touch a line of sight), projected the same way.
  pcl::PointCloud<pcl::PointXYZ>::Ptr projected(new pcl::PointCloud<pcl::PointXYZ>);
  std::vector<int> kept;
  double min_depth = std::numeric_limits<double>::infinity();
  Eigen::AlignedBox2d occluder_box;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Eigen::Vector3d u = camera_frame * (points_[i] - camera_object);
    if (u.z() <= 2.0 * radius_ || u.z() > max_surface_depth + radius_) continue;
    const Eigen::Vector2d q = u.head<2>() / u.z();
    projected->push_back(pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()), 0.f));
    kept.push_back(static_cast<int>(i));
    min_depth = std::min(min_depth, u.z());
    max_image_radius = std::max(max_image_radius, q.norm());
    occluder_box.extend(q);
  }
  if (kept.empty()) return result;
  // An occluder point o within `radius` of a segment point p (on s's pixel ray) is joined to p by
  // a 3D segment of length <= radius whose depth stays >= min_depth - radius and whose image stays
  // within max_image_radius of the centre (perspective maps segments to segments). The
  // projection's gradient norm there is sqrt(1 + |q|^2) / z, which bounds the image distance.
  const double search_radius =
      1.01 * radius_ * std::sqrt(1.0 + max_image_radius * max_image_radius) / (min_depth - radius_);
  occluder_box.min() -= Eigen::Vector2d::Constant(search_radius);
  occluder_box.max() += Eigen::Vector2d::Constant(search_radius);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setSortedResults(false);
  tree.setInputCloud(projected);
  std::vector<int> neighbours;
  std::vector<float> distances_sq;
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    if (!in_front[i] || !occluder_box.contains(surface_image[i])) continue;
    const Eigen::Vector3d& s = surface_points[i];
    const Eigen::Vector3d to_camera = camera_object - s;
    const double length = to_camera.norm();
    if (length <= 2.0 * radius_) continue;
    const Eigen::Vector3d start = s + (2.0 * radius_ / length) * to_camera;
    const pcl::PointXYZ query(static_cast<float>(surface_image[i].x()),
                              static_cast<float>(surface_image[i].y()), 0.f);
    if (tree.radiusSearch(query, search_radius, neighbours, distances_sq) == 0) continue;
    for (int n : neighbours) {
      if (distanceToSegment(points_[kept[n]], start, camera_object) <= radius_) {
        result[i] = true;
        break;
      }
    }
  }
  return result;
}

NextBestViewPlanner::NextBestViewPlanner(std::shared_ptr<const ModelBundle> model)
    : model_(std::move(model)) {
  if (!model_) throw Error("The next-best-view planner needs a model bundle.");
  const ModelBundle& b = *model_;
  const Eigen::Index views = static_cast<Eigen::Index>(b.view_directions.size());
  const Eigen::Index points = static_cast<Eigen::Index>(b.surface_points.size());
  if (views == 0) throw Error("The model bundle has no view directions.");
  const auto& vi = b.view_informativeness;
  if (vi.confusion.rows() != views || vi.confusion.cols() != views ||
      vi.view_scores.size() != views) {
    throw Error("The model bundle's confusion matrix or view scores do not match its " +
                std::to_string(views) + " view directions.");
  }
  if (static_cast<Eigen::Index>(b.surface_normals.size()) != points ||
      b.score_matrix.rows() != points || b.score_matrix.cols() != views) {
    throw Error("The model bundle's surface normals or score matrix do not match its " +
                std::to_string(points) + " surface points and " + std::to_string(views) +
                " view directions.");
  }
  for (const auto& d : b.view_directions) {
    if (!d.allFinite() || !(d.norm() > 0.0)) {
      throw Error("The model bundle has a zero or non-finite view direction.");
    }
    directions_.push_back(d.normalized());
  }
}

int NextBestViewPlanner::nearestView(const Eigen::Vector3d& direction) const {
  const double length = direction.norm();
  if (!std::isfinite(length) || !(length > 0.0)) {
    throw Error("A viewing direction must be a non-zero finite vector.");
  }
  int best = 0;
  double best_dot = -2.0;
  for (int m = 0; m < viewCount(); ++m) {
    const double dot = directions_[m].dot(direction) / length;
    if (dot > best_dot) {  // strict: ties go to the lower index, as ViewSphere::nearest
      best_dot = dot;
      best = m;
    }
  }
  return best;
}

double NextBestViewPlanner::worstUtility() { return std::log(kKlProbabilityFloor); }

double NextBestViewPlanner::informativeness(const Eigen::Vector3d& camera_object,
                                            const OccluderCloud* occluder) const {
  checkFinitePosition(camera_object, "camera position");
  const int view = nearestView(camera_object);
  const ModelBundle& b = *model_;
  std::vector<Eigen::Vector3d> seen_points;
  std::vector<double> seen_scores;
  for (std::size_t i = 0; i < b.surface_points.size(); ++i) {
    const double score = b.score_matrix(static_cast<Eigen::Index>(i), view);
    if (score < 0.0) continue;  // -1: never observed from m*
    const Eigen::Vector3d s = b.surface_points[i].cast<double>();
    if (b.surface_normals[i].cast<double>().dot(camera_object - s) <= 0.0) continue;
    seen_points.push_back(s);
    seen_scores.push_back(score);
  }
  if (seen_points.empty()) {
    const double v = b.view_informativeness.view_scores(view);
    return v >= 0.0 ? -v : worstUtility();
  }
  std::vector<bool> hidden(seen_points.size(), false);
  if (occluder != nullptr) hidden = occluder->hidden(camera_object, seen_points);
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < seen_points.size(); ++i) {
    if (hidden[i]) continue;
    sum += seen_scores[i];
    ++count;
  }
  return count > 0 ? -sum / count : worstUtility();
}

double NextBestViewPlanner::informationGain(
    const Eigen::Vector3d& camera_world, const Eigen::Vector3d& object_world,
    const std::vector<OrientationHypothesis>& hypotheses) const {
  checkFinitePosition(camera_world, "camera position");
  checkFinitePosition(object_world, "object position");
  const Eigen::Vector3d line_of_sight = camera_world - object_world;
  if (!(line_of_sight.norm() > 0.0)) {
    throw Error(
        "A candidate camera sits at the object's position, so it has no viewing direction.");
  }
  std::vector<int> views;
  std::vector<double> weights;
  views.reserve(hypotheses.size());
  weights.reserve(hypotheses.size());
  for (const auto& h : hypotheses) {
    checkUnitQuaternion(h.orientation, "an orientation hypothesis");
    // R_WO^T (c - p): the line of sight in the object frame under this hypothesis.
    views.push_back(nearestView(rotateVector(quaternionConjugate(h.orientation), line_of_sight)));
    weights.push_back(h.weight);
  }
  return mutualInformation(model_->view_informativeness.confusion, views, weights);
}

std::vector<RankedCandidate> rankCandidates(const NextBestViewPlanner& planner,
                                            const std::vector<Eigen::Vector3d>& camera_positions,
                                            ViewUtility utility, const PlanningScene& scene,
                                            const NextBestViewOptions& options) {
  if (camera_positions.empty()) throw Error("There are no candidate camera positions to rank.");
  checkFinitePosition(scene.object_position, "object position");
  checkUnitQuaternion(scene.orientation, "the object orientation");
  const Eigen::Vector4d to_object = quaternionConjugate(scene.orientation);
  std::unique_ptr<OccluderCloud> occluder;
  if (!scene.occluder_world.empty() && utility == ViewUtility::kInformativeness) {
    std::vector<Eigen::Vector3d> occluder_object;
    occluder_object.reserve(scene.occluder_world.size());
    for (const auto& p : scene.occluder_world) {
      if (!p.allFinite()) throw Error("The occluder cloud contains a non-finite point.");
      occluder_object.push_back(rotateVector(to_object, p - scene.object_position));
    }
    occluder = std::make_unique<OccluderCloud>(std::move(occluder_object), scene.occluder_radius);
  }
  std::vector<OrientationHypothesis> hypotheses;
  if (utility == ViewUtility::kInformationGain) {
    hypotheses = beliefHypotheses(scene.belief, options.samples_per_component, options.seed);
  }
  std::vector<RankedCandidate> ranked(camera_positions.size());
  for (std::size_t i = 0; i < camera_positions.size(); ++i) {
    const Eigen::Vector3d& c = camera_positions[i];
    checkFinitePosition(c, "candidate camera position");
    const Eigen::Vector3d camera_object = rotateVector(to_object, c - scene.object_position);
    if (!(camera_object.norm() > 0.0)) {
      throw Error("Candidate " + std::to_string(i) +
                  " sits at the object's position, so it has no viewing direction.");
    }
    ranked[i].index = static_cast<int>(i);
    ranked[i].view = planner.nearestView(camera_object);
    ranked[i].utility = utility == ViewUtility::kInformativeness
                            ? planner.informativeness(camera_object, occluder.get())
                            : planner.informationGain(c, scene.object_position, hypotheses);
  }
  std::stable_sort(
      ranked.begin(), ranked.end(),
      [](const RankedCandidate& a, const RankedCandidate& b) { return a.utility > b.utility; });
  return ranked;
}

std::vector<Eigen::Isometry3d> sampleCandidatePoses(int count, double distance,
                                                    const Eigen::Vector3d& object_position) {
  if (count < 2 || count > 10000) {
    throw Error("The number of sampled candidate views must be between 2 and 10000, got " +
                std::to_string(count) + ".");
  }
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw Error("The candidate camera distance must be positive and finite, got " +
                std::to_string(distance) + " m.");
  }
  checkFinitePosition(object_position, "object position");
  const ViewSphere sphere(count);
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(count);
  for (const auto& d : sphere.directions()) {
    // cameraFromObject looks at the origin of a frame with the fixed frame's axes; moving that
    // frame to the object's position gives T_WC.
    poses.push_back(Eigen::Translation3d(object_position) *
                    cameraFromObject(d, distance, 0.0).inverse());
  }
  return poses;
}

}  // namespace vdc

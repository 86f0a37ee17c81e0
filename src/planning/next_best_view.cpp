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
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/view_sphere.h"
#include "view_direction_classification/informativeness/informativeness.h"

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

// The steps of OccluderCloud::hidden: the camera's image plane, the query points and occluder
// points projected onto it, a kd-tree of the occluders' images, and per query point an exact test
// of the occluders near its image.

// Rows e1, e2, axis of the image plane of a camera at `camera` looking at the object origin (or
// along -z if the camera is at the origin).
Eigen::Matrix3d viewingFrame(const Eigen::Vector3d& camera) {
  const Eigen::Vector3d axis =
      camera.norm() > 0.0 ? Eigen::Vector3d(-camera.normalized()) : Eigen::Vector3d(0, 0, -1);
  return frameAround(axis).transpose();
}

// The query points' image coordinates (x/z, y/z); points behind the camera are never hidden.
struct ProjectedSurface {
  std::vector<Eigen::Vector2d> image;
  std::vector<bool> in_front;
  double max_image_radius = 0.0;
  double max_depth = 0.0;
};

ProjectedSurface projectSurface(const Eigen::Matrix3d& frame, const Eigen::Vector3d& camera,
                                const std::vector<Eigen::Vector3d>& surface_points) {
  ProjectedSurface surface;
  surface.image.resize(surface_points.size());
  surface.in_front.assign(surface_points.size(), false);
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    const Eigen::Vector3d u = frame * (surface_points[i] - camera);
    if (u.z() <= 0.0) continue;
    surface.in_front[i] = true;
    surface.image[i] = u.head<2>() / u.z();
    surface.max_image_radius = std::max(surface.max_image_radius, surface.image[i].norm());
    surface.max_depth = std::max(surface.max_depth, u.z());
  }
  return surface;
}

// Occluder points at least 2 radii in front of the camera (points nearer the camera plane are
// left out: an occluder touching the lens) and not beyond every query point (those cannot touch
// a line of sight), projected the same way.
struct ProjectedOccluders {
  pcl::PointCloud<pcl::PointXYZ>::Ptr image{new pcl::PointCloud<pcl::PointXYZ>};
  std::vector<int> index;  // of each image point in the occluder cloud
  double min_depth = std::numeric_limits<double>::infinity();
  double max_image_radius = 0.0;
  Eigen::AlignedBox2d box;  // of the image points
};

ProjectedOccluders projectOccluders(const Eigen::Matrix3d& frame, const Eigen::Vector3d& camera,
                                    const std::vector<Eigen::Vector3d>& points, double radius,
                                    double max_surface_depth) {
  ProjectedOccluders occluders;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d u = frame * (points[i] - camera);
    if (u.z() <= 2.0 * radius || u.z() > max_surface_depth + radius) continue;
    const Eigen::Vector2d q = u.head<2>() / u.z();
    occluders.image->push_back(
        pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()), 0.f));
    occluders.index.push_back(static_cast<int>(i));
    occluders.min_depth = std::min(occluders.min_depth, u.z());
    occluders.max_image_radius = std::max(occluders.max_image_radius, q.norm());
    occluders.box.extend(q);
  }
  return occluders;
}

// An occluder point o within `radius` of a segment point p (on s's pixel ray) is joined to p by a
// 3D segment of length <= radius whose depth stays >= min_depth - radius and whose image stays
// within max_image_radius of the centre (perspective maps segments to segments). The
// projection's gradient norm there is sqrt(1 + |q|^2) / z, which bounds the image distance.
double imageSearchRadius(double radius, double max_image_radius, double min_depth) {
  return 1.01 * radius * std::sqrt(1.0 + max_image_radius * max_image_radius) /
         (min_depth - radius);
}

// Whether one of the occluder points points[index[n]] for n in `neighbours` lies within `radius`
// of the sight line from s to the camera, leaving out the first 2 radii next to s.
bool sightLineBlocked(const Eigen::Vector3d& s, const Eigen::Vector3d& camera, double radius,
                      const std::vector<Eigen::Vector3d>& points, const std::vector<int>& index,
                      const std::vector<int>& neighbours) {
  const Eigen::Vector3d to_camera = camera - s;
  const double length = to_camera.norm();
  if (length <= 2.0 * radius) return false;
  const Eigen::Vector3d start = s + (2.0 * radius / length) * to_camera;
  for (int n : neighbours) {
    if (distanceToSegment(points[static_cast<std::size_t>(index[static_cast<std::size_t>(n)])],
                          start, camera) <= radius) {
      return true;
    }
  }
  return false;
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
  const Eigen::Matrix3d frame = viewingFrame(camera_object);
  const ProjectedSurface surface = projectSurface(frame, camera_object, surface_points);
  const ProjectedOccluders occluders =
      projectOccluders(frame, camera_object, points_, radius_, surface.max_depth);
  if (occluders.index.empty()) return result;
  const double search_radius = imageSearchRadius(
      radius_, std::max(surface.max_image_radius, occluders.max_image_radius), occluders.min_depth);
  Eigen::AlignedBox2d search_box = occluders.box;
  search_box.min() -= Eigen::Vector2d::Constant(search_radius);
  search_box.max() += Eigen::Vector2d::Constant(search_radius);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setSortedResults(false);
  tree.setInputCloud(occluders.image);
  std::vector<int> neighbours;
  std::vector<float> distances_sq;
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    if (!surface.in_front[i] || !search_box.contains(surface.image[i])) continue;
    const pcl::PointXYZ query(static_cast<float>(surface.image[i].x()),
                              static_cast<float>(surface.image[i].y()), 0.f);
    if (tree.radiusSearch(query, search_radius, neighbours, distances_sq) == 0) continue;
    result[i] = sightLineBlocked(surface_points[i], camera_object, radius_, points_,
                                 occluders.index, neighbours);
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

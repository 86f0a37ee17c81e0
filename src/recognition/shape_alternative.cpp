#include "view_direction_classification/recognition/shape_alternative.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "face_free_space.h"
#include "view_direction_classification/geometry/point_spread.h"

namespace vdc {
namespace {

constexpr int kMinPoints = 30;
constexpr std::size_t kMaxPoints = 2000;
// Faces and axes within this of upright (or horizontal) count: a box on a table stands square.
constexpr double kTiltTolerance = 10.0 * M_PI / 180.0;
constexpr int kRansacIterations = 300;
// The shapes are fitted in centimetres: PCL's samplers refuse three points whose cross product
// is under 1e-5 (float precision, meant for metres), and a candidate's points a few millimetres
// apart failed most samples, each with an error line (hundreds per patrol pass). Scaled, the same
// samples pass; the fractions are scale-free.
constexpr float kFitScale = 100.0f;
// [fit units: cm] Points left for a face or a side that spread less than this across their main
// direction (a line of them, a few) are not fitted: no shape's part, and RANSAC on them drew
// only degenerate samples.
constexpr double kMinFitSpread = 0.1;

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// The finite points, evenly strided down to at most kMaxPoints, scaled by kFitScale.
Cloud::Ptr strided(const Cloud& points) {
  Cloud finite;
  for (const auto& p : points.points) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      finite.push_back(pcl::PointXYZ(kFitScale * p.x, kFitScale * p.y, kFitScale * p.z));
    }
  }
  auto result = pcl::make_shared<Cloud>();
  const std::size_t stride =
      std::max<std::size_t>(1, (finite.size() + kMaxPoints - 1) / kMaxPoints);
  for (std::size_t i = 0; i < finite.size(); i += stride) result->push_back(finite[i]);
  return result;
}

// Marks point i explained at residual `distance`: level 2 within half of `tolerance`, 1 up to it
// (a point keeps the better level of the parts that explain it).
void explain(std::size_t i, float distance, double tolerance, std::vector<char>* explained) {
  const char level = distance <= 0.5 * tolerance ? 2 : (distance <= tolerance ? 1 : 0);
  (*explained)[i] = std::max((*explained)[i], level);
}

// RANSAC for one upright plane (PCL's PARALLEL_PLANE: containing `up`, within kTiltTolerance)
// among the points not yet explained: a box's first face. Marks its inliers explained; returns
// the plane's unit normal (zero when none was found).
Eigen::Vector3f explainByUprightPlane(const Cloud::Ptr& cloud, const Eigen::Vector3f& up,
                                      double tolerance, std::vector<char>* explained) {
  auto remaining = pcl::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    if (!(*explained)[i]) remaining->push_back(static_cast<int>(i));
  }
  if (!spreadsInTwoDirections(*cloud, *remaining, kMinFitSpread)) return Eigen::Vector3f::Zero();
  pcl::SACSegmentation<pcl::PointXYZ> ransac;  // seeded with a constant: deterministic
  ransac.setModelType(pcl::SACMODEL_PARALLEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setAxis(up);
  ransac.setEpsAngle(kTiltTolerance);
  ransac.setDistanceThreshold(tolerance);
  ransac.setMaxIterations(kRansacIterations);
  ransac.setInputCloud(cloud);
  ransac.setIndices(remaining);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (inliers.indices.empty() || coefficients.values.size() < 4) return Eigen::Vector3f::Zero();
  const Eigen::Vector4f plane(coefficients.values[0], coefficients.values[1],
                              coefficients.values[2], coefficients.values[3]);
  const float norm = plane.head<3>().norm();
  for (int i : inliers.indices) {
    const float distance = std::abs(plane.head<3>().dot((*cloud)[i].getVector3fMap()) + plane[3]);
    explain(i, distance / norm, tolerance, explained);
  }
  return plane.head<3>() / norm;
}

// The most points within `tolerance` of one plane of unit `normal` (fit units) among those at
// `indices`, found by sliding a window of twice the tolerance along their projections on the
// normal; its offset in *offset.
std::size_t bestOffset(const Cloud& cloud, const pcl::Indices& indices,
                       const Eigen::Vector3f& normal, double tolerance, float* offset) {
  std::vector<float> offsets;
  for (int i : indices) offsets.push_back(normal.dot(cloud[i].getVector3fMap()));
  std::sort(offsets.begin(), offsets.end());
  std::size_t best_count = 0, best_first = 0;
  for (std::size_t first = 0, last = 0; first < offsets.size(); ++first) {
    while (last < offsets.size() && offsets[last] - offsets[first] <= 2.0 * tolerance) ++last;
    if (last - first > best_count) best_count = last - first, best_first = first;
  }
  // The window's median, not its middle: the face's points gather about it, and the inner half
  // of the tolerance counts double (explain).
  if (best_count > 0) *offset = offsets[best_first + best_count / 2];
  return best_count;
}

// A box's second face: upright and, within kTiltTolerance, square to the first (whose fitted
// normal is a few degrees off on a small face). Its normal is searched about `up` in half-degree
// steps around `across`, and for each its offset (bestOffset): a deterministic search over
// the two unknowns, where RANSAC printed an error line for every shape without such a face (a
// plate, a spool's flange: a hundred in half an hour of the patrol soak). Marks its inliers
// explained; returns whether there was such a face.
bool explainBySquareFace(const Cloud& cloud, const Eigen::Vector3f& up,
                         const Eigen::Vector3f& across, double tolerance,
                         std::vector<char>* explained) {
  pcl::Indices remaining;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!(*explained)[i]) remaining.push_back(static_cast<int>(i));
  }
  // Empty indices would mean the whole cloud to spreadsInTwoDirections (PCL's convention):
  // nothing is left once the first face explained everything (a flat disc seen face-on).
  if (remaining.empty() || !spreadsInTwoDirections(cloud, remaining, kMinFitSpread)) return false;
  constexpr double kStep = 0.5 * M_PI / 180.0;
  const int steps = static_cast<int>(std::round(kTiltTolerance / kStep));
  std::size_t best_count = 0;
  float best_offset = 0.0f;
  Eigen::Vector3f best_normal = across;
  for (int step = -steps; step <= steps; ++step) {
    const Eigen::Vector3f normal = Eigen::AngleAxisf(static_cast<float>(step * kStep), up) * across;
    float offset = 0.0f;
    const std::size_t count = bestOffset(cloud, remaining, normal, tolerance, &offset);
    if (count > best_count) best_count = count, best_offset = offset, best_normal = normal;
  }
  if (best_count < 3) return false;  // no face: RANSAC's three points
  for (int i : remaining) {
    const float distance = std::abs(best_normal.dot(cloud[i].getVector3fMap()) - best_offset);
    explain(static_cast<std::size_t>(i), distance, tolerance, explained);
  }
  return true;
}

// The explained share, weighted as the verifier weighs a model's inliers
// (VerificationScore::identityScore): 1 within half the tolerance, 1/2 up to it.
double fractionOf(const std::vector<char>& explained) {
  double total = 0.0;
  for (char level : explained) total += level;
  return total / (2.0 * static_cast<double>(explained.size()));
}

// The points within `tolerance` of the highest (along `up`) become explained: a closed shape's
// top. Not any horizontal plane: a mug's inside bottom, below its rim, is no can's lid.
void explainTop(const Cloud& cloud, const Eigen::Vector3f& up, double tolerance,
                std::vector<char>* explained) {
  std::vector<float> heights;
  for (const auto& p : cloud.points) heights.push_back(up.dot(p.getVector3fMap()));
  // The 98th percentile, not the maximum: one noisy point does not lift the lid.
  std::vector<float> sorted = heights;
  const std::size_t k = (sorted.size() * 98) / 100;
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  // The lid's level: the median of the heights near that percentile, which lies about two noise
  // sigmas above it.
  std::vector<float> near_top;
  for (float h : heights) {
    if (std::abs(h - sorted[k]) <= tolerance) near_top.push_back(h);
  }
  std::nth_element(near_top.begin(), near_top.begin() + near_top.size() / 2, near_top.end());
  const float top = near_top[near_top.size() / 2];
  for (std::size_t i = 0; i < heights.size(); ++i) {
    explain(i, std::abs(heights[i] - top), tolerance, explained);
  }
}

// The points (fit units) whose level in `explained` rose from `before`'s.
std::vector<Eigen::Vector3f> newlyExplained(const Cloud& cloud, const std::vector<char>& before,
                                            const std::vector<char>& explained) {
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (explained[i] > before[i]) points.push_back(cloud[i].getVector3fMap());
  }
  return points;
}

// How the box's faces are judged against the scene (empty scene: not judged).
struct FaceCheck {
  const SceneDepth& scene;
  double free_space_tolerance;  // [m]
};

// Up to two perpendicular upright faces and a horizontal top: what a camera sees of a box. Minus
// the share of each face's rectangle that the scene's depth shows free (judgeFaceRectangle), as
// a model's score is lowered by its contradicted predictions: without it the flat face of a disc
// (a spool's flange) is a box's as much as the spool's.
double boxFraction(const Cloud::Ptr& cloud, const Eigen::Vector3f& up, double tolerance,
                   const FaceCheck& check) {
  std::vector<char> explained(cloud->size(), 0);
  FaceJudgement faces;
  const auto judge = [&](const std::vector<char>& before, const Eigen::Vector3f& normal) {
    const FaceJudgement face =
        judgeFaceRectangle(newlyExplained(*cloud, before, explained), normal, up, kFitScale,
                           check.scene, check.free_space_tolerance);
    faces.samples += face.samples;
    faces.seen_through += face.seen_through;
  };
  std::vector<char> before = explained;
  const Eigen::Vector3f first = explainByUprightPlane(cloud, up, tolerance, &explained);
  if (!first.isZero()) {
    judge(before, first);
    // The second face's normal is horizontal and square to the first's.
    before = explained;
    const Eigen::Vector3f across = up.cross(first).normalized();
    if (explainBySquareFace(*cloud, up, across, tolerance, &explained)) judge(before, across);
  }
  explainTop(*cloud, up, tolerance, &explained);
  const double contradicted =
      faces.samples > 0 ? static_cast<double>(faces.seen_through) / faces.samples : 0.0;
  return fractionOf(explained) - contradicted;
}

// An upright cylinder's side (a circle in the plane square to `up`, PCL's 2D circle RANSAC) and
// a horizontal top.
double cylinderFraction(const Cloud::Ptr& cloud, const Eigen::Vector3f& up, double tolerance) {
  // The top first, and the circle fitted to the rest: seen from above, a lid's many points inside
  // the circle would draw RANSAC to a smaller circle through them.
  std::vector<char> explained(cloud->size(), 0);
  explainTop(*cloud, up, tolerance, &explained);
  const Eigen::Vector3f u = up.unitOrthogonal();
  const Eigen::Vector3f v = up.cross(u);
  auto flat = pcl::make_shared<Cloud>();
  auto side = pcl::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const Eigen::Vector3f p = (*cloud)[i].getVector3fMap();
    flat->push_back(pcl::PointXYZ(u.dot(p), v.dot(p), 0.0f));
    if (!explained[i]) side->push_back(static_cast<int>(i));
  }
  if (side->size() < 3 || !spreadsInTwoDirections(*flat, *side, kMinFitSpread)) {
    return fractionOf(explained);
  }
  pcl::SACSegmentation<pcl::PointXYZ> ransac;
  ransac.setModelType(pcl::SACMODEL_CIRCLE2D);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(tolerance);
  ransac.setMaxIterations(kRansacIterations);
  ransac.setRadiusLimits(0.005 * kFitScale, 0.5 * kFitScale);
  ransac.setInputCloud(flat);
  ransac.setIndices(side);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (coefficients.values.size() >= 3) {
    // Only the side's half that faces the camera (at the origin of the points' frame): what is
    // seen beyond the axis through an open top (a mug's inner wall) is no closed can's side.
    const Eigen::Vector2f centre(coefficients.values[0], coefficients.values[1]);
    const float radius = coefficients.values[2];
    for (int i : inliers.indices) {
      const Eigen::Vector2f outward = (*flat)[i].getVector3fMap().head<2>() - centre;
      const Eigen::Vector2f towards_camera = -(*flat)[i].getVector3fMap().head<2>();
      if (outward.dot(towards_camera) > 0.0f) {
        explain(i, std::abs(outward.norm() - radius), tolerance, &explained);
      }
    }
  }
  return fractionOf(explained);
}

// The fraction of `points` within `tolerance` of the box's faces or, about `axis`, of the
// cylinder through the box's centre with the points' median radius and the box's end caps.
double boxSurfaceFraction(const std::vector<Eigen::Vector3f>& points,
                          const Eigen::AlignedBox3f& box, double tolerance) {
  int near = 0;
  for (const Eigen::Vector3f& p : points) {
    const float inside = std::min((p - box.min()).minCoeff(), (box.max() - p).minCoeff());
    if (std::abs(inside) <= tolerance) ++near;
  }
  return static_cast<double>(near) / points.size();
}

double cylinderSurfaceFraction(const std::vector<Eigen::Vector3f>& points,
                               const Eigen::AlignedBox3f& box, int axis, double tolerance) {
  const Eigen::Vector3f centre = box.center();
  std::vector<float> radii;
  for (const Eigen::Vector3f& p : points) {
    Eigen::Vector3f d = p - centre;
    d[axis] = 0.0f;
    radii.push_back(d.norm());
  }
  std::vector<float> sorted = radii;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float radius = sorted[sorted.size() / 2];
  int near = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float to_cap = std::min(std::abs(points[i][axis] - box.min()[axis]),
                                  std::abs(box.max()[axis] - points[i][axis]));
    if (std::abs(radii[i] - radius) <= tolerance ||
        (to_cap <= tolerance && radii[i] <= radius + tolerance)) {
      ++near;
    }
  }
  return static_cast<double>(near) / points.size();
}

}  // namespace

double simpleShapeFraction(const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector3f& up,
                           double tolerance, const SceneDepth& scene, double free_space_tolerance) {
  if (!up.allFinite() || up.norm() < 0.5f) return 0.0;
  const Cloud::Ptr cloud = strided(points);
  if (static_cast<int>(cloud->size()) < kMinPoints) return 0.0;
  const Eigen::Vector3f unit_up = up.normalized();
  const double fit_tolerance = kFitScale * tolerance;
  return std::max(boxFraction(cloud, unit_up, fit_tolerance, {scene, free_space_tolerance}),
                  cylinderFraction(cloud, unit_up, fit_tolerance));
}

bool isSimpleShape(const std::vector<Eigen::Vector3f>& surface_points, double tolerance,
                   double min_fraction) {
  if (surface_points.empty()) return false;
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& p : surface_points) box.extend(p);
  if (boxSurfaceFraction(surface_points, box, tolerance) >= min_fraction) return true;
  for (int axis = 0; axis < 3; ++axis) {
    if (cylinderSurfaceFraction(surface_points, box, axis, tolerance) >= min_fraction) return true;
  }
  return false;
}

ShapeAlternative::ShapeAlternative(const ModelLibrary& library, VerificationParameters verification,
                                   double unknown_score)
    : verification_(verification), unknown_score_(unknown_score) {
  for (const LibraryModel& model : library.models()) {
    simple_.push_back(isSimpleShape(model.bundle->surface_points));
  }
}

double ShapeAlternative::fraction(const pcl::PointCloud<pcl::PointXYZ>& points,
                                  const Eigen::Vector3f& up, const SceneDepth& scene) const {
  if (up.isZero() || points.empty()) return 0.0;
  std::vector<float> depths;
  for (const auto& p : points.points) {
    if (std::isfinite(p.z)) depths.push_back(p.z);
  }
  if (depths.empty()) return 0.0;
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  const double z = depths[depths.size() / 2];
  // Verification's tolerances at that depth: the model and the shape judged alike.
  return simpleShapeFraction(points, up, inlierTolerance(verification_, z), scene,
                             freeSpaceTolerance(verification_, z));
}

std::vector<double> ShapeAlternative::penalties(const pcl::PointCloud<pcl::PointXYZ>& points,
                                                const Eigen::Vector3f& up,
                                                const SceneDepth& scene) const {
  std::vector<double> result(simple_.size(), 0.0);
  if (std::all_of(simple_.begin(), simple_.end(), [](bool simple) { return simple; })) {
    return result;
  }
  const double excess = std::max(0.0, fraction(points, up, scene) - unknown_score_);
  for (std::size_t m = 0; m < simple_.size(); ++m) result[m] = simple_[m] ? 0.0 : excess;
  return result;
}

}  // namespace vdc

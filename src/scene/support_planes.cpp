#include "support_planes.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "depth_tolerance.h"

namespace vdc::scene {
namespace {

// A plane found by either method, before it is judged as a support.
struct PlaneCandidate {
  Eigen::Vector4d coefficients;
  std::vector<int> inliers;
};

// Fitting and measuring on more points finds the same plane, only slower.
constexpr std::size_t kMaxFitPoints = 20000;
// The width ignores this fraction of the inliers at either end: an infinite RANSAC plane also
// takes in a few points of whatever it cuts far away (a wall, another object).
constexpr double kWidthTrim = 0.02;

double degToRad(double degrees) { return degrees * M_PI / 180.0; }

double signedDistance(const Eigen::Vector4d& plane, const pcl::PointXYZ& p) {
  return plane.head<3>().dot(p.getVector3fMap().cast<double>()) + plane(3);
}

// Within the plane's band, which widens with depth: a far table is noisier and less flat.
bool onPlane(const Eigen::Vector4d& plane, const pcl::PointXYZ& p,
             const SceneSegmentationParameters& parameters) {
  return std::abs(signedDistance(plane, p)) <=
         toleranceAt({parameters.plane_distance, parameters.depth_tolerance_growth}, p);
}

// Unit normal, the camera (origin) on the positive side; false for a degenerate plane.
bool orientTowardsCamera(Eigen::Vector4d* plane) {
  const double length = plane->head<3>().norm();
  if (!(length > 0.0) || !plane->allFinite()) return false;
  *plane /= length;
  if ((*plane)(3) < 0) *plane = -*plane;
  return true;
}

// Extent [m] of the inliers across the plane along their second principal axis (trimmed).
double planeWidth(const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<int>& inliers) {
  if (inliers.size() < 3) return 0.0;
  const std::size_t stride = (inliers.size() + kMaxFitPoints - 1) / kMaxFitPoints;
  std::vector<Eigen::Vector3d> points;
  for (std::size_t k = 0; k < inliers.size(); k += stride)
    points.push_back(cloud[inliers[k]].getVector3fMap().cast<double>());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  // Eigenvalues ascending: column 1 is the second principal axis of a plane's points.
  const Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(1);
  std::vector<double> along(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) along[k] = axis.dot(points[k] - mean);
  std::sort(along.begin(), along.end());
  const auto trim = static_cast<std::size_t>(kWidthTrim * static_cast<double>(along.size()));
  return along[along.size() - 1 - trim] - along[trim];
}

// Regions of one plane joined, largest first: a table seen between the objects on it is several
// regions, each narrower than a support (min_plane_width) though the table is not. Two regions
// are one plane when their normals agree within twice plane_angle_deg and their distances from
// the camera within the plane tolerance at that distance.
std::vector<PlaneCandidate> coplanarJoined(std::vector<PlaneCandidate> candidates,
                                           const SceneSegmentationParameters& parameters) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const PlaneCandidate& a, const PlaneCandidate& b) {
                     return a.inliers.size() > b.inliers.size();
                   });
  const double min_cosine = std::cos(degToRad(2.0 * parameters.plane_angle_deg));
  std::vector<PlaneCandidate> joined;
  for (PlaneCandidate& candidate : candidates) {
    const double distance = candidate.coefficients(3);  // from the camera (normal towards it)
    const double tolerance =
        parameters.plane_distance + parameters.depth_tolerance_growth * distance * distance;
    auto same = std::find_if(joined.begin(), joined.end(), [&](const PlaneCandidate& plane) {
      return plane.coefficients.head<3>().dot(candidate.coefficients.head<3>()) >= min_cosine &&
             std::abs(plane.coefficients(3) - distance) <= tolerance;
    });
    if (same == joined.end()) {
      joined.push_back(std::move(candidate));
    } else {
      same->inliers.insert(same->inliers.end(), candidate.inliers.begin(), candidate.inliers.end());
    }
  }
  return joined;
}

// The supports among the candidates: enough inliers, wide enough, and (all but the largest)
// parallel to the largest. Largest first.
std::vector<SupportPlane> chooseSupports(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                         std::vector<PlaneCandidate> candidates,
                                         const SceneSegmentationParameters& parameters) {
  candidates = coplanarJoined(std::move(candidates), parameters);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const PlaneCandidate& a, const PlaneCandidate& b) {
                     return a.inliers.size() > b.inliers.size();
                   });
  const double min_cosine = std::cos(degToRad(parameters.max_support_tilt_deg));
  std::vector<SupportPlane> supports;
  for (const PlaneCandidate& candidate : candidates) {
    if (static_cast<int>(supports.size()) >= parameters.max_support_planes) break;
    if (candidate.inliers.size() < static_cast<std::size_t>(parameters.min_plane_points)) break;
    if (!supports.empty() && candidate.coefficients.head<3>().dot(
                                 supports.front().coefficients.head<3>()) < min_cosine) {
      continue;
    }
    if (planeWidth(cloud, candidate.inliers) < parameters.min_plane_width) continue;
    supports.push_back({candidate.coefficients, static_cast<int>(candidate.inliers.size())});
  }
  return supports;
}

// The plane RANSAC finds among the points at `pool` (at most kMaxFitPoints of them, evenly
// strided); false if it finds none.
bool ransacPlane(const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<int>& pool,
                 double distance, Eigen::Vector4d* plane) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr sample(new pcl::PointCloud<pcl::PointXYZ>);
  const std::size_t stride = (pool.size() + kMaxFitPoints - 1) / kMaxFitPoints;
  for (std::size_t k = 0; k < pool.size(); k += stride) sample->push_back(cloud[pool[k]]);
  pcl::SACSegmentation<pcl::PointXYZ> ransac;  // deterministic: PCL seeds its RNG with a constant
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(distance);
  ransac.setMaxIterations(200);
  ransac.setOptimizeCoefficients(true);
  ransac.setInputCloud(sample);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (coefficients.values.size() != 4) return false;
  *plane = Eigen::Vector4d(coefficients.values[0], coefficients.values[1], coefficients.values[2],
                           coefficients.values[3]);
  return orientTowardsCamera(plane);
}

}  // namespace

std::vector<SupportPlane> findOrganisedSupportPlanes(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
    const SceneSegmentationParameters& parameters) {
  // The tutorial's settings (PCL's organized_segmentation_demo): 2 cm depth steps end a normal's
  // window, which averages over 10 pixels.
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation;
  normal_estimation.setNormalEstimationMethod(normal_estimation.AVERAGE_3D_GRADIENT);
  normal_estimation.setMaxDepthChangeFactor(0.02f);
  normal_estimation.setNormalSmoothingSize(10.0f);
  normal_estimation.setInputCloud(cloud);
  normal_estimation.compute(*normals);

  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> planes;
  planes.setMinInliers(static_cast<unsigned>(parameters.min_plane_points));
  planes.setAngularThreshold(degToRad(parameters.plane_angle_deg));
  // PCL scales this threshold by z^2 itself (its plane comparator is depth dependent), so it gets
  // the tolerance at 1 m.
  planes.setDistanceThreshold(parameters.plane_distance + parameters.depth_tolerance_growth);
  // A real table's region bends a little (sensor noise, a warped board); PCL's 0.001 default
  // drops Kinect tables.
  planes.setMaximumCurvature(0.01);
  planes.setInputNormals(normals);
  planes.setInputCloud(cloud);
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  planes.segment(coefficients, inliers);

  std::vector<PlaneCandidate> candidates;
  for (std::size_t k = 0; k < coefficients.size() && k < inliers.size(); ++k) {
    if (coefficients[k].values.size() != 4) continue;
    PlaneCandidate candidate;
    candidate.coefficients = Eigen::Vector4d(coefficients[k].values[0], coefficients[k].values[1],
                                             coefficients[k].values[2], coefficients[k].values[3]);
    if (!orientTowardsCamera(&candidate.coefficients)) continue;
    candidate.inliers = std::move(inliers[k].indices);
    candidates.push_back(std::move(candidate));
  }
  return chooseSupports(*cloud, std::move(candidates), parameters);
}

std::vector<SupportPlane> findRansacSupportPlanes(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const std::vector<int>& finite,
                                                  const SceneSegmentationParameters& parameters) {
  // Each round takes the largest plane left and removes its inliers; planes that are no support
  // (box faces, walls) are removed too so that the next round can find a shelf.
  std::vector<PlaneCandidate> candidates;
  std::vector<int> pool = finite;
  const int rounds = parameters.max_support_planes + 3;
  for (int round = 0; round < rounds; ++round) {
    if (pool.size() < static_cast<std::size_t>(std::max(parameters.min_plane_points, 3))) break;
    PlaneCandidate candidate;
    // RANSAC fits with the tolerance near the camera (a tight fit); the inliers are then counted
    // with the band at their depth.
    if (!ransacPlane(cloud, pool, parameters.plane_distance, &candidate.coefficients)) break;
    std::vector<int> rest;
    for (const int i : pool) {
      (onPlane(candidate.coefficients, cloud[i], parameters) ? candidate.inliers : rest)
          .push_back(i);
    }
    if (candidate.inliers.size() < static_cast<std::size_t>(parameters.min_plane_points)) break;
    pool.swap(rest);
    candidates.push_back(std::move(candidate));
  }
  return chooseSupports(cloud, std::move(candidates), parameters);
}

std::vector<int> standingOn(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const std::vector<int>& finite, const std::vector<SupportPlane>& planes,
                            const SceneSegmentationParameters& parameters) {
  std::vector<int> standing(cloud.size(), kNotStanding);
  for (const int i : finite) {
    if (planes.empty()) {
      standing[static_cast<std::size_t>(i)] = kNoSupport;
      continue;
    }
    // The nearest plane below the point: a shelf's objects stand on the shelf, not on the floor.
    // A point on any plane is on no object: a real table often comes as two or three slightly
    // tilted regions (depth distortion, a warped board), each a plane within the others' height.
    double lowest = std::numeric_limits<double>::infinity();
    int below = kNotStanding;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      const double height = signedDistance(planes[p].coefficients, cloud[i]);
      if (onPlane(planes[p].coefficients, cloud[i], parameters)) {
        below = kNotStanding;
        break;
      }
      if (height > 0 && height <= parameters.max_height_above_plane && height < lowest) {
        lowest = height;
        below = static_cast<int>(p);
      }
    }
    standing[static_cast<std::size_t>(i)] = below;
  }
  return standing;
}

int supportOf(const std::vector<int>& indices, const std::vector<int>& standing) {
  std::map<int, int> votes;
  for (const int i : indices) ++votes[standing[static_cast<std::size_t>(i)]];
  int best = -1, most = 0;
  for (const auto& [plane, count] : votes) {
    if (plane >= 0 && count > most) {
      best = plane;
      most = count;
    }
  }
  return best;
}

}  // namespace vdc::scene

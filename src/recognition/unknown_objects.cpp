#include "view_direction_classification/recognition/unknown_objects.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void checkNonNegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(std::string("unknown objects' ") + name + " must be a finite number >= 0, got " +
                std::to_string(value));
  }
}

// The sides longest first, so that boxes seen from different directions compare.
Eigen::Vector3d sortedSides(Eigen::Vector3d sides) {
  std::sort(sides.data(), sides.data() + 3, std::greater<double>());
  return sides;
}

Eigen::AlignedBox3d boxOf(const std::vector<Eigen::Vector3f>& points) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) box.extend(p.cast<double>());
  }
  return box;
}

}  // namespace

void checkUnknownRetryParameters(const UnknownRetryParameters& p) {
  checkNonNegative(p.retry_angle, "retry_angle");
  checkNonNegative(p.growth_fraction, "growth_fraction");
  checkNonNegative(p.growth_distance, "growth_distance");
  checkNonNegative(p.box_margin, "box_margin");
  if (!(p.inside_fraction >= 0.0 && p.inside_fraction <= 1.0)) {
    throw Error("unknown objects' inside_fraction must be in [0, 1], got " +
                std::to_string(p.inside_fraction));
  }
  if (p.max_tries < 1) {
    throw Error("unknown objects' max_tries must be at least 1, got " +
                std::to_string(p.max_tries));
  }
}

UnknownObjects::UnknownObjects(double association_distance, UnknownRetryParameters parameters)
    : association_distance_(association_distance), parameters_(std::move(parameters)) {
  checkNonNegative(association_distance_, "association_distance");
  checkUnknownRetryParameters(parameters_);
}

bool UnknownObjects::liesInBox(const Object& object, const Eigen::Vector3d& sides,
                               const std::vector<Eigen::Vector3f>& points_world) const {
  if (object.box.isEmpty() || points_world.empty() ||
      sortedSides(sides)[0] < (1.0 - parameters_.growth_fraction) * object.largest_sides[0]) {
    return false;
  }
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(parameters_.box_margin);
  const Eigen::AlignedBox3d grown(object.box.min() - margin, object.box.max() + margin);
  const auto inside =
      std::count_if(points_world.begin(), points_world.end(),
                    [&](const Eigen::Vector3f& p) { return grown.contains(p.cast<double>()); });
  return static_cast<double>(inside) >=
         parameters_.inside_fraction * static_cast<double>(points_world.size());
}

const UnknownObjects::Object* UnknownObjects::objectOf(
    const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
    const std::vector<Eigen::Vector3f>& points_world) const {
  for (const Object& object : objects_) {
    if ((object.centroid - centroid).norm() < association_distance_) return &object;
  }
  for (const Object& object : objects_) {
    if (liesInBox(object, sides, points_world)) return &object;
  }
  return nullptr;
}

bool UnknownObjects::grew(const Object& object, const Eigen::Vector3d& sides) const {
  // Measured against the longest side: a thin side's doubling (a box's top seen a little more
  // from above) is not more of the object.
  const double growth =
      std::max(parameters_.growth_fraction * object.largest_sides[0], parameters_.growth_distance);
  return ((sortedSides(sides) - object.largest_sides).array() > growth).any();
}

std::string UnknownObjects::notRetriedBecause(
    const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
    const Eigen::Vector3d& camera_position,
    const std::vector<Eigen::Vector3f>& points_world) const {
  const Object* object = objectOf(centroid, sides, points_world);
  return object ? notRetriedBecause(*object, centroid, sides, camera_position) : "";
}

std::string UnknownObjects::notRetriedBecause(const Object& object, const Eigen::Vector3d& centroid,
                                              const Eigen::Vector3d& sides,
                                              const Eigen::Vector3d& camera_position) const {
  if (grew(object, sides)) return "";
  const Eigen::Vector3d then = (object.camera_position - object.centroid).normalized();
  const Eigen::Vector3d now = (camera_position - centroid).normalized();
  if (std::acos(std::clamp(then.dot(now), -1.0, 1.0)) < parameters_.retry_angle) {
    return "unknown from a nearby direction already";
  }
  if (object.tries >= parameters_.max_tries) {
    return "unknown from " + std::to_string(object.tries) + " direction" +
           (object.tries == 1 ? "" : "s") + " already, and no more of it shows";
  }
  return "";
}

void UnknownObjects::remember(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                              const Eigen::Vector3d& camera_position,
                              const std::vector<Eigen::Vector3f>& points_world) {
  Object object{centroid, sortedSides(sides), camera_position, 1, boxOf(points_world)};
  // An older try of the same object goes: this one is from the newer direction.
  for (auto it = objects_.begin(); it != objects_.end();) {
    if ((it->centroid - centroid).norm() >= association_distance_ &&
        !liesInBox(*it, sides, points_world)) {
      ++it;
      continue;
    }
    object.tries = std::max(object.tries, it->tries + 1);
    object.largest_sides = object.largest_sides.cwiseMax(it->largest_sides);
    object.box.extend(it->box);
    it = objects_.erase(it);
  }
  objects_.push_back(std::move(object));
}

void UnknownObjects::forgetIf(const std::function<bool(const Eigen::Vector3d&)>& gone) {
  objects_.erase(std::remove_if(objects_.begin(), objects_.end(),
                                [&](const Object& object) { return gone(object.centroid); }),
                 objects_.end());
}

}  // namespace vdc

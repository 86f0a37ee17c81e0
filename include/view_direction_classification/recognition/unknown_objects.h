#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace vdc {

// When a candidate that no model explained is tried again.
struct UnknownRetryParameters {
  // An unknown object is tried again when more of it shows than ever before: a side of its
  // visible box (sides sorted, so that the same box seen from another side compares) longer by
  // growth_fraction of its longest side and at least growth_distance [m] (it was partly hidden,
  // or cut off by the image's edge).
  double growth_fraction = 0.25;
  double growth_distance = 0.01;
  // Otherwise only while it was tried from fewer than max_tries directions, each at least
  // retry_angle [rad] from the last. One by default: trying the same view of the same thing
  // again from elsewhere mostly gives a wrong model a second chance (doc/evaluation.md), and a
  // camera circling a table would try every unknown thing on it each retry_angle, for hours,
  // at the cost of every fitting model's search (about half a second each).
  int max_tries = 1;
  double retry_angle = 0.5;
};

// Throws vdc::Error naming the first bad parameter (negative, non-finite, max_tries < 1).
void checkUnknownRetryParameters(const UnknownRetryParameters& parameters);

// The objects of a scene that no model explained, where they were and from where they were
// tried, so that identification does not spend its time on them again and again.
class UnknownObjects {
 public:
  // association_distance [m]: a candidate whose centroid (fixed frame) is this close to an
  // unknown object's is it (the scene's association distance).
  UnknownObjects(double association_distance, UnknownRetryParameters parameters);

  // Why a candidate at `centroid` (fixed frame) whose visible box has `sides` [m], seen from
  // `camera_position`, is not tried again now; empty: try it.
  std::string notRetriedBecause(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                                const Eigen::Vector3d& camera_position) const;
  // It was tried from camera_position and is unknown: it replaces the unknown object it is (one
  // more try of it) or is a new one.
  void remember(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                const Eigen::Vector3d& camera_position);
  // Forgets the unknown objects whose place `gone` (given an object's centroid, fixed frame)
  // says is empty now: what is put there later is a new thing to try. Without it the places
  // piled up for the estimator's life, and a mug put down where a box had stood was never tried.
  void forgetIf(const std::function<bool(const Eigen::Vector3d&)>& gone);
  void clear() { objects_.clear(); }
  std::size_t size() const { return objects_.size(); }

 private:
  struct Object {
    Eigen::Vector3d centroid;
    Eigen::Vector3d largest_sides;    // over its tries, each side sorted longest first
    Eigen::Vector3d camera_position;  // where it was last tried from
    int tries = 0;
  };
  // The unknown object a candidate at `centroid` is, or null.
  const Object* near(const Eigen::Vector3d& centroid) const;
  bool grew(const Object& object, const Eigen::Vector3d& sides) const;

  double association_distance_;
  UnknownRetryParameters parameters_;
  std::vector<Object> objects_;
};

}  // namespace vdc

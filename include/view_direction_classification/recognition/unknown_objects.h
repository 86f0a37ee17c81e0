#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

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
  // A candidate is the unknown object whose centroid is within the association distance of its
  // own or, where none is, one in whose box (fixed frame's axes, round the points the object's
  // tries showed, grown by box_margin [m]) inside_fraction of its points lie, its longest side
  // at least (1 - growth_fraction) of the object's: the same thing, though the view moved its
  // centroid (another side in view, another split into pieces, a union of pieces tried as one). A
  // much smaller candidate inside the box is not it: a known object that stood touching an unknown
  // one may have been tried inside it, and comes out of it smaller.
  double box_margin = 0.01;
  double inside_fraction = 0.9;
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
  // `camera_position`, is not tried again now; empty: try it. `points_world` (fixed frame; may
  // be empty) are its points, compared with the boxes of the unknown objects' points.
  std::string notRetriedBecause(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                                const Eigen::Vector3d& camera_position,
                                const std::vector<Eigen::Vector3f>& points_world = {}) const;
  // It was tried from camera_position and is unknown: it replaces the unknown object it is (one
  // more try of it, its box joined with the earlier ones') or is a new one.
  void remember(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                const Eigen::Vector3d& camera_position,
                const std::vector<Eigen::Vector3f>& points_world = {});
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
    // The box (fixed frame's axes) of the points of its tries; empty while none were given.
    Eigen::AlignedBox3d box;
  };
  // The unknown object a candidate at `centroid` whose visible box has `sides` and whose points
  // are `points_world` is: the first whose centroid is near, else the first it lies in the box
  // of (UnknownRetryParameters); null if none.
  const Object* objectOf(const Eigen::Vector3d& centroid, const Eigen::Vector3d& sides,
                         const std::vector<Eigen::Vector3f>& points_world) const;
  bool liesInBox(const Object& object, const Eigen::Vector3d& sides,
                 const std::vector<Eigen::Vector3f>& points_world) const;
  // Why `object`, which the candidate is, is not tried again; empty: try it.
  std::string notRetriedBecause(const Object& object, const Eigen::Vector3d& centroid,
                                const Eigen::Vector3d& sides,
                                const Eigen::Vector3d& camera_position) const;
  bool grew(const Object& object, const Eigen::Vector3d& sides) const;

  double association_distance_;
  UnknownRetryParameters parameters_;
  std::vector<Object> objects_;
};

}  // namespace vdc

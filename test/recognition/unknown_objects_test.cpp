#include "view_direction_classification/recognition/unknown_objects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

const Eigen::Vector3d kObject(0.4, 0.1, 0.75);
const Eigen::Vector3d kSides(0.10, 0.08, 0.06);

// A camera 0.7 m from the object, `degrees` round it from the x axis, 40 degrees above it.
Eigen::Vector3d cameraAt(double degrees) {
  const double a = degrees * M_PI / 180.0, up = 40.0 * M_PI / 180.0;
  return kObject + 0.7 * Eigen::Vector3d(std::cos(a) * std::cos(up), std::sin(a) * std::cos(up),
                                         std::sin(up));
}

UnknownObjects triedOnceFrom(double degrees, int max_tries) {
  UnknownRetryParameters parameters;
  parameters.max_tries = max_tries;
  UnknownObjects unknowns(0.05, parameters);
  unknowns.remember(kObject, kSides, cameraAt(degrees));
  return unknowns;
}

TEST(UnknownObjects, AnObjectNeverTriedIsTried) {
  const UnknownObjects unknowns = triedOnceFrom(0.0, 3);
  EXPECT_EQ(unknowns.notRetriedBecause(kObject + Eigen::Vector3d(0.2, 0, 0), kSides, cameraAt(0)),
            "");
}

TEST(UnknownObjects, AnUnknownObjectIsNotTriedAgainFromANearbyDirection) {
  const UnknownObjects unknowns = triedOnceFrom(0.0, 3);
  const Eigen::Vector3d nearby = kObject + Eigen::Vector3d(0.01, 0.01, 0);
  EXPECT_EQ(unknowns.notRetriedBecause(nearby, kSides, cameraAt(20.0)),
            "unknown from a nearby direction already");
  EXPECT_EQ(unknowns.notRetriedBecause(nearby, kSides, cameraAt(40.0)), "");
  // From the same direction, with more of it in view (an occluder went): tried again.
  EXPECT_EQ(unknowns.notRetriedBecause(nearby, Eigen::Vector3d(0.14, 0.08, 0.06), cameraAt(0)), "");
}

TEST(UnknownObjects, ByDefaultAnUnknownObjectIsTriedOnceUnlessMoreOfItShows) {
  UnknownObjects unknowns(0.05, UnknownRetryParameters());
  unknowns.remember(kObject, kSides, cameraAt(0.0));
  EXPECT_EQ(unknowns.notRetriedBecause(kObject, kSides, cameraAt(90.0)),
            "unknown from 1 direction already, and no more of it shows");
}

TEST(UnknownObjects, AfterMaxTriesOnlyMoreOfItShowingMakesItTriedAgain) {
  UnknownObjects unknowns = triedOnceFrom(0.0, 2);
  unknowns.remember(kObject, kSides, cameraAt(60.0));  // its second try
  EXPECT_EQ(unknowns.size(), 1u) << "the second try is the same object";
  EXPECT_EQ(unknowns.notRetriedBecause(kObject, kSides, cameraAt(150.0)),
            "unknown from 2 directions already, and no more of it shows");
  // Seen from the other side its box is the same sides in another order: no more of it.
  EXPECT_NE(unknowns.notRetriedBecause(kObject, Eigen::Vector3d(0.06, 0.10, 0.08), cameraAt(150)),
            "");  // not tried
  // Its shortest side 2 cm longer (its top seen a little more from above) is not more of it:
  // growth counts against the longest side (25 % of 10 cm).
  EXPECT_NE(unknowns.notRetriedBecause(kObject, Eigen::Vector3d(0.10, 0.08, 0.08), cameraAt(150)),
            "");
  // A side 3 cm longer than ever seen (it was partly hidden): tried again.
  EXPECT_EQ(unknowns.notRetriedBecause(kObject, Eigen::Vector3d(0.13, 0.08, 0.06), cameraAt(150)),
            "");
}

constexpr double kAssociation = 0.03;

// Points every 5 mm on the face of the box round kObject with sides kSides whose normal is
// `axis` (0, 1, 2) pointing to `sign` (+1, -1): what a camera on that side sees of it.
std::vector<Eigen::Vector3f> faceOfTheBox(int axis, double sign) {
  std::vector<Eigen::Vector3f> points;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (double a = -kSides[u] / 2; a <= kSides[u] / 2; a += 0.005) {
    for (double b = -kSides[v] / 2; b <= kSides[v] / 2; b += 0.005) {
      Eigen::Vector3d p = kObject;
      p[axis] += sign * kSides[axis] / 2;
      p[u] += a;
      p[v] += b;
      points.push_back(p.cast<float>());
    }
  }
  return points;
}

Eigen::Vector3d centroidOf(const std::vector<Eigen::Vector3f>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3f& p : points) sum += p.cast<double>();
  return sum / static_cast<double>(points.size());
}

std::vector<Eigen::Vector3f> joined(std::vector<Eigen::Vector3f> a,
                                    const std::vector<Eigen::Vector3f>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(UnknownObjects, AnUnknownObjectSeenFromAnotherSideIsItThoughItsCentroidMoved) {
  // Tried from +x, where its +x and +z faces showed; seen now from -x, where its -x and +z
  // faces show: the centroid of its points moved farther than the association distance.
  const std::vector<Eigen::Vector3f> then = joined(faceOfTheBox(0, 1), faceOfTheBox(2, 1));
  const std::vector<Eigen::Vector3f> now = joined(faceOfTheBox(0, -1), faceOfTheBox(2, 1));
  ASSERT_GT((centroidOf(then) - centroidOf(now)).norm(), kAssociation);
  UnknownObjects unknowns(kAssociation, UnknownRetryParameters());
  unknowns.remember(centroidOf(then), kSides, cameraAt(0.0), then);
  EXPECT_EQ(unknowns.notRetriedBecause(centroidOf(now), kSides, cameraAt(180.0), now),
            "unknown from 1 direction already, and no more of it shows");
  // Known by its centroid alone it was a new thing, and was tried.
  EXPECT_EQ(unknowns.notRetriedBecause(centroidOf(now), kSides, cameraAt(180.0)), "");
  // Its next try is one more of the same object, not a second object.
  unknowns.remember(centroidOf(now), kSides, cameraAt(180.0), now);
  EXPECT_EQ(unknowns.size(), 1u);
}

TEST(UnknownObjects, APieceMuchSmallerThanTheUnknownObjectItLiesInIsTried) {
  // A mug that stood touching the box was tried inside it; split off now, it is smaller.
  const std::vector<Eigen::Vector3f> then = joined(faceOfTheBox(0, 1), faceOfTheBox(2, 1));
  UnknownObjects unknowns(kAssociation, UnknownRetryParameters());
  unknowns.remember(centroidOf(then), kSides, cameraAt(0.0), then);
  std::vector<Eigen::Vector3f> piece;
  for (const Eigen::Vector3f& p : faceOfTheBox(2, 1)) {
    if (p.x() < kObject.x() - 0.03 && p.y() < kObject.y() - 0.02) piece.push_back(p);
  }
  const Eigen::Vector3d piece_sides(0.03, 0.02, 0.0);
  ASSERT_GT((centroidOf(piece) - centroidOf(then)).norm(), kAssociation);
  EXPECT_EQ(unknowns.notRetriedBecause(centroidOf(piece), piece_sides, cameraAt(180.0), piece), "");
}

TEST(UnknownObjects, ACandidateReachingOutOfTheUnknownObjectsBoxIsTried) {
  const std::vector<Eigen::Vector3f> then = joined(faceOfTheBox(0, 1), faceOfTheBox(2, 1));
  UnknownObjects unknowns(kAssociation, UnknownRetryParameters());
  unknowns.remember(centroidOf(then), kSides, cameraAt(0.0), then);
  // The box's -x face and, beside it, as many points of something else 5 cm further on.
  std::vector<Eigen::Vector3f> now = faceOfTheBox(0, -1);
  const std::size_t face = now.size();
  for (std::size_t i = 0; i < face; ++i) now.push_back(now[i] - Eigen::Vector3f(0.05f, 0, 0));
  EXPECT_EQ(unknowns.notRetriedBecause(centroidOf(now), kSides, cameraAt(180.0), now), "");
}

// Points every 5 mm through the box round `center` with half sides `half`.
std::vector<Eigen::Vector3f> pointsThrough(const Eigen::Vector3d& center,
                                           const Eigen::Vector3d& half) {
  std::vector<Eigen::Vector3f> points;
  for (double x = -half.x(); x <= half.x() + 1e-9; x += 0.005) {
    for (double y = -half.y(); y <= half.y() + 1e-9; y += 0.005) {
      for (double z = -half.z(); z <= half.z() + 1e-9; z += 0.005) {
        points.push_back((center + Eigen::Vector3d(x, y, z)).cast<float>());
      }
    }
  }
  return points;
}

TEST(UnknownObjects, TheUnknownObjectAtTheCandidatesPlaceDecidesBeforeOneWhoseBoxHoldsIt) {
  // A union of things tried and unknown, 18 cm long, and a 5 cm piece tried alone 5 cm from
  // its centre (inside its box, but far smaller: its own object).
  UnknownObjects unknowns(kAssociation, UnknownRetryParameters());
  const Eigen::Vector3d piece = kObject + Eigen::Vector3d(0.05, 0, 0);
  unknowns.remember(kObject, Eigen::Vector3d(0.18, 0.10, 0.06), cameraAt(0.0),
                    pointsThrough(kObject, Eigen::Vector3d(0.09, 0.05, 0.03)));
  unknowns.remember(piece, Eigen::Vector3d(0.05, 0.04, 0.03), cameraAt(0.0),
                    pointsThrough(piece, Eigen::Vector3d(0.025, 0.02, 0.015)));
  ASSERT_EQ(unknowns.size(), 2u);
  // Now 14 cm of it show at the piece's place (a moved object, or the piece grown), inside the
  // union's box: the piece, at its place, says more of it shows, and it is tried. The union
  // would have said no more of it shows, from a nearby direction.
  const Eigen::Vector3d now = kObject + Eigen::Vector3d(0.035, 0, 0);
  const std::vector<Eigen::Vector3f> points = pointsThrough(now, Eigen::Vector3d(0.06, 0.04, 0.03));
  EXPECT_EQ(
      unknowns.notRetriedBecause(now, Eigen::Vector3d(0.14, 0.08, 0.06), cameraAt(0.0), points),
      "");
  // Away from the piece, the same inside the union's box is the union.
  const Eigen::Vector3d elsewhere = kObject - Eigen::Vector3d(0.035, 0, 0);
  EXPECT_EQ(unknowns.notRetriedBecause(elsewhere, Eigen::Vector3d(0.14, 0.08, 0.06), cameraAt(0.0),
                                       pointsThrough(elsewhere, Eigen::Vector3d(0.05, 0.04, 0.03))),
            "unknown from a nearby direction already");
}

TEST(UnknownObjects, BadParametersAreRefusedNamingThem) {
  UnknownRetryParameters parameters;
  parameters.max_tries = 0;
  EXPECT_THROW(UnknownObjects(0.05, parameters), Error);
  parameters = UnknownRetryParameters();
  parameters.retry_angle = -1.0;
  try {
    UnknownObjects unknowns(0.05, parameters);
    FAIL() << "a negative retry_angle was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("retry_angle"), std::string::npos);
  }
  EXPECT_THROW(UnknownObjects(std::nan(""), UnknownRetryParameters()), Error);
  parameters = UnknownRetryParameters();
  parameters.inside_fraction = 1.5;
  EXPECT_THROW(UnknownObjects(0.05, parameters), Error);
  parameters = UnknownRetryParameters();
  parameters.box_margin = -0.01;
  EXPECT_THROW(UnknownObjects(0.05, parameters), Error);
}

}  // namespace
}  // namespace vdc

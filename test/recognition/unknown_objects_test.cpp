#include "view_direction_classification/recognition/unknown_objects.h"

#include <gtest/gtest.h>

#include <cmath>

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
}

}  // namespace
}  // namespace vdc

#include "view_direction_classification/ros/bingham_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/bingham_test_distributions.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Three components of different shapes (sharp, girdle-like, uniform) with random axes.
BinghamMixture makeMixture() {
  return BinghamMixture({0.5, 0.3, 0.2},
                        {makeDistribution({-80.0, -40.0, -3.0}, 1),
                         makeDistribution({-200.0, -200.0, 0.0}, 2), BinghamDistribution()});
}

// Expects fromBinghamMixtureMsg to throw vdc::Error whose message contains `part`.
void expectRefusal(const BinghamMixtureMsg& msg, const std::string& part) {
  try {
    fromBinghamMixtureMsg(msg);
    FAIL() << "accepted a bad message; expected an error mentioning '" << part << "'";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(BinghamConversions, MessageHoldsEveryComponentsFieldsInRosQuaternionOrder) {
  const BinghamMixture mixture = makeMixture();
  const BinghamMixtureMsg msg = toBinghamMixtureMsg(mixture);
  ASSERT_EQ(msg.components.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const BinghamComponentMsg& c = msg.components[k];
    const BinghamDistribution& b = mixture.component(k);
    EXPECT_EQ(c.weight, mixture.weight(k));
    EXPECT_EQ(c.normaliser, b.normalizer());
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(c.concentrations[i], b.concentrations()(i));
      EXPECT_EQ(c.axes[i].w, b.axis(i)(0));
      EXPECT_EQ(c.axes[i].x, b.axis(i)(1));
      EXPECT_EQ(c.axes[i].y, b.axis(i)(2));
      EXPECT_EQ(c.axes[i].z, b.axis(i)(3));
    }
    EXPECT_EQ(c.mode.w, b.mode()(0));
    EXPECT_EQ(c.mode.z, b.mode()(3));
  }
}

TEST(BinghamConversions, MixtureSurvivesMessageRoundTripExactly) {
  const BinghamMixture mixture = makeMixture();
  const BinghamMixture back = fromBinghamMixtureMsg(toBinghamMixtureMsg(mixture));
  ASSERT_EQ(back.size(), mixture.size());
  for (std::size_t k = 0; k < mixture.size(); ++k) {
    // Weights are renormalised by the mixture's constructor: equal to the last bit or two.
    EXPECT_NEAR(back.weight(k), mixture.weight(k), 4 * std::numeric_limits<double>::epsilon());
    EXPECT_EQ(back.component(k).concentrations(), mixture.component(k).concentrations());
    EXPECT_EQ(back.component(k).axes(), mixture.component(k).axes());
    EXPECT_EQ(back.component(k).normalizer(), mixture.component(k).normalizer());
    // The mode is recomputed from the axes (it is redundant in the message).
    EXPECT_LT((back.component(k).mode() - mixture.component(k).mode()).norm(), 1e-12);
  }
}

TEST(BinghamConversions, MessageSurvivesRoundTripThroughTheCoreExactly) {
  const BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  const BinghamMixtureMsg again = toBinghamMixtureMsg(fromBinghamMixtureMsg(msg));
  ASSERT_EQ(again.components.size(), msg.components.size());
  for (std::size_t k = 0; k < msg.components.size(); ++k) {
    EXPECT_EQ(again.components[k].concentrations, msg.components[k].concentrations);
    EXPECT_EQ(again.components[k].axes, msg.components[k].axes);
    EXPECT_EQ(again.components[k].normaliser, msg.components[k].normaliser);
  }
}

TEST(BinghamConversions, RefusesMessageWithoutComponents) {
  expectRefusal(BinghamMixtureMsg(), "no components");
}

TEST(BinghamConversions, RefusesNaNWeightNamingTheComponent) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[1].weight = std::numeric_limits<double>::quiet_NaN();
  expectRefusal(msg, "weight of component 1");
}

TEST(BinghamConversions, RefusesNegativeWeight) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[2].weight = -0.1;
  expectRefusal(msg, "weight of component 2");
}

TEST(BinghamConversions, RefusesWeightsSummingToZero) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  for (auto& c : msg.components) c.weight = 0.0;
  expectRefusal(msg, "positive, finite sum");
}

TEST(BinghamConversions, RefusesNonUnitAxisNamingAxisAndComponent) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[0].axes[2].x *= 1.01;
  expectRefusal(msg, "axis 2 of component 0");
}

TEST(BinghamConversions, RefusesUnitButNonOrthogonalAxes) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[1].axes[1] = msg.components[1].axes[0];
  expectRefusal(msg, "component 1 of the BinghamMixture message is not a valid Bingham");
}

TEST(BinghamConversions, RefusesPositiveConcentration) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[0].concentrations[2] = 1.0;
  expectRefusal(msg, "component 0");
}

TEST(BinghamConversions, RefusesModeThatIsNotOrthogonalToTheAxes) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[0].mode = msg.components[0].axes[0];
  expectRefusal(msg, "mode of component 0");
}

TEST(BinghamConversions, RefusesNormaliserThatDisagreesWithTheConcentrations) {
  BinghamMixtureMsg msg = toBinghamMixtureMsg(makeMixture());
  msg.components[2].normaliser *= 1.001;
  expectRefusal(msg, "normaliser of component 2");
}

}  // namespace
}  // namespace vdc

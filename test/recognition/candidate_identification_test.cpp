#include "view_direction_classification/recognition/candidate_identification.h"

#include <gtest/gtest.h>

#include <numeric>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

double sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

TEST(IdentityProbabilities, TheBestVerifiedModelWinsAndTheyAddUpToOne) {
  const IdentificationParameters parameters;
  const auto p = identityProbabilities({0.95, 0.85, std::nullopt}, parameters);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(sum(p), 1.0, 1e-12);
  EXPECT_GT(p[0], 0.8);
  EXPECT_GT(p[1], p[3]);  // 0.85 beats unknown's 0.8
  EXPECT_EQ(p[2], 0.0);   // no verified pose: not this model
}

TEST(IdentityProbabilities, ScoresBelowUnknownsLeaveTheObjectUnknown) {
  const IdentificationParameters parameters;
  const auto p = identityProbabilities({0.6, 0.7}, parameters);
  EXPECT_GT(p.back(), 0.8);
  const auto none = identityProbabilities({std::nullopt, std::nullopt}, parameters);
  EXPECT_EQ(none.back(), 1.0);
}

TEST(IdentityProbabilities, TwoModelsThatExplainItEquallyShareTheProbability) {
  const auto p = identityProbabilities({0.97, 0.97}, IdentificationParameters{});
  EXPECT_NEAR(p[0], p[1], 1e-12);
  EXPECT_LT(p[0], 0.5);  // neither reaches min_probability: the candidate stays unknown
}

TEST(IdentificationParameters, AreCheckedNamingTheBadOne) {
  IdentificationParameters bad;
  bad.temperature = 0.0;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.min_probability = 1.5;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.unknown_score = 2.0;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

TEST(IdentityEvidence, AViewThatVerifiesWellSupportsTheModelAndOneThatDoesNotOpposesIt) {
  const IdentificationParameters parameters;
  EXPECT_GT(identityEvidence(0.9, parameters), 0.0);
  EXPECT_LT(identityEvidence(0.7, parameters), 0.0);
  EXPECT_LT(identityEvidence(std::nullopt, parameters), 0.0);  // nothing verified
  // Capped: one view never decides alone.
  EXPECT_EQ(identityEvidence(1.0, parameters), parameters.max_view_evidence);
  EXPECT_EQ(identityEvidence(-1.0, parameters), -parameters.max_view_evidence);
}

}  // namespace
}  // namespace vdc

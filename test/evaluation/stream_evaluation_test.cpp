#include "view_direction_classification/evaluation/stream_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

// Small enough for a unit test: 2 views of one sequence as a 6 Hz stream, half a second at each.
EvaluationSettings smallStream() {
  EvaluationSettings settings;
  settings.sequences = 1;
  settings.views = 2;
  settings.candidates = 2;
  settings.seed = 7;
  settings.threads = 1;
  settings.stream_rate_hz = 6.0;
  settings.stream_dwell_s = 0.5;
  return settings;
}

StreamEvaluationResult runSmallStream(const EvaluationSettings& settings) {
  return evaluateStream(test::quickMugModel(), makeMug(), mugHandleAnchors(), settings);
}

TEST(StreamEvaluation, EveryFrameOfThePathGoesToTheEstimatorAndTheViewEndsAreSampled) {
  const EvaluationSettings settings = smallStream();
  const StreamEvaluationResult result = runSmallStream(settings);
  EXPECT_EQ(result.name, "stream_6hz");
  ASSERT_EQ(result.settings.size(), 1u);
  ASSERT_EQ(result.settings[0].sequences.size(), 1u);
  const StreamSequenceResult& sequence = result.settings[0].sequences[0];
  // The path of streamPath: frames every 1/6 s from 0 to its end.
  EXPECT_EQ(sequence.frames, static_cast<int>(sequence.duration_s * 6.0 + 0.5) + 1);
  EXPECT_EQ(sequence.fused + sequence.not_novel + sequence.skipped, sequence.frames);
  EXPECT_GE(sequence.featurised, sequence.fused);
  EXPECT_LT(sequence.featurised, sequence.frames) << "frame selection left every frame in";

  // The first frame is the first view; each fusion adds one distinct view.
  ASSERT_FALSE(sequence.fusions.empty());
  EXPECT_EQ(sequence.fusions.front().time_s, 0.0);
  for (std::size_t k = 0; k < sequence.fusions.size(); ++k) {
    EXPECT_EQ(sequence.fusions[k].views_fused, static_cast<int>(k) + 1);
    EXPECT_GE(sequence.fusions[k].map_error_deg, 0.0);
    EXPECT_LE(sequence.fusions[k].map_error_deg, 180.0);
    EXPECT_GT(sequence.fusions[k].cone90_deg, 0.0);
  }
  EXPECT_EQ(static_cast<int>(sequence.fusions.size()), sequence.fused);

  // One sample at the end of each dwell: view 1 at its last dwelling frame (0.5 s), view 2 at
  // the stream's last frame, which holds the final belief.
  ASSERT_EQ(sequence.view_ends.size(), 2u);
  EXPECT_EQ(sequence.view_ends[0].view, 1);
  EXPECT_EQ(sequence.view_ends[1].view, 2);
  EXPECT_NEAR(sequence.view_ends[0].time_s, 0.5, 1e-9);
  EXPECT_EQ(sequence.view_ends[1].time_s, sequence.duration_s);
  EXPECT_EQ(sequence.view_ends[1].views_fused, sequence.fused);
  EXPECT_EQ(sequence.view_ends[1].map_error_deg, sequence.fusions.back().map_error_deg);
  EXPECT_NEAR(sequence.featurisedPerSecond(), sequence.featurised / sequence.duration_s, 1e-12);

  EXPECT_GT(result.mean_render_ms, 0.0);
  EXPECT_GT(result.mean_featurised_update_ms, result.mean_unfeaturised_update_ms);
}

TEST(StreamEvaluation, MediansAndTheCalibrationFigureAtViewEndsAreOverSequences) {
  StreamSettingResult setting;
  auto sequence = [](double error1, double cone1, double error2, double cone2) {
    StreamSequenceResult result;
    result.view_ends = {{0.5, 1, 1, error1, cone1}, {2.0, 2, 2, error2, cone2}};
    return result;
  };
  setting.sequences = {sequence(100, 120, 10, 5), sequence(50, 40, 4, 6), sequence(20, 90, 6, 6)};
  EXPECT_EQ(setting.medianAtViewEnds(), Eigen::Vector2d(50, 6));
  // Inside when the error is at most the cone: 2 of 3 after view 1, 2 of 3 (6 <= 6) after view 2.
  EXPECT_TRUE(setting.insideCone90AtViewEnds().isApprox(Eigen::Vector2d(2.0 / 3, 2.0 / 3)));
}

TEST(StreamEvaluation, ResultsDoNotDependOnTheThreadCountAndSettingsShareTheNoise) {
  EvaluationSettings settings = smallStream();
  settings.sequences = 2;
  settings.stream_rate_hz = 3.0;
  settings.visibility_radii = {kAllVisible, kAllVisible};
  const StreamEvaluationResult one = runSmallStream(settings);
  settings.threads = 2;
  const StreamEvaluationResult two = runSmallStream(settings);
  ASSERT_EQ(one.settings.size(), 2u);
  for (const StreamEvaluationResult* result : {&one, &two}) {
    for (int s = 0; s < 2; ++s) {
      // Two identical settings see the same frames with the same noise: the same beliefs.
      const auto& a = result->settings[0].sequences[static_cast<std::size_t>(s)];
      const auto& b = result->settings[1].sequences[static_cast<std::size_t>(s)];
      ASSERT_EQ(a.fusions.size(), b.fusions.size());
      for (std::size_t k = 0; k < a.fusions.size(); ++k) {
        EXPECT_EQ(a.fusions[k].map_error_deg, b.fusions[k].map_error_deg);
      }
    }
  }
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t s = 0; s < 2; ++s) {
      const auto& a = one.settings[k].sequences[s];
      const auto& b = two.settings[k].sequences[s];
      EXPECT_EQ(a.frames, b.frames);
      ASSERT_EQ(a.view_ends.size(), b.view_ends.size());
      for (std::size_t v = 0; v < a.view_ends.size(); ++v) {
        EXPECT_EQ(a.view_ends[v].map_error_deg, b.view_ends[v].map_error_deg);
        EXPECT_EQ(a.view_ends[v].cone90_deg, b.view_ends[v].cone90_deg);
      }
    }
  }
  // Different sequences are different paths.
  EXPECT_NE(one.settings[0].sequences[0].duration_s, one.settings[0].sequences[1].duration_s);
}

TEST(StreamEvaluation, ACroppedStreamSeesOnlyTheHandleAndStillRuns) {
  EvaluationSettings settings = smallStream();
  settings.visibility_radii = {0.06};
  const StreamEvaluationResult result = runSmallStream(settings);
  ASSERT_EQ(result.settings.size(), 1u);
  EXPECT_EQ(result.settings[0].radius, 0.06);
  EXPECT_EQ(result.settings[0].sequences[0].view_ends.size(), 2u);
}

TEST(StreamEvaluation, TheCameraPoseErrorReachesTheStreamsEstimatorNotItsRenderer) {
  EvaluationSettings settings = smallStream();
  const StreamSequenceResult exact = runSmallStream(settings).settings[0].sequences[0];
  settings.camera_pose_error.bias_deg = 5.0;
  const StreamSequenceResult biased = runSmallStream(settings).settings[0].sequences[0];
  // The same frames (rendered from the true poses), other errors (measured against the truth).
  EXPECT_EQ(biased.frames, exact.frames);
  ASSERT_FALSE(biased.view_ends.empty());
  ASSERT_EQ(biased.view_ends.size(), exact.view_ends.size());
  EXPECT_NE(biased.view_ends.back().map_error_deg, exact.view_ends.back().map_error_deg);
}

TEST(StreamEvaluation, BadStreamSettingsAreRefused) {
  EvaluationSettings settings = smallStream();
  settings.stream_rate_hz = 0.0;
  EXPECT_THROW(runSmallStream(settings), Error) << "no stream to evaluate";
  for (const double bad : {-1.0, std::nan(""), HUGE_VAL}) {
    settings = smallStream();
    settings.stream_rate_hz = bad;
    EXPECT_THROW(checkEvaluationSettings(settings), Error) << bad;
    settings = smallStream();
    settings.stream_dwell_s = bad;
    EXPECT_THROW(checkEvaluationSettings(settings), Error) << bad;
  }
  EXPECT_THROW(evaluateStream(nullptr, makeMug(), {}, smallStream()), Error);
}

TEST(StreamEvaluation, NamesCarryTheRate) {
  EXPECT_EQ(streamEvaluationName(30.0), "stream_30hz");
  EXPECT_EQ(streamEvaluationName(7.5), "stream_7.5hz");
}

}  // namespace
}  // namespace vdc

#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include "view_direction_classification/common/progress.h"
#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/stream_path.h"
#include "view_direction_classification/geometry/triangle_mesh.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// The belief of a stream at one moment: after a fused frame, or at the end of a view's dwell.
struct StreamSample {
  double time_s = 0.0;  // the frame's time from the stream's start
  int view = 0;         // the path's view the camera is at or last left, from 1
  int views_fused = 0;  // distinct views in the belief
  double map_error_deg = 180.0;
  double cone90_deg = 180.0;  // BeliefSpread::cone90 [deg]
  bool insideCone90() const { return map_error_deg <= cone90_deg; }
};

// One sequence's stream through its views.
struct StreamSequenceResult {
  std::vector<StreamSample> fusions;    // after every fused frame, in time order
  std::vector<StreamSample> view_ends;  // at the last frame of each view's dwell (views entries)
  double duration_s = 0.0;              // time of the last frame
  int frames = 0;
  int featurised = 0;  // frames that passed the selection and had their features computed
  int fused = 0, not_novel = 0, skipped = 0;  // FrameOutcome counts
  // Frames featurised per second of stream.
  double featurisedPerSecond() const { return duration_s > 0.0 ? featurised / duration_s : 0.0; }
};

// The streams of one visibility setting.
struct StreamSettingResult {
  double radius = kAllVisible;
  std::vector<StreamSequenceResult> sequences;
  // Over sequences at the end of each view's dwell (views entries): the median MAP error and the
  // calibration figure (the fraction whose error is at most cone90_deg).
  Eigen::VectorXd medianAtViewEnds() const;
  Eigen::VectorXd insideCone90AtViewEnds() const;
};

struct StreamEvaluationResult {
  std::string name;  // "stream_<rate>hz"
  double rate_hz = 0.0;
  std::vector<StreamSettingResult> settings;
  // [ms] per frame: rendering (the evaluation's own cost, not the estimator's); the estimator's
  // update of a frame that was not featurised (its selection, or a skip before the features);
  // and of a featurised frame.
  double mean_render_ms = 0.0, mean_unfeaturised_update_ms = 0.0, mean_featurised_update_ms = 0.0;
};

// "stream_<rate>hz" with the rate as its shortest decimal ("stream_30hz", "stream_7.5hz").
std::string streamEvaluationName(double rate_hz);

// The random planner's views (the first settings.views candidates of each sequence) as a camera
// stream at settings.stream_rate_hz (streamPath: a dwell of settings.stream_dwell_s at each view,
// arcs at 10-30 deg/s between them, the arcs' rates seeded by (seed, sequence)). Every frame is
// rendered in full with fresh sensor noise (one generator per sequence, so every visibility
// setting sees the same noise), cropped as the setting says, and handed with its time and camera
// pose to a fresh OrientationEstimator per (sequence, setting), whose frame selection decides
// what is featurised and fused, as in the node. The MAP error and the belief's cone90 are taken
// after every fused frame and at the end of every dwell. (sequence, setting) runs are spread over
// OpenMP threads; results do not depend on the thread count. Throws vdc::Error for bad settings
// (a stream rate of 0 included), a mesh or anchors that do not fit, or an estimator error.
StreamEvaluationResult evaluateStream(std::shared_ptr<const ModelBundle> model,
                                      const TriangleMesh& mesh,
                                      const std::vector<Eigen::Vector3d>& anchors,
                                      const EvaluationSettings& settings,
                                      const ProgressCallback& progress = {});

}  // namespace vdc

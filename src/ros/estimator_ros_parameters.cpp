#include "estimator_ros_parameters.h"

#include <cmath>

#include "scene_ros_parameters.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

ParameterTable<EstimatorRosParameters> makeTable() {
  using P = EstimatorRosParameters;
  ParameterTable<P> table;
  // ADDING A PARAMETER: give it a field (here in EstimatorRosParameters, or in the core's
  // EstimatorParameters with its default), one line below, and its entry in
  // config/estimator.yaml. To make it tunable while the node runs, also add it with the same
  // name and type to cfg/OrientationEstimator.cfg: the node then applies it through this line
  // (and the core's OrientationEstimator::setParameters checks it again).
  table.addRequired("model", &P::model_path, nonEmptyString(), kModelMissing)
      .add("fixed_frame", &P::fixed_frame, frameName())
      .add("object_id", &P::object_id, anyString())
      .add("object_frame", &P::object_frame, frameName())
      .add("publish_tf", &P::publish_tf, anyBoolean())
      .add("tf_rate", &P::tf_rate, numberAtLeast(0.0, "0: only on each estimate"))
      .add("tf_timeout", &P::tf_timeout, numberAtLeast(0.0))
      .add("max_points", &P::max_points, integerAtLeast(1))
      .add("position_variance", &P::position_variance, numberAbove(0.0))
      .add("marker_samples", &P::marker_samples, integerBetween(0, 1000))
      .add("marker_length", &P::marker_length, numberAbove(0.0))
      .add("converged_cone90_deg", &P::converged_cone90_deg, numberAbove(0.0));
  // The core's settings.
  using E = EstimatorParameters;
  const auto core = [](auto member) { return fieldPath(&P::core, member); };
  table.add("n_feat", core(&E::n_feat), integerAtLeast(0, "0: the model's value"))
      .add("kappa", core(&E::kappa), numberAtLeast(0.0, "0: from the model's view spacing"))
      .add("max_components", core(&E::max_components), integerAtLeast(1))
      .add("min_features", core(&E::min_features), integerAtLeast(1))
      .add("min_weight", core(&E::min_weight), numberIn(0.0, 1.0, false))
      .add("psum_exponent", core(&E::psum_exponent), numberAbove(0.0))
      .add("belief_weight_floor", core(&E::belief_weight_floor), numberIn(0.0, 1.0, false))
      .add("sharpness_ratio", core(&E::sharpness_ratio),
           ParameterRule<double>{
               "0 (every product exact) or a finite number >= 1",
               [](double value) { return value == 0.0 || (std::isfinite(value) && value >= 1.0); }})
      .add("max_object_shift", core(&E::max_object_shift), numberAtLeast(0.0, "0: from the model"));
  // Frame selection on streams.
  using F = FrameSelectionParameters;
  const auto selection = [](auto member) { return fieldPath(&P::core, &E::selection, member); };
  table
      .add("min_view_separation", selection(&F::min_view_separation),
           finiteNumber("negative: half the model's view spacing"))
      .add("min_information_gain", selection(&F::min_information_gain),
           numberAtLeast(0.0, "0: off"))
      .add("independent_view_separation", selection(&F::independent_view_separation),
           finiteNumber("negative: the model's view spacing, 0: no tempering"))
      .add("max_camera_speed", selection(&F::max_camera_speed), numberAtLeast(0.0, "0: no check"))
      .add("max_camera_turn_rate", selection(&F::max_camera_turn_rate),
           numberAtLeast(0.0, "0: no check"));
  // Geometric refinement after each fused view (doc/method.md, "Refinement").
  using R = RefinementParameters;
  using H = HypothesisParameters;
  const auto refinement = [](auto member) {
    return fieldPath(&P::core, &E::refinement_parameters, member);
  };
  const auto hypotheses = [](auto member) {
    return fieldPath(&P::core, &E::refinement_parameters, &R::hypotheses, member);
  };
  table.addChoice("refinement", core(&E::refinement), refinementModeChoices())
      .add("refinement_max_components", hypotheses(&H::max_components), integerAtLeast(1))
      .add("refinement_girdle_step_deg", hypotheses(&H::girdle_step_deg),
           ParameterRule<double>{"a number in (0, 180]",
                                 [](double value) { return value > 0.0 && value <= 180.0; }})
      .add("refinement_max_refined", refinement(&R::max_refined),
           integerAtLeast(0, "0: every start"))
      .add("refinement_piece_placements", refinement(&R::piece_placements),
           integerAtLeast(0, "0: at the visible part's centroid only"))
      .add("refinement_min_score", refinement(&R::min_score), numberIn(-1.0, 1.0, true))
      .add("refinement_restart_seeds", refinement(&R::restart_seeds),
           integerAtLeast(0, "0: no restarts"))
      .add("refinement_views", core(&E::refinement_views), integerAtLeast(1, "1: this view alone"))
      .add("refinement_depth_noise_at_1m",
           fieldPath(&P::core, &E::refinement_parameters, &R::verification,
                     &VerificationParameters::depth_noise_at_1m),
           numberAtLeast(0.0, "0: the fixed tolerances alone"))
      .add("camera_pose_uncertainty_deg",
           fieldPath(&P::core, &E::refined_fusion,
                     &RefinedFusionParameters::camera_pose_uncertainty_deg),
           numberAtLeast(0.0, "0: exact camera poses"))
      .add("camera_pose_uncertainty_mm",
           fieldPath(&P::core, &E::refined_fusion,
                     &RefinedFusionParameters::camera_pose_uncertainty_mm),
           numberAtLeast(0.0, "0: exact camera poses"))
      .add("model_error_mm",
           fieldPath(&P::core, &E::refined_fusion, &RefinedFusionParameters::model_error_mm),
           numberAtLeast(0.0, "0: the mesh is the object"))
      .add("refinement_search_below_score",
           fieldPath(&P::core, &E::belief_check, &BeliefCheckParameters::search_below_score),
           numberIn(0.0, 1.0, true))
      .add("refinement_rebuild_margin",
           fieldPath(&P::core, &E::belief_check, &BeliefCheckParameters::rebuild_margin),
           numberIn(0.0, 1.0, true));
  // Segmentation (its region of interest is in the fixed frame).
  using S = SegmentationParameters;
  const auto segmentation = [](auto member) {
    return fieldPath(&P::core, &E::segmentation, member);
  };
  table
      .addChoice("segmentation", segmentation(&S::mode),
                 std::vector<std::pair<std::string, SegmentationMode>>{
                     {"none", SegmentationMode::kNone},
                     {"region_of_interest", SegmentationMode::kRegionOfInterest},
                     {"tabletop", SegmentationMode::kTabletop},
                     {"scene", SegmentationMode::kScene},
                     {"labels", SegmentationMode::kLabels}})
      .addPoint("roi_centre", segmentation(&S::roi_centre), "in the fixed frame")
      .add("roi_radius", segmentation(&S::roi_radius), numberAbove(0.0))
      .add("plane_distance", segmentation(&S::plane_distance), numberAbove(0.0))
      .add("min_plane_fraction", segmentation(&S::min_plane_fraction), numberIn(0.0, 1.0, true))
      .add("cluster_tolerance", segmentation(&S::cluster_tolerance), numberAbove(0.0))
      .add("min_cluster_points", segmentation(&S::min_cluster_points), integerAtLeast(1))
      .add("extent_tolerance", segmentation(&S::extent_tolerance), numberIn(0.0, 1.0, false))
      .add("border_margin", segmentation(&S::border_margin), integerAtLeast(0));
  return table;
}

}  // namespace

const ParameterTable<EstimatorRosParameters>& estimatorParameterTable() {
  static const ParameterTable<EstimatorRosParameters> table = makeTable();
  return table;
}

EstimatorRosParameters readEstimatorRosParameters(const ros::NodeHandle& node, bool with_library) {
  EstimatorRosParameters p;
  const ParameterReader reader(node);
  estimatorParameterTable().read(reader, p, with_library);
  // diagnostic_updater reads ~diagnostic_period itself; the library's settings are the node's
  // too (one config serves both uses).
  std::vector<std::string> known = estimatorParameterTable().names();
  known.push_back("diagnostic_period");
  for (const std::string& name : sceneParameterNames()) known.push_back(name);
  reader.warnAboutUnknownParameters(known);
  if (p.object_frame == p.fixed_frame) {
    throw parameterError("object_frame", "different from ~fixed_frame",
                         describeParameterValue(p.object_frame));
  }
  return p;
}

}  // namespace vdc

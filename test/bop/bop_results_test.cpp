#include "view_direction_classification/bop/bop_results.h"

#include <gtest/gtest.h>

#include <sstream>

#include "view_direction_classification/bop/bop_scoring.h"
#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

TEST(BopResults, CsvHasBopsHeaderAndColumns) {
  BopEstimate estimate;
  estimate.scene_id = 2;
  estimate.im_id = 15;
  estimate.obj_id = 7;
  estimate.score = 0.5;
  estimate.camera_from_model.R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  estimate.camera_from_model.t = Eigen::Vector3d(1.5, -2, 800.25);
  estimate.time_s = 0.125;
  std::ostringstream csv;
  writeBopResultsCsv(csv, {estimate});
  EXPECT_EQ(csv.str(),
            "scene_id,im_id,obj_id,score,R,t,time\n"
            "2,15,7,0.5,0 -1 0 1 0 0 0 0 1,1.5 -2 800.25,0.125\n");
}

// Two instances of object 1 (diameter 100 mm) in one image, and one of object 2 never estimated.
struct ScoringCase {
  std::vector<BopTarget> targets{{0, 0, 1, 2}, {0, 0, 2, 1}};
  BopScoringTruth truth;
  std::map<int, BopScoringModel> models;
  ScoringCase() {
    BopSceneFiles& scene = truth.scenes[0];
    scene.cameras[0].intrinsics = {640, 480, 500, 500, 320, 240};
    scene.ground_truth[0] = {{1, {Eigen::Matrix3d::Identity(), {0, 0, 1000}}},
                             {1, {Eigen::Matrix3d::Identity(), {300, 0, 1000}}},
                             {2, {Eigen::Matrix3d::Identity(), {0, 200, 1000}}}};
    BopScoringModel model;
    model.info.diameter = 100;
    model.vertices = {{-50, 0, 0}, {50, 0, 0}};
    models[1] = model;
    models[2] = model;
  }
};

BopEstimate estimateAt(const Eigen::Vector3d& t, double score) {
  BopEstimate e;
  e.obj_id = 1;
  e.score = score;
  e.camera_from_model.t = t;
  return e;
}

TEST(BopResults, RecallOfHandComputedCase) {
  const ScoringCase c;
  // One exact, one 19 mm (0.19 diameters) off along the optical axis, and a third, lower-scored
  // estimate beyond inst_count that must not count.
  const std::vector<BopEstimate> estimates{estimateAt({300, 0, 1019}, 0.9),
                                           estimateAt({0, 0, 1000}, 0.8),
                                           estimateAt({0, 0, 1000}, 0.1)};
  const BopScores scores = scoreBopEstimates(estimates, c.targets, c.truth, c.models);
  ASSERT_EQ(scores.per_object.size(), 2u);
  const BopRecall& one = scores.per_object[0];
  EXPECT_EQ(one.targets, 2);
  EXPECT_EQ(one.estimates, 2);
  // MSSD: thresholds 0.05..0.15 find only the exact one (1/2), 0.20..0.50 both.
  EXPECT_NEAR(one.mssd, (3 * 0.5 + 7 * 1.0) / 10, 1e-12);
  // MSPD: the off one moves the vertices' projections by at most 500 * 350 * (1/1000 - 1/1019)
  // = 3.26 px: correct from 5 px on, like the exact one.
  EXPECT_NEAR(one.mspd, 1.0, 1e-12);
  EXPECT_EQ(scores.per_object[1].obj_id, 2);
  EXPECT_EQ(scores.per_object[1].mssd, 0.0);
  EXPECT_EQ(scores.overall.targets, 3);
  EXPECT_NEAR(scores.overall.mssd, (3 * 1.0 / 3 + 7 * 2.0 / 3) / 10, 1e-12);
}

TEST(BopResults, EstimatesOfAnotherImageAreNotMatched) {
  const ScoringCase c;
  BopEstimate elsewhere = estimateAt({0, 0, 1000}, 1.0);
  elsewhere.im_id = 1;
  c.truth.scenes.at(0);  // image 1 has no camera, but it is no target either
  const BopScores scores = scoreBopEstimates({elsewhere}, c.targets, c.truth, c.models);
  EXPECT_EQ(scores.overall.mssd, 0.0);
  EXPECT_EQ(scores.overall.estimates, 0);
}

TEST(BopResults, VsdIsScoredWithAMeshAndADepthImage) {
  ScoringCase c;
  c.targets = {{0, 0, 1, 1}};
  c.truth.scenes[0].ground_truth[0] = {{1, {Eigen::Matrix3d::Identity(), {0, 0, 600}}}};
  BopScoringModel& model = c.models[1];
  model.mesh_m = makeBoxMesh({0.1, 0.06, 0.04});
  model.vertices = verticesInMillimetres(model.mesh_m);
  BopCamera& camera = c.truth.scenes[0].cameras[0];
  camera.depth_scale = 0.1;
  const BopEstimate exact = estimateAt({0, 0, 600}, 1.0);
  EXPECT_FALSE(scoreBopEstimates({exact}, c.targets, c.truth, c.models).overall.vsd_scored);

  const DepthRenderer renderer(model.mesh_m, camera.intrinsics);
  c.truth.depths[{0, 0}] =
      quantiseDepth(renderer.renderDepth(isometryOf(exact.camera_from_model)), 640, 480, 0.1);
  const BopScores exact_scores = scoreBopEstimates({exact}, c.targets, c.truth, c.models);
  EXPECT_TRUE(exact_scores.overall.vsd_scored);
  EXPECT_EQ(exact_scores.overall.vsd, 1.0);
  // 300 mm aside: no overlap, VSD 1 at every tau, wrong at every threshold.
  const BopScores aside =
      scoreBopEstimates({estimateAt({300, 0, 600}, 1.0)}, c.targets, c.truth, c.models);
  EXPECT_EQ(aside.overall.vsd, 0.0);
}

}  // namespace
}  // namespace vdc

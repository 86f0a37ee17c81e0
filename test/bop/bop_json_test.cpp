#include "view_direction_classification/bop/bop_json.h"

#include <gtest/gtest.h>

#include <string>

#include "support/error_of.h"

namespace vdc {
namespace {

const CameraIntrinsics kSize{640, 480, 1, 1, 0, 0};

TEST(BopJson, SceneCameraReadsIntrinsicsScaleAndPose) {
  const std::string text = R"({"3": {"cam_K": [600, 0, 320.5, 0, 610, 240.25, 0, 0, 1],
      "depth_scale": 0.1, "cam_R_w2c": [0, -1, 0, 1, 0, 0, 0, 0, 1], "cam_t_w2c": [1, 2, 3]}})";
  const auto cameras = parseSceneCamera(text, "scene_camera.json", kSize);
  ASSERT_EQ(cameras.count(3), 1u);
  const BopCamera& camera = cameras.at(3);
  EXPECT_EQ(camera.intrinsics.width, 640);
  EXPECT_EQ(camera.intrinsics.fx, 600);
  EXPECT_EQ(camera.intrinsics.fy, 610);
  EXPECT_EQ(camera.intrinsics.cx, 320.5);
  EXPECT_EQ(camera.intrinsics.cy, 240.25);
  EXPECT_EQ(camera.depth_scale, 0.1);
  ASSERT_TRUE(camera.camera_from_world);
  EXPECT_EQ(camera.camera_from_world->R(0, 1), -1);  // row-major
  EXPECT_EQ(camera.camera_from_world->R(1, 0), 1);
  EXPECT_EQ(camera.camera_from_world->t, Eigen::Vector3d(1, 2, 3));
}

TEST(BopJson, SceneCameraWithoutPoseHasNone) {
  const auto cameras = parseSceneCamera(
      R"({"0": {"cam_K": [1, 0, 0, 0, 1, 0, 0, 0, 1], "depth_scale": 1}})", "c.json", kSize);
  EXPECT_FALSE(cameras.at(0).camera_from_world);
}

TEST(BopJson, MissingKeyIsRefusedWithFileAndKey) {
  const std::string message = test::errorOf([] {
    parseSceneCamera(R"({"7": {"cam_K": [1, 0, 0, 0, 1, 0, 0, 0, 1]}})", "scene_camera.json",
                     kSize);
  });
  EXPECT_NE(message.find("scene_camera.json"), std::string::npos) << message;
  EXPECT_NE(message.find("image 7"), std::string::npos) << message;
  EXPECT_NE(message.find("depth_scale"), std::string::npos) << message;
}

TEST(BopJson, WrongTypesAndSizesAreRefused) {
  EXPECT_NE(test::errorOf([] {
              parseSceneGt(
                  R"({"0": [{"obj_id": 1, "cam_R_m2c": [1, 0, 0], "cam_t_m2c": [0, 0, 0]}]})",
                  "scene_gt.json");
            }).find("cam_R_m2c"),
            std::string::npos);
  EXPECT_NE(test::errorOf([] {
              parseSceneGt(R"({"0": [{"obj_id": "1", "cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1],
                                      "cam_t_m2c": [0, 0, 0]}]})",
                           "scene_gt.json");
            }).find("obj_id"),
            std::string::npos);
  EXPECT_NE(test::errorOf([] { parseSceneGt(R"({"x": []})", "scene_gt.json"); }).find("no image"),
            std::string::npos);
  EXPECT_NE(test::errorOf([] {
              parseModelsInfo(R"({"1": {"diameter": -3}})", "models_info.json");
            }).find("diameter"),
            std::string::npos);
  EXPECT_NE(test::errorOf([] {
              parseTestTargets("{", "test_targets_bop19.json");
            }).find("test_targets_bop19.json: not valid JSON"),
            std::string::npos);
  EXPECT_NE(
      test::errorOf([] { parseCameraInfo(R"({"width": 640})", "camera.json"); }).find("height"),
      std::string::npos);
}

TEST(BopJson, HalfACameraPoseIsRefused) {
  const std::string message = test::errorOf([] {
    parseSceneCamera(
        R"({"0": {"cam_K": [1, 0, 0, 0, 1, 0, 0, 0, 1], "depth_scale": 1, "cam_t_w2c": [0, 0, 0]}})",
        "scene_camera.json", kSize);
  });
  EXPECT_NE(message.find("cam_R_w2c"), std::string::npos) << message;
}

TEST(BopJson, ModelsInfoReadsSymmetries) {
  const auto info = parseModelsInfo(R"({"5": {"diameter": 100.5,
      "symmetries_discrete": [[-1, 0, 0, 4, 0, -1, 0, 5, 0, 0, 1, 6, 0, 0, 0, 1]],
      "symmetries_continuous": [{"axis": [0, 0, 1], "offset": [0, 0, 7]}]}})",
                                    "models_info.json");
  const BopModelInfo& model = info.at(5);
  EXPECT_EQ(model.diameter, 100.5);
  ASSERT_EQ(model.symmetries_discrete.size(), 1u);
  EXPECT_EQ(model.symmetries_discrete[0].R(0, 0), -1);
  EXPECT_EQ(model.symmetries_discrete[0].t, Eigen::Vector3d(4, 5, 6));
  ASSERT_EQ(model.symmetries_continuous.size(), 1u);
  EXPECT_EQ(model.symmetries_continuous[0].offset, Eigen::Vector3d(0, 0, 7));
}

TEST(BopJson, WrittenFilesReadBackExactly) {
  BopCamera camera;
  camera.intrinsics = {640, 480, 525.1234567890123, 524.9, 319.5, 239.5};
  camera.depth_scale = 0.1;
  camera.camera_from_world =
      BopPose{Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
              Eigen::Vector3d(12.345678901, -0.1, 1e-7)};
  const auto cameras = parseSceneCamera(sceneCameraJson({{4, camera}}), "c", camera.intrinsics);
  EXPECT_EQ(cameras.at(4).intrinsics.fx, camera.intrinsics.fx);
  EXPECT_EQ(cameras.at(4).camera_from_world->R, camera.camera_from_world->R);
  EXPECT_EQ(cameras.at(4).camera_from_world->t, camera.camera_from_world->t);

  BopModelInfo info;
  info.diameter = 123.456;
  info.symmetries_discrete.push_back(
      {Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix(), {1, 2, 3}});
  info.symmetries_continuous.push_back({Eigen::Vector3d::UnitY(), {0, 4, 0}});
  const auto models = parseModelsInfo(modelsInfoJson({{2, info}}), "m");
  EXPECT_EQ(models.at(2).diameter, info.diameter);
  EXPECT_EQ(models.at(2).symmetries_discrete[0].R, info.symmetries_discrete[0].R);
  EXPECT_EQ(models.at(2).symmetries_discrete[0].t, info.symmetries_discrete[0].t);
  EXPECT_EQ(models.at(2).symmetries_continuous[0].axis, info.symmetries_continuous[0].axis);

  const std::vector<BopTarget> targets{{1, 2, 3, 4}, {0, 9, 8, 1}};
  const auto read = parseTestTargets(testTargetsJson(targets), "t");
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].scene_id, 1);
  EXPECT_EQ(read[0].im_id, 2);
  EXPECT_EQ(read[0].obj_id, 3);
  EXPECT_EQ(read[0].inst_count, 4);
  EXPECT_EQ(read[1].im_id, 9);
}

}  // namespace
}  // namespace vdc

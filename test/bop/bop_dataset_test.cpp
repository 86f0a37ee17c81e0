#include "view_direction_classification/bop/bop_dataset.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_of.h"
#include "support/temporary_directory_test.h"
#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

namespace fs = std::filesystem;

using BopDatasetTest = test::TemporaryDirectoryTest;

// A rendered two-image scene of one box, the camera turning about the box between the images.
struct RenderedScene {
  TriangleMesh box = makeBoxMesh({0.1, 0.06, 0.04});
  CameraIntrinsics intrinsics{160, 120, 130.5, 131.25, 79.5, 59.75};
  std::map<int, BopImage> images;
  std::vector<std::vector<float>> depths_m;
};

RenderedScene renderScene() {
  RenderedScene scene;
  const DepthRenderer renderer(scene.box, scene.intrinsics);
  const Eigen::Isometry3d world_from_box(Eigen::Translation3d(0.01, -0.02, 0.0) *
                                         Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  for (int im_id = 0; im_id < 2; ++im_id) {
    const Eigen::Isometry3d camera_from_world = cameraFromObject(
        Eigen::Vector3d(std::cos(im_id * 0.5), std::sin(im_id * 0.5), 0.8), 0.45, 0.1 * im_id);
    const Eigen::Isometry3d camera_from_box = camera_from_world * world_from_box;
    BopImage image;
    image.camera.intrinsics = scene.intrinsics;
    image.camera.depth_scale = 0.1;
    image.camera.camera_from_world = bopPoseOf(camera_from_world);
    scene.depths_m.push_back(renderer.renderDepth(camera_from_box));
    image.depth = quantiseDepth(scene.depths_m.back(), scene.intrinsics.width,
                                scene.intrinsics.height, image.camera.depth_scale);
    image.objects.push_back({7, bopPoseOf(camera_from_box)});
    scene.images[im_id * 5] = image;
  }
  return scene;
}

void writeDataset(const fs::path& root, const RenderedScene& scene) {
  BopModelInfo info;
  info.diameter = bopDiameter(scene.box);
  writeBopDatasetFiles(root.string(), scene.intrinsics, 0.1, {{7, info}},
                       {{3, 0, 7, 1}, {3, 5, 7, 1}});
  writeBopModel(root.string(), 7, scene.box);
  writeBopScene(root.string(), "test", 3, scene.images);
}

TEST_F(BopDatasetTest, RenderedSceneReadsBackExactly) {
  const fs::path root = directory();
  const RenderedScene scene = renderScene();
  writeDataset(root, scene);

  const BopDatasetReader reader(root.string(), "test");
  EXPECT_EQ(reader.sceneIds(), std::vector<int>{3});
  EXPECT_NEAR(reader.modelsInfo().at(7).diameter,
              1000.0 * std::sqrt(0.1 * 0.1 + 0.06 * 0.06 + 0.04 * 0.04), 1e-3);
  const BopSceneFiles files = reader.scene(3);
  ASSERT_EQ(files.cameras.size(), 2u);
  int index = 0;
  for (const auto& [im_id, written] : scene.images) {
    const BopCamera& camera = files.cameras.at(im_id);
    EXPECT_EQ(camera.intrinsics.width, scene.intrinsics.width);
    EXPECT_EQ(camera.intrinsics.fx, scene.intrinsics.fx);
    EXPECT_EQ(camera.intrinsics.fy, scene.intrinsics.fy);
    EXPECT_EQ(camera.intrinsics.cx, scene.intrinsics.cx);
    EXPECT_EQ(camera.intrinsics.cy, scene.intrinsics.cy);
    EXPECT_EQ(camera.depth_scale, 0.1);
    EXPECT_EQ(camera.camera_from_world->R, written.camera.camera_from_world->R);
    EXPECT_EQ(camera.camera_from_world->t, written.camera.camera_from_world->t);
    const BopGtObject& object = files.ground_truth.at(im_id).at(0);
    EXPECT_EQ(object.obj_id, 7);
    EXPECT_EQ(object.camera_from_model.R, written.objects[0].camera_from_model.R);
    EXPECT_EQ(object.camera_from_model.t, written.objects[0].camera_from_model.t);
    // Depth within the quantum: 0.1 mm, half of it by rounding.
    const BopDepthImage depth = reader.depth(3, im_id);
    const auto cloud = bopDepthCloud(depth, camera);
    const std::vector<float>& truth = scene.depths_m[index++];
    int hits = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const float z = cloud.points[i].z;
      if (truth[i] == 0.0f) {
        EXPECT_TRUE(std::isnan(z));
        continue;
      }
      ++hits;
      EXPECT_NEAR(z, truth[i], 0.05e-3 + 1e-7);
    }
    EXPECT_GT(hits, 500);
  }
  ASSERT_EQ(reader.targets().size(), 2u);
  EXPECT_EQ(reader.targets()[1].im_id, 5);
  // The mesh comes back in metres; loadMesh may reorder joined vertices, so compare as sets.
  const TriangleMesh mesh = reader.modelMesh(7);
  ASSERT_EQ(mesh.vertices.size(), scene.box.vertices.size());
  for (const Eigen::Vector3f& vertex : mesh.vertices) {
    float nearest = 1.0f;
    for (const Eigen::Vector3f& original : scene.box.vertices) {
      nearest = std::min(nearest, (vertex - original).norm());
    }
    EXPECT_LT(nearest, 1e-7f);
  }
}

TEST_F(BopDatasetTest, DamagedFilesAreRefusedWithTheirName) {
  const fs::path root = directory();
  writeDataset(root, renderScene());
  const fs::path scene_gt = root / "test" / "000003" / "scene_gt.json";
  std::ofstream(scene_gt) << R"({"0": [{"obj_id": 7, "cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1]}]})";
  const BopDatasetReader reader(root.string(), "test");
  const std::string gt_message = test::errorOf([&] { reader.scene(3); });
  EXPECT_NE(gt_message.find(scene_gt.string()), std::string::npos) << gt_message;
  EXPECT_NE(gt_message.find("cam_t_m2c"), std::string::npos) << gt_message;

  const fs::path depth = root / "test" / "000003" / "depth" / "000005.png";
  writeBopDepthPng({3, 3, std::vector<std::uint16_t>(9, 1)}, depth.string());
  const std::string depth_message = test::errorOf([&] { reader.depth(3, 5); });
  EXPECT_NE(depth_message.find(depth.string()), std::string::npos) << depth_message;

  fs::remove(root / "models" / "models_info.json");
  const std::string info_message = test::errorOf([&] { BopDatasetReader(root.string(), "test"); });
  EXPECT_NE(info_message.find("models_info.json"), std::string::npos) << info_message;
}

}  // namespace
}  // namespace vdc

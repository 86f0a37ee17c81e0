#include "bop_rendering.h"

#include <cmath>
#include <random>

#include "view_direction_classification/bop/bop_units.h"

namespace vdc::tools {
namespace {

// Scene generation names models; BOP numbers them. The name is the obj_id's decimal text.
std::vector<KnownModel> knownModels(const std::map<int, TriangleMesh>& models) {
  std::vector<KnownModel> known;
  for (const auto& [obj_id, mesh] : models) known.push_back({std::to_string(obj_id), mesh});
  return known;
}

// The rendered (possibly noisy) cloud's depth per pixel [m], 0 where nothing was hit.
std::vector<float> depthOf(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  std::vector<float> depth(cloud.size(), 0.0f);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (std::isfinite(cloud.points[i].z)) depth[i] = cloud.points[i].z;
  }
  return depth;
}

BopImage bopImageOf(const TableScene& scene, const SceneView& view,
                    const Eigen::Isometry3d& world_from_camera,
                    const BopRenderingSettings& settings) {
  BopImage image;
  image.camera.intrinsics = settings.intrinsics;
  image.camera.depth_scale = settings.depth_scale;
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  image.camera.camera_from_world = bopPoseOf(camera_from_world);
  image.depth = quantiseDepth(depthOf(view.cloud), settings.intrinsics.width,
                              settings.intrinsics.height, settings.depth_scale);
  for (const PlacedKnownObject& object : scene.known) {
    image.objects.push_back(
        {std::stoi(object.model), bopPoseOf(camera_from_world * object.part.world_from_part)});
  }
  return image;
}

// The image's targets: per object, its instances visible enough.
void addTargets(const TableScene& scene, const SceneView& view, int scene_id, int im_id,
                double min_visible_fraction, std::vector<BopTarget>* targets) {
  std::map<int, int> counts;
  for (std::size_t k = 0; k < scene.known.size(); ++k) {
    if (view.known_visible_fraction[k] >= min_visible_fraction) {
      ++counts[std::stoi(scene.known[k].model)];
    }
  }
  for (const auto& [obj_id, count] : counts) targets->push_back({scene_id, im_id, obj_id, count});
}

}  // namespace

int writeRenderedBopDataset(const std::string& root, const std::map<int, TriangleMesh>& models,
                            const std::vector<TriangleMesh>& distractors,
                            const BopRenderingSettings& settings) {
  checkSceneGenerationSettings(settings.generation);
  std::map<int, BopModelInfo> models_info;
  for (const auto& [obj_id, mesh] : models) {
    writeBopModel(root, obj_id, mesh);
    models_info[obj_id].diameter = bopDiameter(mesh);
  }
  std::vector<BopTarget> targets;
  int images_written = 0;
  for (int s = 0; s < settings.scenes; ++s) {
    const std::uint32_t seed = settings.seed + static_cast<std::uint32_t>(s);
    const TableScene scene =
        generateTableScene(knownModels(models), distractors, settings.generation, seed);
    const TableSceneRenderer renderer(scene, settings.intrinsics);
    std::mt19937 rng(seed);
    std::map<int, BopImage> images;
    for (std::size_t v = 0; v < scene.world_from_camera.size(); ++v) {
      const int im_id = static_cast<int>(v);
      const SceneView view =
          renderer.render(scene.world_from_camera[v], DepthNoiseModel{settings.noise}, &rng);
      images[im_id] = bopImageOf(scene, view, scene.world_from_camera[v], settings);
      addTargets(scene, view, s, im_id, settings.min_visible_fraction, &targets);
    }
    writeBopScene(root, "test", s, images);
    images_written += static_cast<int>(images.size());
  }
  writeBopDatasetFiles(root, settings.intrinsics, settings.depth_scale, models_info, targets);
  return images_written;
}

}  // namespace vdc::tools

#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_dataset.h"
#include "view_direction_classification/evaluation/scene_generation.h"

namespace vdc::tools {

// `vdc write-bop`'s work: seeded cluttered table scenes (evaluation/scene_generation.h) rendered
// and written as a BOP dataset, so that the BOP evaluation runs without a download.
struct BopRenderingSettings {
  int scenes = 1;
  std::uint32_t seed = 1;    // scene s uses seed + s, for its layout and its noise
  bool noise = true;         // the renderer's depth noise (DepthNoiseModel)
  double depth_scale = 0.1;  // [mm] per PNG value: 0.1 mm steps, up to 6.5 m
  // BOP lists as targets the instances of which at least this fraction is visible (its
  // visib_fract >= 0.1).
  double min_visible_fraction = 0.1;
  CameraIntrinsics intrinsics;
  SceneGenerationSettings generation;  // its `views` are the scene's images
};

// The models by obj_id, meshes in metres. Writes DIR/camera.json, DIR/models/ (mm PLY and
// models_info.json with each diameter; no symmetries: the meshes' are not known),
// DIR/test/SSSSSS/ (scene_camera.json with the camera poses, scene_gt.json, depth/*.png) and
// DIR/test_targets_bop19.json. Returns the number of images. Throws vdc::Error as the scene
// generation and the writers do.
int writeRenderedBopDataset(const std::string& root, const std::map<int, TriangleMesh>& models,
                            const std::vector<TriangleMesh>& distractors,
                            const BopRenderingSettings& settings);

}  // namespace vdc::tools

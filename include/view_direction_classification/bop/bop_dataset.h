#pragma once

#include <map>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_depth.h"
#include "view_direction_classification/bop/bop_types.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// The layout of a BOP dataset folder (bop_toolkit's docs/bop_datasets_format.md):
//   camera.json                      image size and default intrinsics
//   test_targets_bop19.json          the images' target objects
//   models/models_info.json          diameter and symmetries per object
//   models/obj_OOOOOO.ply            the meshes [mm]
//   <split>/SSSSSS/scene_camera.json per image: cam_K, depth_scale, optional cam_R/t_w2c
//   <split>/SSSSSS/scene_gt.json     per image: the objects' cam_R_m2c, cam_t_m2c [mm], obj_id
//   <split>/SSSSSS/depth/IIIIII.png  16-bit depth, value x depth_scale = mm
// (O, S, I: obj_id, scene_id, im_id as six digits.)
std::string bopSceneDirectory(const std::string& root, const std::string& split, int scene_id);
std::string bopDepthPath(const std::string& root, const std::string& split, int scene_id,
                         int im_id);
std::string bopModelPath(const std::string& root, int obj_id);

// Reads a dataset; every method throws vdc::Error naming the file and the problem for a
// missing or damaged file.
class BopDatasetReader {
 public:
  // Reads camera.json and models/models_info.json.
  BopDatasetReader(std::string root, std::string split);
  const CameraIntrinsics& camera() const { return camera_; }
  const std::map<int, BopModelInfo>& modelsInfo() const { return models_info_; }
  // The scene ids: the split's six-digit folders, ascending.
  std::vector<int> sceneIds() const;
  // scene_camera.json and scene_gt.json of a scene (scene_gt.json may be absent: no truth).
  BopSceneFiles scene(int scene_id) const;
  BopDepthImage depth(int scene_id, int im_id) const;
  std::vector<BopTarget> targets() const;  // test_targets_bop19.json
  // The object's mesh, converted to metres.
  TriangleMesh modelMesh(int obj_id) const;

 private:
  std::string root_, split_;
  CameraIntrinsics camera_;
  std::map<int, BopModelInfo> models_info_;
};

// Writing a dataset in the same layout. Each throws vdc::Error naming the file it cannot write.
// The dataset-wide files: camera.json, models/models_info.json, test_targets_bop19.json.
void writeBopDatasetFiles(const std::string& root, const CameraIntrinsics& camera,
                          double depth_scale, const std::map<int, BopModelInfo>& models_info,
                          const std::vector<BopTarget>& targets);
// A model's mesh, given in metres, written in mm.
void writeBopModel(const std::string& root, int obj_id, const TriangleMesh& mesh_m);
// One image of a scene, as written to the scene's files.
struct BopImage {
  BopCamera camera;
  BopDepthImage depth;
  std::vector<BopGtObject> objects;
};
void writeBopScene(const std::string& root, const std::string& split, int scene_id,
                   const std::map<int, BopImage>& images);

}  // namespace vdc

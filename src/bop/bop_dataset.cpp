#include "view_direction_classification/bop/bop_dataset.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "view_direction_classification/bop/bop_json.h"
#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_io.h"

namespace vdc {
namespace {

namespace fs = std::filesystem;

std::string sixDigits(int id) {
  char text[16];
  std::snprintf(text, sizeof(text), "%06d", id);
  return text;
}

// A JSON file is small (megabytes for a large scene_gt.json); 256 MiB is a damaged one.
constexpr std::uintmax_t kMaxJsonBytes = 256u << 20;

std::string readText(const fs::path& path) {
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) throw Error("cannot read " + path.string() + ": " + error.message());
  if (size > kMaxJsonBytes) throw Error(path.string() + ": larger than 256 MiB");
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  if (!file) throw Error("cannot read " + path.string());
  return text.str();
}

void writeText(const fs::path& path, const std::string& text) {
  std::error_code error;
  fs::create_directories(path.parent_path(), error);
  if (error) throw Error("cannot create " + path.parent_path().string() + ": " + error.message());
  std::ofstream file(path, std::ios::binary);
  file << text;
  if (!file) throw Error("cannot write " + path.string());
}

bool isSixDigits(const std::string& name) {
  return name.size() == 6 && name.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

std::string bopSceneDirectory(const std::string& root, const std::string& split, int scene_id) {
  return (fs::path(root) / split / sixDigits(scene_id)).string();
}

std::string bopDepthPath(const std::string& root, const std::string& split, int scene_id,
                         int im_id) {
  return (fs::path(bopSceneDirectory(root, split, scene_id)) / "depth" /
          (sixDigits(im_id) + ".png"))
      .string();
}

std::string bopModelPath(const std::string& root, int obj_id) {
  return (fs::path(root) / "models" / ("obj_" + sixDigits(obj_id) + ".ply")).string();
}

BopDatasetReader::BopDatasetReader(std::string root, std::string split)
    : root_(std::move(root)), split_(std::move(split)) {
  const fs::path camera_path = fs::path(root_) / "camera.json";
  camera_ = parseCameraInfo(readText(camera_path), camera_path.string());
  const fs::path info_path = fs::path(root_) / "models" / "models_info.json";
  models_info_ = parseModelsInfo(readText(info_path), info_path.string());
}

std::vector<int> BopDatasetReader::sceneIds() const {
  const fs::path split_path = fs::path(root_) / split_;
  std::error_code error;
  fs::directory_iterator entries(split_path, error);
  if (error) throw Error("cannot list " + split_path.string() + ": " + error.message());
  std::vector<int> ids;
  for (const fs::directory_entry& entry : entries) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && isSixDigits(name)) ids.push_back(std::stoi(name));
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

BopSceneFiles BopDatasetReader::scene(int scene_id) const {
  const fs::path directory = bopSceneDirectory(root_, split_, scene_id);
  BopSceneFiles files;
  const fs::path camera_path = directory / "scene_camera.json";
  files.cameras = parseSceneCamera(readText(camera_path), camera_path.string(), camera_);
  const fs::path gt_path = directory / "scene_gt.json";
  if (fs::exists(gt_path)) files.ground_truth = parseSceneGt(readText(gt_path), gt_path.string());
  return files;
}

BopDepthImage BopDatasetReader::depth(int scene_id, int im_id) const {
  return readBopDepthPng(bopDepthPath(root_, split_, scene_id, im_id), camera_.width,
                         camera_.height);
}

std::vector<BopTarget> BopDatasetReader::targets() const {
  const fs::path path = fs::path(root_) / "test_targets_bop19.json";
  return parseTestTargets(readText(path), path.string());
}

TriangleMesh BopDatasetReader::modelMesh(int obj_id) const {
  return scaledMesh(loadMesh(bopModelPath(root_, obj_id)), 1.0 / kMillimetresPerMetre);
}

void writeBopDatasetFiles(const std::string& root, const CameraIntrinsics& camera,
                          double depth_scale, const std::map<int, BopModelInfo>& models_info,
                          const std::vector<BopTarget>& targets) {
  writeText(fs::path(root) / "camera.json", cameraInfoJson(camera, depth_scale));
  writeText(fs::path(root) / "models" / "models_info.json", modelsInfoJson(models_info));
  writeText(fs::path(root) / "test_targets_bop19.json", testTargetsJson(targets));
}

void writeBopModel(const std::string& root, int obj_id, const TriangleMesh& mesh_m) {
  const std::string path = bopModelPath(root, obj_id);
  std::error_code error;
  fs::create_directories(fs::path(path).parent_path(), error);
  if (error) throw Error("cannot create " + fs::path(path).parent_path().string());
  // ASCII: BOP's own models are ASCII or binary PLY, and ASCII keeps the mm vertices readable.
  saveMeshPly(scaledMesh(mesh_m, kMillimetresPerMetre), path, PlyEncoding::kAscii);
}

void writeBopScene(const std::string& root, const std::string& split, int scene_id,
                   const std::map<int, BopImage>& images) {
  const fs::path directory = bopSceneDirectory(root, split, scene_id);
  std::map<int, BopCamera> cameras;
  std::map<int, std::vector<BopGtObject>> ground_truth;
  for (const auto& [im_id, image] : images) {
    cameras[im_id] = image.camera;
    ground_truth[im_id] = image.objects;
  }
  writeText(directory / "scene_camera.json", sceneCameraJson(cameras));
  writeText(directory / "scene_gt.json", sceneGtJson(ground_truth));
  std::error_code error;
  fs::create_directories(directory / "depth", error);
  if (error) throw Error("cannot create " + (directory / "depth").string());
  for (const auto& [im_id, image] : images) {
    writeBopDepthPng(image.depth, bopDepthPath(root, split, scene_id, im_id));
  }
}

}  // namespace vdc

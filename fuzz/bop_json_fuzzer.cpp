// libFuzzer target: the BOP dataset's JSON readers (bop/bop_json.h), which `vdc evaluate-bop`
// runs on files it did not write. The first byte picks the reader (camera.json,
// scene_camera.json, scene_gt.json, models_info.json, test_targets_bop19.json; modulo 5), the
// rest is the file. A damaged file must throw vdc::Error; an accepted one must hold what the
// reader promises (positive focal lengths, depth scale and diameters, unit-free finite values,
// non-negative ids) and must read back the same after writing.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "view_direction_classification/bop/bop_json.h"
#include "view_direction_classification/common/error.h"

namespace {

const vdc::CameraIntrinsics kSize{640, 480, 1, 1, 0, 0};

void require(bool condition) {
  if (!condition) std::abort();
}

void checkCameras(const std::map<int, vdc::BopCamera>& cameras) {
  for (const auto& [im_id, camera] : cameras) {
    require(im_id >= 0 && camera.intrinsics.fx > 0 && camera.intrinsics.fy > 0);
    require(std::isfinite(camera.intrinsics.cx) && std::isfinite(camera.intrinsics.cy));
    require(camera.depth_scale > 0 && std::isfinite(camera.depth_scale));
    if (camera.camera_from_world) require(camera.camera_from_world->R.allFinite());
  }
  const auto again = vdc::parseSceneCamera(vdc::sceneCameraJson(cameras), "again", kSize);
  require(again.size() == cameras.size());
}

void checkGt(const std::map<int, std::vector<vdc::BopGtObject>>& gt) {
  for (const auto& [im_id, objects] : gt) {
    for (const vdc::BopGtObject& object : objects) {
      require(object.obj_id >= 0 && object.camera_from_model.t.allFinite());
    }
  }
  require(vdc::parseSceneGt(vdc::sceneGtJson(gt), "again").size() == gt.size());
}

void checkModels(const std::map<int, vdc::BopModelInfo>& models) {
  for (const auto& [obj_id, info] : models) {
    require(info.diameter > 0 && std::isfinite(info.diameter));
    for (const auto& symmetry : info.symmetries_continuous) require(symmetry.axis.norm() > 0);
  }
  require(vdc::parseModelsInfo(vdc::modelsInfoJson(models), "again").size() == models.size());
}

void parse(std::uint8_t reader, const std::string& text) {
  switch (reader % 5) {
    case 0: {
      const vdc::CameraIntrinsics k = vdc::parseCameraInfo(text, "fuzz");
      require(k.width >= 1 && k.height >= 1 && k.fx > 0 && k.fy > 0);
      break;
    }
    case 1:
      checkCameras(vdc::parseSceneCamera(text, "fuzz", kSize));
      break;
    case 2:
      checkGt(vdc::parseSceneGt(text, "fuzz"));
      break;
    case 3:
      checkModels(vdc::parseModelsInfo(text, "fuzz"));
      break;
    default:
      for (const vdc::BopTarget& t : vdc::parseTestTargets(text, "fuzz")) {
        require(t.scene_id >= 0 && t.im_id >= 0 && t.obj_id >= 0 && t.inst_count >= 0);
      }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0) return 0;
  try {
    parse(bytes[0], std::string(reinterpret_cast<const char*>(bytes + 1), size - 1));
  } catch (const vdc::Error&) {
    // refused with a message naming what is wrong
  }
  return 0;
}

#pragma once

#include <map>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_types.h"

namespace vdc {

// Parsing and writing the JSON files of a BOP dataset. Each parser takes the file's text and its
// name (for messages) and throws vdc::Error naming the file, the entry and the problem for text
// that is no JSON, a missing key, a value of the wrong type or size, or a value out of range
// (a non-positive focal length, depth scale or diameter, an image id that is no number). The
// writers produce what the parsers read back exactly (doubles are printed round-trip).

// image_size: width and height of the images (camera.json); the rest of the intrinsics come from
// each image's cam_K.
std::map<int, BopCamera> parseSceneCamera(const std::string& text, const std::string& name,
                                          const CameraIntrinsics& image_size);
std::map<int, std::vector<BopGtObject>> parseSceneGt(const std::string& text,
                                                     const std::string& name);
std::map<int, BopModelInfo> parseModelsInfo(const std::string& text, const std::string& name);
std::vector<BopTarget> parseTestTargets(const std::string& text, const std::string& name);

// The dataset's camera.json: the image size (scene_camera.json has none) and the default
// intrinsics. parseSceneCamera's intrinsics take their size from it.
CameraIntrinsics parseCameraInfo(const std::string& text, const std::string& name);
std::string cameraInfoJson(const CameraIntrinsics& intrinsics, double depth_scale);

std::string sceneCameraJson(const std::map<int, BopCamera>& cameras);
std::string sceneGtJson(const std::map<int, std::vector<BopGtObject>>& ground_truth);
std::string modelsInfoJson(const std::map<int, BopModelInfo>& models);
std::string testTargetsJson(const std::vector<BopTarget>& targets);

}  // namespace vdc

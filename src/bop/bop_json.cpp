#include "view_direction_classification/bop/bop_json.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

using nlohmann::json;

// Where in which file a value is, for messages: "scene_gt.json, image 3, entry 0, cam_t_m2c".
struct Place {
  const std::string& file;
  std::string path;
  Place at(const std::string& key) const { return {file, path.empty() ? key : path + ", " + key}; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(file + (path.empty() ? "" : ", " + path) + ": " + problem);
  }
};

json parseJson(const std::string& text, const std::string& name) {
  try {
    return json::parse(text);
  } catch (const json::exception& error) {
    throw Error(name + ": not valid JSON (" + error.what() + ")");
  }
}

const json& member(const json& object, const char* key, const Place& place) {
  if (!object.is_object()) place.fail("expected an object");
  const auto it = object.find(key);
  if (it == object.end()) place.fail(std::string("missing key \"") + key + "\"");
  return *it;
}

double number(const json& value, const Place& place) {
  if (!value.is_number()) place.fail("expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) place.fail("expected a finite number");
  return x;
}

double positiveNumber(const json& value, const Place& place) {
  const double x = number(value, place);
  if (!(x > 0.0)) place.fail("expected a positive number");
  return x;
}

int integer(const json& value, const Place& place) {
  if (!value.is_number_integer()) place.fail("expected an integer");
  const auto x = value.get<long long>();
  if (x < 0 || x > 1000000000) place.fail("expected an integer in 0..1e9");
  return static_cast<int>(x);
}

std::vector<double> numbers(const json& value, std::size_t count, const Place& place) {
  if (!value.is_array() || value.size() != count) {
    place.fail("expected an array of " + std::to_string(count) + " numbers");
  }
  std::vector<double> result;
  for (std::size_t i = 0; i < count; ++i) result.push_back(number(value[i], place));
  return result;
}

Eigen::Matrix3d rowMajor3x3(const json& value, const Place& place) {
  const std::vector<double> v = numbers(value, 9, place);
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = v[3 * r + c];
  }
  return m;
}

Eigen::Vector3d vector3(const json& value, const Place& place) {
  const std::vector<double> v = numbers(value, 3, place);
  return {v[0], v[1], v[2]};
}

// Image ids are the object's keys, written as decimal numbers ("0", "12").
int idKey(const std::string& key, const Place& place) {
  if (key.empty() || key.size() > 9 || key.find_first_not_of("0123456789") != std::string::npos) {
    place.fail("key \"" + key + "\" is no image or object id");
  }
  return std::stoi(key);
}

const json& topObject(const json& document, const Place& place) {
  if (!document.is_object()) place.fail("expected an object keyed by id");
  return document;
}

BopPose pose(const json& object, const char* r_key, const char* t_key, const Place& place) {
  BopPose result;
  result.R = rowMajor3x3(member(object, r_key, place), place.at(r_key));
  result.t = vector3(member(object, t_key, place), place.at(t_key));
  return result;
}

BopCamera camera(const json& entry, const CameraIntrinsics& image_size, const Place& place) {
  BopCamera result;
  const Eigen::Matrix3d K = rowMajor3x3(member(entry, "cam_K", place), place.at("cam_K"));
  result.intrinsics = image_size;
  result.intrinsics.fx = K(0, 0);
  result.intrinsics.fy = K(1, 1);
  result.intrinsics.cx = K(0, 2);
  result.intrinsics.cy = K(1, 2);
  if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0)) place.at("cam_K").fail("focal lengths must be > 0");
  result.depth_scale = positiveNumber(member(entry, "depth_scale", place), place.at("depth_scale"));
  // The camera pose is optional, but half of it is a damaged file.
  const bool has_r = entry.contains("cam_R_w2c"), has_t = entry.contains("cam_t_w2c");
  if (has_r != has_t) place.fail("cam_R_w2c and cam_t_w2c must come together");
  if (has_r) result.camera_from_world = pose(entry, "cam_R_w2c", "cam_t_w2c", place);
  return result;
}

json rowMajor(const Eigen::Matrix3d& m) {
  json values = json::array();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) values.push_back(m(r, c));
  }
  return values;
}

json vectorJson(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

Eigen::Matrix3d cameraMatrix(const CameraIntrinsics& k) {
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  K(0, 0) = k.fx, K(1, 1) = k.fy, K(0, 2) = k.cx, K(1, 2) = k.cy;
  return K;
}

BopPose symmetry4x4(const json& value, const Place& place) {
  const std::vector<double> v = numbers(value, 16, place);
  BopPose result;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) result.R(r, c) = v[4 * r + c];
    result.t[r] = v[4 * r + 3];
  }
  return result;
}

BopModelInfo modelInfo(const json& entry, const Place& place) {
  BopModelInfo info;
  info.diameter = positiveNumber(member(entry, "diameter", place), place.at("diameter"));
  if (entry.contains("symmetries_discrete")) {
    const Place list = place.at("symmetries_discrete");
    const json& values = entry["symmetries_discrete"];
    if (!values.is_array()) list.fail("expected an array");
    for (std::size_t i = 0; i < values.size(); ++i) {
      info.symmetries_discrete.push_back(symmetry4x4(values[i], list.at(std::to_string(i))));
    }
  }
  if (entry.contains("symmetries_continuous")) {
    const Place list = place.at("symmetries_continuous");
    const json& values = entry["symmetries_continuous"];
    if (!values.is_array()) list.fail("expected an array");
    for (std::size_t i = 0; i < values.size(); ++i) {
      const Place item = list.at(std::to_string(i));
      BopContinuousSymmetry symmetry;
      symmetry.axis = vector3(member(values[i], "axis", item), item.at("axis"));
      symmetry.offset = vector3(member(values[i], "offset", item), item.at("offset"));
      if (!(symmetry.axis.norm() > 0.0)) item.at("axis").fail("the axis must not be zero");
      info.symmetries_continuous.push_back(symmetry);
    }
  }
  return info;
}

}  // namespace

CameraIntrinsics parseCameraInfo(const std::string& text, const std::string& name) {
  const json document = parseJson(text, name);
  const Place place{name, ""};
  CameraIntrinsics k;
  k.width = integer(member(document, "width", place), place.at("width"));
  k.height = integer(member(document, "height", place), place.at("height"));
  k.fx = positiveNumber(member(document, "fx", place), place.at("fx"));
  k.fy = positiveNumber(member(document, "fy", place), place.at("fy"));
  k.cx = number(member(document, "cx", place), place.at("cx"));
  k.cy = number(member(document, "cy", place), place.at("cy"));
  // 1e5 x 1e5 pixels is far beyond any depth camera; larger is a damaged file.
  if (k.width < 1 || k.height < 1 || k.width > 100000 || k.height > 100000) {
    place.fail("image size must be 1..100000 pixels per side");
  }
  return k;
}

std::string cameraInfoJson(const CameraIntrinsics& k, double depth_scale) {
  const json document = {
      {"width", k.width}, {"height", k.height},        {"fx", k.fx}, {"fy", k.fy}, {"cx", k.cx},
      {"cy", k.cy},       {"depth_scale", depth_scale}};
  return document.dump(2) + "\n";
}

std::map<int, BopCamera> parseSceneCamera(const std::string& text, const std::string& name,
                                          const CameraIntrinsics& image_size) {
  const json document = parseJson(text, name);
  const Place top{name, ""};
  std::map<int, BopCamera> cameras;
  for (const auto& [key, entry] : topObject(document, top).items()) {
    const Place place = top.at("image " + key);
    cameras[idKey(key, place)] = camera(entry, image_size, place);
  }
  return cameras;
}

std::map<int, std::vector<BopGtObject>> parseSceneGt(const std::string& text,
                                                     const std::string& name) {
  const json document = parseJson(text, name);
  const Place top{name, ""};
  std::map<int, std::vector<BopGtObject>> ground_truth;
  for (const auto& [key, entries] : topObject(document, top).items()) {
    const Place image = top.at("image " + key);
    const int im_id = idKey(key, image);
    if (!entries.is_array()) image.fail("expected an array of objects");
    std::vector<BopGtObject>& objects = ground_truth[im_id];
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const Place place = image.at("entry " + std::to_string(i));
      BopGtObject object;
      object.obj_id = integer(member(entries[i], "obj_id", place), place.at("obj_id"));
      object.camera_from_model = pose(entries[i], "cam_R_m2c", "cam_t_m2c", place);
      objects.push_back(object);
    }
  }
  return ground_truth;
}

std::map<int, BopModelInfo> parseModelsInfo(const std::string& text, const std::string& name) {
  const json document = parseJson(text, name);
  const Place top{name, ""};
  std::map<int, BopModelInfo> models;
  for (const auto& [key, entry] : topObject(document, top).items()) {
    const Place place = top.at("object " + key);
    models[idKey(key, place)] = modelInfo(entry, place);
  }
  return models;
}

std::vector<BopTarget> parseTestTargets(const std::string& text, const std::string& name) {
  const json document = parseJson(text, name);
  const Place top{name, ""};
  if (!document.is_array()) top.fail("expected an array of targets");
  std::vector<BopTarget> targets;
  for (std::size_t i = 0; i < document.size(); ++i) {
    const Place place = top.at("target " + std::to_string(i));
    BopTarget target;
    target.scene_id = integer(member(document[i], "scene_id", place), place.at("scene_id"));
    target.im_id = integer(member(document[i], "im_id", place), place.at("im_id"));
    target.obj_id = integer(member(document[i], "obj_id", place), place.at("obj_id"));
    target.inst_count = integer(member(document[i], "inst_count", place), place.at("inst_count"));
    targets.push_back(target);
  }
  return targets;
}

std::string sceneCameraJson(const std::map<int, BopCamera>& cameras) {
  json document = json::object();
  for (const auto& [im_id, camera] : cameras) {
    json entry = {{"cam_K", rowMajor(cameraMatrix(camera.intrinsics))},
                  {"depth_scale", camera.depth_scale}};
    if (camera.camera_from_world) {
      entry["cam_R_w2c"] = rowMajor(camera.camera_from_world->R);
      entry["cam_t_w2c"] = vectorJson(camera.camera_from_world->t);
    }
    document[std::to_string(im_id)] = entry;
  }
  return document.dump(2) + "\n";
}

std::string sceneGtJson(const std::map<int, std::vector<BopGtObject>>& ground_truth) {
  json document = json::object();
  for (const auto& [im_id, objects] : ground_truth) {
    json entries = json::array();
    for (const BopGtObject& object : objects) {
      entries.push_back({{"obj_id", object.obj_id},
                         {"cam_R_m2c", rowMajor(object.camera_from_model.R)},
                         {"cam_t_m2c", vectorJson(object.camera_from_model.t)}});
    }
    document[std::to_string(im_id)] = entries;
  }
  return document.dump(2) + "\n";
}

std::string modelsInfoJson(const std::map<int, BopModelInfo>& models) {
  json document = json::object();
  for (const auto& [obj_id, info] : models) {
    json entry = {{"diameter", info.diameter}};
    if (!info.symmetries_discrete.empty()) {
      json list = json::array();
      for (const BopPose& s : info.symmetries_discrete) {
        json m = json::array();
        for (int r = 0; r < 4; ++r) {
          for (int c = 0; c < 4; ++c) {
            m.push_back(r == 3 ? (c == 3 ? 1.0 : 0.0) : (c == 3 ? s.t[r] : s.R(r, c)));
          }
        }
        list.push_back(m);
      }
      entry["symmetries_discrete"] = list;
    }
    if (!info.symmetries_continuous.empty()) {
      json list = json::array();
      for (const BopContinuousSymmetry& s : info.symmetries_continuous) {
        list.push_back({{"axis", vectorJson(s.axis)}, {"offset", vectorJson(s.offset)}});
      }
      entry["symmetries_continuous"] = list;
    }
    document[std::to_string(obj_id)] = entry;
  }
  return document.dump(2) + "\n";
}

std::string testTargetsJson(const std::vector<BopTarget>& targets) {
  json document = json::array();
  for (const BopTarget& t : targets) {
    document.push_back({{"im_id", t.im_id},
                        {"inst_count", t.inst_count},
                        {"obj_id", t.obj_id},
                        {"scene_id", t.scene_id}});
  }
  return document.dump(2) + "\n";
}

}  // namespace vdc

#include "view_direction_classification/recognition/model_library.h"

#include <set>

#include "view_direction_classification/common/error.h"

namespace vdc {

ModelLibrary::ModelLibrary(
    std::vector<std::pair<std::string, std::shared_ptr<const ModelBundle>>> models) {
  if (models.empty()) throw Error("the model library is empty: give at least one model");
  std::set<std::string> names;
  for (auto& [name, bundle] : models) {
    if (name.empty()) throw Error("a model of the library has an empty name");
    if (!names.insert(name).second) throw Error("the model library names '" + name + "' twice");
    if (!bundle) throw Error("the library's model '" + name + "' has no bundle");
    try {
      models_.push_back({name, bundle, ObjectExtent::of(bundle->bounds)});
    } catch (const Error& error) {
      throw Error("the library's model '" + name + "': " + error.what());
    }
  }
}

ModelLibrary ModelLibrary::load(
    const std::vector<std::pair<std::string, std::string>>& name_to_path) {
  std::vector<std::pair<std::string, std::shared_ptr<const ModelBundle>>> models;
  for (const auto& [name, path] : name_to_path) {
    try {
      models.emplace_back(name, std::make_shared<const ModelBundle>(loadModelBundle(path)));
    } catch (const Error& error) {
      throw Error("the library's model '" + name + "' (" + path +
                  ") cannot be loaded: " + error.what());
    }
  }
  return ModelLibrary(std::move(models));
}

int ModelLibrary::find(const std::string& name) const {
  for (int i = 0; i < size(); ++i) {
    if (models_[i].name == name) return i;
  }
  return -1;
}

std::vector<int> ModelLibrary::fitting(const Eigen::Vector3d& candidate_sides,
                                       double tolerance) const {
  std::vector<int> result;
  const double largest = candidate_sides.maxCoeff();
  for (int i = 0; i < size(); ++i) {
    const ObjectExtent& extent = models_[i].extent;
    if (largest > (1.0 + tolerance) * extent.diagonal()) continue;
    if (largest < (1.0 - tolerance) * extent.sizes.minCoeff()) continue;
    result.push_back(i);
  }
  return result;
}

bool ModelLibrary::sharesFeatureSettings() const {
  const TrainingParameters& first = models_.front().bundle->parameters;
  for (const LibraryModel& model : models_) {
    const TrainingParameters& p = model.bundle->parameters;
    if (p.keypoint_voxel != first.keypoint_voxel || p.normal_radius != first.normal_radius ||
        p.fpfh_radius != first.fpfh_radius || p.support_voxel != first.support_voxel ||
        p.min_neighbours != first.min_neighbours) {
      return false;
    }
  }
  return true;
}

}  // namespace vdc

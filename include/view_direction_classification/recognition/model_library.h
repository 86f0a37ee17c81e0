#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/estimation/tabletop_segmentation.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// One known object: its name (the tf frames and messages use it) and its trained bundle.
struct LibraryModel {
  std::string name;
  std::shared_ptr<const ModelBundle> bundle;
  ObjectExtent extent;  // from the bundle's bounds
};

// The known objects a scene is searched for (the node's `models`: a map from a name to a bundle;
// the single `model` is a library of one).
class ModelLibrary {
 public:
  // Throws vdc::Error naming the entry for an empty library, an empty or repeated name, a null
  // bundle or one without a usable bounding box.
  explicit ModelLibrary(
      std::vector<std::pair<std::string, std::shared_ptr<const ModelBundle>>> models);
  // Loads each bundle; throws vdc::Error naming the entry and its file when one cannot be loaded.
  static ModelLibrary load(const std::vector<std::pair<std::string, std::string>>& name_to_path);

  const std::vector<LibraryModel>& models() const { return models_; }
  int size() const { return static_cast<int>(models_.size()); }
  // The index of `name`, -1 if it is not in the library.
  int find(const std::string& name) const;

  // The models a candidate of these sides [m] (its box along its principal axes, largest first)
  // can be: a partial view is never larger than the model's diagonal, and its largest side is at
  // least the model's smallest side, both with `tolerance` (a fraction) to spare.
  std::vector<int> fitting(const Eigen::Vector3d& candidate_sides, double tolerance) const;

  // Whether every model computes its features with the same settings, so that one scene's
  // features could serve them all.
  bool sharesFeatureSettings() const;

 private:
  std::vector<LibraryModel> models_;
};

}  // namespace vdc

#include "shared_surfaces.h"

#include <mutex>
#include <vector>

namespace vdc {

namespace {

// What tells one bundle's samples from another's, besides its address.
struct SurfaceKey {
  const ModelBundle* bundle = nullptr;
  double spacing = 0.0, source_spacing = 0.0;
  std::size_t samples = 0;
  Eigen::Vector3f first = Eigen::Vector3f::Zero(), last = Eigen::Vector3f::Zero();
  Eigen::AlignedBox3d bounds;

  bool operator==(const SurfaceKey& other) const {
    return bundle == other.bundle && spacing == other.spacing &&
           source_spacing == other.source_spacing && samples == other.samples &&
           first == other.first && last == other.last && bounds.min() == other.bounds.min() &&
           bounds.max() == other.bounds.max();
  }
};

SurfaceKey keyOf(const ModelBundle& model, double spacing) {
  SurfaceKey key;
  key.bundle = &model;
  key.spacing = spacing;
  key.source_spacing = model.parameters.surface_spacing;
  key.samples = model.surface_points.size();
  if (!model.surface_points.empty()) {
    key.first = model.surface_points.front();
    key.last = model.surface_points.back();
  }
  key.bounds = model.bounds;
  return key;
}

}  // namespace

std::shared_ptr<const ModelSurface> sharedModelSurface(const ModelBundle& model, double spacing) {
  static std::mutex mutex;
  static std::vector<std::pair<SurfaceKey, std::weak_ptr<const ModelSurface>>> surfaces;
  const SurfaceKey key = keyOf(model, spacing);
  const std::lock_guard<std::mutex> lock(mutex);
  // Entries no refiner holds any more are dropped on the way: the list stays as short as the
  // surfaces in use.
  std::shared_ptr<const ModelSurface> found;
  for (auto it = surfaces.begin(); it != surfaces.end();) {
    std::shared_ptr<const ModelSurface> surface = it->second.lock();
    if (!surface) {
      it = surfaces.erase(it);
      continue;
    }
    if (it->first == key) found = surface;
    ++it;
  }
  if (found) return found;
  auto surface =
      std::make_shared<const ModelSurface>(model.surface_points, model.surface_normals,
                                           model.bounds, model.parameters.surface_spacing, spacing);
  surfaces.emplace_back(key, surface);
  return surface;
}

}  // namespace vdc

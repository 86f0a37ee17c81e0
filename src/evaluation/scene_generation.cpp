#include "view_direction_classification/evaluation/scene_generation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/table_footprint.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;
// Bisection steps for a contact distance: 2^-40 of a metre-sized bracket is far below a pixel.
constexpr int kBisectionSteps = 40;
// Half the contact gap is kept between any two footprints, so contact placements pass the test.
constexpr double kRequiredGapShare = 0.5;

// How an object chooses its place.
enum class PlacementMode { kScattered, kInContact, kInFront, kAnywhere };

// An object that is being placed: its mesh, turned by its yaw, with its origin at (0, 0).
struct TurnedObject {
  const TriangleMesh* mesh;
  Eigen::Matrix3d rotation;
  Footprint footprint;  // about its origin
  double lift;          // origin height that puts its lowest vertex on the table
};

// What has been placed so far, in placement order (known objects first).
struct PlacedFootprint {
  Footprint footprint;
  bool known;
};

// The camera path without the centre it looks at (known only once everything is placed).
struct CameraArc {
  std::vector<double> azimuth, elevation, distance;  // [rad], [rad], [m]
};

void checkRange(double low, double high, const std::string& what) {
  if (!std::isfinite(low) || !std::isfinite(high) || !(low <= high)) {
    throw Error("the scene generator's " + what + " range must be finite with min <= max, got " +
                std::to_string(low) + " .. " + std::to_string(high));
  }
}

void checkFraction(double fraction, const std::string& what) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) {
    throw Error("the scene generator's " + what + " must be in [0, 1], got " +
                std::to_string(fraction));
  }
}

// Indices 0..n-1 repeated to `count` entries, in a shuffled order.
std::vector<std::size_t> takeInTurn(std::size_t n, int count, std::mt19937& rng) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<std::size_t> taken;
  for (int i = 0; i < count; ++i) taken.push_back(order[static_cast<std::size_t>(i) % n]);
  return taken;
}

TurnedObject turned(const TriangleMesh& mesh, double yaw) {
  Eigen::Isometry3d rotation = Eigen::Isometry3d::Identity();
  rotation.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  double lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3f& v : mesh.vertices) lowest = std::min(lowest, double{v.z()});
  return {&mesh, rotation.linear(), footprintOf(mesh, rotation), -lowest};
}

double radiusAbout(const Footprint& footprint, const Eigen::Vector2d& point) {
  double radius = 0.0;
  for (const Eigen::Vector2d& c : footprint.corners) radius = std::max(radius, (c - point).norm());
  return radius;
}

// The origin for `object` on the ray from the neighbour's centre along unit `direction` where
// its footprint is `gap` away from the neighbour's (their separation grows convexly along it).
Eigen::Vector2d originAtGap(const TurnedObject& object, const Footprint& neighbour,
                            const Eigen::Vector2d& direction, double gap) {
  const Eigen::Vector2d start = neighbour.centre();
  auto excess = [&](double d) {
    return footprintSeparation(object.footprint.shifted(start + d * direction), neighbour) - gap;
  };
  double low = 0.0;
  double high = radiusAbout(neighbour, start) +
                radiusAbout(object.footprint, Eigen::Vector2d::Zero()) + gap + 0.01;
  if (excess(low) >= 0.0) return start;
  for (int step = 0; step < kBisectionSteps; ++step) {
    const double middle = 0.5 * (low + high);
    (excess(middle) < 0.0 ? low : high) = middle;
  }
  return start + high * direction;
}

Eigen::Vector2d unitAt(double angle) { return {std::cos(angle), std::sin(angle)}; }

class TablePlacer {
 public:
  TablePlacer(const SceneGenerationSettings& settings, double first_view_azimuth, std::mt19937& rng)
      : settings_(settings), towards_first_view_(first_view_azimuth), rng_(rng) {}

  // Places `mesh` and returns its pose; the index of a neighbour it was put against, or -1.
  Eigen::Isometry3d place(const TriangleMesh& mesh, PlacementMode mode, bool known,
                          int* neighbour) {
    std::uniform_real_distribution<double> yaw(0.0, 2.0 * M_PI);
    for (int attempt = 0; attempt < settings_.attempts_per_object; ++attempt) {
      // Half the attempts in the requested mode, then anywhere on the table, so that a crowded
      // scatter disc does not stop the scene.
      const bool keep_mode = attempt < settings_.attempts_per_object / 2;
      const TurnedObject object = turned(mesh, yaw(rng_));
      int chosen = -1;
      const Eigen::Vector2d origin =
          proposeOrigin(object, keep_mode ? mode : PlacementMode::kAnywhere, &chosen);
      const Footprint footprint = object.footprint.shifted(origin);
      if (!isFree(footprint)) continue;
      placed_.push_back({footprint, known});
      *neighbour = chosen;
      Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
      world_from_object.linear() = object.rotation;
      world_from_object.translation() = Eigen::Vector3d(origin.x(), origin.y(), object.lift);
      return world_from_object;
    }
    throw Error("the scene generator found no free place on the " +
                std::to_string(settings_.table_size.x()) + " x " +
                std::to_string(settings_.table_size.y()) + " m table for object " +
                std::to_string(placed_.size() + 1) + "; use a larger table or fewer objects");
  }

  bool anyKnownPlaced() const {
    return std::any_of(placed_.begin(), placed_.end(), [](const auto& p) { return p.known; });
  }

 private:
  Eigen::Vector2d proposeOrigin(const TurnedObject& object, PlacementMode mode, int* neighbour) {
    if (mode == PlacementMode::kInContact && !placed_.empty()) {
      *neighbour = pickPlaced(false);
      std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
      return originAtGap(object, placed_[*neighbour].footprint, unitAt(angle(rng_)),
                         settings_.contact_gap);
    }
    if (mode == PlacementMode::kInFront && anyKnownPlaced()) {
      const int hidden = pickPlaced(true);
      std::uniform_real_distribution<double> bearing(settings_.occluder_bearing_min_deg * kDegree,
                                                     settings_.occluder_bearing_max_deg * kDegree);
      std::uniform_real_distribution<double> gap(settings_.occluder_gap_min,
                                                 settings_.occluder_gap_max);
      std::bernoulli_distribution to_the_left(0.5);
      const double turn = to_the_left(rng_) ? bearing(rng_) : -bearing(rng_);
      const Eigen::Vector2d direction = unitAt(towards_first_view_ + turn);
      return originAtGap(object, placed_[hidden].footprint, direction, gap(rng_));
    }
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (mode == PlacementMode::kAnywhere) {
      return settings_.table_size.cwiseProduct(Eigen::Vector2d(unit(rng_), unit(rng_))) -
             settings_.table_size / 2.0;
    }
    // Uniform in the scatter disc.
    const double radius = settings_.scatter_radius * std::sqrt(unit(rng_));
    return radius * unitAt(2.0 * M_PI * unit(rng_));
  }

  // A random placed object (only known ones if `known_only`).
  int pickPlaced(bool known_only) {
    std::vector<int> candidates;
    for (std::size_t i = 0; i < placed_.size(); ++i) {
      if (!known_only || placed_[i].known) candidates.push_back(static_cast<int>(i));
    }
    std::uniform_int_distribution<std::size_t> pick(0, candidates.size() - 1);
    return candidates[pick(rng_)];
  }

  bool isFree(const Footprint& footprint) const {
    if (!footprintInsideRectangle(footprint, settings_.table_size)) return false;
    const double required = kRequiredGapShare * settings_.contact_gap;
    return std::all_of(placed_.begin(), placed_.end(), [&](const PlacedFootprint& other) {
      return footprintSeparation(footprint, other.footprint) >= required;
    });
  }

  const SceneGenerationSettings& settings_;
  double towards_first_view_;
  std::mt19937& rng_;
  std::vector<PlacedFootprint> placed_;
};

CameraArc drawCameraArc(const SceneGenerationSettings& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> start(0.0, 2.0 * M_PI);
  std::uniform_real_distribution<double> elevation(s.min_elevation_deg * kDegree,
                                                   s.max_elevation_deg * kDegree);
  std::uniform_real_distribution<double> distance(s.min_camera_distance, s.max_camera_distance);
  CameraArc arc;
  const double first = start(rng);
  for (int v = 0; v < s.views; ++v) {
    const double along = s.views > 1 ? static_cast<double>(v) / (s.views - 1) : 0.0;
    arc.azimuth.push_back(first + along * s.arc_deg * kDegree);
    arc.elevation.push_back(elevation(rng));
    arc.distance.push_back(distance(rng));
  }
  return arc;
}

Eigen::Vector3d centreOfBounds(const TableScene& scene) {
  Eigen::AlignedBox3d bounds;
  auto extend = [&](const ScenePart& part) {
    for (const Eigen::Vector3f& v : part.mesh.vertices) {
      bounds.extend(part.world_from_part * v.cast<double>());
    }
  };
  for (const PlacedKnownObject& object : scene.known) extend(object.part);
  for (const ScenePart& part : scene.distractors) extend(part);
  return bounds.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(bounds.center());
}

// The camera at `distance` from `target` in the direction (azimuth, elevation), the fixed frame's
// +z up in the image (cameraFromObject's roll 0).
Eigen::Isometry3d worldFromCamera(const Eigen::Vector3d& target, double azimuth, double elevation,
                                  double distance) {
  const Eigen::Vector3d direction(std::cos(elevation) * std::cos(azimuth),
                                  std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  const Eigen::Isometry3d camera_from_world =
      cameraFromObject(direction, distance, 0.0) * Eigen::Translation3d(-target);
  return camera_from_world.inverse();
}

void checkInputs(const std::vector<KnownModel>& models,
                 const std::vector<TriangleMesh>& distractor_meshes,
                 const SceneGenerationSettings& settings) {
  checkSceneGenerationSettings(settings);
  if (models.empty()) throw Error("the scene generator needs at least one known model");
  if (settings.distractors > 0 && distractor_meshes.empty()) {
    throw Error("the scene generator needs distractor meshes for " +
                std::to_string(settings.distractors) + " distractors");
  }
  for (const KnownModel& model : models) {
    if (model.mesh.vertices.empty()) throw Error("known model '" + model.name + "' has no mesh");
  }
  for (const TriangleMesh& mesh : distractor_meshes) {
    if (mesh.vertices.empty()) throw Error("a distractor mesh has no vertices");
  }
}

}  // namespace

void checkSceneGenerationSettings(const SceneGenerationSettings& s) {
  if (s.known_objects < 0 || s.distractors < 0 || s.views < 1 || s.attempts_per_object < 1) {
    throw Error(
        "the scene generator needs >= 0 known objects and distractors, >= 1 view and "
        ">= 1 attempt per object");
  }
  if (!(s.table_size.minCoeff() > 0.0) || !s.table_size.allFinite()) {
    throw Error("the scene generator's table size must be positive and finite");
  }
  if (!(s.scatter_radius >= 0.0) || !(s.contact_gap >= 0.0) || !std::isfinite(s.scatter_radius) ||
      !std::isfinite(s.contact_gap)) {
    throw Error("the scene generator's scatter radius and contact gap must be >= 0 and finite");
  }
  checkFraction(s.contact_fraction, "contact fraction");
  checkFraction(s.occluder_fraction, "occluder fraction");
  checkRange(s.occluder_gap_min, s.occluder_gap_max, "occluder gap");
  checkRange(s.occluder_bearing_min_deg, s.occluder_bearing_max_deg, "occluder bearing");
  checkRange(s.min_camera_distance, s.max_camera_distance, "camera distance");
  checkRange(s.min_elevation_deg, s.max_elevation_deg, "camera elevation");
  if (!(s.min_camera_distance > 0.0) || !(s.min_elevation_deg > 0.0) ||
      !(s.max_elevation_deg < 90.0) || !std::isfinite(s.arc_deg)) {
    throw Error(
        "the scene generator's cameras must be at a positive distance, with elevations "
        "in (0, 90) deg, and a finite arc");
  }
}

TableScene generateTableScene(const std::vector<KnownModel>& models,
                              const std::vector<TriangleMesh>& distractor_meshes,
                              const SceneGenerationSettings& settings, std::uint32_t seed) {
  checkInputs(models, distractor_meshes, settings);
  std::mt19937 rng(seed);
  TableScene scene;
  scene.table_size = settings.table_size;
  // The arc is drawn first: occluders go between known objects and the first view.
  const CameraArc arc = drawCameraArc(settings, rng);
  TablePlacer placer(settings, arc.azimuth.front(), rng);
  std::bernoulli_distribution in_contact(settings.contact_fraction);
  auto contactOrScattered = [&](int index) {
    return index > 0 && in_contact(rng) ? PlacementMode::kInContact : PlacementMode::kScattered;
  };
  int index = 0;
  for (const std::size_t m : takeInTurn(models.size(), settings.known_objects, rng)) {
    int neighbour = -1;
    const Eigen::Isometry3d pose =
        placer.place(models[m].mesh, contactOrScattered(index), true, &neighbour);
    if (neighbour >= 0) scene.touching.emplace_back(neighbour, index);
    scene.known.push_back({models[m].name, {models[m].mesh, pose}});
    ++index;
  }
  const int occluders =
      static_cast<int>(std::lround(settings.occluder_fraction * settings.distractors));
  for (const std::size_t d : takeInTurn(distractor_meshes.size(), settings.distractors, rng)) {
    const bool occluder = static_cast<int>(scene.distractors.size()) < occluders;
    const PlacementMode mode = occluder ? PlacementMode::kInFront : contactOrScattered(index);
    int neighbour = -1;
    const Eigen::Isometry3d pose = placer.place(distractor_meshes[d], mode, false, &neighbour);
    if (neighbour >= 0 && mode == PlacementMode::kInContact) {
      scene.touching.emplace_back(neighbour, index);
    }
    scene.distractors.push_back({distractor_meshes[d], pose});
    ++index;
  }
  scene.centre = centreOfBounds(scene);
  for (int v = 0; v < settings.views; ++v) {
    scene.world_from_camera.push_back(
        worldFromCamera(scene.centre, arc.azimuth[v], arc.elevation[v], arc.distance[v]));
  }
  return scene;
}

}  // namespace vdc

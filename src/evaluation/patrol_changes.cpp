#include "view_direction_classification/evaluation/patrol_changes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/table_footprint.h"

namespace vdc {
namespace {

Eigen::Vector2d unitAt(double angle) { return {std::cos(angle), std::sin(angle)}; }

// `pose` turned by `turn` about the vertical and slid to `xy`: it keeps standing on the table.
Eigen::Isometry3d slid(const Eigen::Isometry3d& pose, double turn, const Eigen::Vector2d& xy) {
  Eigen::Isometry3d result = pose;
  result.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * pose.linear();
  result.translation().head<2>() = xy;
  return result;
}

// The origin height that puts the mesh's lowest vertex on the table (as the generator does).
double standingLift(const TriangleMesh& mesh) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3f& v : mesh.vertices) lowest = std::min(lowest, double{v.z()});
  return -lowest;
}

// Whether a place is free: on the table, inside the place disc and apart from every footprint
// on the table but the one of the object being changed (it leaves its place).
class FreePlaces {
 public:
  FreePlaces(const PatrolScene& scene, const PatrolChangeSettings& settings, int skip_object,
             int skip_distractor)
      : table_size_(scene.table_size), centre_(scene.centre.head<2>()), settings_(settings) {
    for (const PatrolObject& object : scene.objects) {
      if (object.present && object.id != skip_object) {
        taken_.push_back(footprintOf(object.placed.part.mesh, object.placed.part.world_from_part));
      }
    }
    for (std::size_t d = 0; d < scene.distractors.size(); ++d) {
      if (static_cast<int>(d) == skip_distractor) continue;
      taken_.push_back(
          footprintOf(scene.distractors[d].mesh, scene.distractors[d].world_from_part));
    }
  }

  bool isFree(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) const {
    if ((pose.translation().head<2>() - centre_).norm() > settings_.place_radius) return false;
    const Footprint footprint = footprintOf(mesh, pose);
    if (!footprintInsideRectangle(footprint, table_size_)) return false;
    return std::all_of(taken_.begin(), taken_.end(), [&](const Footprint& other) {
      return footprintSeparation(footprint, other) >= settings_.gap;
    });
  }

 private:
  Eigen::Vector2d table_size_, centre_;
  const PatrolChangeSettings& settings_;
  std::vector<Footprint> taken_;
};

// A free pose min_move..max_move from `from`, turned at random.
std::optional<Eigen::Isometry3d> movedPose(const TriangleMesh& mesh, const Eigen::Isometry3d& from,
                                           const FreePlaces& places,
                                           const PatrolChangeSettings& settings,
                                           std::mt19937& rng) {
  std::uniform_real_distribution<double> distance(settings.min_move, settings.max_move);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int attempt = 0; attempt < settings.attempts; ++attempt) {
    const double d = distance(rng), direction = angle(rng), turn = angle(rng);
    const Eigen::Isometry3d pose =
        slid(from, turn, from.translation().head<2>() + d * unitAt(direction));
    if (places.isFree(mesh, pose)) return pose;
  }
  return std::nullopt;
}

// A free upright pose anywhere in the place disc.
std::optional<Eigen::Isometry3d> addedPose(const TriangleMesh& mesh, const Eigen::Vector2d& centre,
                                           const FreePlaces& places,
                                           const PatrolChangeSettings& settings,
                                           std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::Isometry3d standing = Eigen::Isometry3d::Identity();
  standing.translation().z() = standingLift(mesh);
  for (int attempt = 0; attempt < settings.attempts; ++attempt) {
    const double radius = settings.place_radius * std::sqrt(unit(rng));
    const double direction = 2.0 * M_PI * unit(rng), yaw = 2.0 * M_PI * unit(rng);
    const Eigen::Isometry3d pose = slid(standing, yaw, centre + radius * unitAt(direction));
    if (places.isFree(mesh, pose)) return pose;
  }
  return std::nullopt;
}

template <typename T>
T pickOne(const std::vector<T>& items, std::mt19937& rng) {
  std::uniform_int_distribution<std::size_t> pick(0, items.size() - 1);
  return items[pick(rng)];
}

// Changes one round applies to one scene; each object at most once.
class ChangeMaker {
 public:
  ChangeMaker(const std::vector<KnownModel>& models, const PatrolChangeSettings& settings,
              std::mt19937& rng, PatrolScene* scene)
      : models_(models), settings_(settings), rng_(rng), scene_(*scene) {}

  // kind: what the change was drawn to be (drawKinds); a distractor that finds no place makes
  // it a known object's move.
  std::optional<PatrolChange> next(PatrolChangeKind kind) {
    if (kind == PatrolChangeKind::kDistractorMoved) {
      if (auto change = moveDistractor()) return change;
      kind = PatrolChangeKind::kMoved;
    }
    return changeKnown(kind);
  }

 private:
  // Indices into scene_.objects of the unchanged ones that are present (or not).
  std::vector<std::size_t> unchanged(bool present) const {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const PatrolObject& object = scene_.objects[i];
      if (object.present == present && !changed_objects_.count(object.id)) found.push_back(i);
    }
    return found;
  }

  // A move or an addition that finds no place becomes a removal; without a present object,
  // the change is an addition.
  std::optional<PatrolChange> changeKnown(PatrolChangeKind kind) {
    const std::vector<std::size_t> present = unchanged(true);
    if (present.empty()) kind = PatrolChangeKind::kAdded;
    if (kind == PatrolChangeKind::kMoved) {
      if (auto change = move(pickOne(present, rng_))) return change;
    }
    if (kind == PatrolChangeKind::kAdded) {
      if (auto change = add()) return change;
    }
    if (present.empty()) return std::nullopt;
    return remove(pickOne(present, rng_));
  }

  PatrolChange record(PatrolChangeKind kind, const PatrolObject& object) {
    changed_objects_.insert(object.id);
    PatrolChange change;
    change.kind = kind;
    change.object = object.id;
    change.model = object.placed.model;
    change.from = change.to = object.placed.part.world_from_part;
    return change;
  }

  std::optional<PatrolChange> move(std::size_t index) {
    PatrolObject& object = scene_.objects[index];
    const FreePlaces places(scene_, settings_, object.id, -1);
    const auto pose = movedPose(object.placed.part.mesh, object.placed.part.world_from_part, places,
                                settings_, rng_);
    if (!pose) return std::nullopt;
    PatrolChange change = record(PatrolChangeKind::kMoved, object);
    object.placed.part.world_from_part = change.to = *pose;
    return change;
  }

  PatrolChange remove(std::size_t index) {
    PatrolObject& object = scene_.objects[index];
    object.present = false;
    return record(PatrolChangeKind::kRemoved, object);
  }

  // One taken away put back (half the time, when there is one), else a new object.
  std::optional<PatrolChange> add() {
    const std::vector<std::size_t> away = unchanged(false);
    std::bernoulli_distribution put_back(0.5);
    PatrolObject object;
    std::size_t index = scene_.objects.size();
    if (!away.empty() && (models_.empty() || put_back(rng_))) {
      index = pickOne(away, rng_);
      object = scene_.objects[index];
    } else if (!models_.empty()) {
      const KnownModel& model = pickOne(models_, rng_);
      object.id = nextId();
      object.placed = {model.name, {model.mesh, Eigen::Isometry3d::Identity()}};
    } else {
      return std::nullopt;
    }
    const FreePlaces places(scene_, settings_, object.id, -1);
    const auto pose =
        addedPose(object.placed.part.mesh, scene_.centre.head<2>(), places, settings_, rng_);
    if (!pose) return std::nullopt;
    object.present = true;
    object.placed.part.world_from_part = *pose;
    if (index == scene_.objects.size()) scene_.objects.push_back(object);
    scene_.objects[index] = object;
    return record(PatrolChangeKind::kAdded, object);  // from = to: it left no place on the table
  }

  std::optional<PatrolChange> moveDistractor() {
    std::vector<int> unmoved;
    for (std::size_t d = 0; d < scene_.distractors.size(); ++d) {
      if (!changed_distractors_.count(static_cast<int>(d))) unmoved.push_back(static_cast<int>(d));
    }
    if (unmoved.empty()) return std::nullopt;
    const int d = pickOne(unmoved, rng_);
    ScenePart& part = scene_.distractors[d];
    const FreePlaces places(scene_, settings_, -1, d);
    const auto pose = movedPose(part.mesh, part.world_from_part, places, settings_, rng_);
    if (!pose) return std::nullopt;
    changed_distractors_.insert(d);
    PatrolChange change;
    change.kind = PatrolChangeKind::kDistractorMoved;
    change.object = d;
    change.from = part.world_from_part;
    part.world_from_part = change.to = *pose;
    return change;
  }

  int nextId() const {
    int id = 0;
    for (const PatrolObject& object : scene_.objects) id = std::max(id, object.id + 1);
    return id;
  }

  const std::vector<KnownModel>& models_;
  const PatrolChangeSettings& settings_;
  std::mt19937& rng_;
  PatrolScene& scene_;
  std::set<int> changed_objects_, changed_distractors_;
};

// Every change's kind, drawn before any is made, so that the kinds do not depend on how many
// draws finding the places took.
std::vector<PatrolChangeKind> drawKinds(const PatrolChangeSettings& settings, std::mt19937& rng) {
  std::bernoulli_distribution distractor(settings.distractor_share);
  std::uniform_int_distribution<int> known(0, 2);
  constexpr PatrolChangeKind kKnownKinds[] = {PatrolChangeKind::kMoved, PatrolChangeKind::kRemoved,
                                              PatrolChangeKind::kAdded};
  std::vector<PatrolChangeKind> kinds;
  for (int c = 0; c < settings.changes; ++c) {
    const bool moves_distractor = distractor(rng);
    const PatrolChangeKind kind = kKnownKinds[known(rng)];
    kinds.push_back(moves_distractor ? PatrolChangeKind::kDistractorMoved : kind);
  }
  return kinds;
}

}  // namespace

PatrolScene patrolSceneOf(const TableScene& scene) {
  PatrolScene patrol;
  patrol.table_size = scene.table_size;
  for (std::size_t i = 0; i < scene.known.size(); ++i) {
    patrol.objects.push_back({static_cast<int>(i), scene.known[i], true});
  }
  patrol.distractors = scene.distractors;
  patrol.centre = scene.centre;
  patrol.world_from_camera = scene.world_from_camera;
  return patrol;
}

TableScene presentScene(const PatrolScene& scene, std::vector<int>* ids) {
  TableScene table;
  table.table_size = scene.table_size;
  if (ids != nullptr) ids->clear();
  for (const PatrolObject& object : scene.objects) {
    if (!object.present) continue;
    table.known.push_back(object.placed);
    if (ids != nullptr) ids->push_back(object.id);
  }
  table.distractors = scene.distractors;
  table.centre = scene.centre;
  table.world_from_camera = scene.world_from_camera;
  return table;
}

const char* patrolChangeKindName(PatrolChangeKind kind) {
  switch (kind) {
    case PatrolChangeKind::kMoved:
      return "moved";
    case PatrolChangeKind::kRemoved:
      return "removed";
    case PatrolChangeKind::kAdded:
      return "added";
    case PatrolChangeKind::kDistractorMoved:
      return "distractor_moved";
  }
  return "?";
}

void checkPatrolChangeSettings(const PatrolChangeSettings& s) {
  if (s.changes < 0 || s.attempts < 1) {
    throw Error("patrol changes: changes must be >= 0 and attempts >= 1");
  }
  if (!(s.min_move > 0.0) || !(s.min_move <= s.max_move) || !std::isfinite(s.max_move)) {
    throw Error("patrol changes: the move distances must be finite with 0 < min <= max");
  }
  if (!(s.distractor_share >= 0.0 && s.distractor_share <= 1.0)) {
    throw Error("patrol changes: the distractor share must be in [0, 1]");
  }
  if (!(s.place_radius > 0.0) || !(s.gap >= 0.0) || !std::isfinite(s.place_radius + s.gap)) {
    throw Error("patrol changes: the place radius must be > 0 and the gap >= 0, both finite");
  }
}

std::vector<PatrolChange> applyRandomChanges(const std::vector<KnownModel>& models,
                                             const PatrolChangeSettings& settings,
                                             std::mt19937& rng, PatrolScene* scene) {
  checkPatrolChangeSettings(settings);
  ChangeMaker maker(models, settings, rng, scene);
  std::vector<PatrolChange> changes;
  for (const PatrolChangeKind kind : drawKinds(settings, rng)) {
    if (auto change = maker.next(kind)) changes.push_back(*change);
  }
  return changes;
}

}  // namespace vdc

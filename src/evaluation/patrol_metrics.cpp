#include "view_direction_classification/evaluation/patrol_metrics.h"

#include <algorithm>
#include <cmath>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

double distanceBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

bool on(const InstanceEstimate& estimate, const std::string& model,
        const Eigen::Isometry3d& world_from_object, double near) {
  return estimate.model == model &&
         distanceBetween(estimate.world_from_object, world_from_object) <= near;
}

// Per present object, whether an instance has it right: the scene metrics' one-to-one match
// within match_distance (every present object counted, seen or not: the memory should hold
// it), then the rotation error.
std::vector<bool> rightObjects(const PatrolTruth& truth,
                               const std::vector<InstanceEstimate>& confirmed,
                               const PatrolMetricSettings& settings) {
  ViewTruth view;
  for (KnownObjectTruth object : truth.present) {
    object.visible_fraction = 1.0;
    view.known.push_back(object);
  }
  SceneMetricSettings match;
  match.visible_fraction = 0.0;
  match.match_distance = settings.match_distance;
  std::vector<bool> right(truth.present.size(), false);
  for (const IdentifiedInstance& instance : sceneViewMetrics(view, confirmed, match).identified) {
    right[instance.truth] = instance.rotation_error_deg <= settings.match_rotation_deg;
  }
  return right;
}

int duplicatesOn(const PatrolTruth& truth, const std::vector<InstanceEstimate>& confirmed,
                 double near) {
  int duplicates = 0;
  for (const KnownObjectTruth& object : truth.present) {
    const auto count = std::count_if(confirmed.begin(), confirmed.end(), [&](const auto& e) {
      return on(e, object.model, object.world_from_object, near);
    });
    duplicates += std::max(0, static_cast<int>(count) - 1);
  }
  return duplicates;
}

// Counts the stale instances and marks the places they fill.
int countStale(const PatrolTruth& truth, const std::vector<InstanceEstimate>& confirmed,
               double near, std::vector<bool>* place_stale) {
  place_stale->assign(truth.vacated.size(), false);
  int stale = 0;
  for (const InstanceEstimate& estimate : confirmed) {
    const bool on_present =
        std::any_of(truth.present.begin(), truth.present.end(), [&](const auto& object) {
          return on(estimate, object.model, object.world_from_object, near);
        });
    if (on_present) continue;
    bool counted = false;
    for (std::size_t p = 0; p < truth.vacated.size(); ++p) {
      const VacatedPlace& place = truth.vacated[p];
      if (!on(estimate, place.model, place.world_from_object, near)) continue;
      (*place_stale)[p] = true;
      if (!counted) ++stale, counted = true;
    }
  }
  return stale;
}

int presentIndex(const PatrolTruth& truth, int object) {
  const auto found = std::find(truth.ids.begin(), truth.ids.end(), object);
  return found == truth.ids.end() ? -1 : static_cast<int>(found - truth.ids.begin());
}

int vacatedIndex(const PatrolTruth& truth, int object) {
  for (std::size_t p = 0; p < truth.vacated.size(); ++p) {
    if (truth.vacated[p].object == object) return static_cast<int>(p);
  }
  return -1;
}

}  // namespace

void checkPatrolMetricSettings(const PatrolMetricSettings& s) {
  if (!(s.match_distance >= 0.0) || !(s.match_rotation_deg >= 0.0) || !(s.near >= 0.0) ||
      !(s.visible_fraction >= 0.0)) {
    throw Error("patrol metrics: distances, angle and visible fraction must be >= 0");
  }
}

PatrolMemoryMetrics patrolMemoryMetrics(const PatrolTruth& truth,
                                        const std::vector<InstanceEstimate>& confirmed,
                                        const PatrolMetricSettings& settings) {
  checkPatrolMetricSettings(settings);
  if (truth.ids.size() != truth.present.size()) {
    throw Error("patrol metrics: the truth needs one id per present object");
  }
  PatrolMemoryMetrics metrics;
  metrics.present = static_cast<int>(truth.present.size());
  metrics.confirmed = static_cast<int>(confirmed.size());
  metrics.object_right = rightObjects(truth, confirmed, settings);
  metrics.right =
      static_cast<int>(std::count(metrics.object_right.begin(), metrics.object_right.end(), true));
  metrics.duplicates = duplicatesOn(truth, confirmed, settings.near);
  metrics.stale = countStale(truth, confirmed, settings.near, &metrics.place_stale);
  return metrics;
}

bool changeReflected(const ChangeNotice& notice, const PatrolTruth& truth,
                     const PatrolMemoryMetrics& metrics) {
  const int present = presentIndex(truth, notice.object);
  const int place = vacatedIndex(truth, notice.object);
  const bool right = present >= 0 && metrics.object_right[present];
  const bool place_free = place < 0 || !metrics.place_stale[place];
  switch (notice.kind) {
    case PatrolChangeKind::kRemoved:
      return place_free;
    case PatrolChangeKind::kMoved:
      return right && place_free;
    case PatrolChangeKind::kAdded:
      return right;
    case PatrolChangeKind::kDistractorMoved:
      return true;
  }
  return true;
}

bool changePlaceSeen(const ChangeNotice& notice, const PatrolTruth& truth,
                     const PatrolMetricSettings& settings) {
  if (notice.kind == PatrolChangeKind::kRemoved) {
    const int place = vacatedIndex(truth, notice.object);
    return place >= 0 && truth.vacated[place].visible_fraction > settings.visible_fraction;
  }
  const int present = presentIndex(truth, notice.object);
  return present >= 0 && truth.present[present].visible_fraction > settings.visible_fraction;
}

void advanceNotice(bool reflected, bool place_seen, ChangeNotice* notice) {
  if (notice->noticed || notice->superseded) return;
  ++notice->views;
  if (place_seen) ++notice->place_views;
  notice->noticed = reflected;
}

}  // namespace vdc

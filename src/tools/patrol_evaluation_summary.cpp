#include "patrol_evaluation_summary.h"

#include <algorithm>
#include <cstdio>

#include "patrol_evaluation_csv.h"

namespace vdc::tools {

namespace {

// A change counts as taken in within kWithinViews views of its place.
bool inTime(const ChangeNotice& notice) {
  return notice.noticed && notice.place_views <= PatrolTargets::kWithinViews;
}

void countNotice(const ChangeNotice& notice, PatrolTargets* targets) {
  if (notice.superseded) {
    ++targets->superseded;
    return;
  }
  switch (notice.kind) {
    case PatrolChangeKind::kRemoved:
      ++targets->removals;
      targets->removals_in_time += inTime(notice) ? 1 : 0;
      targets->removals_unnoticed += notice.noticed ? 0 : 1;
      break;
    case PatrolChangeKind::kMoved:
      ++targets->moves;
      targets->moves_in_time += inTime(notice) ? 1 : 0;
      targets->moves_unnoticed += notice.noticed ? 0 : 1;
      break;
    case PatrolChangeKind::kAdded:
      ++targets->additions;
      targets->additions_found += notice.noticed ? 1 : 0;
      break;
    case PatrolChangeKind::kDistractorMoved:
      break;
  }
}

const char* verdict(bool met) { return met ? "met" : "NOT met"; }

void printPasses(const PatrolResult& result) {
  std::printf("%4s %5s %7s %5s %5s %5s %9s %5s %9s  %s\n", "pass", "views", "present", "right",
              "dupl", "stale", "instances", "gone", "ms/view", "changes before the pass");
  for (const PatrolPassRecord& r : result.passes) {
    std::string changes;
    for (const PatrolChange& c : r.changes)
      changes += (changes.empty() ? "" : " ") + patrolChangeLabel(c);
    std::printf("%4d %5d %7d %5d %5d %5d %9d %5d %9.0f  %s\n", r.pass, r.views, r.metrics.present,
                r.metrics.right, r.max_duplicates, r.max_stale, r.instances, r.gone_instances,
                r.mean_time_ms, changes.c_str());
  }
}

}  // namespace

PatrolTargets patrolTargets(const PatrolResult& result) {
  PatrolTargets targets;
  double time_sum = 0.0;
  int views = 0;
  for (const PatrolPassRecord& pass : result.passes) {
    targets.max_duplicates = std::max(targets.max_duplicates, pass.max_duplicates);
    targets.max_instances = std::max(targets.max_instances, pass.instances);
    targets.final_instances = pass.instances;
    targets.objects_ever = pass.objects_ever;
    targets.max_time_ms = std::max(targets.max_time_ms, pass.max_time_ms);
    time_sum += pass.mean_time_ms * pass.views;
    views += pass.views;
  }
  targets.mean_time_ms = views > 0 ? time_sum / views : 0.0;
  for (const ChangeNotice& notice : result.notices) countNotice(notice, &targets);
  return targets;
}

void printPatrolSummary(const PatrolResult& result) {
  printPasses(result);
  const PatrolTargets t = patrolTargets(result);
  const int within = PatrolTargets::kWithinViews;
  std::printf("\ntargets (issue 30 item 6):\n");
  std::printf("  no duplicates:                       %s (at most %d on a view)\n",
              verdict(t.noDuplicates()), t.max_duplicates);
  std::printf("  removals noticed within %d views of their place: %s (%d of %d; %d never)\n",
              within, verdict(t.removalsInTime()), t.removals_in_time, t.removals,
              t.removals_unnoticed);
  std::printf("  moved objects right within %d views of their place: %s (%d of %d; %d never)\n",
              within, verdict(t.movesInTime()), t.moves_in_time, t.moves, t.moves_unnoticed);
  std::printf(
      "  memory bounded:                      %s (at most %d instances, %d at the end, "
      "for %d objects ever on the table)\n",
      verdict(t.memoryBounded()), t.max_instances, t.final_instances, t.objects_ever);
  std::printf("  objects added found: %d of %d; changes overtaken by another: %d\n",
              t.additions_found, t.additions, t.superseded);
  std::printf("  time per view: mean %.0f ms, max %.0f ms\n", t.mean_time_ms, t.max_time_ms);
}

}  // namespace vdc::tools

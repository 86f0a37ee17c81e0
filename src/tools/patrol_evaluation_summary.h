#pragma once

#include "view_direction_classification/evaluation/patrol_evaluation.h"

namespace vdc::tools {

// The targets for the object memory over a patrol (issue 30 item 6), as counts.
struct PatrolTargets {
  static constexpr int kWithinViews = 2;  // views of the place a change may take to be noticed
  int max_duplicates = 0;                 // over every view: the target is 0
  int removals = 0, removals_in_time = 0, removals_unnoticed = 0;
  int moves = 0, moves_in_time = 0, moves_unnoticed = 0;
  int additions = 0, additions_found = 0;
  int superseded = 0;  // changes overtaken by another change of their object (not counted)
  // The memory's size after the last pass, against the known objects ever on the table: bounded
  // when it holds at most one instance per object.
  int final_instances = 0, objects_ever = 0, max_instances = 0;
  double mean_time_ms = 0.0, max_time_ms = 0.0;  // per arc view, over every pass

  bool noDuplicates() const { return max_duplicates == 0; }
  bool removalsInTime() const { return removals_in_time == removals; }
  bool movesInTime() const { return moves_in_time == moves; }
  bool memoryBounded() const { return max_instances <= objects_ever; }
};

PatrolTargets patrolTargets(const PatrolResult& result);

// The per-pass table and the targets on stdout.
void printPatrolSummary(const PatrolResult& result);

}  // namespace vdc::tools

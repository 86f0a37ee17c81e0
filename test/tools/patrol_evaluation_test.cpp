// `vdc evaluate-patrol`'s own business without running the tool: a short patrol with the quick
// mug model (two passes, the mug taken away between them), its patrol.csv and its targets.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "patrol_evaluation_csv.h"
#include "patrol_evaluation_summary.h"
#include "support/quick_mug_model.h"
#include "support/split_text.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc::tools {
namespace {

using test::split;

// One mug alone on the table, seen on three views per pass, taken away before the second pass.
const PatrolResult& mugTakenAway() {
  static const PatrolResult result = [] {
    PatrolSettings settings;
    settings.passes = 2;
    settings.seed = 7;
    settings.generation.known_objects = 1;
    settings.generation.distractors = 0;
    settings.generation.views = 3;
    const auto removeTheMug = [](int, PatrolScene* scene) {
      PatrolObject& mug = scene->objects.front();
      mug.present = false;
      PatrolChange change;
      change.kind = PatrolChangeKind::kRemoved;
      change.object = mug.id;
      change.model = mug.placed.model;
      change.from = change.to = mug.placed.part.world_from_part;
      return std::vector<PatrolChange>{change};
    };
    return evaluatePatrol({{"mug", test::quickMugModel(), makeMug()}}, {}, settings, {},
                          removeTheMug);
  }();
  return result;
}

TEST(PatrolEvaluation, TheMugTakenAwayIsNoticedWithinTwoViewsOfItsPlace) {
  const PatrolResult& result = mugTakenAway();
  std::ostringstream csv;
  writePatrolCsv(csv, result);
  ASSERT_EQ(result.passes.size(), 2u);
  const PatrolPassRecord& first = result.passes[0];
  EXPECT_EQ(first.views, 3);
  EXPECT_EQ(first.metrics.present, 1);
  EXPECT_EQ(first.metrics.confirmed, 1) << csv.str();  // the memory had the mug
  EXPECT_EQ(first.max_duplicates, 0) << csv.str();
  const PatrolPassRecord& second = result.passes[1];
  ASSERT_EQ(second.changes.size(), 1u);
  EXPECT_EQ(second.metrics.present, 0);
  EXPECT_EQ(second.metrics.stale, 0) << csv.str();
  EXPECT_EQ(second.gone_instances, 1) << csv.str();
  EXPECT_EQ(second.instances, 1) << csv.str();  // kept, gone: the memory did not grow
  ASSERT_EQ(result.notices.size(), 1u);
  const ChangeNotice& notice = result.notices.front();
  EXPECT_EQ(notice.pass, 2);
  EXPECT_TRUE(notice.noticed) << csv.str();
  EXPECT_LE(notice.place_views, PatrolTargets::kWithinViews) << csv.str();
  const PatrolTargets targets = patrolTargets(result);
  EXPECT_EQ(targets.removals, 1);
  EXPECT_TRUE(targets.removalsInTime());
  EXPECT_TRUE(targets.noDuplicates());
  EXPECT_TRUE(targets.memoryBounded());
}

TEST(PatrolEvaluation, PatrolCsvHasAHeaderAndOneRowPerPassOfEqualWidth) {
  std::ostringstream csv;
  writePatrolCsv(csv, mugTakenAway());
  const std::vector<std::string> lines = split(csv.str(), '\n');
  ASSERT_EQ(lines.size(), 3u) << csv.str();
  const std::vector<std::string> header = split(lines[0], ',');
  for (std::size_t row = 1; row < lines.size(); ++row) {
    const std::vector<std::string> cells = split(lines[row], ',');
    ASSERT_EQ(cells.size(), header.size()) << lines[row];
    EXPECT_EQ(cells[0], std::to_string(row));
  }
  const std::vector<std::string> second = split(lines[2], ',');
  auto cell = [&](const std::string& name) {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return second[c];
    }
    return std::string("no column ") + name;
  };
  EXPECT_EQ(cell("changes"), "removed:mug#0");
  EXPECT_EQ(cell("notice_changes"), "removed:mug#0");
  EXPECT_NE(cell("notice_views"), "-");
}

}  // namespace
}  // namespace vdc::tools

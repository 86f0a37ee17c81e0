#include "scene_evaluation_summary.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

namespace vdc::tools {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  if (values.size() % 2 == 1) return values[mid];
  return 0.5 * (values[mid] + *std::max_element(values.begin(), values.begin() + mid));
}

double mean(const std::vector<double>& values) {
  return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

double fraction(int part, int whole) { return whole > 0 ? static_cast<double>(part) / whole : 0; }

void countFalseKinds(const SceneViewRecord& record, SceneViewSummary* summary) {
  for (const FalseIdentificationKind kind : record.false_kinds) {
    switch (kind) {
      case FalseIdentificationKind::kOnDistractor:
        ++summary->false_on_distractor;
        break;
      case FalseIdentificationKind::kWrongModel:
        ++summary->false_wrong_model;
        break;
      case FalseIdentificationKind::kDuplicate:
        ++summary->false_duplicate;
        break;
      case FalseIdentificationKind::kElsewhere:
        ++summary->false_elsewhere;
        break;
    }
  }
}

void addStageTimes(const SceneViewRecord& record, SceneViewSummary* summary) {
  if (!record.segmented) return;
  ++summary->segmented;
  summary->mean_segmentation_ms += record.segmentation_ms;
  SceneStageTimes& sum = summary->mean_stage_ms;
  sum.preparation += record.stage_ms.preparation;
  sum.instances += record.stage_ms.instances;
  sum.identification += record.stage_ms.identification;
  sum.groups += record.stage_ms.groups;
  sum.parts += record.stage_ms.parts;
}

void divideStageTimes(SceneViewSummary* summary) {
  if (summary->segmented == 0) return;
  const double n = summary->segmented;
  summary->mean_segmentation_ms /= n;
  SceneStageTimes& mean = summary->mean_stage_ms;
  mean.preparation /= n;
  mean.instances /= n;
  mean.identification /= n;
  mean.groups /= n;
  mean.parts /= n;
}

SceneViewSummary summariseView(int view, const std::vector<SceneViewRecord>& records) {
  SceneViewSummary summary;
  summary.view = view;
  std::vector<double> rotations, positions, times;
  int inside = 0;
  for (const SceneViewRecord& record : records) {
    if (record.view != view) continue;
    ++summary.views;
    summary.visible_known += record.metrics.visible_known;
    summary.identified += static_cast<int>(record.metrics.identified.size());
    summary.false_identifications += static_cast<int>(record.metrics.false_identifications.size());
    summary.estimates += static_cast<int>(record.estimates.size());
    countFalseKinds(record, &summary);
    times.push_back(record.time_ms);
    addStageTimes(record, &summary);
    for (const IdentifiedInstance& instance : record.metrics.identified) {
      rotations.push_back(instance.rotation_error_deg);
      positions.push_back(instance.position_error * 1000.0);
      if (instance.inside_cone90) ++inside;
    }
  }
  summary.median_rotation_deg = median(rotations);
  summary.median_position_mm = median(positions);
  summary.inside_cone90 = fraction(inside, summary.identified);
  summary.mean_time_ms = mean(times);
  summary.median_time_ms = median(times);
  divideStageTimes(&summary);
  return summary;
}

}  // namespace

double SceneViewSummary::identifiedFraction() const { return fraction(identified, visible_known); }
double SceneViewSummary::falsePerView() const {
  return views > 0 ? static_cast<double>(false_identifications) / views : 0.0;
}
double SceneViewSummary::falseFractionOfEstimates() const {
  return fraction(false_identifications, estimates);
}

std::vector<SceneViewSummary> summariseByView(const std::vector<SceneViewRecord>& records) {
  int views = 0;
  for (const SceneViewRecord& record : records) views = std::max(views, record.view);
  std::vector<SceneViewSummary> summaries;
  for (int view = 1; view <= views; ++view) summaries.push_back(summariseView(view, records));
  return summaries;
}

std::vector<CandidateTimeBin> timeByCandidates(const std::vector<SceneViewRecord>& records,
                                               int width) {
  std::map<int, std::vector<const SceneViewRecord*>> bins;
  for (const SceneViewRecord& record : records) {
    if (record.segmented) bins[record.candidates / width].push_back(&record);
  }
  std::vector<CandidateTimeBin> result;
  for (const auto& [index, members] : bins) {
    CandidateTimeBin bin{index * width, index * width + width - 1};
    std::vector<double> times, candidates;
    for (const SceneViewRecord* record : members) {
      times.push_back(record->time_ms);
      candidates.push_back(record->candidates);
    }
    bin.views = static_cast<int>(members.size());
    bin.mean_time_ms = mean(times);
    bin.median_time_ms = median(times);
    bin.mean_candidates = mean(candidates);
    result.push_back(bin);
  }
  return result;
}

void printSceneEvaluationSummary(const std::vector<SceneViewRecord>& records) {
  std::printf(
      "view  views  identified      false/view  false/estimates  (distractor wrong-model "
      "duplicate elsewhere)  rot med [deg]  pos med [mm]  in cone90  time mean/med [ms]\n");
  for (const SceneViewSummary& s : summariseByView(records)) {
    std::printf(
        "%4d  %5d  %5.1f %% (%d/%d)  %10.2f  %13.1f %%  (%d %d %d %d)  %13.2f  %12.2f  %7.1f %%  "
        "%.0f / %.0f\n",
        s.view, s.views, 100.0 * s.identifiedFraction(), s.identified, s.visible_known,
        s.falsePerView(), 100.0 * s.falseFractionOfEstimates(), s.false_on_distractor,
        s.false_wrong_model, s.false_duplicate, s.false_elsewhere, s.median_rotation_deg,
        s.median_position_mm, 100.0 * s.inside_cone90, s.mean_time_ms, s.median_time_ms);
  }
  std::printf(
      "time per segmented view by stage, mean [ms]: view  segmented  segmentation  preparation  "
      "instances  identification  groups  parts\n");
  for (const SceneViewSummary& s : summariseByView(records)) {
    const SceneStageTimes& stage = s.mean_stage_ms;
    std::printf("%49d  %9d  %12.0f  %11.0f  %9.0f  %14.0f  %6.0f  %5.0f\n", s.view, s.segmented,
                s.mean_segmentation_ms, stage.preparation, stage.instances, stage.identification,
                stage.groups, stage.parts);
  }
  const int models = records.empty() ? 0 : records.front().models;
  std::printf("time per segmented view against candidates (%d models):\n", models);
  for (const CandidateTimeBin& bin : timeByCandidates(records)) {
    std::printf(
        "  %2d-%2d candidates: %3d views, mean %.1f candidates, time mean %.0f ms, "
        "median %.0f ms\n",
        bin.low, bin.high, bin.views, bin.mean_candidates, bin.mean_time_ms, bin.median_time_ms);
  }
}

}  // namespace vdc::tools

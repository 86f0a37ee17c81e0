#include "scene_evaluation_csv.h"

#include <cstdio>
#include <functional>
#include <string>

namespace vdc::tools {

namespace {

std::string number(double value, const char* format = "%.3f") {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

// `cell` of each item, ';'-separated.
template <typename Item>
std::string joined(const std::vector<Item>& items,
                   const std::function<std::string(const Item&)>& cell) {
  std::string text;
  for (const Item& item : items) text += (text.empty() ? "" : ";") + cell(item);
  return text;
}

struct Column {
  const char* name;
  std::function<std::string(const SceneViewRecord&)> cell;
};

const std::vector<Column>& columns() {
  using Identified = IdentifiedInstance;
  static const std::vector<Column> kColumns = {
      {"scene", [](const auto& r) { return std::to_string(r.scene); }},
      {"view", [](const auto& r) { return std::to_string(r.view); }},
      {"segmented", [](const auto& r) { return std::to_string(r.segmented ? 1 : 0); }},
      {"visible_known", [](const auto& r) { return std::to_string(r.metrics.visible_known); }},
      {"identified", [](const auto& r) { return std::to_string(r.metrics.identified.size()); }},
      {"false_identifications",
       [](const auto& r) { return std::to_string(r.metrics.false_identifications.size()); }},
      {"estimates", [](const auto& r) { return std::to_string(r.estimates.size()); }},
      {"matched_hidden", [](const auto& r) { return std::to_string(r.metrics.matched_hidden); }},
      {"candidates", [](const auto& r) { return std::to_string(r.candidates); }},
      {"new_instances", [](const auto& r) { return std::to_string(r.new_instances); }},
      {"models", [](const auto& r) { return std::to_string(r.models); }},
      {"time_ms", [](const auto& r) { return number(r.time_ms, "%.1f"); }},
      {"segmentation_ms", [](const auto& r) { return number(r.segmentation_ms, "%.1f"); }},
      {"identified_models",
       [](const auto& r) {
         return joined<Identified>(r.metrics.identified, [&r](const Identified& i) {
           return r.truth.known[i.truth].model;
         });
       }},
      {"rotation_error_deg",
       [](const auto& r) {
         return joined<Identified>(r.metrics.identified, [](const Identified& i) {
           return number(i.rotation_error_deg);
         });
       }},
      {"position_error_mm",
       [](const auto& r) {
         return joined<Identified>(r.metrics.identified, [](const Identified& i) {
           return number(i.position_error * 1000.0);
         });
       }},
      {"inside_cone90",
       [](const auto& r) {
         return joined<Identified>(r.metrics.identified, [](const Identified& i) {
           return std::string(i.inside_cone90 ? "1" : "0");
         });
       }},
      {"missed_models",
       [](const auto& r) {
         return joined<int>(r.missed, [&r](int k) { return r.truth.known[k].model; });
       }},
      {"missed_visible_fraction",
       [](const auto& r) {
         return joined<int>(
             r.missed, [&r](int k) { return number(r.truth.known[k].visible_fraction, "%.2f"); });
       }},
      {"false_models",
       [](const auto& r) {
         return joined<FalseIdentification>(
             r.metrics.false_identifications,
             [&r](const FalseIdentification& f) { return r.estimates[f.estimate].model; });
       }},
      {"false_kinds",
       [](const auto& r) {
         return joined<FalseIdentificationKind>(r.false_kinds, [](FalseIdentificationKind k) {
           return std::string(falseIdentificationKindName(k));
         });
       }},
      // The stages of time_ms after segmentation (SceneStageTimes), last so that older column
      // positions hold.
      {"preparation_ms", [](const auto& r) { return number(r.stage_ms.preparation, "%.1f"); }},
      {"instances_ms", [](const auto& r) { return number(r.stage_ms.instances, "%.1f"); }},
      {"identification_ms",
       [](const auto& r) { return number(r.stage_ms.identification, "%.1f"); }},
      {"groups_ms", [](const auto& r) { return number(r.stage_ms.groups, "%.1f"); }},
      {"parts_ms", [](const auto& r) { return number(r.stage_ms.parts, "%.1f"); }},
  };
  return kColumns;
}

}  // namespace

void writeScenesCsv(std::ostream& out, const std::vector<SceneViewRecord>& records) {
  const auto& all = columns();
  for (std::size_t c = 0; c < all.size(); ++c) out << (c ? "," : "") << all[c].name;
  out << "\n";
  for (const SceneViewRecord& record : records) {
    for (std::size_t c = 0; c < all.size(); ++c) out << (c ? "," : "") << all[c].cell(record);
    out << "\n";
  }
}

}  // namespace vdc::tools

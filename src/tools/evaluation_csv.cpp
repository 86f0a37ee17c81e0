#include "evaluation_csv.h"

#include <cstdio>
#include <string>

#include "evaluation_labels.h"

namespace vdc::tools {

namespace {

// The cell a row of errors.csv is about: one view of one sequence of one result's setting.
struct ErrorsCsvCell {
  const EvaluationResult& result;
  const SettingErrors& setting;
  Eigen::Index sequence = 0;  // row of setting.errors_deg
  Eigen::Index view = 0;      // column of setting.errors_deg (0-based)
};

struct ErrorsCsvColumn {
  const char* name;
  std::string (*value)(const ErrorsCsvCell& cell);
};

std::string fixed4(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4f", value);
  return text;
}

// The columns of errors.csv in order: a new column is one entry here (and its data in
// EvaluationResult).
const ErrorsCsvColumn kColumns[] = {
    {"planner", [](const ErrorsCsvCell& c) { return c.result.planner; }},
    {"visibility", [](const ErrorsCsvCell& c) { return visibilityLabel(c.setting.radius); }},
    {"sequence", [](const ErrorsCsvCell& c) { return std::to_string(c.sequence); }},
    {"view", [](const ErrorsCsvCell& c) { return std::to_string(c.view + 1); }},
    {"map_error_deg",
     [](const ErrorsCsvCell& c) { return fixed4(c.setting.errors_deg(c.sequence, c.view)); }},
};

void writeHeader(std::ostream& out) {
  const char* separator = "";
  for (const ErrorsCsvColumn& column : kColumns) {
    out << separator << column.name;
    separator = ",";
  }
  out << '\n';
}

void writeRow(std::ostream& out, const ErrorsCsvCell& cell) {
  const char* separator = "";
  for (const ErrorsCsvColumn& column : kColumns) {
    out << separator << column.value(cell);
    separator = ",";
  }
  out << '\n';
}

}  // namespace

void writeErrorsCsv(std::ostream& out, const std::vector<EvaluationResult>& results) {
  writeHeader(out);
  for (const auto& result : results) {
    for (const auto& setting : result.settings) {
      for (Eigen::Index s = 0; s < setting.errors_deg.rows(); ++s) {
        for (Eigen::Index v = 0; v < setting.errors_deg.cols(); ++v) {
          writeRow(out, {result, setting, s, v});
        }
      }
    }
  }
}

}  // namespace vdc::tools

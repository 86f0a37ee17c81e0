#include "evaluation_csv.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <string>

#include "evaluation_labels.h"

namespace vdc::tools {

namespace {

// One row of errors.csv: the belief of one sequence at one moment of one run and setting.
struct ErrorsCsvRow {
  std::string planner, visibility;
  Eigen::Index sequence = 0;  // from 0
  int view = 0;               // from 1
  double map_error_deg = 0.0;
  std::string event;               // "view", "fused" or "dwell_end"
  std::optional<double> time_s;    // streams only
  std::optional<int> views_fused;  // the estimator's trust signals
  std::optional<double> cone90_deg;
  // Distance of the estimated object origin from the true one; none where there is no position
  // estimate (a baseline's view without a pose, stream rows).
  std::optional<double> position_error_mm;
};

struct ErrorsCsvColumn {
  const char* name;
  std::string (*value)(const ErrorsCsvRow& row);
};

std::string fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string optionalFixed(const std::optional<double>& value, int decimals) {
  return value ? fixed(*value, decimals) : std::string();
}

// The columns of errors.csv in order: a new column is one entry here (and its data in
// ErrorsCsvRow).
const ErrorsCsvColumn kColumns[] = {
    {"planner", [](const ErrorsCsvRow& r) { return r.planner; }},
    {"visibility", [](const ErrorsCsvRow& r) { return r.visibility; }},
    {"sequence", [](const ErrorsCsvRow& r) { return std::to_string(r.sequence); }},
    {"view", [](const ErrorsCsvRow& r) { return std::to_string(r.view); }},
    {"map_error_deg", [](const ErrorsCsvRow& r) { return fixed(r.map_error_deg, 4); }},
    {"event", [](const ErrorsCsvRow& r) { return r.event; }},
    {"time_s", [](const ErrorsCsvRow& r) { return optionalFixed(r.time_s, 4); }},
    {"views_fused",
     [](const ErrorsCsvRow& r) {
       return r.views_fused ? std::to_string(*r.views_fused) : std::string();
     }},
    {"cone90_deg", [](const ErrorsCsvRow& r) { return optionalFixed(r.cone90_deg, 4); }},
    {"inside_cone90",
     [](const ErrorsCsvRow& r) {
       if (!r.cone90_deg) return std::string();
       return std::string(r.map_error_deg <= *r.cone90_deg ? "1" : "0");
     }},
    {"position_error_mm",
     [](const ErrorsCsvRow& r) { return optionalFixed(r.position_error_mm, 4); }},
};

void writeHeader(std::ostream& out) {
  const char* separator = "";
  for (const ErrorsCsvColumn& column : kColumns) {
    out << separator << column.name;
    separator = ",";
  }
  out << '\n';
}

void writeRow(std::ostream& out, const ErrorsCsvRow& row) {
  const char* separator = "";
  for (const ErrorsCsvColumn& column : kColumns) {
    out << separator << column.value(row);
    separator = ",";
  }
  out << '\n';
}

void writeResultRows(std::ostream& out, const EvaluationResult& result) {
  for (const auto& setting : result.settings) {
    const bool trust = setting.cone90_deg.size() == setting.errors_deg.size() &&
                       setting.views_fused.size() == setting.errors_deg.size();
    for (Eigen::Index s = 0; s < setting.errors_deg.rows(); ++s) {
      for (Eigen::Index v = 0; v < setting.errors_deg.cols(); ++v) {
        ErrorsCsvRow row;
        row.planner = result.planner;
        row.visibility = visibilityLabel(setting.radius);
        row.sequence = s;
        row.view = static_cast<int>(v) + 1;
        row.map_error_deg = setting.errors_deg(s, v);
        row.event = "view";
        if (trust) {
          row.views_fused = setting.views_fused(s, v);
          row.cone90_deg = setting.cone90_deg(s, v);
        }
        if (s < setting.position_errors_mm.rows() && v < setting.position_errors_mm.cols() &&
            !std::isnan(setting.position_errors_mm(s, v))) {
          row.position_error_mm = setting.position_errors_mm(s, v);
        }
        writeRow(out, row);
      }
    }
  }
}

void writeStreamRows(std::ostream& out, const StreamEvaluationResult& stream) {
  for (const auto& setting : stream.settings) {
    for (std::size_t s = 0; s < setting.sequences.size(); ++s) {
      auto write = [&](const StreamSample& sample, const char* event) {
        writeRow(out, {stream.name, visibilityLabel(setting.radius), static_cast<Eigen::Index>(s),
                       sample.view, sample.map_error_deg, event, sample.time_s, sample.views_fused,
                       sample.cone90_deg, std::nullopt});  // the stream has no position
      };
      for (const StreamSample& sample : setting.sequences[s].fusions) write(sample, "fused");
      for (const StreamSample& sample : setting.sequences[s].view_ends) write(sample, "dwell_end");
    }
  }
}

}  // namespace

void writeErrorsCsv(std::ostream& out, const std::vector<EvaluationResult>& results,
                    const std::vector<StreamEvaluationResult>& streams) {
  writeHeader(out);
  for (const auto& result : results) writeResultRows(out, result);
  for (const auto& stream : streams) writeStreamRows(out, stream);
}

void writeErrorsCsv(std::ostream& out, const EvaluationReport& report) {
  std::vector<EvaluationResult> rows = report.results;
  for (const auto* baseline : {&report.baseline, &report.baseline_icp}) {
    if (*baseline) rows.push_back((*baseline)->result);
  }
  writeErrorsCsv(out, rows, report.streams);
}

}  // namespace vdc::tools

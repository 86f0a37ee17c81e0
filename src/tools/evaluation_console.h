#pragma once

#include <string>

#include "evaluation_report.h"

namespace vdc::tools {

// The terminal lines of `vdc evaluate`: what is about to run (stderr), and the figures the
// evaluation documents quote (stdout).
void printEvaluationStart(const std::string& model_path, const std::string& mesh_path,
                          const EvaluationSettings& settings);
void printEvaluationReport(const EvaluationReport& report);

}  // namespace vdc::tools

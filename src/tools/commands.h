#pragma once

#include <CLI/CLI.hpp>

namespace vdc::tools {

// Each subcommand of `vdc` registers itself on the app; its callback does the work and throws
// vdc::Error for a failure the user must see (main prints it as one line, exit code 1).
void addMeshCommand(CLI::App& app);
void addViewsCommand(CLI::App& app);
void addTrainCommand(CLI::App& app);
void addInspectCommand(CLI::App& app);
void addHeatmapCommand(CLI::App& app);
void addEvaluateCommand(CLI::App& app);
void addEvaluateScenesCommand(CLI::App& app);
void addEvaluatePatrolCommand(CLI::App& app);
void addWriteBopCommand(CLI::App& app);
void addEvaluateBopCommand(CLI::App& app);
void addSensorStatsCommand(CLI::App& app);

}  // namespace vdc::tools

// `vdc`: the offline command-line tool (build the object, train, inspect, evaluate, draw).
// Every subcommand lives in its own file and registers itself here; failures are one line on
// stderr and exit code 1, usage errors exit code 2.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "commands.h"
#include "view_direction_classification/common/error.h"

int main(int argc, char** argv) {
  CLI::App app{"vdc: viewing-direction classification for object orientation (offline tool)"};
  app.require_subcommand(1);
  vdc::tools::addMeshCommand(app);
  vdc::tools::addViewsCommand(app);
  vdc::tools::addTrainCommand(app);
  vdc::tools::addInspectCommand(app);
  vdc::tools::addHeatmapCommand(app);
  vdc::tools::addEvaluateCommand(app);
  vdc::tools::addEvaluateScenesCommand(app);
  vdc::tools::addEvaluatePatrolCommand(app);
  vdc::tools::addWriteBopCommand(app);
  vdc::tools::addEvaluateBopCommand(app);
  vdc::tools::addSensorStatsCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help is a "parse error" with exit code 0; every real usage error exits with 2.
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  } catch (const vdc::Error& error) {
    std::cerr << "vdc: " << error.what() << "\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "vdc: unexpected failure: " << error.what() << "\n";
    return 1;
  }
  return 0;
}

// `vdc`: the offline command-line tool (build the object, train, inspect, evaluate, draw).
// Every subcommand lives in its own file and registers itself here; failures are one line on
// stderr and exit code 1, usage errors exit code 2.
#include <CLI/CLI.hpp>

#include <iostream>

#include "view_direction_classification/core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"vdc: viewing-direction classification for object orientation (offline tool)"};
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  } catch (const vdc::Error& error) {
    std::cerr << "vdc: " << error.what() << "\n";
    return 1;
  }
  return 0;
}

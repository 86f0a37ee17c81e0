#include "identity_options.h"

namespace vdc::tools {

void addIdentityOptions(CLI::App& command, IdentificationParameters* identity) {
  command
      .add_option("--unknown-score", identity->unknown_score,
                  "verification score of \"unknown\" (identity_unknown_score)")
      ->capture_default_str()
      ->check(CLI::Range(-1.0, 1.0));
  command
      .add_option("--min-probability", identity->min_probability,
                  "identity probability from which an instance is reported "
                  "(identity_min_probability)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  command
      .add_option("--track-probability", identity->track_probability,
                  "identity probability from which a candidate becomes a tentative instance, "
                  "reported once it reaches --min-probability (identity_track_probability)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
}

}  // namespace vdc::tools

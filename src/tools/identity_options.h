#pragma once

#include <CLI/CLI.hpp>

#include "view_direction_classification/recognition/candidate_identification.h"

namespace vdc::tools {

// `--unknown-score`, `--min-probability` and `--track-probability` of `vdc evaluate-scenes`,
// `vdc evaluate-patrol` and `vdc evaluate-bop`: the scene estimator's identity settings, as the node's
// identity_unknown_score, identity_min_probability and identity_track_probability. Bound to
// *identity, which must outlive the parse.
void addIdentityOptions(CLI::App& command, IdentificationParameters* identity);

}  // namespace vdc::tools

#pragma once

#include <ostream>
#include <vector>

#include "view_direction_classification/bop/bop_types.h"

namespace vdc {

// One pose estimate of the BOP results file.
struct BopEstimate {
  int scene_id = 0, im_id = 0, obj_id = 0;
  double score = 0.0;         // higher is more confident
  BopPose camera_from_model;  // R, t [mm]
  double time_s = 0.0;        // the image's processing time, the same for all its estimates
};

// BOP's results CSV (bop_toolkit's docs: the header "scene_id,im_id,obj_id,score,R,t,time", R as
// nine space-separated values row-major, t as three [mm], time [s]); doubles are printed
// round-trip.
void writeBopResultsCsv(std::ostream& out, const std::vector<BopEstimate>& estimates);

}  // namespace vdc

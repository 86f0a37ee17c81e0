#include "view_direction_classification/bop/bop_results.h"

#include <iomanip>
#include <limits>

namespace vdc {

void writeBopResultsCsv(std::ostream& out, const std::vector<BopEstimate>& estimates) {
  const auto precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << "scene_id,im_id,obj_id,score,R,t,time\n";
  for (const BopEstimate& e : estimates) {
    out << e.scene_id << ',' << e.im_id << ',' << e.obj_id << ',' << e.score << ',';
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) out << (r + c > 0 ? " " : "") << e.camera_from_model.R(r, c);
    }
    out << ',' << e.camera_from_model.t.x() << ' ' << e.camera_from_model.t.y() << ' '
        << e.camera_from_model.t.z() << ',' << e.time_s << '\n';
  }
  out.precision(precision);
}

}  // namespace vdc

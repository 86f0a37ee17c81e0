#pragma once

namespace vdc {

// PCL 1.13's pcl::PPFRegistration votes into floor(2 pi / s) bins per model point at bin
// floor((alpha + pi) / s), s being the hash map's float angle step and alpha a float in
// [-kLargestPpfAngle, kLargestPpfAngle] after its wrap into [-pi, pi] (ppf_registration.hpp,
// computeTransformation). For most steps the largest alpha votes one bin past the end: a heap
// overflow (doc/hardening.md). A step is safe iff (kLargestPpfAngle + pi) / s < floor(2 pi / s),
// evaluated as PCL does (double arithmetic on the float step); for a bin count N that is
// s in ((kLargestPpfAngle + pi) / N, 2 pi / N], an interval narrower than the spacing of floats
// for most N, so only some bin counts have a safe step at all (none has N = 30, 12 degrees).

// The largest float alpha that passes PCL's wrap: the largest float not above pi.
constexpr double kLargestPpfAngle = 3.1415925025939941;

// True when PCL's voting with this float angle step stays inside its accumulator.
bool isSafePpfAngleStep(float step_rad);

// The safe float angle step nearest to `requested_rad` (in (0, pi/2]): searches the bin counts
// around 2 pi / requested_rad, outwards, through every float of each count's interval. Throws
// vdc::Error for a requested step that is not positive and finite or above pi / 2, or when no
// bin count within the search has a safe step.
float safePpfAngleStep(double requested_rad);

}  // namespace vdc

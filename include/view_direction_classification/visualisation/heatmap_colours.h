#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace vdc {

// The paper's heatmap scale (doc/method.md section 7): white at score 0, black at `black_at`, linear
// grey in between, black above. Scores below 0 (the -1 of "not observable") or NaN get
// kUnobservableColour, a muted blue that cannot be mistaken for a grey level.
constexpr std::array<std::uint8_t, 3> kUnobservableColour = {70, 110, 170};

// Median of the values >= 0 (mean of the two middle ones for an even count); 0 if there is none.
double medianOfValid(const Eigen::VectorXf& values);
// Maximum of the values >= 0 (the paper's second scaling); 0 if there is none.
double maximumOfValid(const Eigen::VectorXf& values);

// RGB of `value` on the scale. With black_at <= 0 (no valid value, or all zero) the scale
// degenerates to a step: 0 is white, anything above black.
std::array<std::uint8_t, 3> heatmapColour(double value, double black_at);

}  // namespace vdc

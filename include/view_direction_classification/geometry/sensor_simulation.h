#pragma once

#include <random>
#include <vector>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/sensor_model.h"

namespace vdc {

// Turns a noise-free depth image (row-major, width x height of `intrinsics`, 0 = no hit) into
// what the sensor `model` measures, 0 where it measures nothing. `projector_depth` is the
// noise-free image rendered from the projector / second imager (translated by model.baseline
// along +x, same intrinsics); it is read only when model.shadows is set. Order: shadows, edge
// effects (dropouts, flying pixels), then per-pixel depth noise and quantisation, each drawing
// from rng in row-major order, so the result is a function of the inputs and rng's state.
// Throws vdc::Error for a bad model (checkSensorModel) or images of the wrong size.
std::vector<float> simulateSensor(const SensorModel& model, const CameraIntrinsics& intrinsics,
                                  const std::vector<float>& depth,
                                  const std::vector<float>& projector_depth, std::mt19937& rng);

}  // namespace vdc

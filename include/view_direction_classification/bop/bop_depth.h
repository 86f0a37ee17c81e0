#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_types.h"

namespace vdc {

// A BOP depth image: 16-bit values, row-major; a value times the image's depth_scale is the depth
// in mm, 0 is no measurement.
struct BopDepthImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> values;
};

// Reads a depth PNG. Throws vdc::Error naming the file if it is missing or no PNG, is not a
// 16-bit single-channel (grayscale) image, or is not expected_width x expected_height.
// libpng's simplified reader takes 16-bit data as linear and returns it unchanged; a file with a
// gAMA or sRGB chunk saying otherwise would be converted (BOP's depth PNGs carry neither).
BopDepthImage readBopDepthPng(const std::string& path, int expected_width, int expected_height);

// Writes a 16-bit grayscale PNG; throws vdc::Error naming the file if it cannot be written.
void writeBopDepthPng(const BopDepthImage& image, const std::string& path);

// Quantises a depth image in metres (0: no hit, as DepthRenderer::renderDepth gives it) to the
// format's values: round(depth [mm] / depth_scale). A depth beyond the 16-bit range becomes 0
// (no measurement) rather than wrapping. Throws vdc::Error for a depth_scale that is not > 0.
BopDepthImage quantiseDepth(const std::vector<float>& depth_m, int width, int height,
                            double depth_scale);

// The organised cloud (width x height, optical frame, metres) of a depth image seen with
// `camera`: pixel (u, v) with depth z gives ((u - cx) z / fx, (v - cy) z / fy, z), as the
// renderer casts its rays; pixels without a measurement are NaN. Throws vdc::Error if the
// image's size is not the camera's.
pcl::PointCloud<pcl::PointXYZ> bopDepthCloud(const BopDepthImage& image, const BopCamera& camera);

}  // namespace vdc

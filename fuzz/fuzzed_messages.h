#pragma once

// Messages built from a fuzzer's bytes, shared by the fuzz targets. Each builder draws its
// fields from the bytes so that any field may take any value, but plausible values (valid
// quaternions, consistent cloud sizes, the field names the readers look for) come often enough
// for the fuzzer to get past the first check and into the code behind it.

#include <fuzzer/FuzzedDataProvider.h>
#include <geometry_msgs/Quaternion.h>
#include <sensor_msgs/PointCloud2.h>
#include <view_direction_classification/BinghamMixture.h>

#include <string>

namespace vdc::fuzz {

// A double that is often one of the values that break arithmetic (0, -0, NaN, +-inf, tiny,
// huge, 1, -1) and otherwise any double of the bytes.
double fuzzedDouble(FuzzedDataProvider& data);

// A concentration: often in the valid range [-500, 0], else any fuzzedDouble.
double fuzzedConcentration(FuzzedDataProvider& data);

// A quaternion: a normalised one, or four fuzzedDoubles.
geometry_msgs::Quaternion fuzzedQuaternionMsg(FuzzedDataProvider& data);

// A frame name: empty, one of "world", "object", "camera", or a short string of the bytes.
std::string fuzzedFrame(FuzzedDataProvider& data);

// 0 to 8 components, each either a valid one (the core's own message of concentrations and
// axes drawn from the bytes, then perhaps one field overwritten) or every field fuzzed.
view_direction_classification::BinghamMixture fuzzedBinghamMixtureMsg(FuzzedDataProvider& data);

// A cloud with 0 to 6 fields (names x, y, z, rgb, intensity or any; any offset, datatype and
// count), width, height, point_step and row_step either consistent with each other or any
// 32-bit value, either endianness, and the rest of the bytes (up to 64 KiB) as data (repeated to
// the size the layout needs when the sizes are meant to agree).
sensor_msgs::PointCloud2 fuzzedPointCloud2(FuzzedDataProvider& data);

}  // namespace vdc::fuzz

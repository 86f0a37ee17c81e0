#include "fuzzed_messages.h"

#include <sensor_msgs/PointField.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/ros/bingham_conversions.h"
#include "view_direction_classification/ros/geometry_conversions.h"

namespace vdc::fuzz {
namespace {

using view_direction_classification::BinghamComponent;
using view_direction_classification::BinghamMixture;

constexpr std::uint32_t kMaxCloudBytes = 64 * 1024;

Eigen::Vector4d fuzzedUnitQuaternion(FuzzedDataProvider& data) {
  Eigen::Vector4d q;
  for (int i = 0; i < 4; ++i) q(i) = data.ConsumeFloatingPointInRange(-1.0, 1.0);
  if (q.norm() < 1e-3) q = Eigen::Vector4d(1, 0, 0, 0);
  return q.normalized();
}

// A valid component of the core (sorted concentrations, orthonormal axes from a rotation of
// the identity basis) as the message the estimator would publish.
BinghamComponent validComponentMsg(FuzzedDataProvider& data) {
  const Eigen::Vector3d concentrations(fuzzedConcentration(data), fuzzedConcentration(data),
                                       fuzzedConcentration(data));
  const Eigen::Matrix4d basis = quaternionLeftMatrix(fuzzedUnitQuaternion(data));
  const double weight = data.ConsumeProbability<double>();
  try {
    return toBinghamComponentMsg(weight, BinghamDistribution(concentrations, basis.leftCols<3>()));
  } catch (const Error&) {
    // Concentrations the core refuses (e.g. positive): a uniform component instead.
    return toBinghamComponentMsg(weight, BinghamDistribution());
  }
}

// A component with every field drawn from the bytes.
BinghamComponent fuzzedComponentMsg(FuzzedDataProvider& data) {
  BinghamComponent msg;
  msg.weight = fuzzedDouble(data);
  for (double& z : msg.concentrations) z = fuzzedConcentration(data);
  for (auto& axis : msg.axes) axis = fuzzedQuaternionMsg(data);
  msg.mode = fuzzedQuaternionMsg(data);
  msg.normaliser = fuzzedDouble(data);
  return msg;
}

// One field of a valid component overwritten with a fuzzed value.
void corruptOneField(FuzzedDataProvider& data, BinghamComponent& msg) {
  switch (data.ConsumeIntegralInRange(0, 5)) {
    case 0:
      msg.weight = fuzzedDouble(data);
      break;
    case 1:
      msg.concentrations[data.ConsumeIntegralInRange(0, 2)] = fuzzedDouble(data);
      break;
    case 2:
      msg.axes[data.ConsumeIntegralInRange(0, 2)] = fuzzedQuaternionMsg(data);
      break;
    case 3:
      msg.mode = fuzzedQuaternionMsg(data);
      break;
    case 4:
      msg.normaliser = fuzzedDouble(data);
      break;
    default:
      break;  // left valid
  }
}

sensor_msgs::PointField fuzzedField(FuzzedDataProvider& data) {
  static const std::array<const char*, 5> kNames = {"x", "y", "z", "rgb", "intensity"};
  sensor_msgs::PointField field;
  const std::size_t name = data.ConsumeIntegralInRange<std::size_t>(0, kNames.size());
  field.name = name < kNames.size() ? kNames[name] : data.ConsumeRandomLengthString(8);
  field.offset = data.ConsumeBool() ? data.ConsumeIntegralInRange<std::uint32_t>(0, 32)
                                    : data.ConsumeIntegral<std::uint32_t>();
  field.datatype =
      data.ConsumeBool() ? sensor_msgs::PointField::FLOAT32 : data.ConsumeIntegral<std::uint8_t>();
  field.count = data.ConsumeBool() ? 1 : data.ConsumeIntegral<std::uint32_t>();
  return field;
}

sensor_msgs::PointField floatField(const char* name, std::uint32_t offset) {
  sensor_msgs::PointField field;
  field.name = name;
  field.offset = offset;
  field.datatype = sensor_msgs::PointField::FLOAT32;
  field.count = 1;
  return field;
}

}  // namespace

double fuzzedDouble(FuzzedDataProvider& data) {
  static const std::array<double, 10> kSpecial = {0.0,
                                                  -0.0,
                                                  1.0,
                                                  -1.0,
                                                  std::numeric_limits<double>::quiet_NaN(),
                                                  std::numeric_limits<double>::infinity(),
                                                  -std::numeric_limits<double>::infinity(),
                                                  std::numeric_limits<double>::denorm_min(),
                                                  1e300,
                                                  -1e300};
  const std::size_t pick = data.ConsumeIntegralInRange<std::size_t>(0, kSpecial.size());
  return pick < kSpecial.size() ? kSpecial[pick] : data.ConsumeFloatingPoint<double>();
}

double fuzzedConcentration(FuzzedDataProvider& data) {
  return data.ConsumeBool() ? data.ConsumeFloatingPointInRange(-500.0, 0.0) : fuzzedDouble(data);
}

geometry_msgs::Quaternion fuzzedQuaternionMsg(FuzzedDataProvider& data) {
  if (data.ConsumeBool()) return toQuaternionMsg(fuzzedUnitQuaternion(data));
  geometry_msgs::Quaternion msg;
  msg.x = fuzzedDouble(data);
  msg.y = fuzzedDouble(data);
  msg.z = fuzzedDouble(data);
  msg.w = fuzzedDouble(data);
  return msg;
}

std::string fuzzedFrame(FuzzedDataProvider& data) {
  static const std::array<const char*, 4> kFrames = {"", "world", "object", "camera"};
  const std::size_t pick = data.ConsumeIntegralInRange<std::size_t>(0, kFrames.size());
  return pick < kFrames.size() ? kFrames[pick] : data.ConsumeRandomLengthString(16);
}

BinghamMixture fuzzedBinghamMixtureMsg(FuzzedDataProvider& data) {
  BinghamMixture msg;
  msg.header.frame_id = fuzzedFrame(data);
  const int count = data.ConsumeIntegralInRange(0, 8);
  for (int k = 0; k < count; ++k) {
    if (data.ConsumeBool()) {
      msg.components.push_back(validComponentMsg(data));
      corruptOneField(data, msg.components.back());
    } else {
      msg.components.push_back(fuzzedComponentMsg(data));
    }
  }
  msg.map_orientation = fuzzedQuaternionMsg(data);
  return msg;
}

sensor_msgs::PointCloud2 fuzzedPointCloud2(FuzzedDataProvider& data) {
  sensor_msgs::PointCloud2 msg;
  msg.header.frame_id = fuzzedFrame(data);
  msg.is_bigendian = data.ConsumeBool();
  msg.is_dense = data.ConsumeBool();
  std::uint32_t data_size = 0;
  const bool consistent = data.ConsumeBool();
  if (consistent) {
    // Sizes that agree (or nearly: a few bytes of padding or of data more or less).
    msg.point_step = data.ConsumeIntegralInRange<std::uint32_t>(0, 64);
    msg.width = data.ConsumeIntegralInRange<std::uint32_t>(0, 64);
    msg.height = data.ConsumeIntegralInRange<std::uint32_t>(0, 8);
    msg.row_step = msg.width * msg.point_step + data.ConsumeIntegralInRange<std::uint32_t>(0, 8);
    const std::int64_t size =
        std::int64_t(msg.height) * msg.row_step + data.ConsumeIntegralInRange<std::int64_t>(-8, 8);
    data_size =
        std::uint32_t(std::max<std::int64_t>(0, std::min<std::int64_t>(size, kMaxCloudBytes)));
  } else {
    msg.point_step = data.ConsumeIntegral<std::uint32_t>();
    msg.width = data.ConsumeIntegral<std::uint32_t>();
    msg.height = data.ConsumeIntegral<std::uint32_t>();
    msg.row_step = data.ConsumeIntegral<std::uint32_t>();
    data_size = data.ConsumeIntegralInRange<std::uint32_t>(0, kMaxCloudBytes);
  }
  if (data.ConsumeBool()) {
    // The layout every depth camera driver publishes first: x, y, z as FLOAT32 at 0, 4, 8.
    for (const auto& [name, offset] : {std::pair{"x", 0u}, {"y", 4u}, {"z", 8u}}) {
      msg.fields.push_back(floatField(name, offset));
    }
  }
  const int extra_fields = data.ConsumeIntegralInRange(0, 6);
  for (int i = 0; i < extra_fields; ++i) msg.fields.push_back(fuzzedField(data));
  msg.data = data.ConsumeBytes<std::uint8_t>(data_size);
  if (consistent && msg.data.size() < data_size) {
    // Sizes that agree need more bytes than a short input has: repeat the ones it has (a cloud's
    // values matter less than its layout).
    const std::size_t given = msg.data.size();
    msg.data.resize(data_size, 0x3f);
    for (std::size_t i = given; given > 0 && i < data_size; ++i) msg.data[i] = msg.data[i % given];
  }
  return msg;
}

}  // namespace vdc::fuzz

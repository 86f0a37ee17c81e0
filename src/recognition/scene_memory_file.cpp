#include "view_direction_classification/recognition/scene_memory_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "../training/hdf5_file.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// File layout (format version 1). K belief components, V fused views; an optional value is a
// dataset of 0 rows (absent) or 1 row, so every dataset is always there and a missing one means
// a damaged file.
//   /                     attributes format = "view_direction_classification object memory",
//                         format_version = 2, next_id, instances (their count)
//   /instances_named      attribute per model name: instances of it named so far
//   /instances/<k>        k = 0 .. instances - 1; attributes id, model, name, frames_seen,
//                         identity_probability, identity_unknown; from version 2 also gone
//                         (0/1) and absent_frames
//     gone_since          0 or 1 float64 [s] (version 2; version 1 files load as present)
//     identity            attribute per model name: identification's probability
//     centroid_world      3 float64
//     last_seen           0 or 1 float64 [s]
//     estimator/          attribute update_count
//       belief_weights               K float64
//       belief_concentrations        K x 3 float64 (z1 <= z2 <= z3 <= 0)
//       belief_axes                  K x 12 float64: v1, v2, v3 as (w, x, y, z) each
//       fused_views                  V x 3 float64, unit, fixed frame
//       track_centroid               0/1 x 3      track_table      0/1 x 4 (n, d)
//       last_centroid_world          0/1 x 3      last_camera_position_world   0/1 x 3
//       refined_position             0/1 x 3      refined_position_covariance  0/1 x 9 (row-major)
//       confirmed_fit_score          0/1
constexpr char kFormatName[] = "view_direction_classification object memory";
// Version 2 added each instance's presence; version 1 files still load, every instance present.
constexpr std::int64_t kFormatVersion = 2;
constexpr std::int64_t kOldestReadableVersion = 1;

// Shape and value checks, with messages naming the dataset as it is called in the file.
class Checker {
 public:
  explicit Checker(std::string prefix) : prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const std::string& problem) const { throw Error(prefix_ + problem); }

  void shape(const std::string& dataset, const Eigen::MatrixXd& m, Eigen::Index rows,
             Eigen::Index cols) const {
    if (m.rows() != rows || m.cols() != cols) {
      fail("dataset " + dataset + " is " + std::to_string(m.rows()) + " x " +
           std::to_string(m.cols()) + ", expected " + std::to_string(rows) + " x " +
           std::to_string(cols));
    }
    if (!m.allFinite()) fail("dataset " + dataset + " contains NaN or infinite values");
  }

  double finite(const std::string& attribute, double value) const {
    if (!std::isfinite(value)) fail("attribute " + attribute + " is NaN or infinite");
    return value;
  }

  int integer(const std::string& attribute, std::int64_t value, std::int64_t min) const {
    if (value < min || value > std::numeric_limits<int>::max()) {
      fail("attribute " + attribute + " = " + std::to_string(value) + " is out of range");
    }
    return static_cast<int>(value);
  }

 private:
  std::string prefix_;
};

// One row holding a fixed-size value row by row (a 3 x 3 matrix as 9 values), or no row.
template <typename Fixed>
Eigen::MatrixXd optionalRow(const std::optional<Fixed>& value) {
  if (!value) return Eigen::MatrixXd(0, Fixed::SizeAtCompileTime);
  // The transpose's column-major storage is the value's row-major order.
  const Eigen::Matrix<double, Fixed::ColsAtCompileTime, Fixed::RowsAtCompileTime> transposed =
      value->transpose();
  return Eigen::Map<const Eigen::RowVectorXd>(transposed.data(), transposed.size());
}

Eigen::VectorXd optionalScalar(const std::optional<double>& value) {
  return value ? Eigen::VectorXd::Constant(1, *value) : Eigen::VectorXd(0);
}

void writeBelief(Hdf5File& file, const std::string& group, const BinghamMixture& belief) {
  const Eigen::Index k = static_cast<Eigen::Index>(belief.size());
  Eigen::VectorXd weights(k);
  Eigen::MatrixXd concentrations(k, 3), axes(k, 12);
  for (Eigen::Index i = 0; i < k; ++i) {
    const BinghamDistribution& component = belief.component(static_cast<std::size_t>(i));
    weights(i) = belief.weight(static_cast<std::size_t>(i));
    concentrations.row(i) = component.concentrations().transpose();
    const BinghamDistribution::Axes a = component.axes();
    axes.row(i) = Eigen::Map<const Eigen::RowVectorXd>(a.data(), 12);  // column-major: v1, v2, v3
  }
  file.writeVector<double>(group + "/belief_weights", weights);
  file.writeMatrix<double>(group + "/belief_concentrations", concentrations);
  file.writeMatrix<double>(group + "/belief_axes", axes);
}

void writeEstimator(Hdf5File& file, const std::string& group, const EstimatorSnapshot& s) {
  file.createGroup(group);
  file.writeAttribute(group, "update_count", std::int64_t{s.update_count});
  writeBelief(file, group, s.belief);
  Eigen::MatrixXd views(static_cast<Eigen::Index>(s.fused_views.size()), 3);
  for (std::size_t v = 0; v < s.fused_views.size(); ++v) {
    views.row(static_cast<Eigen::Index>(v)) = s.fused_views[v].transpose();
  }
  file.writeMatrix<double>(group + "/fused_views", views);
  file.writeMatrix<double>(group + "/track_centroid",
                           optionalRow(s.track ? std::optional(s.track->centroid) : std::nullopt));
  file.writeMatrix<double>(group + "/track_table",
                           optionalRow(s.track ? s.track->table : std::nullopt));
  file.writeMatrix<double>(group + "/last_centroid_world", optionalRow(s.last_centroid_world));
  file.writeMatrix<double>(group + "/last_camera_position_world",
                           optionalRow(s.last_camera_position_world));
  file.writeMatrix<double>(group + "/refined_position", optionalRow(s.refined_position));
  file.writeMatrix<double>(group + "/refined_position_covariance",
                           optionalRow(s.refined_position_covariance));
  file.writeVector<double>(group + "/confirmed_fit_score", optionalScalar(s.confirmed_fit_score));
}

void writeInstance(Hdf5File& file, const std::string& group, const InstanceMemory& m) {
  file.createGroup(group);
  file.writeAttribute(group, "id", std::int64_t{m.id});
  file.writeAttribute(group, "model", m.model);
  file.writeAttribute(group, "name", m.name);
  file.writeAttribute(group, "frames_seen", std::int64_t{m.frames_seen});
  file.writeAttribute(group, "gone", std::int64_t{m.gone ? 1 : 0});
  file.writeAttribute(group, "absent_frames", std::int64_t{m.absent_frames});
  file.writeVector<double>(group + "/gone_since", optionalScalar(m.gone_since));
  file.writeAttribute(group, "identity_probability", m.identity_probability);
  file.writeAttribute(group, "identity_unknown", m.identity_unknown);
  file.createGroup(group + "/identity");
  for (const auto& [model, probability] : m.identity) {
    file.writeAttribute(group + "/identity", model, probability);
  }
  file.writeVector<double>(group + "/centroid_world", m.centroid_world);
  file.writeVector<double>(group + "/last_seen", optionalScalar(m.last_seen));
  writeEstimator(file, group + "/estimator", m.estimator);
}

void writeMemory(Hdf5File& file, const SceneMemory& memory) {
  file.writeAttribute("/", "format", std::string(kFormatName));
  file.writeAttribute("/", "format_version", kFormatVersion);
  file.writeAttribute("/", "next_id", std::int64_t{memory.next_id});
  file.writeAttribute("/", "instances", static_cast<std::int64_t>(memory.instances.size()));
  file.createGroup("instances_named");
  for (const auto& [model, count] : memory.instances_named) {
    file.writeAttribute("instances_named", model, std::int64_t{count});
  }
  file.createGroup("instances");
  for (std::size_t k = 0; k < memory.instances.size(); ++k) {
    writeInstance(file, "instances/" + std::to_string(k), memory.instances[k]);
  }
}

// A dataset of 0 rows (absent) or 1 row holding the value row by row (optionalRow).
template <typename Fixed>
std::optional<Fixed> readOptional(const Hdf5File& file, const Checker& check,
                                  const std::string& name) {
  constexpr Eigen::Index kCols = Fixed::SizeAtCompileTime;
  const Eigen::MatrixXd m = file.readMatrix<double>(name);
  if (m.rows() == 0) {
    check.shape(name, m, 0, kCols);
    return std::nullopt;
  }
  check.shape(name, m, 1, kCols);
  const Eigen::Matrix<double, Fixed::ColsAtCompileTime, Fixed::RowsAtCompileTime> transposed =
      Eigen::Map<const Eigen::Matrix<double, Fixed::ColsAtCompileTime, Fixed::RowsAtCompileTime>>(
          m.data());
  return Fixed(transposed.transpose());
}

std::optional<double> readOptionalScalar(const Hdf5File& file, const Checker& check,
                                         const std::string& name) {
  const Eigen::VectorXd v = file.readVector<double>(name);
  if (v.size() > 1) {
    check.fail("dataset " + name + " holds " + std::to_string(v.size()) +
               " values, expected 0 or 1");
  }
  if (v.size() == 0) return std::nullopt;
  check.shape(name, v, 1, 1);
  return v(0);
}

BinghamMixture readBelief(const Hdf5File& file, const Checker& check, const std::string& group) {
  const Eigen::VectorXd weights = file.readVector<double>(group + "/belief_weights");
  const Eigen::MatrixXd concentrations = file.readMatrix<double>(group + "/belief_concentrations");
  const Eigen::MatrixXd axes = file.readMatrix<double>(group + "/belief_axes");
  const Eigen::Index k = weights.size();
  if (k == 0) check.fail("dataset " + group + "/belief_weights is empty");
  check.shape(group + "/belief_weights", weights, k, 1);
  check.shape(group + "/belief_concentrations", concentrations, k, 3);
  check.shape(group + "/belief_axes", axes, k, 12);
  std::vector<BinghamDistribution> components;
  try {
    for (Eigen::Index i = 0; i < k; ++i) {
      const Eigen::RowVectorXd row = axes.row(i);
      const BinghamDistribution::Axes a = Eigen::Map<const BinghamDistribution::Axes>(row.data());
      components.emplace_back(concentrations.row(i).transpose(), a);
    }
    return BinghamMixture(std::vector<double>(weights.data(), weights.data() + k),
                          std::move(components));
  } catch (const Error& error) {
    check.fail("the belief in " + group + " is invalid: " + error.what());
  }
}

EstimatorSnapshot readEstimator(const Hdf5File& file, const Checker& check,
                                const std::string& group) {
  EstimatorSnapshot s;
  s.belief = readBelief(file, check, group);
  s.update_count =
      check.integer(group + "/update_count", file.readIntegerAttribute(group, "update_count"), 0);
  const Eigen::MatrixXd views = file.readMatrix<double>(group + "/fused_views");
  check.shape(group + "/fused_views", views, views.rows(), 3);
  for (Eigen::Index v = 0; v < views.rows(); ++v) s.fused_views.push_back(views.row(v));
  if (auto centroid = readOptional<Eigen::Vector3d>(file, check, group + "/track_centroid")) {
    s.track =
        ObjectTrack{*centroid, readOptional<Eigen::Vector4d>(file, check, group + "/track_table")};
  }
  s.last_centroid_world =
      readOptional<Eigen::Vector3d>(file, check, group + "/last_centroid_world");
  s.last_camera_position_world =
      readOptional<Eigen::Vector3d>(file, check, group + "/last_camera_position_world");
  s.refined_position = readOptional<Eigen::Vector3d>(file, check, group + "/refined_position");
  s.refined_position_covariance =
      readOptional<Eigen::Matrix3d>(file, check, group + "/refined_position_covariance");
  s.confirmed_fit_score = readOptionalScalar(file, check, group + "/confirmed_fit_score");
  return s;
}

// The finite double attributes of a group keyed by model name (an instance's identity).
std::map<std::string, double> readPerModel(const Hdf5File& file, const Checker& check,
                                           const std::string& group) {
  if (!file.exists(group)) check.fail("group " + group + " is missing");
  std::map<std::string, double> values;
  for (const std::string& model : file.attributeNames(group)) {
    values[model] = check.finite(group + "/" + model, file.readDoubleAttribute(group, model));
  }
  return values;
}

// The presence datasets of version 2 (ObjectInstance::presence).
void readPresence(const Hdf5File& file, const Checker& check, const std::string& group,
                  InstanceMemory* m) {
  m->gone = check.integer(group + "/gone", file.readIntegerAttribute(group, "gone"), 0) != 0;
  m->absent_frames =
      check.integer(group + "/absent_frames", file.readIntegerAttribute(group, "absent_frames"), 0);
  m->gone_since = readOptionalScalar(file, check, group + "/gone_since");
}

InstanceMemory readInstance(const Hdf5File& file, const Checker& check, const std::string& group,
                            std::int64_t version) {
  if (!file.exists(group)) check.fail("group " + group + " is missing");
  InstanceMemory m;
  m.id = check.integer(group + "/id", file.readIntegerAttribute(group, "id"), 1);
  m.model = file.readStringAttribute(group, "model");
  m.name = file.readStringAttribute(group, "name");
  m.frames_seen =
      check.integer(group + "/frames_seen", file.readIntegerAttribute(group, "frames_seen"), 0);
  m.identity_probability = check.finite(group + "/identity_probability",
                                        file.readDoubleAttribute(group, "identity_probability"));
  m.identity_unknown = check.finite(group + "/identity_unknown",
                                    file.readDoubleAttribute(group, "identity_unknown"));
  m.identity = readPerModel(file, check, group + "/identity");
  const Eigen::VectorXd centroid = file.readVector<double>(group + "/centroid_world");
  check.shape(group + "/centroid_world", centroid, 3, 1);
  m.centroid_world = centroid;
  m.last_seen = readOptionalScalar(file, check, group + "/last_seen");
  if (version >= 2) readPresence(file, check, group, &m);
  m.estimator = readEstimator(file, check, group + "/estimator");
  return m;
}

// The file's format version (one this build reads).
std::int64_t checkFormat(const Hdf5File& file, const Checker& check) {
  std::string format;
  try {
    format = file.readStringAttribute("/", "format");
  } catch (const Error&) {
    // Missing or not a string: either way a foreign file.
  }
  if (format != kFormatName) check.fail("not a view_direction_classification object memory");
  const std::int64_t version = file.readIntegerAttribute("/", "format_version");
  if (version < kOldestReadableVersion || version > kFormatVersion) {
    check.fail("written in format version " + std::to_string(version) + ", this build reads " +
               std::to_string(kOldestReadableVersion) + " to " + std::to_string(kFormatVersion));
  }
  return version;
}

// The memory's values that the file could not hold faithfully (HDF5 stores NaN happily).
void checkWritable(const SceneMemory& memory, const Checker& check) {
  for (const InstanceMemory& m : memory.instances) {
    if (!m.centroid_world.allFinite() || !std::isfinite(m.identity_probability) ||
        (m.last_seen && !std::isfinite(*m.last_seen))) {
      check.fail("instance " + m.name + " has a non-finite value");
    }
  }
}

}  // namespace

void writeSceneMemoryFile(const SceneMemory& memory, const std::string& path) {
  const Checker check(path + ": not saved: ");
  checkWritable(memory, check);
  Hdf5File::writeAtomically(path, [&](Hdf5File& file) { writeMemory(file, memory); });
}

SceneMemory readSceneMemoryFile(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(status)) throw Error(path + ": is a directory, not a file");
  const Hdf5File file = Hdf5File::openReadOnly(path, path);
  const Checker check(path + ": ");
  const std::int64_t version = checkFormat(file, check);
  SceneMemory memory;
  memory.next_id = check.integer("next_id", file.readIntegerAttribute("/", "next_id"), 1);
  const int count = check.integer("instances", file.readIntegerAttribute("/", "instances"), 0);
  if (!file.exists("instances_named")) check.fail("group instances_named is missing");
  for (const std::string& model : file.attributeNames("instances_named")) {
    memory.instances_named[model] = check.integer(
        "instances_named/" + model, file.readIntegerAttribute("instances_named", model), 0);
  }
  if (!file.exists("instances")) check.fail("group instances is missing");
  for (int k = 0; k < count; ++k) {
    memory.instances.push_back(
        readInstance(file, check, "instances/" + std::to_string(k), version));
  }
  return memory;
}

void saveSceneMemory(const SceneEstimator& estimator, const std::string& path) {
  writeSceneMemoryFile(estimator.memory(), path);
}

void loadSceneMemory(const std::string& path, SceneEstimator* estimator) {
  const SceneMemory memory = readSceneMemoryFile(path);
  try {
    estimator->restoreMemory(memory);
  } catch (const Error& error) {
    throw Error(path + ": " + error.what());
  }
}

}  // namespace vdc

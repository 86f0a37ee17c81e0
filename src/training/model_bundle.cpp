#include "view_direction_classification/training/model_bundle.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>

#include "hdf5_file.h"
#include "view_direction_classification/common/error.h"

// File layout (format version 2; version 1 lacks surface/bounds). M views, N surface points, d
// descriptor dimensions, K clusters.
//   /                          attributes format = "view_direction_classification model bundle",
//                              format_version = 2
//   /parameters                attributes: one per TrainingParameters field, same names;
//                              `sensor` (a sensor name, sensor_model.h) is optional: bundles
//                              written before it was recorded trained with kinect_gaussian
//   /views/directions          M x 3 float64, unit viewing directions, object frame
//   /views/centroid_offsets    M x 3 float64, mean visible-part centroid per direction
//   /classifier                attributes num_views (= M), clusters (= K)
//   /classifier/mean, scale    d float32, standardisation
//   /classifier/centroids      K x d float32, k-means centroids in the standardised space
//   /classifier/weights        K(d+1) x M float64: cluster k's logistic regression in rows
//                              k(d+1) .. k(d+1)+d, the last of them the bias
//   /surface/points, normals   N x 3 float32, object frame
//   /surface/bounds            2 x 3 float64, the mesh's bounding box: min corner, max corner
//   /informativeness/view_scores    M float64, v(m), -1 for views without clouds
//   /informativeness/ranking        <= M int32, views by ascending score
//   /informativeness/confusion      M x M float64, C[m', m]
//   /informativeness/score_matrix   N x M float32, K[i, m], -1 = not observable
//   /informativeness/global_scores  N float32, g_i, -1 = never observed
//   /held_out                  attributes accuracy, log_loss, features
// Matrices are row-major (h5py shows rows x columns). Scalars keep their in-memory precision, so
// a save/load round trip is bit-exact.

namespace vdc {
namespace {

constexpr char kFormatName[] = "view_direction_classification model bundle";

// The classifier as stored: its regressions' weights stacked into one matrix.
struct ClassifierArrays {
  std::int64_t num_views = 0;
  Eigen::VectorXf mean, scale;
  Eigen::MatrixXf centroids;
  Eigen::MatrixXd weights;
};

ClassifierArrays arraysOf(const ViewClassifier& classifier) {
  ClassifierArrays arrays;
  arrays.num_views = classifier.numViews();
  arrays.mean = classifier.mean();
  arrays.scale = classifier.scale();
  arrays.centroids = classifier.centroids();
  const Eigen::Index block = classifier.mean().size() + 1;
  arrays.weights.resize(block * classifier.clusters(), classifier.numViews());
  for (int k = 0; k < classifier.clusters(); ++k) {
    arrays.weights.middleRows(k * block, block) =
        classifier.regressions()[static_cast<std::size_t>(k)].weights();
  }
  return arrays;
}

// Only called after checkBundle, so the shapes fit.
ViewClassifier classifierOf(const ClassifierArrays& arrays) {
  const Eigen::Index block = arrays.mean.size() + 1;
  std::vector<MultinomialLogisticRegression> regressions;
  for (Eigen::Index k = 0; k < arrays.centroids.rows(); ++k) {
    regressions.emplace_back(arrays.weights.middleRows(k * block, block));
  }
  return ViewClassifier(arrays.mean, arrays.scale, arrays.centroids, std::move(regressions),
                        static_cast<int>(arrays.num_views));
}

template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> toMatrix(
    const std::vector<Eigen::Matrix<Scalar, 3, 1>>& points) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> matrix(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    matrix.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  }
  return matrix;
}

// Only called after the shape check (3 columns).
template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> toPoints(
    const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& matrix) {
  std::vector<Eigen::Matrix<Scalar, 3, 1>> points(static_cast<std::size_t>(matrix.rows()));
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    points[static_cast<std::size_t>(i)] = matrix.row(i).transpose();
  }
  return points;
}

// Shape and value checks, with messages naming the dataset as it is called in the file.
class Checker {
 public:
  explicit Checker(std::string prefix) : prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const std::string& problem) const { throw Error(prefix_ + problem); }

  template <typename Derived>
  void matrix(const std::string& dataset, const Eigen::DenseBase<Derived>& m, Eigen::Index rows,
              Eigen::Index cols) const {
    if (m.rows() != rows) {
      fail("dataset " + dataset + " has " + std::to_string(m.rows()) + " rows, expected " +
           std::to_string(rows));
    }
    if (m.cols() != cols) {
      fail("dataset " + dataset + " has " + std::to_string(m.cols()) + " columns, expected " +
           std::to_string(cols));
    }
    finite(dataset, m);
  }

  template <typename Derived>
  void vector(const std::string& dataset, const Eigen::DenseBase<Derived>& v,
              Eigen::Index size) const {
    if (v.size() != size) {
      fail("dataset " + dataset + " has " + std::to_string(v.size()) + " entries, expected " +
           std::to_string(size));
    }
    finite(dataset, v);
  }

  template <typename Derived>
  void finite(const std::string& dataset, const Eigen::DenseBase<Derived>& m) const {
    if (!m.derived().allFinite()) fail("dataset " + dataset + " contains NaN or infinite values");
  }

  void finiteAttribute(const std::string& attribute, double value) const {
    if (!std::isfinite(value)) fail("attribute " + attribute + " is NaN or infinite");
  }

 private:
  std::string prefix_;
};

Eigen::MatrixXd boundsMatrix(const Eigen::AlignedBox3d& bounds) {
  Eigen::MatrixXd matrix(2, 3);
  matrix.row(0) = bounds.min().transpose();
  matrix.row(1) = bounds.max().transpose();
  return matrix;
}

// Bundles of format version 1 carry no bounds: the surface samples' box is within one sample
// spacing of the mesh's.
Eigen::AlignedBox3d boundsOfPoints(const std::vector<Eigen::Vector3f>& points) {
  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3f& p : points) bounds.extend(p.cast<double>());
  return bounds;
}

template <typename Parameters, typename Visit>
void forEachParameter(Parameters& p, Visit&& visit) {
  visit("mesh_name", p.mesh_name);
  visit("views", p.views);
  visit("clouds_per_view", p.clouds_per_view);
  visit("seed", p.seed);
  visit("distance", p.distance);
  visit("distance_jitter", p.distance_jitter);
  visit("noise", p.noise);
  visit("image_width", p.image_width);
  visit("image_height", p.image_height);
  visit("fx", p.fx);
  visit("fy", p.fy);
  visit("cx", p.cx);
  visit("cy", p.cy);
  visit("keypoint_voxel", p.keypoint_voxel);
  visit("normal_radius", p.normal_radius);
  visit("fpfh_radius", p.fpfh_radius);
  visit("support_voxel", p.support_voxel);
  visit("min_neighbours", p.min_neighbours);
  visit("n_feat", p.n_feat);
  visit("surface_spacing", p.surface_spacing);
  visit("score_radius", p.score_radius);
  visit("clusters", p.clusters);
  visit("l2", p.l2);
}

void checkBundle(const Checker& check, const ModelBundle& b, const ClassifierArrays& c) {
  const auto M = static_cast<Eigen::Index>(b.view_directions.size());
  if (M < 1) check.fail("dataset views/directions is empty (a model needs at least one view)");
  check.matrix("views/directions", toMatrix(b.view_directions), M, 3);
  // Every measurement is built along these directions: a bad one would fail each cloud online.
  for (Eigen::Index m = 0; m < M; ++m) {
    const double length = b.view_directions[static_cast<std::size_t>(m)].norm();
    if (std::abs(length - 1.0) > 1e-6) {
      check.fail("dataset views/directions row " + std::to_string(m) +
                 " is not a unit vector (length " + std::to_string(length) + ")");
    }
  }
  if (b.parameters.views != M) {
    check.fail("attribute parameters/views is " + std::to_string(b.parameters.views) +
               ", expected " + std::to_string(M) + " (the rows of views/directions)");
  }
  check.matrix("views/centroid_offsets", b.centroid_offsets, M, 3);

  if (c.num_views != M) {
    check.fail("attribute classifier/num_views is " + std::to_string(c.num_views) + ", expected " +
               std::to_string(M) + " (the rows of views/directions)");
  }
  const Eigen::Index d = c.mean.size();
  if (d < 1) check.fail("dataset classifier/mean is empty");
  check.vector("classifier/mean", c.mean, d);
  check.vector("classifier/scale", c.scale, d);
  if ((c.scale.array() <= 0.0f).any()) check.fail("dataset classifier/scale has a value <= 0");
  const Eigen::Index K = c.centroids.rows();
  if (K < 1) check.fail("dataset classifier/centroids has no rows (at least one cluster needed)");
  check.matrix("classifier/centroids", c.centroids, K, d);
  check.matrix("classifier/weights", c.weights, K * (d + 1), M);

  const auto N = static_cast<Eigen::Index>(b.surface_points.size());
  check.matrix("surface/points", toMatrix(b.surface_points), N, 3);
  check.matrix("surface/normals", toMatrix(b.surface_normals), N, 3);
  check.matrix("surface/bounds", boundsMatrix(b.bounds), 2, 3);
  if ((b.bounds.min().array() > b.bounds.max().array()).any()) {
    check.fail("dataset surface/bounds has a minimum above its maximum");
  }

  const ViewInformativeness& info = b.view_informativeness;
  check.vector("informativeness/view_scores", info.view_scores, M);
  if (static_cast<Eigen::Index>(info.ranking.size()) > M) {
    check.fail("dataset informativeness/ranking has " + std::to_string(info.ranking.size()) +
               " entries, expected at most " + std::to_string(M));
  }
  std::set<int> seen;
  for (int view : info.ranking) {
    if (view < 0 || view >= M || !seen.insert(view).second) {
      check.fail("dataset informativeness/ranking holds view " + std::to_string(view) +
                 " twice or outside [0, " + std::to_string(M) + ")");
    }
  }
  check.matrix("informativeness/confusion", info.confusion, M, M);
  check.matrix("informativeness/score_matrix", b.score_matrix, N, M);
  check.vector("informativeness/global_scores", b.global_scores, N);

  check.finiteAttribute("held_out/accuracy", b.held_out.accuracy);
  check.finiteAttribute("held_out/log_loss", b.held_out.log_loss);
  forEachParameter(b.parameters, [&](const char* name, const auto& value) {
    if constexpr (std::is_floating_point_v<std::decay_t<decltype(value)>>) {
      check.finiteAttribute(std::string("parameters/") + name, value);
    }
  });
}

void writeBundle(Hdf5File& file, const ModelBundle& b, const ClassifierArrays& c) {
  file.writeAttribute("/", "format", std::string(kFormatName));
  file.writeAttribute("/", "format_version", std::int64_t{ModelBundle::kFormatVersion});

  file.createGroup("parameters");
  forEachParameter(b.parameters, [&](const char* name, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, std::string> || std::is_floating_point_v<T>) {
      file.writeAttribute("parameters", name, value);
    } else {  // int, std::uint32_t, bool
      file.writeAttribute("parameters", name, static_cast<std::int64_t>(value));
    }
  });

  file.writeAttribute("parameters", "sensor", std::string(sensorName(b.parameters.sensor)));

  file.createGroup("views");
  file.writeMatrix<double>("views/directions", toMatrix(b.view_directions));
  file.writeMatrix<double>("views/centroid_offsets", b.centroid_offsets);

  file.createGroup("classifier");
  file.writeAttribute("classifier", "num_views", c.num_views);
  file.writeAttribute("classifier", "clusters", static_cast<std::int64_t>(c.centroids.rows()));
  file.writeVector<float>("classifier/mean", c.mean);
  file.writeVector<float>("classifier/scale", c.scale);
  file.writeMatrix<float>("classifier/centroids", c.centroids);
  file.writeMatrix<double>("classifier/weights", c.weights);

  file.createGroup("surface");
  file.writeMatrix<float>("surface/points", toMatrix(b.surface_points));
  file.writeMatrix<float>("surface/normals", toMatrix(b.surface_normals));
  file.writeMatrix<double>("surface/bounds", boundsMatrix(b.bounds));

  const ViewInformativeness& info = b.view_informativeness;
  file.createGroup("informativeness");
  file.writeVector<double>("informativeness/view_scores", info.view_scores);
  file.writeVector<int>("informativeness/ranking",
                        Eigen::Map<const Eigen::VectorXi>(
                            info.ranking.data(), static_cast<Eigen::Index>(info.ranking.size())));
  file.writeMatrix<double>("informativeness/confusion", info.confusion);
  file.writeMatrix<float>("informativeness/score_matrix", b.score_matrix);
  file.writeVector<float>("informativeness/global_scores", b.global_scores);

  file.createGroup("held_out");
  file.writeAttribute("held_out", "accuracy", b.held_out.accuracy);
  file.writeAttribute("held_out", "log_loss", b.held_out.log_loss);
  file.writeAttribute("held_out", "features", static_cast<std::int64_t>(b.held_out.features));
}

// Reads an integer attribute into T, refusing values T cannot hold.
template <typename T>
T readInteger(const Hdf5File& file, const Checker& check, const std::string& object,
              const std::string& name) {
  const std::int64_t value = file.readIntegerAttribute(object, name);
  const bool too_small =
      value < 0 &&
      (std::is_unsigned_v<T> || value < static_cast<std::int64_t>(std::numeric_limits<T>::min()));
  const bool too_large = value > 0 && static_cast<std::uint64_t>(value) >
                                          static_cast<std::uint64_t>(std::numeric_limits<T>::max());
  if (too_small || too_large) {
    check.fail("attribute " + object + "/" + name + " = " + std::to_string(value) +
               " is out of range");
  }
  return static_cast<T>(value);
}

// The training sensor; optional (kinect_gaussian, the only one before it was recorded).
DepthSensor readSensor(const Hdf5File& file, const Checker& check) {
  if (!file.hasAttribute("parameters", "sensor")) return DepthSensor::kKinectGaussian;
  const std::string name = file.readStringAttribute("parameters", "sensor");
  try {
    return parseDepthSensor(name);
  } catch (const Error& e) {
    check.fail(std::string("attribute parameters/sensor: ") + e.what());
  }
  return DepthSensor::kKinectGaussian;  // not reached: fail() throws
}

ModelBundle readBundle(const Hdf5File& file, const Checker& check, std::int64_t version,
                       ClassifierArrays* c) {
  ModelBundle b;
  forEachParameter(b.parameters, [&](const char* name, auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, std::string>) {
      value = file.readStringAttribute("parameters", name);
    } else if constexpr (std::is_floating_point_v<T>) {
      value = file.readDoubleAttribute("parameters", name);
    } else if constexpr (std::is_same_v<T, bool>) {
      const std::int64_t flag = file.readIntegerAttribute("parameters", name);
      if (flag != 0 && flag != 1) {
        check.fail(std::string("attribute parameters/") + name + " must be 0 or 1");
      }
      value = flag == 1;
    } else {
      value = readInteger<T>(file, check, "parameters", name);
    }
  });

  b.parameters.sensor = readSensor(file, check);

  const Eigen::MatrixXd directions = file.readMatrix<double>("views/directions");
  check.matrix("views/directions", directions, directions.rows(), 3);
  b.view_directions = toPoints<double>(directions);
  b.centroid_offsets = file.readMatrix<double>("views/centroid_offsets");

  c->num_views = file.readIntegerAttribute("classifier", "num_views");
  c->mean = file.readVector<float>("classifier/mean");
  c->scale = file.readVector<float>("classifier/scale");
  c->centroids = file.readMatrix<float>("classifier/centroids");
  c->weights = file.readMatrix<double>("classifier/weights");
  const std::int64_t clusters = file.readIntegerAttribute("classifier", "clusters");
  if (clusters != c->centroids.rows()) {
    check.fail("attribute classifier/clusters is " + std::to_string(clusters) + " but dataset " +
               "classifier/centroids has " + std::to_string(c->centroids.rows()) + " rows");
  }

  const Eigen::MatrixXf points = file.readMatrix<float>("surface/points");
  const Eigen::MatrixXf normals = file.readMatrix<float>("surface/normals");
  check.matrix("surface/points", points, points.rows(), 3);
  check.matrix("surface/normals", normals, points.rows(), 3);
  b.surface_points = toPoints<float>(points);
  b.surface_normals = toPoints<float>(normals);
  if (version >= 2) {
    const Eigen::MatrixXd bounds = file.readMatrix<double>("surface/bounds");
    check.matrix("surface/bounds", bounds, 2, 3);
    b.bounds = Eigen::AlignedBox3d(bounds.row(0).transpose(), bounds.row(1).transpose());
  } else {
    b.bounds = boundsOfPoints(b.surface_points);
  }

  ViewInformativeness& info = b.view_informativeness;
  info.view_scores = file.readVector<double>("informativeness/view_scores");
  const Eigen::VectorXi ranking = file.readVector<int>("informativeness/ranking");
  info.ranking.assign(ranking.data(), ranking.data() + ranking.size());
  info.confusion = file.readMatrix<double>("informativeness/confusion");
  b.score_matrix = file.readMatrix<float>("informativeness/score_matrix");
  b.global_scores = file.readVector<float>("informativeness/global_scores");

  b.held_out.accuracy = file.readDoubleAttribute("held_out", "accuracy");
  b.held_out.log_loss = file.readDoubleAttribute("held_out", "log_loss");
  b.held_out.features = readInteger<std::size_t>(file, check, "held_out", "features");
  return b;
}

}  // namespace

void saveModelBundle(const ModelBundle& bundle, const std::string& path) {
  const Checker check(path + ": not saved: ");
  if (!bundle.classifier.trained()) check.fail("the classifier is not trained");
  const ClassifierArrays arrays = arraysOf(bundle.classifier);
  checkBundle(check, bundle, arrays);

  Hdf5File::writeAtomically(path, [&](Hdf5File& file) { writeBundle(file, bundle, arrays); });
}

ModelBundle loadModelBundle(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(status)) throw Error(path + ": is a directory, not a file");
  if (std::filesystem::is_regular_file(status) && std::filesystem::file_size(path, error) == 0 &&
      !error) {
    throw Error(path + ": the file is empty, not a model bundle");
  }

  const Hdf5File file = Hdf5File::openReadOnly(path, path);
  const Checker check(path + ": ");
  std::string format;
  try {
    format = file.readStringAttribute("/", "format");
  } catch (const Error&) {
    // Missing or not a string: either way a foreign file.
  }
  if (format != kFormatName) check.fail("not a view_direction_classification model bundle");
  const std::int64_t version = file.readIntegerAttribute("/", "format_version");
  if (version > ModelBundle::kFormatVersion) {
    check.fail("written by format version " + std::to_string(version) +
               ", this build reads up to " + std::to_string(ModelBundle::kFormatVersion));
  }
  if (version < 1) check.fail("invalid format version " + std::to_string(version));

  ClassifierArrays arrays;
  ModelBundle bundle = readBundle(file, check, version, &arrays);
  checkBundle(check, bundle, arrays);
  try {
    bundle.classifier = classifierOf(arrays);
  } catch (const Error& e) {
    check.fail(e.what());
  }
  return bundle;
}

}  // namespace vdc

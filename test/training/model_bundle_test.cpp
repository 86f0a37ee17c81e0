#include "view_direction_classification/training/model_bundle.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "support/temporary_directory_test.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

namespace fs = std::filesystem;

// A complete bundle with arbitrary but non-trivial values: M = 4 views, N = 6 surface points,
// d = 33, K = 2 clusters, one view without clouds.
ModelBundle makeBundle() {
  std::mt19937 rng(42);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto random = [&](Eigen::Index rows, Eigen::Index cols) {
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index i = 0; i < m.size(); ++i) m(i) = normal(rng);
    return m;
  };
  const int M = 4, N = 6, d = 33, K = 2;
  ModelBundle b;
  b.parameters.mesh_name = "mug with handle, 9.5 cm";
  b.parameters.views = M;
  b.parameters.clouds_per_view = 3;
  b.parameters.seed = 4000000000u;  // above INT_MAX: must survive as unsigned
  b.parameters.distance = 0.65;
  b.parameters.noise = false;
  b.parameters.sensor = DepthSensor::kTimeOfFlight;  // not the default: must be recorded
  b.parameters.fx = 525.123456789;
  b.parameters.clusters = K;
  b.parameters.l2 = 1.0 / 3.0;
  for (int m = 0; m < M; ++m) b.view_directions.push_back(random(3, 1).normalized());

  const Eigen::VectorXf scale = random(d, 1).cwiseAbs().cast<float>().array() + 0.1f;
  std::vector<MultinomialLogisticRegression> regressions;
  for (int k = 0; k < K; ++k) regressions.emplace_back(random(d + 1, M));
  b.classifier =
      ViewClassifier(random(d, 1).cast<float>(), scale, random(K, d).cast<float>(), regressions, M);

  for (int i = 0; i < N; ++i) {
    b.surface_points.push_back(random(3, 1).cast<float>());
    b.surface_normals.push_back(random(3, 1).normalized().cast<float>());
  }
  b.view_informativeness.view_scores = random(M, 1).cwiseAbs();
  b.view_informativeness.view_scores(2) = -1.0;
  b.view_informativeness.ranking = {3, 0, 1};
  b.view_informativeness.confusion = random(M, M).cwiseAbs();
  b.score_matrix = random(N, M).cwiseAbs().cast<float>();
  b.score_matrix(1, 2) = -1.0f;
  b.global_scores = random(N, 1).cwiseAbs().cast<float>();
  b.global_scores(5) = -1.0f;
  b.centroid_offsets = random(M, 3);
  b.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-0.04, -0.04, -0.0475),
                                 Eigen::Vector3d(0.071, 0.04, 0.0475));
  b.held_out = HeldOutMetrics{0.123456789, 2.718281828, 987654321};
  return b;
}

class ModelBundleFiles : public test::TemporaryDirectoryTest {
 protected:
  // A valid bundle at `name`, then `edit` applied to it through the raw HDF5 API.
  template <typename Edit>
  std::string editedBundle(const std::string& name, Edit edit) {
    const std::string path = this->path(name);
    saveModelBundle(makeBundle(), path);
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    EXPECT_GE(id, 0);
    edit(id);
    H5Fclose(id);
    return path;
  }

  // The message of the vdc::Error that loading `path` throws ("" if it does not throw).
  static std::string loadError(const std::string& path) {
    try {
      loadModelBundle(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
};

void replaceDataset(hid_t file, const char* name, hsize_t rows, hsize_t cols) {
  H5Ldelete(file, name, H5P_DEFAULT);
  const hsize_t dims[2] = {rows, cols};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t set =
      H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double> zeros(rows * cols, 0.0);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  H5Dclose(set);
  H5Sclose(space);
}

TEST_F(ModelBundleFiles, RoundTripIsBitIdentical) {
  const ModelBundle saved = makeBundle();
  saveModelBundle(saved, path("model.h5"));
  const ModelBundle loaded = loadModelBundle(path("model.h5"));

  const TrainingParameters &a = saved.parameters, &b = loaded.parameters;
  EXPECT_EQ(a.mesh_name, b.mesh_name);
  EXPECT_EQ(a.views, b.views);
  EXPECT_EQ(a.clouds_per_view, b.clouds_per_view);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.distance_jitter, b.distance_jitter);
  EXPECT_EQ(a.noise, b.noise);
  EXPECT_EQ(a.sensor, b.sensor);
  EXPECT_EQ(a.image_width, b.image_width);
  EXPECT_EQ(a.image_height, b.image_height);
  EXPECT_EQ(a.fx, b.fx);
  EXPECT_EQ(a.fy, b.fy);
  EXPECT_EQ(a.cx, b.cx);
  EXPECT_EQ(a.cy, b.cy);
  EXPECT_EQ(a.keypoint_voxel, b.keypoint_voxel);
  EXPECT_EQ(a.normal_radius, b.normal_radius);
  EXPECT_EQ(a.fpfh_radius, b.fpfh_radius);
  EXPECT_EQ(a.min_neighbours, b.min_neighbours);
  EXPECT_EQ(a.n_feat, b.n_feat);
  EXPECT_EQ(a.surface_spacing, b.surface_spacing);
  EXPECT_EQ(a.score_radius, b.score_radius);
  EXPECT_EQ(a.clusters, b.clusters);
  EXPECT_EQ(a.l2, b.l2);

  EXPECT_EQ(saved.view_directions, loaded.view_directions);
  EXPECT_EQ(saved.classifier.numViews(), loaded.classifier.numViews());
  EXPECT_EQ(saved.classifier.mean(), loaded.classifier.mean());
  EXPECT_EQ(saved.classifier.scale(), loaded.classifier.scale());
  EXPECT_EQ(saved.classifier.centroids(), loaded.classifier.centroids());
  ASSERT_EQ(loaded.classifier.clusters(), 2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(saved.classifier.regressions()[k].weights(),
              loaded.classifier.regressions()[k].weights());
  }
  EXPECT_EQ(saved.surface_points, loaded.surface_points);
  EXPECT_EQ(saved.surface_normals, loaded.surface_normals);
  EXPECT_EQ(saved.view_informativeness.view_scores, loaded.view_informativeness.view_scores);
  EXPECT_EQ(saved.view_informativeness.ranking, loaded.view_informativeness.ranking);
  EXPECT_EQ(saved.view_informativeness.confusion, loaded.view_informativeness.confusion);
  EXPECT_EQ(saved.score_matrix, loaded.score_matrix);
  EXPECT_EQ(saved.global_scores, loaded.global_scores);
  EXPECT_EQ(saved.centroid_offsets, loaded.centroid_offsets);
  EXPECT_EQ(saved.bounds.min(), loaded.bounds.min());
  EXPECT_EQ(saved.bounds.max(), loaded.bounds.max());
  EXPECT_EQ(saved.held_out.accuracy, loaded.held_out.accuracy);
  EXPECT_EQ(saved.held_out.log_loss, loaded.held_out.log_loss);
  EXPECT_EQ(saved.held_out.features, loaded.held_out.features);

  // And the loaded classifier predicts exactly as the saved one.
  const Eigen::MatrixXf probe = Eigen::MatrixXf::Random(5, 33);
  EXPECT_EQ(saved.classifier.predict(probe), loaded.classifier.predict(probe));
}

TEST_F(ModelBundleFiles, SavingOverAnExistingBundleReplacesIt) {
  ModelBundle bundle = makeBundle();
  saveModelBundle(bundle, path("model.h5"));
  bundle.parameters.mesh_name = "second";
  saveModelBundle(bundle, path("model.h5"));
  EXPECT_EQ(loadModelBundle(path("model.h5")).parameters.mesh_name, "second");
  EXPECT_EQ(entryCount(), 1);
}

TEST_F(ModelBundleFiles, RefusesMissingFile) {
  EXPECT_EQ(loadError(path("absent.h5")), path("absent.h5") + ": no such file");
}

TEST_F(ModelBundleFiles, RefusesEmptyFile) {
  std::ofstream(path("empty.h5")).close();
  const std::string message = loadError(path("empty.h5"));
  EXPECT_EQ(message.rfind(path("empty.h5") + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

TEST_F(ModelBundleFiles, RefusesTruncatedFileWithOneLineOnly) {
  saveModelBundle(makeBundle(), path("model.h5"));
  std::ifstream in(path("model.h5"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(path("half.h5"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);

  ::testing::internal::CaptureStderr();
  const std::string message = loadError(path("half.h5"));
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(message, path("half.h5") + ": truncated or not an HDF5 file");
  EXPECT_EQ(printed, "");  // HDF5's own error stack is silenced
}

TEST_F(ModelBundleFiles, RefusesTextFile) {
  std::ofstream(path("notes.h5")) << "not hdf5 at all\n";
  EXPECT_EQ(loadError(path("notes.h5")), path("notes.h5") + ": truncated or not an HDF5 file");
}

// An HDF5 file in the given library version bounds' format, holding one dataset.
void writeForeignHdf5File(const std::string& path, H5F_libver_t format) {
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_libver_bounds(access, format, H5F_LIBVER_LATEST);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
  replaceDataset(id, "temperature", 3, 2);
  H5Fclose(id);
  H5Pclose(access);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Replaces the first occurrence of `pattern` in the file by `replacement` (same length).
void overwriteBytes(const std::string& path, const std::string& pattern,
                    const std::string& replacement) {
  std::string bytes = fileBytes(path);
  const std::size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos) << "pattern not in " << path;
  bytes.replace(at, replacement.size(), replacement);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

TEST_F(ModelBundleFiles, RefusesForeignHdf5File) {
  const std::string path = this->path("foreign.h5");
  writeForeignHdf5File(path, H5F_LIBVER_V110);
  EXPECT_EQ(loadError(path), path + ": not a view_direction_classification model bundle");
}

// HDF5 1.10.8 reads past a buffer while decoding some damaged headers that carry no checksum
// (found by fuzz/model_bundle_fuzzer.cpp), so such files are refused before HDF5 decodes them.
TEST_F(ModelBundleFiles, RefusesAnHdf5FileWithoutMetadataChecksumsNamingTheConversion) {
  const std::string path = this->path("old_format.h5");
  writeForeignHdf5File(path, H5F_LIBVER_EARLIEST);
  const std::string message = loadError(path);
  EXPECT_EQ(
      message.rfind(path + ": an HDF5 file without metadata checksums (superblock version 0)", 0),
      0u)
      << message;
  EXPECT_NE(message.find("h5repack --low=2 --high=2 -f FLET"), std::string::npos) << message;
}

// Each input on which the model_bundle fuzzer once crashed or leaked (HDF5's own faults, see
// doc/hardening.md) is refused with one line naming the file, here as in the fuzzer.
TEST_F(ModelBundleFiles, RefusesEveryFuzzRegressionInput) {
  const fs::path corpus = fs::path(VDC_FUZZ_CORPUS_DIR) / "model_bundle";
  int inputs = 0;
  for (const auto& entry : fs::directory_iterator(corpus)) {
    if (entry.path().filename().string().rfind("regression-", 0) != 0) continue;
    ++inputs;
    const std::string message = loadError(entry.path().string());
    EXPECT_EQ(message.rfind(entry.path().string() + ": ", 0), 0u)
        << entry.path() << " gave: " << message;
  }
  EXPECT_GE(inputs, 2) << "the regression inputs are missing from " << corpus;
}

TEST_F(ModelBundleFiles, RefusesADamagedObjectHeaderByItsChecksum) {
  saveModelBundle(makeBundle(), path("model.h5"));
  overwriteBytes(path("model.h5"), "format_version", "format_versioN");
  EXPECT_EQ(loadError(path("model.h5")),
            path("model.h5") + ": the header of / is damaged (its checksum does not match)");
}

// Without the datasets' checksum a changed byte would load as a plausible, wrong value.
TEST_F(ModelBundleFiles, RefusesAChangedValueInADatasetByItsChecksum) {
  saveModelBundle(makeBundle(), path("model.h5"));
  const double bound = 0.071;  // makeBundle's bounds.max().x(), stored once, little-endian
  const std::string stored(reinterpret_cast<const char*>(&bound), sizeof bound);
  std::string changed = stored;
  changed[0] = static_cast<char>(changed[0] ^ 0x01);  // the least significant mantissa bit
  overwriteBytes(path("model.h5"), stored, changed);
  EXPECT_EQ(loadError(path("model.h5")),
            path("model.h5") +
                ": cannot read dataset surface/bounds (the file is truncated or "
                "damaged)");
}

TEST_F(ModelBundleFiles, RefusesNewerFormatVersion) {
  const std::string path = editedBundle("newer.h5", [](hid_t id) {
    const hid_t attribute = H5Aopen_by_name(id, "/", "format_version", H5P_DEFAULT, H5P_DEFAULT);
    const std::int64_t version = ModelBundle::kFormatVersion + 1;
    H5Awrite(attribute, H5T_NATIVE_INT64, &version);
    H5Aclose(attribute);
  });
  EXPECT_EQ(loadError(path), path + ": written by format version 3, this build reads up to 2");
}

// Format version 1 had no surface/bounds: such a bundle still loads, its extent taken from the
// surface samples.
TEST_F(ModelBundleFiles, LoadsAVersionOneBundleWithTheSurfaceSamplesBoundingBox) {
  const std::string path = editedBundle("version1.h5", [](hid_t id) {
    H5Ldelete(id, "surface/bounds", H5P_DEFAULT);
    const hid_t attribute = H5Aopen_by_name(id, "/", "format_version", H5P_DEFAULT, H5P_DEFAULT);
    const std::int64_t version = 1;
    H5Awrite(attribute, H5T_NATIVE_INT64, &version);
    H5Aclose(attribute);
  });
  const ModelBundle loaded = loadModelBundle(path);
  Eigen::AlignedBox3d expected;
  for (const Eigen::Vector3f& p : makeBundle().surface_points) expected.extend(p.cast<double>());
  EXPECT_EQ(loaded.bounds.min(), expected.min());
  EXPECT_EQ(loaded.bounds.max(), expected.max());
}

// Bundles written before the training sensor was recorded were trained with the default.
TEST_F(ModelBundleFiles, LoadsABundleWithoutASensorAsTrainedWithTheDefaultSensor) {
  const std::string path = editedBundle(
      "nosensor.h5", [](hid_t id) { H5Adelete_by_name(id, "parameters", "sensor", H5P_DEFAULT); });
  EXPECT_EQ(loadModelBundle(path).parameters.sensor, DepthSensor::kKinectGaussian);
}

TEST_F(ModelBundleFiles, RefusesAnUnknownSensorNamingIt) {
  const std::string path = editedBundle("badsensor.h5", [](hid_t id) {
    H5Adelete_by_name(id, "parameters", "sensor", H5P_DEFAULT);
    const hid_t group = H5Gopen2(id, "parameters", H5P_DEFAULT);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, 6);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(group, "sensor", type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, type, "lidar");
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
    H5Gclose(group);
  });
  const std::string error = loadError(path);
  EXPECT_NE(error.find("parameters/sensor"), std::string::npos) << error;
  EXPECT_NE(error.find("'lidar'"), std::string::npos) << error;
}

TEST_F(ModelBundleFiles, RefusesAVersionTwoBundleWithoutBounds) {
  const std::string path =
      editedBundle("nobounds.h5", [](hid_t id) { H5Ldelete(id, "surface/bounds", H5P_DEFAULT); });
  EXPECT_EQ(loadError(path), path + ": dataset surface/bounds is missing");
}

TEST_F(ModelBundleFiles, RefusesBoundsWhoseMinimumLiesAboveTheirMaximum) {
  ModelBundle bundle = makeBundle();
  bundle.bounds = Eigen::AlignedBox3d();  // empty: min = +max double, max = lowest
  EXPECT_THROW(saveModelBundle(bundle, path("empty_bounds.h5")), Error);
}

TEST_F(ModelBundleFiles, RefusesWrongShape) {
  const std::string path =
      editedBundle("shape.h5", [](hid_t id) { replaceDataset(id, "classifier/weights", 7, 4); });
  // K = 2 clusters of d + 1 = 34 rows each.
  EXPECT_EQ(loadError(path), path + ": dataset classifier/weights has 7 rows, expected 68");
}

TEST_F(ModelBundleFiles, RefusesViewDirectionsThatAreNotUnitVectors) {
  const std::string path = editedBundle("directions.h5", [](hid_t id) {
    const hid_t set = H5Dopen2(id, "views/directions", H5P_DEFAULT);
    std::vector<double> values(4 * 3, 0.0);
    for (int m = 0; m < 4; ++m) values[3 * m + 2] = 1.0;
    values[3 * 2 + 2] = 2.0;  // row 2 twice as long
    H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(set);
  });
  EXPECT_EQ(loadError(path),
            path + ": dataset views/directions row 2 is not a unit vector (length 2.000000)");
}

TEST_F(ModelBundleFiles, RefusesAViewCountThatDisagreesWithTheDirections) {
  const std::string path = editedBundle("views.h5", [](hid_t id) {
    // Through the group: HDF5 1.10 cannot write an attribute opened by path from the file.
    const hid_t group = H5Gopen2(id, "parameters", H5P_DEFAULT);
    const hid_t attribute = H5Aopen(group, "views", H5P_DEFAULT);
    const std::int64_t views = 42;
    EXPECT_GE(H5Awrite(attribute, H5T_NATIVE_INT64, &views), 0);
    H5Aclose(attribute);
    H5Gclose(group);
  });
  EXPECT_EQ(loadError(path),
            path + ": attribute parameters/views is 42, expected 4 (the rows of views/directions)");
}

TEST_F(ModelBundleFiles, RefusesMissingDataset) {
  const std::string path =
      editedBundle("missing.h5", [](hid_t id) { H5Ldelete(id, "surface/normals", H5P_DEFAULT); });
  EXPECT_EQ(loadError(path), path + ": dataset surface/normals is missing");
}

TEST_F(ModelBundleFiles, RefusesNaNInADataset) {
  const std::string path = editedBundle("nan.h5", [](hid_t id) {
    const hid_t set = H5Dopen2(id, "informativeness/score_matrix", H5P_DEFAULT);
    std::vector<float> values(6 * 4, 1.0f);
    values[5] = std::nanf("");
    H5Dwrite(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(set);
  });
  EXPECT_EQ(loadError(path),
            path + ": dataset informativeness/score_matrix contains NaN or infinite values");
}

TEST_F(ModelBundleFiles, FailedSaveIntoMissingDirectoryLeavesNoFile) {
  const std::string path = this->path("no/such/dir/model.h5");
  EXPECT_THROW(saveModelBundle(makeBundle(), path), Error);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(entryCount(), 0);
}

TEST_F(ModelBundleFiles, InconsistentBundleIsNotSavedAndTheOldFileSurvives) {
  saveModelBundle(makeBundle(), path("model.h5"));
  ModelBundle broken = makeBundle();
  broken.score_matrix.resize(6, 3);  // M = 4 views
  broken.score_matrix.setZero();
  try {
    saveModelBundle(broken, path("model.h5"));
    FAIL() << "an inconsistent bundle was saved";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path("model.h5") + ": not saved: dataset " +
                                         "informativeness/score_matrix has 3 columns, expected 4");
  }
  EXPECT_NO_THROW(loadModelBundle(path("model.h5")));
  EXPECT_EQ(entryCount(), 1);
}

TEST_F(ModelBundleFiles, UntrainedClassifierIsNotSaved) {
  ModelBundle bundle = makeBundle();
  bundle.classifier = ViewClassifier();
  EXPECT_THROW(saveModelBundle(bundle, path("model.h5")), Error);
  EXPECT_FALSE(fs::exists(path("model.h5")));
}

}  // namespace
}  // namespace vdc

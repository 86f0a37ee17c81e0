#include "view_direction_classification/training/model_training.h"

#include <chrono>
#include <cmath>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/learning/feature_selection.h"
#include "view_direction_classification/informativeness/informativeness.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/learning/view_classifier.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void checkParameters(const TrainingParameters& p) {
  if (p.views < 2) throw Error("--views must be at least 2, got " + std::to_string(p.views));
  if (p.clouds_per_view < 1) {
    throw Error("--clouds-per-view must be at least 1, got " + std::to_string(p.clouds_per_view));
  }
  if (!(p.distance > 0.0) || !(p.distance_jitter >= 0.0 && p.distance_jitter < 1.0)) {
    throw Error("the camera distance must be positive and its jitter in [0, 1)");
  }
  if (p.n_feat < 1) throw Error("n_feat must be at least 1, got " + std::to_string(p.n_feat));
  if (!(p.surface_spacing > 0.0) || !(p.score_radius > 0.0)) {
    throw Error("the surface spacing and the score radius must be positive lengths");
  }
  if (p.clusters < 1) throw Error("clusters must be at least 1, got " + std::to_string(p.clusters));
}

}  // namespace

TrainingParameters quickTrainingParameters(TrainingParameters parameters) {
  parameters.views = 12;
  parameters.clouds_per_view = 4;
  parameters.surface_spacing = 0.004;
  return parameters;
}

FeatureParameters featureParametersOf(const TrainingParameters& p) {
  FeatureParameters f;
  f.keypoint_voxel = p.keypoint_voxel;
  f.normal_radius = p.normal_radius;
  f.fpfh_radius = p.fpfh_radius;
  f.support_voxel = p.support_voxel;
  f.min_neighbours = p.min_neighbours;
  return f;
}

CameraIntrinsics intrinsicsOf(const TrainingParameters& p) {
  CameraIntrinsics c;
  c.width = p.image_width;
  c.height = p.image_height;
  c.fx = p.fx;
  c.fy = p.fy;
  c.cx = p.cx;
  c.cy = p.cy;
  return c;
}

ViewSimulation simulationOf(const TrainingParameters& p) {
  ViewSimulation s;
  s.distance = p.distance;
  s.distance_jitter = p.distance_jitter;
  s.noise = p.noise;
  s.sensor = p.sensor;
  return s;
}

ModelBundle trainModel(const TriangleMesh& mesh, const TrainingParameters& parameters,
                       TrainingReport* report, const ProgressCallback& progress) {
  checkParameters(parameters);
  TrainingReport local_report;
  TrainingReport& out = report ? *report : local_report;
  const std::vector<std::string> mesh_warnings = validateObjectMesh(mesh, parameters.mesh_name);
  out.warnings.insert(out.warnings.end(), mesh_warnings.begin(), mesh_warnings.end());

  const ViewSphere sphere(parameters.views);
  const DepthRenderer renderer(mesh, intrinsicsOf(parameters));
  const FeatureParameters feature_parameters = featureParametersOf(parameters);
  const ViewSimulation simulation = simulationOf(parameters);

  // Training clouds and held-out clouds come from disjoint seeds, so held-out figures are
  // measured on views the classifier never saw.
  auto start = std::chrono::steady_clock::now();
  const TrainingSet training =
      generateTrainingSet(renderer, sphere, parameters.clouds_per_view, simulation,
                          feature_parameters, parameters.seed, progress);
  const int held_out_per_view = std::max(1, parameters.clouds_per_view / 4);
  const TrainingSet held_out =
      generateTrainingSet(renderer, sphere, held_out_per_view, simulation, feature_parameters,
                          parameters.seed ^ 0x9e3779b9u, progress);
  out.seconds_rendering = secondsSince(start);
  out.training_features = training.featureCount();
  out.held_out_features = held_out.featureCount();
  if (training.featureCount() == 0) {
    throw Error("no features in any training view of " + parameters.mesh_name +
                ": is the object too small or too far away for the camera?");
  }
  const Eigen::VectorXi per_view = training.featuresPerView();
  for (int m = 0; m < sphere.size(); ++m) {
    if (per_view(m) == 0) {
      out.warnings.push_back("view " + std::to_string(m) +
                             " produced no features: the classifier will rarely predict it and "
                             "its view score is undefined (-1)");
    }
  }

  ModelBundle bundle;
  bundle.parameters = parameters;
  bundle.view_directions = sphere.directions();

  start = std::chrono::steady_clock::now();
  reportProgress(progress, "train classifier", 0, 1);
  ViewClassifier::Options options;
  options.clusters = parameters.clusters;
  options.regression.l2 = parameters.l2;
  options.seed = parameters.seed;
  bundle.classifier.train(training.descriptors, training.labels, sphere.size(), options);
  reportProgress(progress, "train classifier", 1, 1);
  out.seconds_training = secondsSince(start);
  if (held_out.featureCount() > 0) {
    bundle.held_out = evaluateClassifier(bundle.classifier, held_out.descriptors, held_out.labels);
  }

  start = std::chrono::steady_clock::now();
  reportProgress(progress, "score informativeness", 0, training.clouds.size());
  // View informativeness (paper section III): every training cloud's summed distribution.
  const Eigen::MatrixXf probabilities = bundle.classifier.predict(training.descriptors);
  std::vector<CloudPrediction> predictions;
  predictions.reserve(training.clouds.size());
  Eigen::Index row = 0;
  for (const auto& cloud : training.clouds) {
    const Eigen::Index n = cloud.descriptors.rows();
    if (n > 0) {
      predictions.push_back(
          {cloud.view, summedDistribution(probabilities.middleRows(row, n), parameters.n_feat)});
    }
    row += n;
  }
  bundle.view_informativeness = computeViewInformativeness(predictions, sphere.size());

  // Surface informativeness (paper section IV): every feature's KL to its true view, pooled at
  // the surface points near its keypoint.
  LabelledFeatureScores scores;
  scores.positions = training.object_keypoints;
  scores.views = training.labels;
  scores.kl.resize(training.labels.size());
  for (Eigen::Index i = 0; i < training.labels.size(); ++i) {
    Eigen::VectorXd one_hot_p = probabilities.row(i).transpose().cast<double>();
    scores.kl(i) = static_cast<float>(viewKlDivergence(one_hot_p, training.labels(i)));
  }
  const SurfaceSamples surface = sampleSurface(mesh, parameters.surface_spacing, parameters.seed);
  bundle.surface_points = surface.points;
  bundle.surface_normals = surface.normals;
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  bundle.bounds = Eigen::AlignedBox3d(bounds.min().cast<double>(), bounds.max().cast<double>());
  bundle.score_matrix =
      computeScoreMatrix(surface.points, scores, sphere.size(), parameters.score_radius);
  bundle.global_scores = globalScores(bundle.score_matrix);

  // Centroid offsets: where the visible part's centroid sits in the object, per direction.
  bundle.centroid_offsets = Eigen::MatrixXd::Zero(sphere.size(), 3);
  Eigen::VectorXi clouds_with_points = Eigen::VectorXi::Zero(sphere.size());
  for (const auto& cloud : training.clouds) {
    if (cloud.points == 0) continue;
    bundle.centroid_offsets.row(cloud.view) += cloud.visible_centroid.transpose();
    ++clouds_with_points(cloud.view);
  }
  for (int m = 0; m < sphere.size(); ++m) {
    if (clouds_with_points(m) > 0) bundle.centroid_offsets.row(m) /= clouds_with_points(m);
  }
  reportProgress(progress, "score informativeness", training.clouds.size(), training.clouds.size());
  out.seconds_scoring = secondsSince(start);
  return bundle;
}

}  // namespace vdc

#include "view_direction_classification/training/training_set.h"

#include <cmath>
#include <random>

#include "view_direction_classification/common/error.h"

namespace vdc {

Eigen::VectorXi TrainingSet::featuresPerView() const {
  Eigen::VectorXi counts = Eigen::VectorXi::Zero(num_views);
  for (Eigen::Index i = 0; i < labels.size(); ++i) ++counts(labels(i));
  return counts;
}

Eigen::Isometry3d sampleTrainingPose(const ViewSphere& sphere, int view,
                                     const ViewSimulation& simulation, std::mt19937& rng) {
  // Directions between grid directions must be covered too: the authors' thesis names them
  // as the method's main weakness when only grid directions are trained.
  const Eigen::Vector3d direction = sphere.sampleInCell(view, rng);
  std::uniform_real_distribution<double> roll(-M_PI, M_PI);
  std::uniform_real_distribution<double> scale(1.0 - simulation.distance_jitter,
                                               1.0 + simulation.distance_jitter);
  const double r = roll(rng);
  const double distance = simulation.distance * scale(rng);
  return cameraFromObject(direction, distance, r);
}

TrainingSet generateTrainingSet(const DepthRenderer& renderer, const ViewSphere& sphere,
                                int clouds_per_view, const ViewSimulation& simulation,
                                const FeatureParameters& features, std::uint32_t seed,
                                const ProgressCallback& progress) {
  if (clouds_per_view < 1) {
    throw Error("clouds per view must be at least 1, got " + std::to_string(clouds_per_view));
  }
  const int num_views = sphere.size();
  const int total = num_views * clouds_per_view;
  TrainingSet set;
  set.num_views = num_views;
  set.clouds.resize(static_cast<std::size_t>(total));

  int done = 0;
  reportProgress(progress, "render + features", 0, static_cast<std::size_t>(total));
  // Clouds are independent; the features of each run on its one thread (threads = 1), which
  // keeps every core busy with less synchronisation than parallelising inside each cloud.
#pragma omp parallel for schedule(dynamic)
  for (int c = 0; c < total; ++c) {
    const int view = c / clouds_per_view;
    const int index = c % clouds_per_view;
    std::seed_seq seeds{seed, static_cast<std::uint32_t>(view), static_cast<std::uint32_t>(index)};
    std::mt19937 rng(seeds);
    TrainingCloud& cloud = set.clouds[static_cast<std::size_t>(c)];
    cloud.view = view;
    cloud.camera_from_object = sampleTrainingPose(sphere, view, simulation, rng);
    const DepthNoiseModel noise{simulation.noise, sensorModel(simulation.sensor)};
    const auto rendered = renderer.render(cloud.camera_from_object, noise, &rng);

    const Eigen::Isometry3d object_from_camera = cloud.camera_from_object.inverse();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : rendered) {
      if (!std::isfinite(p.z)) continue;
      sum += p.getVector3fMap().cast<double>();
      ++cloud.points;
    }
    if (cloud.points > 0) {
      cloud.visible_centroid = object_from_camera * (sum / static_cast<double>(cloud.points));
    }
    // Normals face the camera, which sits at the origin of the cloud's own frame.
    const FeatureSet f = computeFeatures(rendered, features, Eigen::Vector3f::Zero(), 1);
    cloud.descriptors = f.descriptors;
    cloud.object_keypoints.reserve(f.size());
    const Eigen::Isometry3f to_object = object_from_camera.cast<float>();
    for (const auto& k : f.keypoints) cloud.object_keypoints.push_back(to_object * k);
#pragma omp critical(vdc_training_progress)
    reportProgress(progress, "render + features", static_cast<std::size_t>(++done),
                   static_cast<std::size_t>(total));
  }

  std::size_t features_total = 0;
  for (const auto& cloud : set.clouds) features_total += cloud.object_keypoints.size();
  set.descriptors.resize(static_cast<Eigen::Index>(features_total), kFpfhBins);
  set.labels.resize(static_cast<Eigen::Index>(features_total));
  set.cloud_of_feature.resize(static_cast<Eigen::Index>(features_total));
  set.object_keypoints.reserve(features_total);
  Eigen::Index row = 0;
  for (std::size_t c = 0; c < set.clouds.size(); ++c) {
    TrainingCloud& cloud = set.clouds[c];
    const Eigen::Index n = cloud.descriptors.rows();
    if (n > 0) set.descriptors.middleRows(row, n) = cloud.descriptors;
    set.labels.segment(row, n).setConstant(cloud.view);
    set.cloud_of_feature.segment(row, n).setConstant(static_cast<int>(c));
    set.object_keypoints.insert(set.object_keypoints.end(), cloud.object_keypoints.begin(),
                                cloud.object_keypoints.end());
    row += n;
  }
  return set;
}

}  // namespace vdc

// Uses the installed core across its modules: loads a model bundle (training), renders the
// built-in mug (geometry) and fuses one view (features, learning, bingham, estimation).
#include <cstdio>
#include <exception>
#include <memory>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/training/model_bundle.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vdc_consumer MODEL.h5\n");
    return 2;
  }
  try {
    auto model = std::make_shared<const vdc::ModelBundle>(vdc::loadModelBundle(argv[1]));
    vdc::OrientationEstimator estimator(model, vdc::EstimatorParameters{});
    const vdc::DepthRenderer renderer(vdc::makeMug());
    Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
    camera_from_object.translation() = Eigen::Vector3d(0, 0, 0.6);
    const auto cloud = renderer.render(camera_from_object);
    const vdc::ViewUpdate update = estimator.update(cloud, Eigen::Isometry3d::Identity());
    std::printf("views %d updated %d components %zu\n",
                static_cast<int>(model->view_directions.size()), update.updated ? 1 : 0,
                estimator.belief().size());
    return update.updated ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vdc_consumer: %s\n", error.what());
    return 1;
  }
}

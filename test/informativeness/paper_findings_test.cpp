// The paper's findings on its mug (doc/method.md section 11, paper sections III and IV) checked on
// the built-in mug from a model trained here (42 directions as in the paper, 6 clouds each: about
// half a minute). What reproduces: handle points score better (lower global score g) than the
// body; the most informative views show the handle or the inside, the least informative show
// mostly the body; the single most informative view looks into the mug along its axis. What
// does not: that the best views lie on the symmetry plane (the top view is on every plane through
// the axis, so it shows nothing about that plane; as a group they do not lie near it). The
// paper explains that finding by features that cannot tell a view from its mirror image; PCL's
// FPFH can (its alpha angle changes sign under reflection), and the last test pins that down.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/training/model_training.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

enum class MugPart { kBody, kHandle, kInside };

// Which part of the default mug an object-frame point lies on.
MugPart partOf(const Eigen::Vector3d& p) {
  const MugShape shape;
  const double radius = std::hypot(p.x(), p.y());
  if (radius > shape.outer_radius + 0.001) return MugPart::kHandle;
  const bool above_outer_bottom = p.z() > -shape.height / 2 + 0.001;
  if (radius < shape.outer_radius - shape.wall + 0.0005 && above_outer_bottom) {
    return MugPart::kInside;
  }
  return MugPart::kBody;
}

class PaperFindingsTest : public ::testing::Test {
 protected:
  // 42 directions as in the paper; 6 clouds per direction and the thesis' K-means routing
  // keep training to a few minutes while the findings are stable (doc/evaluation.md, "The paper's
  // findings on the mug").
  static void SetUpTestSuite() {
    TrainingParameters parameters;
    parameters.mesh_name = "mug";
    parameters.views = 42;
    parameters.clouds_per_view = kCloudsPerView;
    parameters.clusters = 4;
    parameters.surface_spacing = 0.003;
    parameters.seed = 1;
    model_ = std::make_shared<const ModelBundle>(trainModel(makeMug(), parameters));
  }
  static void TearDownTestSuite() { model_.reset(); }

  static std::vector<int> best(int count) {
    const auto& ranking = model_->view_informativeness.ranking;
    return std::vector<int>(ranking.begin(), ranking.begin() + count);
  }
  static std::vector<int> worst(int count) {
    const auto& ranking = model_->view_informativeness.ranking;
    return std::vector<int>(ranking.end() - count, ranking.end());
  }
  // Fraction of the rendered points (seen from direction m at 0.6 m) on the handle or inside.
  static double handleOrInsideFraction(int m) {
    static const DepthRenderer renderer(makeMug());
    const Eigen::Isometry3d camera_from_object =
        cameraFromObject(model_->view_directions[static_cast<std::size_t>(m)], 0.6, 0.0);
    const Eigen::Isometry3d object_from_camera = camera_from_object.inverse();
    int total = 0, special = 0;
    for (const pcl::PointXYZ& p : renderer.render(camera_from_object).points) {
      if (!std::isfinite(p.z)) continue;
      ++total;
      if (partOf(object_from_camera * p.getVector3fMap().cast<double>()) != MugPart::kBody) {
        ++special;
      }
    }
    return total > 0 ? static_cast<double>(special) / total : 0.0;
  }
  static double meanHandleOrInsideFraction(const std::vector<int>& views) {
    double sum = 0;
    for (int m : views) sum += handleOrInsideFraction(m);
    return sum / static_cast<double>(views.size());
  }

  static constexpr int kCloudsPerView = 6;
  static constexpr int kCompared = 8;  // best and worst fifth of the 42 directions
  static std::shared_ptr<const ModelBundle> model_;
};
std::shared_ptr<const ModelBundle> PaperFindingsTest::model_;

TEST_F(PaperFindingsTest, TheMostInformativeViewLooksIntoTheMugAlongItsAxis) {
  const Eigen::Vector3d& top = model_->view_directions[static_cast<std::size_t>(best(1)[0])];
  std::printf("most informative direction (%.2f, %.2f, %.2f)\n", top.x(), top.y(), top.z());
  // +z is a training direction (an icosphere vertex); the opening faces +z.
  EXPECT_GT(top.z(), 0.99);
}

TEST_F(PaperFindingsTest, FpfhTellsMostViewsFromTheirMirrorImages) {
  // C[m, m'] for m' the mirror image of m in the symmetry plane: features that could not resolve
  // the reflection (the paper's explanation for its best views) would split p_sum evenly.
  const Eigen::MatrixXd& confusion = model_->view_informativeness.confusion;
  double own = 0.0, mirror = 0.0;
  int count = 0;
  for (std::size_t m = 0; m < model_->view_directions.size(); ++m) {
    Eigen::Vector3d reflected = model_->view_directions[m];
    reflected.y() = -reflected.y();
    std::size_t image = m;
    double closest = -2.0;
    for (std::size_t k = 0; k < model_->view_directions.size(); ++k) {
      const double cosine = model_->view_directions[k].dot(reflected);
      if (cosine > closest) closest = cosine, image = k;
    }
    if (image == m) continue;  // on the plane: its own mirror image
    own += confusion(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    mirror += confusion(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(image));
    ++count;
  }
  ASSERT_GT(count, 20);
  std::printf("mean p_sum on the true view %.3f, on its mirror image %.3f (%d views)\n",
              own / count, mirror / count, count);
  EXPECT_GT(own, 2.0 * mirror);
}

TEST_F(PaperFindingsTest, BestRankedViewsShowTheHandleOrTheInsideMoreThanTheWorst) {
  const double best_fraction = meanHandleOrInsideFraction(best(kCompared));
  const double worst_fraction = meanHandleOrInsideFraction(worst(kCompared));
  std::printf("handle-or-inside share of the view: best %.3f, worst %.3f\n", best_fraction,
              worst_fraction);
  EXPECT_GT(best_fraction, worst_fraction + 0.1);
  EXPECT_LT(worst_fraction, 0.5);  // the worst views show mostly the body
}

TEST_F(PaperFindingsTest, HandlePointsHaveALowerMeanGlobalScoreThanBodyPoints) {
  double handle_sum = 0, body_sum = 0;
  int handle_count = 0, body_count = 0;
  const MugShape shape;
  for (std::size_t i = 0; i < model_->surface_points.size(); ++i) {
    const float g = model_->global_scores(static_cast<Eigen::Index>(i));
    if (g < 0) continue;  // not observable
    const Eigen::Vector3d p = model_->surface_points[i].cast<double>();
    const MugPart part = partOf(p);
    if (part == MugPart::kHandle) {
      handle_sum += g;
      ++handle_count;
    } else if (part == MugPart::kBody &&
               std::abs(std::hypot(p.x(), p.y()) - shape.outer_radius) < 0.0007) {
      body_sum += g;  // the outer side wall
      ++body_count;
    }
  }
  ASSERT_GT(handle_count, 50);
  ASSERT_GT(body_count, 500);
  const double handle_mean = handle_sum / handle_count, body_mean = body_sum / body_count;
  std::printf("mean global score: handle %.3f (%d points), body %.3f (%d points)\n", handle_mean,
              handle_count, body_mean, body_count);
  EXPECT_LT(handle_mean, body_mean - 0.1);
}

}  // namespace
}  // namespace vdc

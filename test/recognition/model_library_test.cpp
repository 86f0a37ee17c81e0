#include "view_direction_classification/recognition/model_library.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "support/error_of.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

using test::errorOf;

TEST(ModelLibrary, RefusesAnEmptyLibraryARepeatedNameAndAMissingBundle) {
  const auto mug = test::quickMugModel();
  EXPECT_NE(errorOf([] { ModelLibrary({}); }).find("empty"), std::string::npos);
  EXPECT_NE(errorOf([&] {
              ModelLibrary({{"mug", mug}, {"mug", mug}});
            }).find("'mug' twice"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { ModelLibrary({{"", mug}}); }).find("empty name"), std::string::npos);
  EXPECT_NE(errorOf([] { ModelLibrary({{"cup", nullptr}}); }).find("'cup'"), std::string::npos);
}

TEST(ModelLibrary, ALoadFailureNamesTheEntryAndItsFile) {
  const std::string message = errorOf([] { ModelLibrary::load({{"cup", "/nonexistent/cup.h5"}}); });
  EXPECT_NE(message.find("'cup'"), std::string::npos) << message;
  EXPECT_NE(message.find("/nonexistent/cup.h5"), std::string::npos) << message;
}

TEST(ModelLibrary, FindsModelsByNameAndBySize) {
  const ModelLibrary library({{"mug", test::quickMugModel()}});
  EXPECT_EQ(library.find("mug"), 0);
  EXPECT_EQ(library.find("bowl"), -1);
  // The mug is 11.4 x 9.5 x 8 cm: a view of it is between its smallest side and its diagonal.
  EXPECT_EQ(library.fitting(Eigen::Vector3d(0.11, 0.09, 0.05), 0.15), std::vector<int>{0});
  EXPECT_TRUE(library.fitting(Eigen::Vector3d(0.04, 0.04, 0.04), 0.15).empty());
  EXPECT_TRUE(library.fitting(Eigen::Vector3d(0.30, 0.20, 0.05), 0.15).empty());
  EXPECT_TRUE(library.sharesFeatureSettings());
}

TEST(ModelLibrary, TellsWhenModelsComputeFeaturesDifferently) {
  auto other = std::make_shared<ModelBundle>(*test::quickMugModel());
  other->parameters.fpfh_radius *= 2.0;
  const ModelLibrary library({{"mug", test::quickMugModel()}, {"big_mug", other}});
  EXPECT_FALSE(library.sharesFeatureSettings());
}

}  // namespace
}  // namespace vdc

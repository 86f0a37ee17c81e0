#include "view_direction_classification/ros/parameter_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/error_of.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

enum class Mode { kOff, kOn };

struct Inner {
  double gain = 2.0;
  Eigen::Vector3d centre = Eigen::Vector3d(1, 2, 3);
};

struct Settings {
  int count = 3;
  std::string frame = "world";
  Mode mode = Mode::kOff;
  Inner inner;
};

ParameterTable<Settings> table() {
  ParameterTable<Settings> t;
  t.add("count", &Settings::count, integerAtLeast(1))
      .add("frame", &Settings::frame, frameName())
      .addChoice("mode", &Settings::mode,
                 std::vector<std::pair<std::string, Mode>>{{"off", Mode::kOff}, {"on", Mode::kOn}})
      .add("gain", fieldPath(&Settings::inner, &Inner::gain), numberIn(0.0, 1.0, false, "0: none"))
      .addPoint(
          "centre", [](auto& s) -> auto& { return s.inner.centre; }, "in the fixed frame");
  return t;
}

// Sets `name` to `value` through the table's binding, as a dynamic_reconfigure request would.
template <typename T>
void set(const ParameterTable<Settings>& t, Settings& settings, const std::string& name,
         const T& value) {
  const auto* entry = t.find(name);
  ASSERT_NE(entry, nullptr) << name;
  std::get<typename ParameterTable<Settings>::template Binding<T>>(entry->binding)
      .set(settings, value);
}

using test::errorOf;

TEST(ParameterTable, ABadValueIsAnErrorNamingTheParameterTheRuleAndTheValue) {
  const ParameterTable<Settings> t = table();
  Settings settings;
  EXPECT_EQ(errorOf([&] { set(t, settings, "count", 0); }),
            "Parameter ~count must be an integer >= 1, got 0.");
  EXPECT_EQ(errorOf([&] { set(t, settings, "gain", 1.0); }),
            "Parameter ~gain must be a number in [0, 1) (0: none), got 1.");
  EXPECT_EQ(errorOf([&] { set(t, settings, "frame", std::string("my frame")); }),
            "Parameter ~frame must be a non-empty frame name without spaces, got 'my frame'.");
  EXPECT_EQ(errorOf([&] { set(t, settings, "mode", std::string("auto")); }),
            "Parameter ~mode must be one of 'off', 'on', got 'auto'.");
  EXPECT_EQ(errorOf([&] {
              set(t, settings, "centre", std::vector<double>{1, 2});
            }),
            "Parameter ~centre must be a list of 3 finite numbers [x, y, z] in the fixed frame, "
            "got [1, 2].");
  // Nothing was changed by the refused values.
  EXPECT_EQ(settings.count, 3);
  EXPECT_EQ(settings.inner.gain, 2.0);
  EXPECT_EQ(settings.frame, "world");
  EXPECT_EQ(settings.mode, Mode::kOff);
  EXPECT_EQ(settings.inner.centre, Eigen::Vector3d(1, 2, 3));
}

TEST(ParameterTable, AGoodValueReachesItsFieldAndReadsBack) {
  const ParameterTable<Settings> t = table();
  Settings settings;
  set(t, settings, "count", 7);
  set(t, settings, "gain", 0.5);
  set(t, settings, "mode", std::string("on"));
  set(t, settings, "centre", std::vector<double>{-1, 0, 4});
  EXPECT_EQ(settings.count, 7);
  EXPECT_EQ(settings.inner.gain, 0.5);
  EXPECT_EQ(settings.mode, Mode::kOn);
  EXPECT_EQ(settings.inner.centre, Eigen::Vector3d(-1, 0, 4));
  const auto& mode =
      std::get<ParameterTable<Settings>::Binding<std::string>>(t.find("mode")->binding);
  EXPECT_EQ(mode.get(settings), "on");
  EXPECT_EQ(t.names(), (std::vector<std::string>{"count", "frame", "mode", "gain", "centre"}));
  EXPECT_EQ(t.find("unknown"), nullptr);
}

TEST(ParameterRules, NumbersMustBeFiniteAndListsHaveTheirLength) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(numberAtLeast(0.0).accepts(nan));
  EXPECT_FALSE(numberAtLeast(0.0).accepts(inf));
  EXPECT_TRUE(numberAtLeast(0.0).accepts(0.0));
  EXPECT_FALSE(numberAbove(0.0).accepts(0.0));
  EXPECT_FALSE(numberIn(0.0, 1.0, false).accepts(nan));
  EXPECT_TRUE(numberIn(0.0, 1.0, true).accepts(1.0));
  EXPECT_FALSE(finiteNumber().accepts(-inf));
  EXPECT_TRUE(integerBetween(0, 10).accepts(10));
  EXPECT_FALSE(integerBetween(0, 10).accepts(11));
  EXPECT_TRUE(finiteNumbers(0, "").accepts({}));
  EXPECT_FALSE(finiteNumbers(2, "").accepts({1.0, nan}));
  EXPECT_TRUE(finiteGroupsOf(3, "").accepts({}));
  EXPECT_TRUE(finiteGroupsOf(3, "").accepts({1, 2, 3, 4, 5, 6}));
  EXPECT_FALSE(finiteGroupsOf(3, "").accepts({1, 2, 3, 4}));
  EXPECT_FALSE(frameName().accepts(""));
}

}  // namespace
}  // namespace vdc

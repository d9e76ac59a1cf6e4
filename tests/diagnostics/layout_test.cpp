// The diagnostics pages of spec 04 §9.1-§9.3: every item of every TO type's layout resolves against that
// type's reflection table (so the positioning-axis and external-encoder pages are right before their
// behaviour classes exist), and the item expressions evaluate as specified.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tomc/diagnostics/layout.hpp"
#include "tomc/diagnostics/object_view.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace {

using namespace tomc;
using techobjects::TechnologyObjectType;

class EveryType : public ::testing::TestWithParam<TechnologyObjectType> {};

// spec 04 §9.1–§9.3 (every item of each TO type's diagnostics page is a variable of its data block).
TEST_P(EveryType, EveryItemResolves) {
  const auto table = diagnostics::variables_of(GetParam());
  ASSERT_FALSE(table.empty());
  const auto layout = diagnostics::diagnostics_layout(GetParam());
  ASSERT_FALSE(layout.empty());
  for (const auto& area : layout) {
    EXPECT_TRUE(area.page == "status" || area.page == "motion") << area.title;
    for (const auto& item : area.items) {
      std::string problem;
      EXPECT_TRUE(diagnostics::resolve(item, table, &problem).has_value()) << area.title << ": " << problem;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Diagnostics, EveryType,
                         ::testing::Values(TechnologyObjectType::kSpeedAxis,
                                           TechnologyObjectType::kPositioningAxis,
                                           TechnologyObjectType::kSynchronousAxis,
                                           TechnologyObjectType::kExternalEncoder,
                                           TechnologyObjectType::kCam));

std::vector<std::string_view> titles(TechnologyObjectType type) {
  std::vector<std::string_view> out;
  for (const auto& a : diagnostics::diagnostics_layout(type))
    out.push_back(a.title);
  return out;
}

// spec 04 §9.1-§9.3: the areas of each page. The external encoder has no "Warnings" area; only axes with
// positions have "Limit switch status".
TEST(DiagnosticsLayout, AreasPerType) {
  using V = std::vector<std::string_view>;
  EXPECT_EQ(titles(TechnologyObjectType::kSpeedAxis), (V{"Axis status", "Motion status", "Warnings", "Errors",
                                                         "Setpoints", "Actual values", "Dynamic limits"}));
  // Issue 18's jobs in their own areas beside the manual's.
  EXPECT_EQ(titles(TechnologyObjectType::kPositioningAxis),
            (V{"Axis status", "Limit switch status", "Motion status",
               "Superimposed, torque, profile and MotionIn jobs", "Warnings", "Errors", "Setpoints",
               "Actual values", "Superimposed motion and torque", "Dynamic limits"}));
  // Issue 19: the synchronous axis has its own view (spec 07 §1.9), the cam its status and range.
  EXPECT_EQ(titles(TechnologyObjectType::kSynchronousAxis),
            (V{"Axis status", "Limit switch status", "Motion status", "Synchronous operation",
               "Superimposed, torque, profile and MotionIn jobs", "Warnings", "Errors", "Leading value",
               "Following value", "Setpoints", "Actual values", "Superimposed motion and torque",
               "Dynamic limits"}));
  EXPECT_EQ(titles(TechnologyObjectType::kCam), (V{"Cam status", "Definition range"}));
  EXPECT_EQ(titles(TechnologyObjectType::kExternalEncoder),
            (V{"Encoder status", "Motion status", "Errors", "Actual values"}));
}

const diagnostics::LayoutItem& item(TechnologyObjectType type, std::string_view area,
                                    std::string_view label) {
  for (const auto& a : diagnostics::diagnostics_layout(type)) {
    if (a.title != area) continue;
    for (const auto& i : a.items) {
      if (i.label == label) return i;
    }
  }
  ADD_FAILURE() << "no item " << area << " / " << label;
  static const diagnostics::LayoutItem none{};
  return none;
}

// spec 04 §9.2 "Position-controlled operation" is NOT StatusWord.X28; "Encoder actual values valid" is
// StatusSensor[1].State = 2; "Positioning job" is X8 OR StatusWord2.X9.
TEST(DiagnosticsLayout, ExpressionsEvaluate) {
  const auto type = TechnologyObjectType::kPositioningAxis;
  const auto table = diagnostics::variables_of(type);
  std::vector<double> values(table.size(), 0.0);
  auto index = [&](std::string_view path) {
    const auto* v = techobjects::find_variable(table, path);
    EXPECT_NE(v, nullptr) << path;
    return static_cast<std::size_t>(v - table.data());
  };
  const auto position_controlled =
      diagnostics::resolve(item(type, "Axis status", "Position-controlled operation"), table);
  const auto encoder_valid =
      diagnostics::resolve(item(type, "Axis status", "Encoder actual values valid"), table);
  const auto positioning = diagnostics::resolve(item(type, "Motion status", "Positioning job"), table);
  const auto actual = diagnostics::resolve(item(type, "Actual values", "Actual position"), table);
  ASSERT_TRUE(position_controlled && encoder_valid && positioning && actual);

  EXPECT_EQ(position_controlled->evaluate(values), 1.0);
  values[index("StatusWord")] = static_cast<double>(1u << 28);
  EXPECT_EQ(position_controlled->evaluate(values), 0.0);

  values[index("StatusSensor[1].State")] = 1.0;
  EXPECT_EQ(encoder_valid->evaluate(values), 0.0);
  values[index("StatusSensor[1].State")] = 2.0;
  EXPECT_EQ(encoder_valid->evaluate(values), 1.0);

  EXPECT_EQ(positioning->evaluate(values), 0.0);
  values[index("StatusWord2")] = static_cast<double>(1u << 9);
  EXPECT_EQ(positioning->evaluate(values), 1.0);
  values[index("StatusWord2")] = 0.0;
  values[index("StatusWord")] = static_cast<double>(1u << 8);
  EXPECT_EQ(positioning->evaluate(values), 1.0);

  values[index("ActualPosition")] = -12.5;
  EXPECT_EQ(actual->evaluate(values), -12.5);
}

// tomc's own: layout expressions that name no variable or bit are refused with the name, never shown as 0.
TEST(DiagnosticsLayout, MalformedExpressionsDoNotResolve) {
  const auto table = diagnostics::variables_of(TechnologyObjectType::kSpeedAxis);
  std::string problem;
  EXPECT_FALSE(diagnostics::resolve({"x", "StatusWord.X32"}, table, &problem));
  EXPECT_NE(problem.find("StatusWord.X32"), std::string::npos);
  EXPECT_FALSE(diagnostics::resolve({"x", "NoSuchVariable"}, table));
  EXPECT_FALSE(diagnostics::resolve({"x", "VirtualAxis.Mode=one"}, table));
  EXPECT_FALSE(diagnostics::resolve({"x", "StatusWord.X1=1"}, table));      // a bit is not compared
  EXPECT_FALSE(diagnostics::resolve({"x", "StatusWord.X1", true}, table));  // a value item needs a variable
  EXPECT_FALSE(diagnostics::resolve({"x", " | "}, table));
}

}  // namespace

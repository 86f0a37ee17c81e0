// doc/nodes.md against the nodes: every parameter a node reads (its ParameterTable) has one row
// in its "Parameters" table with its type and the shipped config's value as default, and every
// row names a parameter; every parameter of a .cfg has its row, with the .cfg's range, in the
// node's "Reconfiguring" table; the planner loop's PARAMETERS have theirs. So the reference
// cannot drift from the code: a parameter added without its row, or a row left behind, fails.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <boost/any.hpp>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "estimator_ros_parameters.h"
#include "informativeness_server_ros_parameters.h"
#include "ros/node_reference_table.h"
#include "scene_ros_parameters.h"
#include "simulated_depth_camera_ros_parameters.h"
#include "support/command_run.h"
#include "view_direction_classification/InformativenessServerConfig.h"
#include "view_direction_classification/OrientationEstimatorConfig.h"

namespace vdc {
namespace {

using test::NodeReference;
using test::ReferenceRow;

const NodeReference& reference() {
  static const NodeReference doc(VDC_SOURCE_DIR "/doc/nodes.md");
  return doc;
}

// The value at the start of a table cell: a `quoted` text (`""` is the empty string), a [list]
// or the first word.
std::string leadingValue(const std::string& cell) {
  if (cell.rfind("`\"\"`", 0) == 0) return "";
  if (cell.rfind('`', 0) == 0) return NodeReference::backticked(cell);
  if (cell.rfind('[', 0) == 0) return cell.substr(0, cell.find(']') + 1);
  return cell.substr(0, cell.find_first_of(" ;,"));
}

// The value written after "unset: " in a cell, or "" without one.
std::string fallbackValue(const std::string& cell) {
  const auto at = cell.find("unset: ");
  return at == std::string::npos ? "" : leadingValue(cell.substr(at + 7));
}

bool parseNumber(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

bool sameNumber(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

// Whether the documented `text` says `value`.
bool says(const std::string& text, bool value) { return text == (value ? "true" : "false"); }
bool says(const std::string& text, int value) {
  double number = 0;
  return parseNumber(text, number) && number == value;
}
bool says(const std::string& text, double value) {
  double number = 0;
  return parseNumber(text, number) && sameNumber(number, value);
}
bool says(const std::string& text, const std::string& value) { return text == value; }
bool says(const std::string& text, const std::vector<double>& value) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') return false;
  std::vector<double> numbers;
  std::istringstream items(text.substr(1, text.size() - 2));
  for (std::string item; std::getline(items, item, ',');) {
    double number = 0;
    const auto begin = item.find_first_not_of(' ');
    if (begin == std::string::npos || !parseNumber(item.substr(begin), number)) return false;
    numbers.push_back(number);
  }
  if (numbers.size() != value.size()) return false;
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (!sameNumber(numbers[i], value[i])) return false;
  }
  return true;
}

template <typename T>
std::string typeWord() {
  if constexpr (std::is_same_v<T, bool>) return "bool";
  if constexpr (std::is_same_v<T, int>) return "int";
  if constexpr (std::is_same_v<T, double>) return "double";
  if constexpr (std::is_same_v<T, std::string>) return "string";
  return "double[";
}

// The choices of an addChoice entry, from its rule "one of 'a', 'b'".
std::vector<std::string> choicesOf(const std::string& rule) {
  std::vector<std::string> choices;
  if (rule.rfind("one of", 0) != 0) return choices;
  for (auto open = rule.find('\''); open != std::string::npos;) {
    const auto close = rule.find('\'', open + 1);
    choices.push_back(rule.substr(open + 1, close - open - 1));
    open = rule.find('\'', close + 1);
  }
  return choices;
}

// One node: its section in nodes.md, its shipped config and its parameter table.
template <typename Settings>
struct DocumentedNode {
  std::string section;
  std::string config;
  const ParameterTable<Settings>& table;
  std::string subsection = "Parameters";
  // Parameters the node reads outside the table (a map): documented, not type-checked here.
  std::vector<std::string> outside_table = {};
  // Keys of the shipped config that the node reads through another of its tables.
  std::vector<std::string> elsewhere = {};

  std::vector<ReferenceRow> rows() const { return reference().rows(section, subsection); }
  bool outside(const std::string& name) const {
    return std::find(outside_table.begin(), outside_table.end(), name) != outside_table.end();
  }
  YAML::Node shipped() const { return YAML::LoadFile(VDC_SOURCE_DIR "/config/" + config); }
};

template <typename Settings>
void expectOneRowPerParameter(const DocumentedNode<Settings>& node) {
  std::multiset<std::string> documented;
  for (const ReferenceRow& row : node.rows()) documented.insert(row.name);
  std::vector<std::string> names = node.table.names();
  names.insert(names.end(), node.outside_table.begin(), node.outside_table.end());
  for (const std::string& name : names) {
    EXPECT_EQ(documented.count(name), 1u)
        << node.section << " reads ~" << name << ": doc/nodes.md needs exactly one row for it";
  }
  for (const ReferenceRow& row : node.rows()) {
    EXPECT_TRUE(node.table.find(row.name) != nullptr || node.outside(row.name))
        << "doc/nodes.md:" << row.line << " documents `" << row.name << "`, which " << node.section
        << " does not read";
  }
}

template <typename Settings>
void expectTypesAndDefaults(const DocumentedNode<Settings>& node) {
  const YAML::Node shipped = node.shipped();
  const Settings built_in{};
  for (const ReferenceRow& row : node.rows()) {
    const auto* entry = node.table.find(row.name);
    if (entry == nullptr || row.cells.size() < 4) continue;
    const std::string where = "doc/nodes.md:" + std::to_string(row.line) + " `" + row.name + "`";
    std::visit(
        [&](const auto& binding) {
          using T = std::decay_t<decltype(binding.get(built_in))>;
          EXPECT_EQ(row.cells[1].rfind(typeWord<T>(), 0), 0u)
              << where << ": the type column must start with " << typeWord<T>();
          for (const std::string& choice : choicesOf(entry->rule)) {
            EXPECT_NE(row.cells[1].find("`" + choice + "`"), std::string::npos)
                << where << ": the type column must list the choice `" << choice << "`";
          }
          const std::string written = leadingValue(row.cells[2]);
          if (!entry->missing_message.empty()) {
            EXPECT_EQ(written, "required") << where;
            return;
          }
          const T fallback = binding.get(built_in);
          if (!shipped[row.name]) {
            EXPECT_TRUE(says(written, fallback))
                << where << ": config/" << node.config << " leaves it unset, so the default is "
                << "the node's own; the row says " << row.cells[2];
            return;
          }
          const T configured = shipped[row.name].template as<T>();
          EXPECT_TRUE(says(written, configured))
              << where << ": config/" << node.config << " sets it; the row says " << row.cells[2];
          if (!says(written, fallback)) {
            EXPECT_TRUE(says(fallbackValue(row.cells[2]), fallback))
                << where << ": the node's value when it is unset differs from the config's, and "
                << "the default column must say it as (unset: value); it says " << row.cells[2];
          }
        },
        entry->binding);
  }
}

template <typename Settings>
void expectTheConfigSetsOnlyParameters(const DocumentedNode<Settings>& node) {
  for (const auto& item : node.shipped()) {
    const auto name = item.first.template as<std::string>();
    const bool elsewhere =
        std::find(node.elsewhere.begin(), node.elsewhere.end(), name) != node.elsewhere.end();
    EXPECT_TRUE(node.table.find(name) != nullptr || elsewhere)
        << "config/" << node.config << " sets ~" << name;
  }
}

const DocumentedNode<EstimatorRosParameters> kEstimator{
    "orientation_estimator", "estimator.yaml", estimatorParameterTable(), "Parameters", {},
    sceneParameterNames()};
// The estimator with a model library: its scene settings, documented in their own table.
const DocumentedNode<SceneRosParameters> kScene{
    "orientation_estimator", "estimator.yaml",           sceneParameterTable(),
    "Scene parameters",      {"models", "label_models"}, estimatorParameterTable().names()};
const DocumentedNode<InformativenessServerRosParameters> kServer{
    "informativeness_server",
    "informativeness_server.yaml",
    informativenessServerParameterTable(),
    "Parameters",
    {"models"}};
const DocumentedNode<SimulatedDepthCameraRosParameters> kCamera{
    "simulated_depth_camera", "simulated_depth_camera.yaml", simulatedDepthCameraParameterTable()};

TEST(NodeReference, IsRead) { ASSERT_TRUE(reference().read()) << VDC_SOURCE_DIR "/doc/nodes.md"; }

TEST(NodeReference, EveryParameterANodeReadsHasOneRowAndEveryRowNamesOne) {
  expectOneRowPerParameter(kEstimator);
  expectOneRowPerParameter(kServer);
  expectOneRowPerParameter(kCamera);
  expectOneRowPerParameter(kScene);
}

TEST(NodeReference, EachRowGivesItsTypeAndTheShippedConfigsValue) {
  expectTypesAndDefaults(kEstimator);
  expectTypesAndDefaults(kServer);
  expectTypesAndDefaults(kCamera);
  expectTypesAndDefaults(kScene);
}

TEST(NodeReference, TheShippedConfigsSetOnlyParametersTheNodesRead) {
  expectTheConfigSetsOnlyParameters(kEstimator);
  expectTheConfigSetsOnlyParameters(kServer);
  expectTheConfigSetsOnlyParameters(kCamera);
  expectTheConfigSetsOnlyParameters(kScene);
}

// A .cfg parameter's type as the parameter table names it.
std::string tableTypeOf(const std::string& cfg_type) {
  if (cfg_type == "str") return "string";
  return cfg_type;
}

// Every parameter of `Config` (a .cfg) is one the node reads, with the same type, and has one
// row "| `name` | min to max |" in the node's "Reconfiguring" table; every row there names one.
template <typename Config, typename Settings>
void expectReconfigureRows(const DocumentedNode<Settings>& node) {
  const auto rows = reference().rows(node.section, "Reconfiguring");
  std::multiset<std::string> documented;
  for (const ReferenceRow& row : rows) documented.insert(row.name);
  std::set<std::string> tunable;
  for (const auto& description : Config::__getParamDescriptions__()) {
    const std::string& name = description->name;
    tunable.insert(name);
    const auto* entry = node.table.find(name);
    ASSERT_NE(entry, nullptr) << "the .cfg of " << node.section << " has " << name;
    std::visit(
        [&](const auto& binding) {
          using T = std::decay_t<decltype(binding.get(Settings{}))>;
          EXPECT_EQ(typeWord<T>(), tableTypeOf(description->type)) << name;
        },
        entry->binding);
    EXPECT_EQ(documented.count(name), 1u) << name << " is tunable live: the Reconfiguring table of "
                                          << node.section << " needs exactly one row for it";
    for (const ReferenceRow& row : rows) {
      if (row.name != name || row.cells.size() < 2) continue;
      boost::any min, max;
      description->getValue(Config::__getMin__(), min);
      description->getValue(Config::__getMax__(), max);
      const auto to = row.cells[1].find(" to ");
      const std::string low = row.cells[1].substr(0, to);
      const std::string high =
          to == std::string::npos ? "" : leadingValue(row.cells[1].substr(to + 4));
      if (description->type == "int") {
        EXPECT_TRUE(says(low, boost::any_cast<int>(min)) && says(high, boost::any_cast<int>(max)))
            << "doc/nodes.md:" << row.line << " must give the .cfg's range of " << name;
      } else if (description->type == "double") {
        EXPECT_TRUE(says(low, boost::any_cast<double>(min)) &&
                    says(high, boost::any_cast<double>(max)))
            << "doc/nodes.md:" << row.line << " must give the .cfg's range of " << name;
      } else {
        for (const std::string& choice : choicesOf(entry->rule)) {
          EXPECT_NE(row.cells[1].find("`" + choice + "`"), std::string::npos)
              << "doc/nodes.md:" << row.line << " must list the choice `" << choice << "`";
        }
      }
    }
  }
  for (const ReferenceRow& row : rows) {
    EXPECT_EQ(tunable.count(row.name), 1u)
        << "doc/nodes.md:" << row.line << " lists `" << row.name << "` as tunable live; the .cfg "
        << "of " << node.section << " has no such parameter";
  }
}

TEST(NodeReference, EveryLiveTunableParameterHasItsRowWithTheCfgsRange) {
  expectReconfigureRows<view_direction_classification::OrientationEstimatorConfig>(kEstimator);
  expectReconfigureRows<view_direction_classification::InformativenessServerConfig>(kServer);
}

// The planner loop (a rospy script) declares its parameters in its dict PARAMETERS: name ->
// (default, meaning). Read with Python's ast, without importing rospy.
TEST(NodeReference, ThePlannerLoopsParametersHaveTheirRowsAndDefaults) {
  const auto run = test::runCommand(
      "/usr/bin/python3 -c \"import ast, sys\n"
      "for node in ast.parse(open(sys.argv[1]).read()).body:\n"
      "    if isinstance(node, ast.Assign) and node.targets[0].id == 'PARAMETERS':\n"
      "        for key, value in zip(node.value.keys, node.value.values):\n"
      "            print(key.value, ast.literal_eval(value)[0])\n\" '" VDC_SOURCE_DIR
      "/scripts/planner_loop.py'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::vector<ReferenceRow> rows;
  for (const ReferenceRow& row : reference().rows("planner_loop.py:", "")) {
    if (row.table == "parameter") rows.push_back(row);
  }
  std::set<std::string> declared;
  std::istringstream lines(run.output);
  for (std::string name, value; lines >> name >> value;) {
    declared.insert(name);
    int count = 0;
    for (const ReferenceRow& row : rows) {
      if (row.name != name || row.cells.size() < 3) continue;
      ++count;
      const std::string written = leadingValue(row.cells[1]);
      double number = 0;
      EXPECT_TRUE(parseNumber(value, number) ? says(written, number) : written == value)
          << "doc/nodes.md:" << row.line << " `" << name << "`: the default is " << value;
    }
    EXPECT_EQ(count, 1) << "planner_loop.py reads ~" << name << ": one row in doc/nodes.md";
  }
  ASSERT_FALSE(declared.empty()) << run.output;
  for (const ReferenceRow& row : rows) {
    EXPECT_EQ(declared.count(row.name), 1u)
        << "doc/nodes.md:" << row.line << " documents `" << row.name
        << "`, which planner_loop.py does not declare";
  }
}

}  // namespace
}  // namespace vdc

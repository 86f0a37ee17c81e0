#include "view_direction_classification/ros/parameter_reader.h"

#include <ros/console.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <algorithm>
#include <cmath>

#include "view_direction_classification/common/number_text.h"

namespace vdc {
namespace {

std::string withNote(std::string words, const std::string& note) {
  return note.empty() ? words : words + " (" + note + ")";
}

// "a string ('abc')", "an integer (3)", ... for the type error's "got ...".
std::string describeXmlRpc(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return "a boolean (" + describeParameterValue(static_cast<bool>(value)) + ")";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an integer (" + std::to_string(static_cast<int>(value)) + ")";
    case XmlRpc::XmlRpcValue::TypeDouble: {
      // 3.0, not 3: where an integer is expected, the message must show why 3.0 is not one.
      const double number = static_cast<double>(value);
      const bool integral = std::isfinite(number) && number == std::floor(number);
      return "a number (" + numberText(number) + (integral ? ".0" : "") + ")";
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string (" + describeParameterValue(static_cast<std::string>(value)) + ")";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list of " + std::to_string(value.size()) + " values";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "a value of another type";
  }
}

bool isNumber(const XmlRpc::XmlRpcValue& value) {
  return value.getType() == XmlRpc::XmlRpcValue::TypeDouble ||
         value.getType() == XmlRpc::XmlRpcValue::TypeInt;
}

double toNumber(XmlRpc::XmlRpcValue& value) {
  return value.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(value)
                                                         : static_cast<double>(value);
}

}  // namespace

ParameterRule<bool> anyBoolean() {
  return {"true or false", [](bool) { return true; }};
}

ParameterRule<std::string> anyString() {
  return {"a string", [](const std::string&) { return true; }};
}

ParameterRule<std::string> nonEmptyString() {
  return {"a non-empty string", [](const std::string& value) { return !value.empty(); }};
}

ParameterRule<std::string> frameName() {
  return {"a non-empty frame name without spaces", [](const std::string& value) {
            return !value.empty() && value.find(' ') == std::string::npos;
          }};
}

ParameterRule<int> integerAtLeast(int minimum, const std::string& note) {
  return {withNote("an integer >= " + std::to_string(minimum), note),
          [minimum](int value) { return value >= minimum; }};
}

ParameterRule<int> integerBetween(int minimum, int maximum, const std::string& note) {
  return {
      withNote("an integer between " + std::to_string(minimum) + " and " + std::to_string(maximum),
               note),
      [minimum, maximum](int value) { return value >= minimum && value <= maximum; }};
}

ParameterRule<double> finiteNumber(const std::string& note) {
  return {withNote("a finite number", note), [](double value) { return std::isfinite(value); }};
}

ParameterRule<double> numberAtLeast(double minimum, const std::string& note) {
  return {withNote("a finite number >= " + numberText(minimum), note),
          [minimum](double value) { return std::isfinite(value) && value >= minimum; }};
}

ParameterRule<double> numberAbove(double minimum, const std::string& note) {
  return {withNote("a finite number > " + numberText(minimum), note),
          [minimum](double value) { return std::isfinite(value) && value > minimum; }};
}

ParameterRule<double> numberIn(double minimum, double maximum, bool include_maximum,
                               const std::string& note) {
  return {withNote("a number in [" + numberText(minimum) + ", " + numberText(maximum) +
                       (include_maximum ? "]" : ")"),
                   note),
          [=](double value) {
            return value >= minimum && (include_maximum ? value <= maximum : value < maximum);
          }};
}

ParameterRule<std::vector<double>> finiteNumbers(std::size_t count, const std::string& layout) {
  const std::string words =
      count == 0 ? "a list of finite numbers " + layout
                 : "a list of " + std::to_string(count) + " finite numbers " + layout;
  return {words, [count](const std::vector<double>& values) {
            return (count == 0 || values.size() == count) &&
                   std::all_of(values.begin(), values.end(),
                               [](double v) { return std::isfinite(v); });
          }};
}

ParameterRule<std::vector<double>> finiteGroupsOf(std::size_t group, const std::string& layout) {
  return {"a list of finite numbers in groups of " + std::to_string(group) + " " + layout,
          [group](const std::vector<double>& values) {
            return values.size() % group == 0 &&
                   std::all_of(values.begin(), values.end(),
                               [](double v) { return std::isfinite(v); });
          }};
}

std::string describeParameterValue(bool value) { return value ? "true" : "false"; }
std::string describeParameterValue(int value) { return std::to_string(value); }
std::string describeParameterValue(double value) { return numberText(value); }
std::string describeParameterValue(const std::string& value) { return "'" + value + "'"; }

std::string describeParameterValue(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    text += (i == 0 ? "" : ", ") + numberText(values[i]);
  }
  return text + "]";
}

Error parameterError(const std::string& name, const std::string& words, const std::string& value) {
  return Error("Parameter ~" + name + " must be " + words + ", got " + value + ".");
}

namespace {

// The raw value of `name`, which must be set.
XmlRpc::XmlRpcValue rawValue(const ros::NodeHandle& node, const std::string& name) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam(name, value)) throw Error("Parameter ~" + name + " is not set.");
  return value;
}

}  // namespace

template <>
bool ParameterReader::get<bool>(const std::string& name) const {
  XmlRpc::XmlRpcValue value = rawValue(node_, name);
  if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
    throw parameterError(name, "true or false", describeXmlRpc(value));
  }
  return static_cast<bool>(value);
}

template <>
int ParameterReader::get<int>(const std::string& name) const {
  XmlRpc::XmlRpcValue value = rawValue(node_, name);
  if (value.getType() != XmlRpc::XmlRpcValue::TypeInt) {
    throw parameterError(name, "an integer", describeXmlRpc(value));
  }
  return static_cast<int>(value);
}

template <>
double ParameterReader::get<double>(const std::string& name) const {
  XmlRpc::XmlRpcValue value = rawValue(node_, name);
  if (!isNumber(value)) throw parameterError(name, "a number", describeXmlRpc(value));
  return toNumber(value);
}

template <>
std::string ParameterReader::get<std::string>(const std::string& name) const {
  XmlRpc::XmlRpcValue value = rawValue(node_, name);
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) {
    throw parameterError(name, "a string", describeXmlRpc(value));
  }
  return static_cast<std::string>(value);
}

template <>
std::vector<double> ParameterReader::get<std::vector<double>>(const std::string& name) const {
  XmlRpc::XmlRpcValue value = rawValue(node_, name);
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw parameterError(name, "a list of numbers", describeXmlRpc(value));
  }
  std::vector<double> numbers;
  for (int i = 0; i < value.size(); ++i) {
    if (!isNumber(value[i])) {
      throw parameterError(
          name, "a list of numbers",
          "a list whose element " + std::to_string(i) + " is " + describeXmlRpc(value[i]));
    }
    numbers.push_back(toNumber(value[i]));
  }
  return numbers;
}

std::vector<std::string> ParameterReader::unknownParameters(
    const std::vector<std::string>& known) const {
  std::vector<std::string> names;
  if (!node_.getParamNames(names)) return {};
  const std::string prefix = node_.getNamespace() + "/";
  std::vector<std::string> unknown;
  for (const std::string& full : names) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name =
        full.substr(prefix.size(), full.find('/', prefix.size()) - prefix.size());
    if (std::find(known.begin(), known.end(), name) == known.end() &&
        std::find(unknown.begin(), unknown.end(), name) == unknown.end()) {
      unknown.push_back(name);
    }
  }
  return unknown;
}

void ParameterReader::warnAboutUnknownParameters(const std::vector<std::string>& known) const {
  const std::vector<std::string> unknown = unknownParameters(known);
  if (unknown.empty()) return;
  std::string names;
  for (const std::string& name : unknown) names += (names.empty() ? "~" : ", ~") + name;
  ROS_WARN_NAMED(node_.getNamespace(),
                 "%s: ignoring parameters this node does not read (misspelt?): %s",
                 node_.getNamespace().c_str(), names.c_str());
}

}  // namespace vdc

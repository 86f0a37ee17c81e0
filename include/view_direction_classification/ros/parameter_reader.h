#pragma once

#include <ros/node_handle.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {

// What a parameter's value may be: a test and the same rule in words, which complete the
// sentence "Parameter ~name must be <words>, got <value>."
template <typename T>
struct ParameterRule {
  std::string words;
  std::function<bool(const T&)> accepts;
};

// The rules the nodes use. A `note` follows the words in parentheses, e.g. "0: the model's
// value". Every number rule also requires a finite value.
ParameterRule<bool> anyBoolean();
ParameterRule<std::string> anyString();
ParameterRule<std::string> nonEmptyString();
ParameterRule<std::string> frameName();  // a tf frame: non-empty, no spaces
ParameterRule<int> integerAtLeast(int minimum, const std::string& note = "");
ParameterRule<int> integerBetween(int minimum, int maximum, const std::string& note = "");
ParameterRule<double> finiteNumber(const std::string& note = "");
ParameterRule<double> numberAtLeast(double minimum, const std::string& note = "");
ParameterRule<double> numberAbove(double minimum, const std::string& note = "");
// [minimum, maximum) or [minimum, maximum] (include_maximum).
ParameterRule<double> numberIn(double minimum, double maximum, bool include_maximum,
                               const std::string& note = "");
// `count` finite numbers (count 0: any number of them, including none); `layout` names them,
// e.g. "[x, y, z] in the fixed frame".
ParameterRule<std::vector<double>> finiteNumbers(std::size_t count, const std::string& layout);
// Finite numbers in groups of `group` (e.g. 3: x, y, z triples), possibly none.
ParameterRule<std::vector<double>> finiteGroupsOf(std::size_t group, const std::string& layout);

// The value as a message shows it: 0.25, 'text', true, [1, 2, 3].
std::string describeParameterValue(bool value);
std::string describeParameterValue(int value);
std::string describeParameterValue(double value);
std::string describeParameterValue(const std::string& value);
std::string describeParameterValue(const std::vector<double>& value);

// vdc::Error("Parameter ~<name> must be <words>, got <value>."): the one form in which every
// node reports a bad parameter, at start-up (one FATAL line, exit 1) and on a refused
// dynamic_reconfigure request.
Error parameterError(const std::string& name, const std::string& words, const std::string& value);

// Checks `value` against `rule`; throws parameterError(name, ...) if it does not pass.
template <typename T>
void checkParameter(const std::string& name, const T& value, const ParameterRule<T>& rule) {
  if (!rule.accepts(value)) throw parameterError(name, rule.words, describeParameterValue(value));
}

// The error for a missing ~model, the parameter of the estimator and the server that names the
// model bundle.
inline constexpr const char* kModelMissing =
    "Parameter ~model (the model bundle's path) is required; train one with `vdc train` and "
    "pass it as model:=<file.h5>.";

// Reads a node's private parameters with strict types: a value of another type is an error
// naming the parameter and what it holds, never silently the default (as ros::NodeHandle::param
// makes it). The one exception is an integer where a number is expected (YAML `rate: 2`).
class ParameterReader {
 public:
  explicit ParameterReader(ros::NodeHandle node) : node_(std::move(node)) {}

  bool has(const std::string& name) const { return node_.hasParam(name); }

  // The value of `name` (which must be set). Throws vdc::Error ("Parameter ~kappa must be a
  // number, got a string ('abc').") for another type.
  template <typename T>
  T get(const std::string& name) const;

  // The value of `name` checked by `rule`, or `fallback` (unchecked: a default) if it is unset.
  template <typename T>
  T get(const std::string& name, const T& fallback, const ParameterRule<T>& rule) const {
    if (!has(name)) return fallback;
    T value = get<T>(name);
    checkParameter(name, value, rule);
    return value;
  }

  // The private parameters that are set but not in `known` (e.g. a misspelt one in a YAML file).
  std::vector<std::string> unknownParameters(const std::vector<std::string>& known) const;
  // Logs one warning listing them: a misspelt name would otherwise be ignored without a word.
  void warnAboutUnknownParameters(const std::vector<std::string>& known) const;

 private:
  ros::NodeHandle node_;
};

template <>
bool ParameterReader::get<bool>(const std::string& name) const;
template <>
int ParameterReader::get<int>(const std::string& name) const;
template <>
double ParameterReader::get<double>(const std::string& name) const;
template <>
std::string ParameterReader::get<std::string>(const std::string& name) const;
template <>
std::vector<double> ParameterReader::get<std::vector<double>>(const std::string& name) const;

}  // namespace vdc

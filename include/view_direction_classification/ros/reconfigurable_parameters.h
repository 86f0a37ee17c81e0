#pragma once

#include <dynamic_reconfigure/Config.h>

#include <string>
#include <variant>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// dynamic_reconfigure for a node whose parameters a ParameterTable lists: a generated Config
// (cfg/*.cfg) names a subset of the table's parameters with the same names and types, and these
// two functions move values between it and the node's settings through the table's bindings, so
// a reconfigure request passes the same rules as the start-up parameters.

namespace reconfigure_detail {

template <typename T, typename Settings>
const typename ParameterTable<Settings>::template Binding<T>& bindingOf(
    const ParameterTable<Settings>& table, const std::string& name) {
  const auto* entry = table.find(name);
  if (!entry) throw Error("the reconfigurable parameter ~" + name + " is not a node parameter");
  const auto* binding =
      std::get_if<typename ParameterTable<Settings>::template Binding<T>>(&entry->binding);
  if (!binding) {
    throw Error("the reconfigurable parameter ~" + name + " has another type than the node's");
  }
  return *binding;
}

}  // namespace reconfigure_detail

// The Config holding the values `settings` has (what the node runs with): given to the
// reconfigure server before its callback is set, so the first callback applies what the node
// started with, not the .cfg's defaults.
template <typename Config, typename Settings>
Config toReconfigureConfig(const ParameterTable<Settings>& table, const Settings& settings) {
  using reconfigure_detail::bindingOf;
  dynamic_reconfigure::Config message;
  Config config = Config::__getDefault__();
  config.__toMessage__(message);
  for (auto& p : message.bools) p.value = bindingOf<bool>(table, p.name).get(settings);
  for (auto& p : message.ints) p.value = bindingOf<int>(table, p.name).get(settings);
  for (auto& p : message.doubles) p.value = bindingOf<double>(table, p.name).get(settings);
  for (auto& p : message.strs) p.value = bindingOf<std::string>(table, p.name).get(settings);
  config.__fromMessage__(message);
  return config;
}

// `settings` with the values of `config`. Throws parameterError ("Parameter ~min_weight must
// be a number in [0, 1), got 1.") for a value its rule refuses; `settings` is not changed.
template <typename Config, typename Settings>
Settings withReconfigureConfig(const ParameterTable<Settings>& table, const Settings& settings,
                               const Config& config) {
  using reconfigure_detail::bindingOf;
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  Settings result = settings;
  for (const auto& p : message.bools) bindingOf<bool>(table, p.name).set(result, p.value);
  for (const auto& p : message.ints) bindingOf<int>(table, p.name).set(result, p.value);
  for (const auto& p : message.doubles) bindingOf<double>(table, p.name).set(result, p.value);
  for (const auto& p : message.strs) bindingOf<std::string>(table, p.name).set(result, p.value);
  return result;
}

}  // namespace vdc

#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "view_direction_classification/ros/parameter_reader.h"

namespace vdc {

// The parameters of one node: for each, its name, where its value goes in the node's settings
// struct and the rule it must pass. The node reads all of them at start-up from this one list
// (ParameterTable::read) and, for those it lets a user tune live, applies dynamic_reconfigure
// requests through the same list (reconfigurable_parameters.h), so a parameter is declared,
// checked and documented in one place.
//
// A field is named by a member pointer (&Settings::rate), a path of them for a nested one
// (fieldPath(&Settings::core, &Core::kappa)) or any callable returning a reference into the
// settings for a const and a non-const argument.
template <typename... Members>
auto fieldPath(Members... members) {
  return [members...](auto& settings) -> auto& { return (settings.*....*members); };
}

template <typename Settings>
class ParameterTable {
 public:
  // How one parameter of type T is read from and written into the settings; `set` checks the
  // rule and throws parameterError naming the parameter.
  template <typename T>
  struct Binding {
    std::function<T(const Settings&)> get;
    std::function<void(Settings&, const T&)> set;
  };
  struct Entry {
    std::string name;
    std::string rule;  // the rule in words, for messages and documentation
    // Non-empty for a required parameter: the error when it is not set.
    std::string missing_message;
    std::variant<Binding<bool>, Binding<int>, Binding<double>, Binding<std::string>,
                 Binding<std::vector<double>>>
        binding;
  };

  // A parameter stored as it is on the parameter server (bool, int, double, std::string or
  // std::vector<double>).
  template <typename T, typename Field>
  ParameterTable& add(std::string name, Field field, ParameterRule<T> rule) {
    static_assert(std::is_same_v<std::decay_t<std::invoke_result_t<Field, Settings&>>, T>,
                  "the rule's type must be the field's type");
    Binding<T> binding;
    binding.get = [field](const Settings& settings) { return std::invoke(field, settings); };
    binding.set = [field, name, rule](Settings& settings, const T& value) {
      checkParameter(name, value, rule);
      std::invoke(field, settings) = value;
    };
    entries_.push_back({std::move(name), rule.words, "", std::move(binding)});
    return *this;
  }

  // A parameter that must be set; `missing_message` is the whole error if it is not.
  template <typename T, typename Field>
  ParameterTable& addRequired(std::string name, Field field, ParameterRule<T> rule,
                              std::string missing_message) {
    add(std::move(name), field, std::move(rule));
    entries_.back().missing_message = std::move(missing_message);
    return *this;
  }

  // A string parameter naming one of `choices` for an enum field.
  template <typename Enum, typename Field>
  ParameterTable& addChoice(std::string name, Field field,
                            std::vector<std::pair<std::string, Enum>> choices) {
    std::string words = "one of";
    for (std::size_t i = 0; i < choices.size(); ++i) {
      words += (i == 0 ? " '" : ", '") + choices[i].first + "'";
    }
    Binding<std::string> binding;
    binding.get = [field, choices](const Settings& settings) {
      for (const auto& [text, value] : choices) {
        if (value == std::invoke(field, settings)) return text;
      }
      return std::string();
    };
    binding.set = [field, name, choices, words](Settings& settings, const std::string& text) {
      for (const auto& [choice, value] : choices) {
        if (choice != text) continue;
        std::invoke(field, settings) = value;
        return;
      }
      throw parameterError(name, words, describeParameterValue(text));
    };
    entries_.push_back({std::move(name), words, "", std::move(binding)});
    return *this;
  }

  // A list [x, y, z] for an Eigen::Vector3d field; `where` says in which frame.
  template <typename Field>
  ParameterTable& addPoint(std::string name, Field field, const std::string& where) {
    const ParameterRule<std::vector<double>> rule = finiteNumbers(3, "[x, y, z] " + where);
    Binding<std::vector<double>> binding;
    binding.get = [field](const Settings& settings) {
      const Eigen::Vector3d& point = std::invoke(field, settings);
      return std::vector<double>{point.x(), point.y(), point.z()};
    };
    binding.set = [field, name, rule](Settings& settings, const std::vector<double>& value) {
      checkParameter(name, value, rule);
      std::invoke(field, settings) = Eigen::Vector3d(value[0], value[1], value[2]);
    };
    entries_.push_back({std::move(name), rule.words, "", std::move(binding)});
    return *this;
  }

  // Reads every listed parameter that is set into `settings`; the unset ones keep the value
  // `settings` has (its default). Throws vdc::Error naming the first bad or missing parameter;
  // with `waive_required`, a required parameter may be missing (another one replaces it).
  void read(const ParameterReader& reader, Settings& settings, bool waive_required = false) const {
    for (const Entry& entry : entries_) {
      if (!reader.has(entry.name)) {
        if (!entry.missing_message.empty() && !waive_required) throw Error(entry.missing_message);
        continue;
      }
      std::visit(
          [&](const auto& binding) {
            using T = std::decay_t<decltype(binding.get(settings))>;
            binding.set(settings, reader.template get<T>(entry.name));
          },
          entry.binding);
    }
  }

  const std::vector<Entry>& entries() const { return entries_; }
  const Entry* find(const std::string& name) const {
    for (const Entry& entry : entries_) {
      if (entry.name == name) return &entry;
    }
    return nullptr;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const Entry& entry : entries_) result.push_back(entry.name);
    return result;
  }

 private:
  std::vector<Entry> entries_;
};

}  // namespace vdc

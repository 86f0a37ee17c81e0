#pragma once

#include <stdexcept>
#include <string>

namespace vdc {

// The one exception type of the core. Its message is a complete sentence meant for a user: it
// names the input (file, parameter, value) and what is wrong with it, so the CLI and the nodes
// can print it as one line without adding context they do not have.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace vdc

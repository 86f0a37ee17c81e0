#pragma once

// The message of the vdc::Error an action throws, for tests that check what a refusal says.

#include <functional>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc::test {

// The message of the vdc::Error `action` throws; empty when it throws none.
inline std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace vdc::test

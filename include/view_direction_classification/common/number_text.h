#pragma once

#include <sstream>
#include <string>

namespace vdc {

// A number as a message shows it: short, whatever its size (std::to_string writes 1e300 in full
// and 0.1 as 0.100000).
inline std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace vdc

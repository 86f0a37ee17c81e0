#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace vdc::test {

// The fields of `text` between `separator`s (a CSV line's cells, a file's lines).
inline std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  // getline drops an empty last field ("a,b," has three cells); a last newline ends a line.
  if (separator != '\n' && !text.empty() && text.back() == separator) parts.push_back("");
  return parts;
}

}  // namespace vdc::test

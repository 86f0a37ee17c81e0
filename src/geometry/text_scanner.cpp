#include "text_scanner.h"

#include <charconv>
#include <system_error>

namespace vdc::mesh_readers {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

bool TextScanner::nextLine(std::string_view* line) {
  if (atEnd()) return false;
  const std::size_t end = text_.find('\n', position_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  std::string_view result = text_.substr(position_, stop - position_);
  if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
  *line = result;
  last_line_ = line_;
  position_ = stop == text_.size() ? stop : stop + 1;
  ++line_;
  return true;
}

bool TextScanner::nextToken(std::string_view* token) {
  while (position_ < text_.size() && isSpace(text_[position_])) {
    if (text_[position_] == '\n') ++line_;
    ++position_;
  }
  if (atEnd()) return false;
  const std::size_t start = position_;
  while (position_ < text_.size() && !isSpace(text_[position_])) ++position_;
  *token = text_.substr(start, position_ - start);
  last_line_ = line_;
  return true;
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 32;
  static const char kHex[] = "0123456789abcdef";
  std::string result = "'";
  for (const char c : token.substr(0, kShown)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      result += c;
    } else {
      result += "\\x";
      result += kHex[byte >> 4];
      result += kHex[byte & 15];
    }
  }
  return result + (token.size() > kShown ? "...'" : "'");
}

std::vector<std::string_view> splitWords(std::string_view line, std::size_t limit) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (words.size() < limit) {
    while (i < line.size() && isSpace(line[i])) ++i;
    if (i == line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::string_view withoutComment(std::string_view text, char comment) {
  const std::size_t at = text.find(comment);
  return at == std::string_view::npos ? text : text.substr(0, at);
}

bool parseReal(std::string_view token, double* value) {
  // from_chars takes no leading '+', which some writers emit.
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, *value);
  // Out of range (e.g. 1e999) is an error code with nothing stored; the file is still bad.
  return error == std::errc() && stop == end && !token.empty();
}

bool parseInteger(std::string_view token, std::int64_t* value) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, *value);
  return error == std::errc() && stop == end && !token.empty();
}

}  // namespace vdc::mesh_readers

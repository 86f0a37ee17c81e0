#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vdc::mesh_readers {

// Reads a text mesh file (ASCII PLY, OFF, OBJ, ASCII STL) held in memory, by lines or by
// whitespace-separated tokens, and knows the line it is on for error messages. It never reads
// past its text and every call consumes at least one byte or returns false, so a reader built on
// it ends after at most one step per byte, whatever the file claims.
class TextScanner {
 public:
  explicit TextScanner(std::string_view text) : text_(text) {}

  // The next line without its end ("\n" or "\r\n"); false at the end of the text.
  bool nextLine(std::string_view* line);
  // The next token (spaces, tabs, '\r', '\n', '\f' and '\v' separate tokens); false at the end.
  bool nextToken(std::string_view* token);
  // The 1-based line of the last line or token returned.
  std::size_t lineNumber() const { return last_line_; }
  bool atEnd() const { return position_ >= text_.size(); }
  // Where the next line or token starts (after the end of the last line returned).
  std::size_t offset() const { return position_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;       // line of text_[position_]
  std::size_t last_line_ = 0;  // line of the last result
};

bool isSpace(char c);
// A token for a message: in quotes, at most 32 characters, bytes that do not print as \xNN.
std::string quoted(std::string_view token);
// The whitespace-separated words of one line, at most `limit` of them (the rest are ignored):
// a line cannot make a reader collect more than it can use.
std::vector<std::string_view> splitWords(std::string_view line, std::size_t limit);
// `text` without what follows the first `comment` character.
std::string_view withoutComment(std::string_view text, char comment);

// The number a whole token spells (decimal, optional sign, exponent, "inf" and "nan" too; the
// caller decides about non-finite values); false if the token is not exactly one number.
bool parseReal(std::string_view token, double* value);
// The integer a whole token spells (optional sign); false if it is not one or overflows.
bool parseInteger(std::string_view token, std::int64_t* value);

}  // namespace vdc::mesh_readers

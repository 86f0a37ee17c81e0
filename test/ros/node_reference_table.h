#pragma once

// The tables of doc/nodes.md as the node reference test reads them: one row per parameter, the
// name in backticks in the first column.

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace vdc::test {

struct ReferenceRow {
  std::string name;
  std::vector<std::string> cells;  // every cell, the name's included, trimmed
  std::string table;               // the first cell of its table's header ("name", "parameter")
  int line = 0;                    // 1-based line in the file
};

// The rows of every table under the heading `## <section>` and, inside it, the subheading that
// starts with `### <subsection>`, in file order. A row is a line "| `name` | ... |".
class NodeReference {
 public:
  explicit NodeReference(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::string section;
    std::string subsection;
    std::string header;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.rfind("## ", 0) == 0) {
        section = firstWord(line.substr(3));
        subsection.clear();
      } else if (line.rfind("### ", 0) == 0) {
        subsection = line.substr(4);
      } else if (line.rfind("| ", 0) == 0 && line.rfind("| `", 0) != 0 &&
                 line.rfind("| -", 0) != 0) {
        header = splitCells(line).front();
      } else if (line.rfind("| `", 0) == 0) {
        ReferenceRow row{"", splitCells(line), header, number};
        row.name = backticked(row.cells.front());
        rows_[section + "\n" + subsection].push_back(row);
      }
    }
    read_ = in.eof() && !rows_.empty();
  }

  bool read() const { return read_; }

  std::vector<ReferenceRow> rows(const std::string& section, const std::string& subsection) const {
    std::vector<ReferenceRow> result;
    for (const auto& [key, rows] : rows_) {
      const auto split = key.find('\n');
      if (key.substr(0, split) != section) continue;
      if (key.compare(split + 1, subsection.size(), subsection) != 0) continue;
      result.insert(result.end(), rows.begin(), rows.end());
    }
    return result;
  }

  // The text between the first pair of backticks of `cell`, or "" without one.
  static std::string backticked(const std::string& cell) {
    const auto open = cell.find('`');
    const auto close = open == std::string::npos ? open : cell.find('`', open + 1);
    return close == std::string::npos ? "" : cell.substr(open + 1, close - open - 1);
  }

 private:
  static std::string firstWord(const std::string& text) {
    std::istringstream words(text);
    std::string word;
    words >> word;
    return word;
  }
  static std::string trim(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t");
    if (begin == std::string::npos) return "";
    return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
  }
  // A row's cells; a '|' inside backticks belongs to its cell.
  static std::vector<std::string> splitCells(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    bool in_code = false;
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (line[i] == '`') in_code = !in_code;
      if (line[i] == '|' && !in_code) {
        cells.push_back(trim(cell));
        cell.clear();
      } else {
        cell += line[i];
      }
    }
    return cells;
  }

  std::map<std::string, std::vector<ReferenceRow>> rows_;
  bool read_ = false;
};

}  // namespace vdc::test

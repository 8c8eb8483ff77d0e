#include "frictionlab/io/csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "frictionlab/io/sha256.hpp"

namespace frictionlab {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string unquote(std::string s) {
  s = trim(s);
  if (s.size() >= 2 && ((s.front() == '"' && s.back() == '"') || (s.front() == '\'' && s.back() == '\''))) {
    s = trim(s.substr(1, s.size() - 2));
  }
  return s;
}

std::vector<std::string> split(const std::string& line, char delimiter) {
  std::vector<std::string> cells;
  std::string cell;
  for (char c : line) {
    if (c == delimiter) {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

enum class Cell { number, empty, not_finite, text };

// Parses a cell with the C locale; "nan", "inf" (any case) are recognised as not finite.
Cell parse_cell(const std::string& raw, double& value) {
  const std::string s = unquote(raw);
  if (s.empty()) return Cell::empty;
  const char* begin = s.data();
  if (*begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range) return Cell::not_finite;
  if (ec != std::errc() || ptr != s.data() + s.size()) return Cell::text;
  return std::isfinite(value) ? Cell::number : Cell::not_finite;
}

bool skip_line(const std::string& line, char comment) {
  const std::string t = trim(line);
  return t.empty() || (comment != '\0' && t.front() == comment);
}

}  // namespace

Dataset read_csv(const std::string& path, const CsvOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open the CSV file (does it exist and is it readable?)");

  Dataset data;
  data.file = path;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
  std::string line;
  std::size_t line_no = 0;
  bool have_header = false;
  std::size_t dropped = 0;

  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // BOM
    if (skip_line(line, options.comment)) continue;
    const std::vector<std::string> cells = split(line, options.delimiter);
    if (!have_header) {
      std::set<std::string> seen;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        std::string name = unquote(cells[c]);
        if (name.empty()) {
          throw std::invalid_argument(path + ": line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) +
                                      ": empty name in the header row (expected a column name)");
        }
        if (!seen.insert(name).second) {
          throw std::invalid_argument(path + ": line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) +
                                      ": duplicate column name '" + name + "' in the header row");
        }
        double dummy = 0;
        if (c == 0 && parse_cell(name, dummy) == Cell::number) {
          throw std::invalid_argument(path + ": line " + std::to_string(line_no) +
                                      ": the first row holds numbers; expected a header row of column names");
        }
        names.push_back(std::move(name));
      }
      values.resize(names.size());
      have_header = true;
      continue;
    }
    if (cells.size() != names.size()) {
      throw std::invalid_argument(path + ": line " + std::to_string(line_no) + ": " + std::to_string(cells.size()) +
                                  " cells; expected " + std::to_string(names.size()) +
                                  " like the header row (separator '" + std::string(1, options.delimiter) + "')");
    }
    std::vector<double> row(names.size());
    bool invalid = false;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const Cell kind = parse_cell(cells[c], row[c]);
      if (kind == Cell::number) continue;
      const std::string where = path + ": line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) +
                                " '" + names[c] + "': ";
      if (kind == Cell::text) {
        throw std::invalid_argument(where + "expected a number, got '" + unquote(cells[c]) + "'");
      }
      if (!options.drop_invalid) {
        throw std::invalid_argument(where + (kind == Cell::empty ? "empty cell" : "'" + unquote(cells[c]) + "'") +
                                    "; expected a finite number (use drop_invalid / --drop-invalid to skip such rows)");
      }
      invalid = true;
    }
    if (invalid) {
      ++dropped;
      continue;
    }
    for (std::size_t c = 0; c < row.size(); ++c) values[c].push_back(row[c]);
    data.lines.push_back(line_no);
  }
  if (in.bad()) throw std::invalid_argument(path + ": read error");
  if (!have_header) throw std::invalid_argument(path + ": empty file; expected a header row and data rows");
  if (data.lines.empty()) {
    throw std::invalid_argument(path + ": no data rows after the header" +
                                (dropped ? " (all " + std::to_string(dropped) + " rows had invalid cells)" : ""));
  }
  for (std::size_t c = 0; c < names.size(); ++c) {
    data.add_column(names[c], Eigen::Map<const Eigen::VectorXd>(values[c].data(), static_cast<Eigen::Index>(values[c].size())));
  }
  data.sha256 = sha256_file(path);
  return data;
}

}  // namespace frictionlab

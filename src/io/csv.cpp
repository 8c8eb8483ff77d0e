#include "frictionlab/io/csv.hpp"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <locale.h>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "frictionlab/error.hpp"
#include "io/input_file.hpp"
#include "io/sha256.hpp"

namespace frictionlab {
namespace {

constexpr char kBlanks = ' ';  // CsvOptions::delimiter for runs of blanks

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Header names may also be in single quotes (double quotes are removed while splitting).
std::string unquote_name(std::string s) {
  s = trim(s);
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') s = trim(s.substr(1, s.size() - 2));
  return s;
}

std::string delimiter_name(char d) {
  switch (d) {
    case '\t': return "tab";
    case kBlanks: return "runs of blanks";
    default: return "'" + std::string(1, d) + "'";
  }
}

// The delimiter of a row: the first of tab, ';', ',' found outside double quotes (in that order,
// so that "1,5;2,5" with decimal commas splits on ';'), else runs of blanks.
char detect_delimiter(const std::string& line) {
  bool quoted = false, tab = false, semicolon = false, comma = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    tab |= c == '\t';
    semicolon |= c == ';';
    comma |= c == ',';
  }
  return tab ? '\t' : semicolon ? ';' : comma ? ',' : kBlanks;
}

// Splits a row into trimmed cells, honouring double quotes ("a,b" is one cell, "" inside quotes
// is a quote). Returns false for a quote left open at the end of the line.
bool split(const std::string& line, char delimiter, std::vector<std::string>& cells) {
  cells.clear();
  std::string cell;
  bool quoted = false, was_quoted = false, any = false;
  const auto push = [&] {
    cells.push_back(was_quoted ? cell : trim(cell));
    cell.clear();
    was_quoted = false;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') cell += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') cell += line[++i];
      else quoted = false;
      continue;
    }
    const bool blank = c == ' ' || c == '\t' || c == '\r';
    if (delimiter == kBlanks ? blank : c == delimiter) {
      if (delimiter == kBlanks) {
        if (any) push();
        any = false;
      } else {
        push();
      }
      continue;
    }
    if (c == '"' && trim(cell).empty()) {  // a quote opens a cell only at its start
      cell.clear();
      quoted = was_quoted = any = true;
      continue;
    }
    if (was_quoted) {  // text after the closing quote: keep it (the cell is then not a clean quote)
      if (blank) continue;
      was_quoted = false;
    }
    cell += c;
    any = any || !blank;
  }
  if (quoted) return false;
  if (delimiter != kBlanks || any) push();
  return true;
}

enum class Cell { number, empty, not_finite, too_large, text };

// Parses a cell with the C locale; "nan", "inf" (any case) are recognised as not finite.
Cell parse_cell(const std::string& s, double& value) {
  if (s.empty()) return Cell::empty;
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  if (*begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec == std::errc::result_out_of_range && ptr == end) {
    // from_chars refuses both underflow (1e-400) and overflow (1e400); strtod in the C locale
    // tells them apart: on underflow it returns 0 or the subnormal, which is the value.
    static const locale_t c_locale = newlocale(LC_NUMERIC_MASK, "C", nullptr);
    value = strtod_l(s.c_str(), nullptr, c_locale);
    return std::isinf(value) ? Cell::too_large : Cell::number;
  }
  if (ec != std::errc() || ptr != end) return Cell::text;
  return std::isfinite(value) ? Cell::number : Cell::not_finite;
}

bool skip_line(const std::string& line, char comment) {
  const std::string t = trim(line);
  return t.empty() || (comment != '\0' && t.front() == comment);
}

std::string at_line(const std::string& path, std::size_t line_no) { return path + ": line " + std::to_string(line_no); }

}  // namespace

Dataset read_csv(const std::string& path, const CsvOptions& options) {
  // Read once, within the budget (a FIFO too: its bytes are hashed and parsed from memory).
  const std::string bytes = read_input_file(path, "CSV file", errc::data_file_unreadable);
  std::istringstream in(bytes);

  Dataset data;
  data.file = path;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
  std::string line;
  std::size_t line_no = 0;
  bool have_first_row = false;
  char delimiter = options.delimiter;
  std::size_t dropped = 0;
  std::vector<std::string> cells;
  std::vector<double> row;

  // Reads the cells of a data row into `row`; false when the row is dropped (drop_invalid).
  const auto parse_row = [&]() {
    row.assign(cells.size(), 0.0);
    bool invalid = false;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const Cell kind = parse_cell(cells[c], row[c]);
      if (kind == Cell::number) continue;
      const std::string where = at_line(path, line_no) + ", column " + std::to_string(c + 1) + " '" + names[c] + "': ";
      const ErrorFields fields{.file = path, .row = line_no, .column = names[c], .value = cells[c]};
      const bool droppable = kind == Cell::empty || kind == Cell::not_finite;
      if (droppable && options.drop_invalid) {
        invalid = true;
        continue;
      }
      // Refused now, or (defer_invalid) when a command uses the column.
      const auto refuse = [&](const char* code, const std::string& message) {
        if (!options.defer_invalid) throw InputError(code, message, fields);
        data.invalid_cells.try_emplace(names[c], code, message, fields);
        row[c] = std::numeric_limits<double>::quiet_NaN();
      };
      if (kind == Cell::text) {
        const bool decimal_comma = delimiter != ',' && cells[c].find(',') != std::string::npos;
        refuse(errc::data_not_a_number, where + "expected a number, got '" + cells[c] + "'" +
                                            (decimal_comma ? " (a decimal comma? numbers need a decimal point)" : ""));
      } else if (kind == Cell::too_large) {
        refuse(errc::data_not_finite,
               where + "'" + cells[c] + "' is out of the range of a double (magnitude above 1.8e308); expected a finite number");
      } else {
        refuse(errc::data_not_finite, where + (kind == Cell::empty ? "empty cell" : "'" + cells[c] + "'") +
                                          "; expected a finite number (use " + options.drop_invalid_option + " to skip such rows)");
      }
    }
    return !invalid;
  };
  const auto keep_row = [&] {
    for (std::size_t c = 0; c < row.size(); ++c) values[c].push_back(row[c]);
    data.lines.push_back(line_no);
  };

  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // BOM
    if (skip_line(line, options.comment)) continue;
    if (delimiter == '\0') delimiter = detect_delimiter(line);
    if (!split(line, delimiter, cells)) {
      throw InputError(errc::data_format,
                       at_line(path, line_no) + ": a quoted cell is not closed (expected a closing '\"' on the same line)",
                       {.file = path, .row = line_no});
    }
    if (!have_first_row) {
      have_first_row = true;
      // Is the first row data? Every cell a number (or NaN, inf, empty) and at least one number.
      std::size_t numbers = 0, text = 0, first_number = 0, first_text = 0;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        double v = 0;
        const Cell kind = parse_cell(cells[c], v);
        if (kind == Cell::text) {
          if (text++ == 0) first_text = c;
        } else if (kind == Cell::number) {
          if (numbers++ == 0) first_number = c;
        }
      }
      if (options.header == CsvHeader::required && numbers > 0 && first_number == 0) {
        throw InputError(errc::data_format,
                         at_line(path, line_no) +
                             ": the first row holds numbers; expected a header row of column names (or read "
                             "the file with header detection, which names the columns c1, c2, ...)",
                         {.file = path, .row = line_no});
      }
      const bool headerless = options.header == CsvHeader::detect && numbers > 0 && text == 0;
      if (options.header == CsvHeader::detect && numbers > 0 && text > 0) {
        throw InputError(errc::data_format,
                         at_line(path, line_no) + ": the first row mixes numbers and text (column " +
                             std::to_string(first_number + 1) + " '" + cells[first_number] + "', column " +
                             std::to_string(first_text + 1) + " '" + cells[first_text] +
                             "'); expected a header row of column names or a row of numbers",
                         {.file = path, .row = line_no});
      }
      data.header_row = !headerless;
      data.names_option = options.names_option;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        names.push_back(headerless ? std::string(1, 'c').append(std::to_string(c + 1)) : unquote_name(cells[c]));
      }
      if (options.names.size() > names.size()) {
        throw InputError(errc::option_invalid,
                         path + ": " + options.names_option + " gives " + std::to_string(options.names.size()) +
                             " names but the file has " + std::to_string(names.size()) + " columns (" +
                             delimiter_name(delimiter) + " separated, line " + std::to_string(line_no) + ")",
                         {.file = path, .row = line_no, .option = options.names_option});
      }
      for (std::size_t c = 0; c < options.names.size(); ++c) {
        const std::string name = trim(options.names[c]);
        if (name.empty()) {
          throw InputError(errc::option_invalid,
                           path + ": " + options.names_option + ": name " + std::to_string(c + 1) +
                               " is empty; expected a name for column " + std::to_string(c + 1),
                           {.file = path, .option = options.names_option});
        }
        names[c] = name;
      }
      std::set<std::string> seen;
      for (std::size_t c = 0; c < names.size(); ++c) {
        const bool given = c < options.names.size();
        if (names[c].empty()) {
          throw InputError(errc::data_format,
                           at_line(path, line_no) + ", column " + std::to_string(c + 1) +
                               ": empty name in the header row (expected a column name)",
                           {.file = path, .row = line_no});
        }
        if (!seen.insert(names[c]).second) {
          throw InputError(
              errc::data_column_duplicate,
              given ? path + ": " + options.names_option + ": '" + names[c] + "' names two columns (column " +
                          std::to_string(c + 1) + " and an earlier one); expected distinct names"
                    : at_line(path, line_no) + ", column " + std::to_string(c + 1) + ": duplicate column name '" +
                          names[c] + "' in the " + (headerless ? "column names" : "header row"),
              given ? ErrorFields{.file = path, .column = names[c], .option = options.names_option}
                    : ErrorFields{.file = path, .row = line_no, .column = names[c]});
        }
      }
      values.resize(names.size());
      if (headerless && parse_row()) keep_row();
      else if (headerless) ++dropped;
      continue;
    }
    if (cells.size() != names.size()) {
      throw InputError(errc::data_format,
                       at_line(path, line_no) + ": " + std::to_string(cells.size()) + " cells; expected " +
                           std::to_string(names.size()) + (data.header_row ? " like the header row" : " like the first row") +
                           " (separator " + delimiter_name(delimiter) + ")",
                       {.file = path, .row = line_no});
    }
    if (parse_row()) keep_row();
    else ++dropped;
  }
  if (in.bad()) throw InputError(errc::data_file_unreadable, path + ": read error", {.file = path});
  if (!have_first_row) {
    throw InputError(errc::data_format, path + ": empty file; expected a header row and data rows", {.file = path});
  }
  if (data.lines.empty()) {
    throw InputError(errc::data_format,
                     path + ": no data rows after the header" +
                         (dropped ? " (all " + std::to_string(dropped) + " rows had invalid cells)" : ""),
                     {.file = path});
  }
  for (std::size_t c = 0; c < names.size(); ++c) {
    data.add_column(names[c], Eigen::Map<const Eigen::VectorXd>(values[c].data(), static_cast<Eigen::Index>(values[c].size())));
  }
  data.sha256 = sha256_hex(bytes);
  return data;
}

}  // namespace frictionlab

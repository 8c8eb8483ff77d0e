#include "finite_output.hpp"

#include <cctype>
#include <string>
#include <utility>

#include "frictionlab/error.hpp"
#include "frictionlab/identify/finite_result.hpp"

namespace frictionlab::cli {
namespace {

bool separator(char c) {
  return std::isspace(static_cast<unsigned char>(c)) || std::string_view(",;=:()[]{}|<>\"").find(c) != std::string_view::npos;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A word as printf and to_chars write a non-finite double: [+-](inf|infinity|nan|nan(chars)).
bool non_finite(std::string_view word) {
  std::string w = lower(word);
  if (!w.empty() && (w[0] == '-' || w[0] == '+')) w.erase(0, 1);
  if (w == "inf" || w == "infinity" || w == "nan") return true;
  return w.size() > 4 && w.compare(0, 4, "nan(") == 0 && w.back() == ')';
}

}  // namespace

std::string non_finite_word(std::string_view text) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size();) {
    if (separator(text[i])) {
      if (text[i] == '\n') ++line;
      ++i;
      continue;
    }
    std::size_t end = i;
    // nan(...) keeps its parentheses: printf may write the payload.
    while (end < text.size() && !separator(text[end])) ++end;
    if (end < text.size() && text[end] == '(' && lower(text.substr(i, end - i)).find("nan") != std::string::npos) {
      const std::size_t close = text.find(')', end);
      if (close != std::string_view::npos && text.substr(end, close - end).find('\n') == std::string_view::npos) end = close + 1;
    }
    const std::string_view word = text.substr(i, end - i);
    if (non_finite(word)) {
      std::string out = "'";  // appended piece by piece: GCC 12 warns (-Wrestrict) on "'" + std::string
      out.append(word);
      out += "' at line ";
      out += std::to_string(line);
      return out;
    }
    i = end;
  }
  return "";
}

Result finite_or_error(Result r, std::string_view text) {
  r = frictionlab::finite_or_error(std::move(r));
  if (!r.ok()) return r;
  const std::string word = non_finite_word(text);
  if (word.empty()) return r;
  r.status = ResultStatus::error;
  r.code = errc::output_not_finite;
  r.message = (r.data_file.empty() ? std::string() : r.data_file + ": ") + r.method + ": the summary's figure " + word +
              " is not a finite number (values or scales beyond what double precision holds); the data cannot "
              "give an answer";
  return r;
}

void require_finite_output(std::string_view text, const std::string& output) {
  const std::string word = non_finite_word(text);
  if (word.empty()) return;
  const std::string name = output.empty() || output == "-" ? "standard output" : output;
  throw InputError(errc::output_not_finite,
                   name + ": the numbers to write hold " + word +
                       ", which is not a finite number (values or scales beyond what double precision holds); "
                       "nothing written",
                   {.file = output, .value = word});
}

}  // namespace frictionlab::cli

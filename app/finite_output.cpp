#include "finite_output.hpp"

#include <string>
#include <utility>

#include "frictionlab/error.hpp"
#include "frictionlab/identify/finite_result.hpp"

namespace frictionlab::cli {

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

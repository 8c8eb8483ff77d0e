#pragma once
// The command line's words for what the library's results name by their parameters: the
// library speaks of its options and inputs ("raise substeps", "the drive gain"), the command
// line adds the flag that sets them. Messages of exceptions need no table: the readers take the
// name to use from their caller (CsvOptions::names_option, apply_scales' option,
// ResampleOptions::dt_name, select_column's role), which data_options.cpp gives as flags.

#include <string>
#include <utility>

#include "frictionlab/identify/result.hpp"

namespace frictionlab::cli {

/// `text` with each library phrase of the table followed by, or turned into, its flag.
inline std::string with_flags(std::string text) {
  static const std::pair<const char*, const char*> kPhrases[] = {
      {"or the drive gain;", "or the drive gain (--gain);"},  // identify_idim: a force that is zero throughout
      {"raise substeps or", "raise --substeps or"},           // identify_lugre: a start beyond the step's reach
  };
  for (const auto& [library, cli] : kPhrases)
    for (std::size_t at = text.find(library); at != std::string::npos; at = text.find(library, at + 1))
      text.replace(at, std::string(library).size(), cli);
  return text;
}

/// A result's message and warnings in the command line's words (with_flags).
inline void name_flags(Result& r) {
  r.message = with_flags(std::move(r.message));
  for (auto& w : r.diagnostics.warnings) w = with_flags(std::move(w));
}

}  // namespace frictionlab::cli

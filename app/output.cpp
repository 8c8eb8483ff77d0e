#include "output.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "frictionlab/io/atomic_write.hpp"

namespace frictionlab::cli {

void add_output_options(CLI::App* cmd, OutputOptions& o) {
  cmd->add_option("--json", o.json, "Write the result as JSON to FILE, or to stdout with '-'")->group("Output");
  cmd->add_flag("--overwrite", o.overwrite, "Replace existing output files")->group("Output");
}

void check_output_path(const std::string& path, bool overwrite, const std::string& option) {
  if (path.empty() || path == "-" || overwrite) return;
  if (std::filesystem::exists(path))
    throw std::invalid_argument(path + " exists (" + option + "); pass --overwrite to replace it");
}

std::string result_text(const Result& r) {
  std::ostringstream s;
  s << "frictionlab identify " << r.method;
  if (!r.data_file.empty()) s << ": " << r.data_file;
  s << "\n";
  if (!r.ok()) {
    s << "error: " << r.message << "\n";
    return s.str();
  }
  s << "model " << r.model << ", " << r.fit.samples << " samples\n";
  std::size_t w = 6;
  for (const auto& p : r.parameters) w = std::max(w, p.name.size());
  for (const auto& p : r.parameters) {
    s << "  " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::right << std::setw(12)
      << std::setprecision(6) << p.value << "  +- " << std::left << std::setw(10) << std::setprecision(3) << p.std << " "
      << p.unit << "\n";
  }
  s << std::setprecision(4) << "fit: relative error " << r.fit.relative_error_percent << " %, rmse " << r.fit.rmse << "\n";
  if (r.validation)
    s << "cross-test " << r.validation->file << ": relative error " << r.validation->relative_error_percent << " %, rmse "
      << r.validation->rmse << "\n";
  if (std::isfinite(r.diagnostics.condition_number)) s << "condition number " << r.diagnostics.condition_number << "\n";
  for (const auto& [name, group] : r.diagnostics.groups) {
    s << name << ":";
    for (const auto& [k, v] : group) s << " " << k << " = " << std::setprecision(6) << v;
    s << "\n";
  }
  for (const auto& w2 : r.diagnostics.warnings) s << "warning: " << w2 << "\n";
  return s.str();
}

int emit(const Result& r, const OutputOptions& o) {
  // Text goes to stderr when stdout carries the JSON, and always when the data gave no answer.
  std::ostream& text = (o.json == "-" || !r.ok()) ? std::cerr : std::cout;
  text << result_text(r);
  if (o.json == "-") {
    std::cout << to_json(r, -1) << "\n";
  } else if (!o.json.empty()) {
    AtomicWriteOptions w;
    w.overwrite = o.overwrite;
    write_file_atomic(o.json, to_json(r) + "\n", w);
  }
  return r.ok() ? 0 : 2;
}

}  // namespace frictionlab::cli

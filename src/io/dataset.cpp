#include "frictionlab/io/dataset.hpp"
#include "frictionlab/error.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace frictionlab {

void Dataset::add_column(const std::string& name, Eigen::VectorXd values) {
  const auto it = std::find(names_.begin(), names_.end(), name);
  const bool replaces_only = it != names_.end() && names_.size() == 1;
  if (!names_.empty() && !replaces_only && values.size() != rows()) {
    std::ostringstream msg;
    msg << where() << "column '" << name << "' has " << values.size() << " samples; expected " << rows()
        << " like the other columns";
    throw InputError(errc::data_column_length, msg.str(), {.file = file, .column = name});
  }
  if (it != names_.end()) {
    columns_[static_cast<std::size_t>(it - names_.begin())] = std::move(values);
  } else {
    names_.push_back(name);
    columns_.push_back(std::move(values));
  }
}

Eigen::Index Dataset::rows() const { return columns_.empty() ? 0 : columns_.front().size(); }

bool Dataset::has_column(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

const Eigen::VectorXd& Dataset::column(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw InputError(errc::data_column_missing, missing_column_message(name), {.file = file, .column = name});
  return columns_[static_cast<std::size_t>(it - names_.begin())];
}

Eigen::VectorXd& Dataset::column(const std::string& name) {
  return const_cast<Eigen::VectorXd&>(static_cast<const Dataset&>(*this).column(name));
}

std::string Dataset::where() const { return file.empty() ? std::string() : file + ": "; }

std::string Dataset::row_label(Eigen::Index k) const {
  if (resampling) return "sample " + std::to_string(k + 1) + " of the resampled grid";
  if (k >= 0 && static_cast<std::size_t>(k) < lines.size()) {
    return "line " + std::to_string(lines[static_cast<std::size_t>(k)]);
  }
  return "sample " + std::to_string(k + 1);
}

std::string Dataset::describe_contents() const {
  std::string out;
  for (std::size_t i = 0; i < names_.size(); ++i) out += (i ? ", " : "") + names_[i];
  if (names_.empty()) out = "(none)";
  if (!scalars.empty()) {
    out += " (scalars: ";
    bool first = true;
    for (const auto& [name, value] : scalars) {
      out += (first ? "" : ", ") + name;
      first = false;
    }
    out += ")";
  }
  if (!header_row) out += " (the file has no header row: its columns are c1, c2, ... from the first, unless named with " + names_option + ")";
  if (!unusable.empty()) {
    out += "; not columns:";
    bool first = true;
    for (const auto& [name, what] : unusable) {
      out += std::string(first ? " " : ", ") + name + " (" + what + ")";
      first = false;
    }
  }
  return out;
}

std::string Dataset::missing_column_message(const std::string& name, const std::string& role) const {
  const std::string named = "'" + name + "'" + (role.empty() ? "" : " (" + role + ")");
  std::string what;
  if (const auto it = unusable.find(name); it != unusable.end()) what = it->second;
  else if (has_scalar(name)) what = "a scalar (1x1)";
  if (what.empty()) return where() + "no column " + named + "; the file has columns: " + describe_contents();
  return where() + "variable " + named + " is " + what + "; expected a real numeric vector (1xN or Nx1) of " +
         std::to_string(rows()) + " samples like the columns: " + describe_contents();
}

}  // namespace frictionlab

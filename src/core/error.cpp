#include "frictionlab/error.hpp"

#include <cstdio>



namespace frictionlab {

std::vector<std::pair<std::string, std::string>> ErrorFields::items() const {
  std::vector<std::pair<std::string, std::string>> out;
  const auto add = [&](const char* name, const std::string& v) {
    if (!v.empty()) out.emplace_back(name, v);
  };
  add("file", file);
  if (row) out.emplace_back("row", std::to_string(*row));
  add("column", column);
  add("key", key);
  add("option", option);
  add("value", value);
  add("other_file", other_file);
  add("other_option", other_option);
  return out;
}

InputError::InputError(std::string code, const std::string& message, ErrorFields fields)
    : std::invalid_argument(message), code_(std::move(code)), fields_(std::move(fields)) {}

InternalError::InternalError(std::string code, const std::string& message, ErrorFields fields)
    : std::runtime_error(message), code_(std::move(code)), fields_(std::move(fields)) {}

std::string error_code(const std::exception& e) noexcept {
  try {
    if (const auto* in = dynamic_cast<const InputError*>(&e)) return in->code();
    if (const auto* internal = dynamic_cast<const InternalError*>(&e)) return internal->code();
    if (dynamic_cast<const std::invalid_argument*>(&e)) return errc::input_invalid;
    return errc::internal;
  } catch (...) {
    return {};
  }
}

ErrorFields error_fields(const std::exception& e) noexcept {
  try {
    if (const auto* in = dynamic_cast<const InputError*>(&e)) return in->fields();
    if (const auto* internal = dynamic_cast<const InternalError*>(&e)) return internal->fields();
  } catch (...) {
  }
  return {};
}

void rethrow_with_option(const std::invalid_argument& e, const std::string& prefix, const std::string& option) {
  ErrorFields f = error_fields(e);
  if (f.option.empty()) f.option = option;
  throw InputError(error_code(e), prefix + e.what(), std::move(f));
}

}  // namespace frictionlab

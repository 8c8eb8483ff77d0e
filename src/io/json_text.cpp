#include "frictionlab/io/json_text.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace frictionlab {

std::string valid_utf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  const auto* b = reinterpret_cast<const unsigned char*>(s.data());
  const std::size_t n = s.size();
  std::size_t i = 0;
  while (i < n) {
    const unsigned char c = b[i];
    std::size_t len = 0;
    if (c < 0x80) len = 1;
    else if (c >= 0xC2 && c <= 0xDF) len = 2;
    else if (c >= 0xE0 && c <= 0xEF) len = 3;
    else if (c >= 0xF0 && c <= 0xF4) len = 4;
    bool ok = len > 0 && i + len <= n;
    for (std::size_t k = 1; ok && k < len; ++k) ok = (b[i + k] & 0xC0) == 0x80;
    if (ok && len == 3) {
      // No overlong forms, no UTF-16 surrogates.
      ok = !(c == 0xE0 && b[i + 1] < 0xA0) && !(c == 0xED && b[i + 1] >= 0xA0);
    } else if (ok && len == 4) {
      ok = !(c == 0xF0 && b[i + 1] < 0x90) && !(c == 0xF4 && b[i + 1] >= 0x90);
    }
    if (!ok) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
      ++i;
      continue;
    }
    out.append(s.data() + i, len);
    i += len;
  }
  return out;
}

namespace {

template <class Json>
void make_valid(Json& j) {
  if (j.is_string()) {
    auto& s = j.template get_ref<std::string&>();
    std::string fixed = valid_utf8(s);
    if (fixed != s) s = std::move(fixed);
  } else if (j.is_array()) {
    for (auto& v : j) make_valid(v);
  } else if (j.is_object()) {
    bool bad_key = false;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (valid_utf8(it.key()) != it.key()) bad_key = true;
      make_valid(it.value());
    }
    if (bad_key) {
      Json fixed = Json::object();
      for (auto it = j.begin(); it != j.end(); ++it) fixed[valid_utf8(it.key())] = std::move(it.value());
      j = std::move(fixed);
    }
  }
}

template <class Json>
std::string dump_valid(const Json& j, int indent) {
  try {
    return j.dump(indent);
  } catch (const nlohmann::json::type_error&) {
    // A string that is not UTF-8 (a CSV header, a MAT variable name, a file name): escape its
    // stray bytes as \xNN text and dump the copy.
    Json copy = j;
    make_valid(copy);
    return copy.dump(indent);
  }
}

}  // namespace

std::string json_text(const nlohmann::json& j, int indent) { return dump_valid(j, indent); }
std::string json_text(const nlohmann::ordered_json& j, int indent) { return dump_valid(j, indent); }

}  // namespace frictionlab

#pragma once
// JSON text that is always valid: every JSON output of frictionlab is dumped here, so a string
// that is not UTF-8 (a CSV header, a MAT variable name, a file name) never makes the output fail.

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// `s` with every byte that is not part of a well-formed UTF-8 sequence written as the four
/// characters \xNN (hex); valid text is returned unchanged.
std::string valid_utf8(std::string_view s);

/// j.dump(indent), with strings and keys that are not UTF-8 escaped by valid_utf8 (nlohmann
/// refuses them with type_error 316). Never throws for bad bytes.
std::string json_text(const nlohmann::json& j, int indent = -1);
/// The same for ordered JSON (shards, map runs, batches).
std::string json_text(const nlohmann::ordered_json& j, int indent = -1);

}  // namespace frictionlab

#pragma once
// SHA-256 digests (FIPS 180-4), recorded in results so a result names the exact data it came from.
// Computed by OpenSSL's libcrypto (Debian libssl-dev): about ten times faster than a portable
// hand-written loop, which mattered because hashing dominated reading a data file. Tested
// against the FIPS examples and the EMPS README digests.

#include <string>
#include <string_view>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Lowercase hex SHA-256 (64 characters) of the given bytes.
std::string sha256_hex(std::string_view bytes);

/// Lowercase hex SHA-256 of a file's bytes, read in binary in blocks.
/// \throws std::invalid_argument naming the file when it cannot be opened or read;
///         std::runtime_error if OpenSSL fails.
std::string sha256_file(const std::string& path);

}  // namespace frictionlab

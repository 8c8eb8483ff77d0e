#pragma once
// Writes a file so that a failed run never leaves a half-written one: the content goes to a
// temporary file in the same directory, which is then renamed over the target.

#include <string>
#include <string_view>

namespace frictionlab {

/// Options of write_file_atomic.
struct AtomicWriteOptions {
  /// Replace an existing file. Default false: an existing file is an error (CLI: --overwrite).
  bool overwrite = false;
};

/// Writes `content` to `path` via "PATH.tmp-XXXXXX" in the same directory, flushed, then renamed.
/// On any failure the temporary is removed and the target is untouched.
/// \throws std::invalid_argument "PATH exists; pass --overwrite to replace it" when the file exists
///         and overwrite is false; std::runtime_error naming the file on an I/O failure (missing
///         directory, no permission, disk full).
void write_file_atomic(const std::string& path, std::string_view content, const AtomicWriteOptions& options = {});

}  // namespace frictionlab

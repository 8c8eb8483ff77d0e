#pragma once
// Writes an output file so that a failed run never leaves a half-written one, and never replaces
// what is not a regular file. The one place where frictionlab decides how an output path is
// written:
//   - a new file, or an existing regular file (with overwrite): the content goes to an unnamed
//     temporary file in the same directory (O_TMPFILE: a crash, even SIGKILL, leaves nothing
//     behind), which is then linked into place (a new file) or linked under a temporary name and
//     renamed over the target at once; where the file system has no O_TMPFILE, a named temporary
//     "PATH.tmp-XXXXXX" is written and renamed. A symbolic link is followed: its target is
//     replaced, the link stays; a dangling link is replaced by the file only with overwrite;
//   - a character device or a FIFO (/dev/null, a terminal, a named pipe), and any path under
//     /dev (but /dev/shm) or /proc (/dev/stdout, /proc/self/fd/1): opened and written in place,
//     as `cat > PATH` would, never renamed over, with or without overwrite (a regular file
//     reached that way is one of the process's own descriptors: it is appended to);
//   - a directory, a block device, a socket: refused.

#include <string>
#include <string_view>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of write_file_atomic.
struct AtomicWriteOptions {
  /// Replace an existing regular file. Default false: an existing regular file is an error
  /// (CLI: --overwrite). Devices and FIFOs are written through without it.
  bool overwrite = false;
};

/// How write_file_atomic will write a path.
enum class OutputKind {
  create,         ///< no such file yet: temporary file, then rename
  replace,        ///< an existing regular file (overwrite given): temporary file, then rename
  write_through,  ///< a device, a FIFO or a path under /dev or /proc: opened and written in place
};

/// Checks, without writing anything, that `path` can take an output, and says how it will be
/// written. Used before any work so that a run fails before its first output is written.
/// \throws InputError (an std::invalid_argument; frictionlab/error.hpp) with code output.exists:
///         "PATH exists; pass --overwrite to replace it" (a regular file, overwrite false), "PATH
///         is a symbolic link to a missing file; pass --overwrite to replace the link"; code
///         output.not_writable: "PATH is a directory; expected a file name", "PATH: directory D
///         does not exist", "PATH is a block device / socket ...", "PATH: no such file under /dev
///         or /proc (frictionlab creates no files there)".
OutputKind check_output_path(const std::string& path, bool overwrite);

/// Writes `content` to `path` as check_output_path says: via "PATH.tmp-XXXXXX" in the target's
/// directory, flushed, then renamed (on any failure the temporary is removed and the target is
/// untouched); or written through for a device or FIFO.
/// \throws InputError as check_output_path; InternalError (a std::runtime_error, code
///         output.write_failed) or std::runtime_error naming the file on an I/O failure (no
///         permission, disk full, a FIFO whose reader went away).
void write_file_atomic(const std::string& path, std::string_view content, const AtomicWriteOptions& options = {});

}  // namespace frictionlab

#include "io/atomic_write.hpp"

#include "frictionlab/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <sys/stat.h>
#include <unistd.h>

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

// /dev and /proc hold devices and this process's descriptors (/dev/stdout, /proc/self/fd/1):
// nothing there is ever renamed over or created.
// (/dev/shm is a plain file system for shared memory: its files follow the usual rules.)
bool system_path(const std::string& path) {
  const std::string p = fs::path(path).lexically_normal().string();
  return (p.rfind("/dev/", 0) == 0 && p.rfind("/dev/shm/", 0) != 0) || p.rfind("/proc/", 0) == 0;
}

struct Target {
  OutputKind kind;
  std::string path;  // where the rename goes (the symbolic link's target), or the path to open
};

// Classifies `path`. Missing parent directories are reported only when `parent_check` (the
// early check); write_file_atomic lets mkstemp report them as an I/O failure.
Target classify(const std::string& path, bool overwrite, bool parent_check) {
  if (path.empty()) throw InputError(errc::output_not_writable, "output file name is empty");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows symbolic links
  const fs::file_type type = st.type();
  if (type == fs::file_type::not_found || type == fs::file_type::none) {
    if (system_path(path))
      throw InputError(errc::output_not_writable, path + ": no such file under /dev or /proc (frictionlab creates no files there)",
                       {.file = path});
    if (parent_check) {
      const fs::path parent = fs::path(path).parent_path();
      if (!parent.empty() && !fs::is_directory(parent, ec))
        throw InputError(errc::output_not_writable, path + ": directory " + parent.string() + " does not exist", {.file = path});
    }
    // A dangling symbolic link: the new file replaces the link (its target directory may not
    // exist), only with overwrite.
    if (!overwrite && fs::is_symlink(fs::symlink_status(path, ec)))
      throw InputError(errc::output_exists, path + " is a symbolic link to a missing file; pass --overwrite to replace the link",
                       {.file = path});
    return {OutputKind::create, path};
  }
  switch (type) {
    case fs::file_type::directory:
      throw InputError(errc::output_not_writable, path + " is a directory; expected a file name", {.file = path});
    case fs::file_type::character:
    case fs::file_type::fifo:
      return {OutputKind::write_through, path};
    case fs::file_type::regular: {
      if (system_path(path)) return {OutputKind::write_through, path};
      if (!overwrite) throw InputError(errc::output_exists, path + " exists; pass --overwrite to replace it", {.file = path});
      // Replace the file a symbolic link points to, not the link.
      std::string target = path;
      if (fs::is_symlink(fs::symlink_status(path, ec))) {
        const fs::path resolved = fs::canonical(path, ec);
        if (!ec) target = resolved.string();
      }
      return {OutputKind::replace, target};
    }
    case fs::file_type::block:
      throw InputError(errc::output_not_writable, path + " is a block device; expected a regular file, a character device or a FIFO",
                       {.file = path});
    case fs::file_type::socket:
      throw InputError(errc::output_not_writable, path + " is a socket; expected a regular file, a character device or a FIFO",
                       {.file = path});
    default:
      throw InputError(errc::output_not_writable, path + " is not a regular file, a character device or a FIFO", {.file = path});
  }
}

// `cat > PATH`: open the existing device or FIFO and write it all. A regular file reached
// through /dev or /proc is one of this process's descriptors (--json /dev/stdout > out.txt): it
// is appended to, after what was already written there (the text table), never truncated.
void write_through(const std::string& path, std::string_view content) {
  std::error_code ec;
  const bool regular = fs::is_regular_file(path, ec);
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | (regular ? O_APPEND : 0));
  if (fd < 0) throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = errno;
      ::close(fd);
      throw std::runtime_error(path + ": write failed: " + std::strerror(err));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 && errno != EINTR) throw std::runtime_error(path + ": write failed on close: " + std::strerror(errno));
}

}  // namespace

OutputKind check_output_path(const std::string& path, bool overwrite) { return classify(path, overwrite, true).kind; }

void write_file_atomic(const std::string& path, std::string_view content, const AtomicWriteOptions& options) {
  const Target target = classify(path, options.overwrite, false);
  if (target.kind == OutputKind::write_through) {
    write_through(target.path, content);
    return;
  }
  // The content goes first to an unnamed file (O_TMPFILE) in the target's directory, which a
  // crash (even SIGKILL) cannot leave behind; it is given a name only when complete. File
  // systems without O_TMPFILE get a named temporary "PATH.tmp-XXXXXX" (mkstemp) instead.
  const std::string dir = [&] {
    const fs::path parent = fs::path(target.path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
  }();
  const mode_t mask = ::umask(0);
  ::umask(mask);
  std::string tmpl;  // the named temporary, when there is one
  int fd = -1;
#ifdef O_TMPFILE
  fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666 & ~mask);
#endif
  const bool unnamed = fd >= 0;
  if (!unnamed) {
    // mkstemp gives a unique temporary in the target's directory, so the rename stays on one
    // file system and is atomic.
    tmpl = target.path + ".tmp-XXXXXX";
    fd = ::mkstemp(tmpl.data());
    if (fd < 0) {
      throw InternalError(errc::output_write_failed,
                          path + ": cannot create a temporary file next to it (does the directory exist "
                                 "and is it writable?)",
                          {.file = path});
    }
  }
  const auto remove_temp = [&] {
    if (!tmpl.empty()) std::remove(tmpl.c_str());
  };
  const auto fail = [&](const std::string& what) {
    ::close(fd);
    remove_temp();
    throw InternalError(errc::output_write_failed, path + ": " + what, {.file = path});
  };
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed (disk full?)");
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot flush the temporary file");
  // mkstemp creates the file 0600; give it the usual permissions (umask applies).
  if (!unnamed) ::fchmod(fd, 0666 & ~mask);
  // The path may have changed while the content was written: check again just before renaming
  // (a file that appeared without overwrite, a directory or a device put in its place).
  try {
    const Target now = classify(path, options.overwrite, false);
    if (now.kind == OutputKind::write_through)
      throw InputError(errc::output_not_writable, path + " became a device or FIFO while writing", {.file = path});
  } catch (...) {
    ::close(fd);
    remove_temp();
    throw;
  }
  if (unnamed) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (target.kind == OutputKind::create) {
      // A new file: linked straight into place (EEXIST if one appeared meanwhile: never replaced).
      if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, target.path.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        if (::close(fd) != 0) throw InternalError(errc::output_write_failed, path + ": cannot close the file", {.file = path});
        return;
      }
      if (errno == EEXIST && !options.overwrite) {
        ::close(fd);
        throw InputError(errc::output_exists, path + " exists; pass --overwrite to replace it", {.file = path});
      }
    }
    // Replacing a file: linked under a temporary name, renamed over the target at once.
    for (int attempt = 0; attempt < 100; ++attempt) {
      tmpl = target.path + ".tmp-XXXXXX";
      static const char kChars[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
      for (std::size_t k = tmpl.size() - 6; k < tmpl.size(); ++k)
        tmpl[k] = kChars[static_cast<std::size_t>(std::rand()) % (sizeof kChars - 1)];
      if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmpl.c_str(), AT_SYMLINK_FOLLOW) == 0) break;
      const int err = errno;
      tmpl.clear();
      if (err != EEXIST) {
        ::close(fd);
        throw InternalError(errc::output_write_failed,
                            path + ": cannot give the temporary file a name next to it: " + std::strerror(err), {.file = path});
      }
    }
    if (tmpl.empty()) fail("cannot find a free temporary name next to it");
  }
  if (::close(fd) != 0) {
    remove_temp();
    throw InternalError(errc::output_write_failed, path + ": cannot close the temporary file", {.file = path});
  }
  if (std::rename(tmpl.c_str(), target.path.c_str()) != 0) {
    const int err = errno;
    remove_temp();
    throw InternalError(errc::output_write_failed,
                        path + ": cannot rename the temporary file into place: " + std::strerror(err), {.file = path});
  }
}

}  // namespace frictionlab

#include "frictionlab/io/atomic_write.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <sys/stat.h>
#include <unistd.h>

namespace frictionlab {

void write_file_atomic(const std::string& path, std::string_view content, const AtomicWriteOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!options.overwrite && fs::exists(path, ec)) {
    throw std::invalid_argument(path + " exists; pass --overwrite to replace it");
  }
  // mkstemp gives a unique temporary in the target's directory, so the rename stays on one
  // file system and is atomic.
  std::string tmpl = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) {
    throw std::runtime_error(path + ": cannot create a temporary file next to it (does the directory exist "
                                    "and is it writable?)");
  }
  const auto fail = [&](const std::string& what) {
    ::close(fd);
    std::remove(tmpl.c_str());
    throw std::runtime_error(path + ": " + what);
  };
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n <= 0) fail("write failed (disk full?)");
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot flush the temporary file");
  // mkstemp creates the file 0600; give it the usual permissions (umask applies).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::close(fd) != 0) {
    std::remove(tmpl.c_str());
    throw std::runtime_error(path + ": cannot close the temporary file");
  }
  if (!options.overwrite && fs::exists(path, ec)) {
    std::remove(tmpl.c_str());
    throw std::invalid_argument(path + " exists; pass --overwrite to replace it");
  }
  if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
    std::remove(tmpl.c_str());
    throw std::runtime_error(path + ": cannot rename the temporary file into place");
  }
}

}  // namespace frictionlab

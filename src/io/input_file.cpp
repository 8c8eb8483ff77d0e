#include "io/input_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "frictionlab/budget.hpp"
#include "frictionlab/cancellation.hpp"
#include "frictionlab/error.hpp"

namespace frictionlab {
namespace {

// Closes a descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void too_large(const std::string& path, const std::string& what, double bytes, bool stream) {
  check_memory(4.0 * bytes,
               path + ": the " + what + " (" + format_bytes(bytes) + (stream ? " read from a pipe so far" : "") +
                   ") and the numbers read from it",
               {.file = path});
  throw InputError(errc::budget_memory, path + ": the " + what + " is larger than the memory budget", {.file = path});
}

}  // namespace

double input_byte_limit() { return 0.25 * memory_budget(); }

void check_input_file(const std::string& path, const std::string& what, const char* code) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw InputError(code, path + ": cannot open the " + what + " (" + std::strerror(errno) + ")", {.file = path});
  }
  const char* kind = S_ISDIR(st.st_mode)   ? "a directory"
                     : S_ISCHR(st.st_mode) ? "a character device"
                     : S_ISBLK(st.st_mode) ? "a block device"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                                            : nullptr;
  if (kind != nullptr) {
    throw InputError(code, path + " is " + kind + "; expected the " + what + " as a regular file or a pipe", {.file = path});
  }
}

int open_input_file(const std::string& path, const std::string& what, const char* code) {
  check_input_file(path, what, code);
  // Non-blocking, so that opening a FIFO does not wait for its writer inside open(), where no
  // cancellation reaches (read_input_block waits in poll() instead).
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw InputError(code, path + ": cannot open the " + what + " (" + std::strerror(errno) + ")", {.file = path});
  return fd;
}

std::size_t read_input_block(int fd, char* buf, std::size_t size, const std::string& path, const std::string& what,
                             const char* code) {
  const auto fail = [&] {
    throw InputError(code, path + ": read error in the " + what + " (" + std::strerror(errno) + ")", {.file = path});
  };
  for (;;) {
    // Wait until there is something to read (bytes, or the writer's end) in slices, polling the
    // cancellation token between them. A read first would not do: a FIFO opened without
    // blocking reads as empty until its first writer comes, while poll() waits for it (Linux
    // reports no hang-up on a FIFO that never had a writer). A regular file is always ready.
    for (;;) {
      throw_if_cancelled();
      pollfd p{fd, POLLIN, 0};
      const int ready = ::poll(&p, 1, kInputPollMilliseconds);
      if (ready > 0) break;
      if (ready < 0 && errno != EINTR) fail();
    }
    const ssize_t got = ::read(fd, buf, size);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK) fail();
  }
}

std::string read_input_file(const std::string& path, const std::string& what, const char* code) {
  const Fd f{open_input_file(path, what, code)};
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw InputError(code, path + ": cannot read the " + what, {.file = path});
  const bool regular = S_ISREG(st.st_mode);
  const double limit = input_byte_limit();
  if (regular && static_cast<double>(st.st_size) > limit) too_large(path, what, static_cast<double>(st.st_size), false);
  std::string bytes;
  if (regular) bytes.reserve(static_cast<std::size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const std::size_t got = read_input_block(f.fd, buf, sizeof buf, path, what, code);
    if (got == 0) break;
    if (static_cast<double>(bytes.size()) + static_cast<double>(got) > limit)
      too_large(path, what, static_cast<double>(bytes.size()) + static_cast<double>(got), !regular);
    bytes.append(buf, got);
  }
  return bytes;
}

}  // namespace frictionlab

#include "io/sha256.hpp"
#include "io/input_file.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/cancellation.hpp"
#include "frictionlab/error.hpp"

#include <openssl/evp.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

namespace frictionlab {
namespace {

// An OpenSSL digest context for SHA-256, freed on scope exit.
class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("sha256: OpenSSL could not start a SHA-256 digest");
  }
  void update(const void* data, std::size_t n) {
    if (EVP_DigestUpdate(ctx_.get(), data, n) != 1) throw std::runtime_error("sha256: OpenSSL digest update failed");
  }
  std::string hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(ctx_.get(), digest, &length) != 1) throw std::runtime_error("sha256: OpenSSL digest failed");
    std::string out;
    out.reserve(2 * length);
    char byte[3];
    for (unsigned int i = 0; i < length; ++i) {
      std::snprintf(byte, sizeof byte, "%02x", digest[i]);
      out += byte;
    }
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
};

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  Sha256 s;
  s.update(bytes.data(), bytes.size());
  return s.hex();
}

std::string sha256_file(const std::string& path) {
  // A device (/dev/zero) would be read without end: refused; a FIFO is read as a stream, counted
  // against the work budget one unit per byte.
  // Read as read_input_file reads (input_file.hpp): a FIFO's open does not block, and its wait
  // for a writer, like every block, stops at a cancellation.
  const char* what = "file to hash";
  struct Fd {
    int fd;
    ~Fd() { ::close(fd); }
  } const f{open_input_file(path, what, errc::data_file_unreadable)};
  const int fd = f.fd;
  Sha256 s;
  double read = 0;
  std::vector<char> buf(1 << 16);
  for (;;) {
    const std::size_t got = read_input_block(fd, buf.data(), buf.size(), path, what, errc::data_file_unreadable);
    if (got == 0) break;
    s.update(buf.data(), got);
    read += static_cast<double>(got);
    if (read > work_budget()) check_work(read, "bytes read", path + ": hashing the file", {.file = path});
  }
  return s.hex();
}

}  // namespace frictionlab

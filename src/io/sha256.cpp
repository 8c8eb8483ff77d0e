#include "io/sha256.hpp"
#include "io/input_file.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/cancellation.hpp"
#include "frictionlab/error.hpp"

#include <openssl/evp.h>

#include <cstdio>
#include <fstream>
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
  check_input_file(path, "file to hash", errc::data_file_unreadable);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(errc::data_file_unreadable, path + ": cannot open the file to compute its sha256", {.file = path});
  Sha256 s;
  double read = 0;
  std::vector<char> buf(1 << 16);
  while (in) {
    throw_if_cancelled();
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const std::streamsize got = in.gcount();
    if (got > 0) s.update(buf.data(), static_cast<std::size_t>(got));
    read += static_cast<double>(got);
    if (read > work_budget()) check_work(read, "bytes read", path + ": hashing the file", {.file = path});
  }
  if (in.bad()) throw InputError(errc::data_file_unreadable, path + ": read error while computing its sha256", {.file = path});
  return s.hex();
}

}  // namespace frictionlab

#pragma once
// Support for the libFuzzer targets: the readers take a path, so each input is written to a file
// of a scratch directory of the process (made once, removed at exit). Included by exactly one
// source file of each target (it defines the target's ASan defaults).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

// A request larger than the memory returns NULL, as malloc does outside ASan, so the fuzzers see
// what the readers then do (matio gives up on the variable) instead of stopping at the request;
// requests over libFuzzer's -malloc_limit_mb (default 2 GB) that succeed are still reported.
extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1"; }

// HDF5 (under matio's v7.3 reader) keeps objects of some corrupt files open until the process
// exits, where it reports "infinite loop closing library" and LeakSanitizer finds its blocks; no
// single input reproduces it, and it is neither our code nor a crash, so its blocks are not
// reported as leaks.
extern "C" const char* __lsan_default_suppressions() { return "leak:libhdf5_serial.so\n"; }

namespace frictionlab::fuzz {

// The scratch directory of this process: $TMPDIR (or /tmp)/frictionlab-fuzz-XXXXXX, removed at
// exit. Each fuzzing process (libFuzzer -jobs/-workers) has its own.
inline const std::filesystem::path& scratch_dir() {
  struct Dir {
    std::filesystem::path path;
    Dir() {
      const char* tmp = std::getenv("TMPDIR");
      std::string templ = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/frictionlab-fuzz-XXXXXX";
      if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("fuzz: cannot create a scratch directory");
      path = templ;
    }
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

// Writes the input to `name` in the scratch directory (replacing the previous one) and returns
// its path.
inline std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = scratch_dir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
  return path.string();
}

}  // namespace frictionlab::fuzz

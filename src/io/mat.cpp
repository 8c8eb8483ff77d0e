#include "frictionlab/io/mat.hpp"

#include <matio.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/io/sha256.hpp"

namespace frictionlab {
namespace {

// matio reports problems through a log function that prints to stderr by default; messages
// are collected here instead, so the error we throw can quote them. (Thread-local: readers on
// different threads keep their own messages.)
thread_local std::string g_matio_log;
thread_local bool g_matio_error = false;  // an error or critical message since the last clear

void matio_log(int level, char* message) {
  if (level == MATIO_LOG_LEVEL_ERROR || level == MATIO_LOG_LEVEL_CRITICAL) g_matio_error = true;
  if (message != nullptr && g_matio_log.size() < 2000) {
    if (!g_matio_log.empty()) g_matio_log += "; ";
    g_matio_log += message;
  }
}

struct MatCloser {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using MatPtr = std::unique_ptr<mat_t, MatCloser>;
using VarPtr = std::unique_ptr<matvar_t, VarFreer>;

template <typename T>
Eigen::VectorXd convert(const void* data, std::size_t n) {
  const T* p = static_cast<const T*>(data);
  Eigen::VectorXd out(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) out(static_cast<Eigen::Index>(i)) = static_cast<double>(p[i]);
  return out;
}

// The values of a real numeric variable as doubles, or false when it is not one.
bool numeric_values(const matvar_t& v, Eigen::VectorXd& out) {
  if (v.isComplex || v.isLogical || v.data == nullptr || v.rank != 2) return false;
  const std::size_t n = v.dims[0] * v.dims[1];
  switch (v.class_type) {
    case MAT_C_DOUBLE: out = convert<double>(v.data, n); return true;
    case MAT_C_SINGLE: out = convert<float>(v.data, n); return true;
    case MAT_C_INT8: out = convert<std::int8_t>(v.data, n); return true;
    case MAT_C_UINT8: out = convert<std::uint8_t>(v.data, n); return true;
    case MAT_C_INT16: out = convert<std::int16_t>(v.data, n); return true;
    case MAT_C_UINT16: out = convert<std::uint16_t>(v.data, n); return true;
    case MAT_C_INT32: out = convert<std::int32_t>(v.data, n); return true;
    case MAT_C_UINT32: out = convert<std::uint32_t>(v.data, n); return true;
    case MAT_C_INT64: out = convert<std::int64_t>(v.data, n); return true;
    case MAT_C_UINT64: out = convert<std::uint64_t>(v.data, n); return true;
    default: return false;
  }
}

// matio (1.5.23) inflates a truncated compressed v5 variable without reporting it, so the
// element structure of a v5 file is walked first: 128-byte header, then data elements each with
// an 8-byte tag (type, byte count; small elements pack both into 8 bytes). An element reaching
// past the end of the file means the file is truncated. v7.3 (HDF5) files are left to HDF5.
std::string v5_structure_problem(const std::string& path) {
  // Only the header and the element tags are read (seeking past each element's data).
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "cannot be opened for reading";
  const std::size_t size = static_cast<std::size_t>(in.tellg());
  if (size < 128) return "shorter than the 128-byte MAT-file header";
  unsigned char header[128];
  in.seekg(0);
  in.read(reinterpret_cast<char*>(header), 128);
  const unsigned char* b = header;
  const bool big_endian_file = b[126] == 'M' && b[127] == 'I';
  const bool little_endian_file = b[126] == 'I' && b[127] == 'M';
  if (!big_endian_file && !little_endian_file) return "no MAT-file endian indicator";
  const auto u32 = [&](const unsigned char* p) {
    return little_endian_file ? std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                                    std::uint32_t(p[3]) << 24
                              : std::uint32_t(p[3]) | std::uint32_t(p[2]) << 8 | std::uint32_t(p[1]) << 16 |
                                    std::uint32_t(p[0]) << 24;
  };
  const std::uint32_t version = little_endian_file ? (std::uint32_t(b[125]) << 8 | b[124]) : (std::uint32_t(b[124]) << 8 | b[125]);
  if (version != 0x0100) return "";  // v7.3: HDF5 checks its own structure
  constexpr std::uint32_t kMiCompressed = 15;
  std::size_t at = 128;
  unsigned char tag[8];
  while (at < size) {
    if (at + 8 > size) return "truncated: a data element tag at byte " + std::to_string(at) + " is cut off";
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(tag), 8)) return "read error at byte " + std::to_string(at);
    const std::uint32_t type = u32(tag);
    if ((type >> 16) != 0) {  // small data element: 4 bytes of tag, up to 4 of data
      at += 8;
      continue;
    }
    const std::uint32_t bytes = u32(tag + 4);
    std::size_t n = bytes;
    if (type != kMiCompressed && n % 8 != 0) n += 8 - n % 8;
    if (at + 8 + bytes > size) {
      return "truncated: the data element at byte " + std::to_string(at) + " needs " + std::to_string(bytes) +
             " bytes but the file has " + std::to_string(size) + " in all";
    }
    at += 8 + n;
  }
  return "";
}

}  // namespace

Dataset read_mat(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw std::invalid_argument(path + ": no such MAT file (or not a regular file)");
  }
  // Hash first: it also proves the file is readable.
  Dataset data;
  data.file = path;
  data.sha256 = sha256_file(path);

  Mat_LogInitFunc("frictionlab", &matio_log);
  g_matio_log.clear();
  const auto fail = [&](const std::string& what) {
    std::string msg = path + ": " + what;
    if (!g_matio_log.empty()) msg += " (matio: " + g_matio_log + ")";
    g_matio_log.clear();
    throw std::invalid_argument(msg);
  };

  if (const std::string problem = v5_structure_problem(path); !problem.empty()) {
    fail("not a valid MATLAB MAT file: " + problem);
  }
  MatPtr mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!mat) fail("not a MATLAB MAT file (v5 or v7.3) or corrupt; expected a file saved by MATLAB's save");

  // A first pass over the variables' headers only. matio (1.5.23) allocates a variable's values
  // by the dimensions its header declares, and when that fails it ends the variables with NULL
  // logging nothing: a 1 kB file declaring 6 GB of doubles would be allocated and converted, or
  // would silently drop the variables after it. A header declaring more bytes than the file could
  // hold (zlib inflates at most 1032 to 1) is refused, and the count tells an early end.
  constexpr double kMaxInflateRatio = 1032.0;  // zlib's largest compression ratio
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);  // -1 when unknown: no bound
  const double file_bytes = static_cast<double>(file_size);
  std::size_t declared_count = 0;
  for (VarPtr info(Mat_VarReadNextInfo(mat.get())); info; info.reset(Mat_VarReadNextInfo(mat.get()))) {
    ++declared_count;
    double bytes = static_cast<double>(Mat_SizeOfClass(info->class_type));
    std::string shape;
    for (int d = 0; d < info->rank && info->dims != nullptr; ++d) {
      bytes *= static_cast<double>(info->dims[d]);
      shape += (d ? " x " : "") + std::to_string(info->dims[d]);
    }
    if (bytes > kMaxInflateRatio * file_bytes) {
      if (info->rank > 3) shape = "rank-" + std::to_string(info->rank) + " array of";
      char gigabytes[32];
      std::snprintf(gigabytes, sizeof gigabytes, "%.3g", bytes / 1e9);  // may be far beyond any integer
      fail("variable " + (info->name != nullptr ? "'" + std::string(info->name) + "'" : std::to_string(declared_count) + " (no name)") +
           " declares " + shape + " values (" + gigabytes + " GB) but the file has " + std::to_string(file_size) +
           " bytes: corrupt file");
    }
  }
  Mat_Rewind(mat.get());
  g_matio_log.clear();

  // One pass over the variables, each read in full.
  std::vector<std::string> names;
  std::vector<std::pair<std::string, Eigen::VectorXd>> vectors;
  std::vector<std::string> skipped;
  Eigen::Index longest = 0;
  while (true) {
    g_matio_log.clear();
    g_matio_error = false;
    VarPtr var(Mat_VarReadNext(mat.get()));
    if (!var) {
      // NULL ends the file; with an error logged on the way it is a damaged variable instead
      // (warnings, e.g. about a class matio skips, are not).
      if (g_matio_error) fail("cannot read the variable after '" + (names.empty() ? std::string("(start)") : names.back()) + "' (corrupt or truncated file)");
      if (names.size() < declared_count) {
        fail("cannot read variable " + std::to_string(names.size() + 1) + " of " + std::to_string(declared_count) +
             " (after '" + (names.empty() ? std::string("(start)") : names.back()) + "'): corrupt file, or more than the memory holds");
      }
      break;
    }
    const std::string name = var->name != nullptr ? var->name : "";
    names.push_back(name);
    Eigen::VectorXd values;
    if (!numeric_values(*var, values) || values.size() == 0) {
      skipped.push_back(name);
      continue;
    }
    const bool vector = var->dims[0] == 1 || var->dims[1] == 1;
    if (values.size() == 1) {
      data.scalars[name] = values(0);
    } else if (vector) {
      longest = std::max(longest, values.size());
      vectors.emplace_back(name, std::move(values));
    } else {
      skipped.push_back(name);
    }
  }
  for (auto& [name, values] : vectors) {
    if (values.size() == longest) data.add_column(name, std::move(values));
    else skipped.push_back(name);
  }
  if (data.rows() == 0) {
    // matio (1.5.23) opens a v7.3 file whose HDF5 part HDF5 cannot open (truncated, corrupt) and
    // then reports no variables and no error: say so rather than "no numeric vector".
    if (names.empty() && Mat_GetVersion(mat.get()) == MAT_FT_MAT73)
      fail("cannot read the MAT v7.3 (HDF5) file: no variable could be read (corrupt, truncated or empty file)");
    std::string listed;
    for (const auto& n : names) listed += (listed.empty() ? "" : ", ") + n;
    fail("no real numeric vector variable (expected time series saved as 1xN or Nx1 arrays); variables: " +
         (listed.empty() ? std::string("(none)") : listed));
  }
  g_matio_log.clear();
  return data;
}

}  // namespace frictionlab

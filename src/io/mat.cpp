#include "frictionlab/io/mat.hpp"
#include "frictionlab/error.hpp"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/format.hpp"
#include "io/sha256.hpp"
#include "matio_library.hpp"

namespace frictionlab {
namespace {

// matio and the HDF5 library under it (v7.3 files) are not thread-safe (Debian's HDF5 is built
// without its thread-safe option): one MAT reader at a time holds this lock while it calls
// matio, so that batches (frictionlab identify DIR --jobs N) may read files from several threads.
std::mutex g_matio_mutex;

// matio reports problems through a log function that prints to stderr by default; messages
// are collected here instead, so the error we throw can quote them. Written and read only under
// g_matio_mutex: the one reader calling matio owns them.
std::string g_matio_log;
bool g_matio_error = false;  // an error or critical message since the last clear

void matio_log(int level, char* message) {
  if (level == MATIO_LOG_LEVEL_ERROR || level == MATIO_LOG_LEVEL_CRITICAL) g_matio_error = true;
  if (message != nullptr && g_matio_log.size() < 2000) {
    if (!g_matio_log.empty()) g_matio_log += "; ";
    g_matio_log += message;
  }
}

struct MatCloser {
  void operator()(mat_t* m) const { detail::matio_library().Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { detail::matio_library().VarFree(v); }
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

std::string dims_text(const matvar_t& v) {
  std::string out;
  for (int d = 0; d < v.rank; ++d) {
    if (d) out += 'x';
    out += std::to_string(v.dims[d]);
  }
  return out.empty() ? "0x0" : out;
}

bool is_numeric_class(matio_classes c) {
  switch (c) {
    case MAT_C_DOUBLE: case MAT_C_SINGLE: case MAT_C_INT8: case MAT_C_UINT8: case MAT_C_INT16: case MAT_C_UINT16:
    case MAT_C_INT32: case MAT_C_UINT32: case MAT_C_INT64: case MAT_C_UINT64: return true;
    default: return false;
  }
}

// The one check of a variable's type and shape: what it is when it cannot be a column or a
// scalar (a real numeric 1xN, Nx1 or 1x1 array), e.g. "a 3x4 matrix", "a 1x1 struct (fields:
// a, b)"; "" when it can. Lengths across variables are compared afterwards (read_mat).
std::string variable_problem(const matvar_t& v) {
  const std::string dims = dims_text(v);
  switch (v.class_type) {
    case MAT_C_CELL: return "a " + dims + " cell array";
    case MAT_C_STRUCT: {
      std::string fields;
      const unsigned n = detail::matio_library().VarGetNumberOfFields(const_cast<matvar_t*>(&v));
      char* const* names = detail::matio_library().VarGetStructFieldnames(&v);
      for (unsigned i = 0; names != nullptr && i < n && i < 10; ++i)
        fields += std::string(i ? ", " : "") + (names[i] != nullptr ? names[i] : "?");
      if (n > 10) fields += ", ...";
      return "a " + dims + " struct" + (fields.empty() ? "" : " (fields: " + fields + ")");
    }
    case MAT_C_OBJECT: return "a " + dims + " MATLAB object";
    case MAT_C_CHAR: return "a " + dims + " char array (text)";
    case MAT_C_SPARSE: return "a " + dims + " sparse matrix";
    case MAT_C_FUNCTION: return "a function handle";
    case MAT_C_OPAQUE: return "an opaque MATLAB object (a string, table or class instance)";
    case MAT_C_EMPTY: return "empty (" + dims + ")";
    default: break;
  }
  if (!is_numeric_class(v.class_type)) return "of an unknown MATLAB class (" + std::to_string(int(v.class_type)) + ")";
  const bool vector_shape = v.rank == 2 && (v.dims[0] == 1 || v.dims[1] == 1);
  const std::string shape = v.rank != 2 ? "array" : vector_shape ? (v.dims[0] * v.dims[1] == 1 ? "scalar" : "vector") : "matrix";
  if (v.isComplex) return "a " + dims + " complex " + shape + " (expected real numbers)";
  if (v.isLogical) return "a " + dims + " logical " + shape + " (true/false, expected numbers)";
  if (v.rank == 2 && v.dims[0] * v.dims[1] == 0) return "empty (" + dims + ")";
  if (!vector_shape) return "a " + dims + " " + shape;
  if (v.data == nullptr) return "a " + dims + " " + shape + " without data";
  return "";
}

// The values of a real numeric array (variable_problem(v) empty) as doubles.
Eigen::VectorXd numeric_values(const matvar_t& v) {
  const std::size_t n = v.dims[0] * v.dims[1];
  switch (v.class_type) {
    case MAT_C_SINGLE: return convert<float>(v.data, n);
    case MAT_C_INT8: return convert<std::int8_t>(v.data, n);
    case MAT_C_UINT8: return convert<std::uint8_t>(v.data, n);
    case MAT_C_INT16: return convert<std::int16_t>(v.data, n);
    case MAT_C_UINT16: return convert<std::uint16_t>(v.data, n);
    case MAT_C_INT32: return convert<std::int32_t>(v.data, n);
    case MAT_C_UINT32: return convert<std::uint32_t>(v.data, n);
    case MAT_C_INT64: return convert<std::int64_t>(v.data, n);
    case MAT_C_UINT64: return convert<std::uint64_t>(v.data, n);
    default: return convert<double>(v.data, n);
  }
}

using U32Reader = std::function<std::uint32_t(const unsigned char*)>;

// Bytes a compressed variable's element may hold after its zlib stream's end (alignment padding);
// more means the stream was cut short by damage.
constexpr std::size_t kMaxStreamPadding = 7;

// One subelement of a v5 variable's header as its tag declares it: data type, byte count, where
// its data start, where the next tag starts.
struct V5Subelement {
  std::uint32_t type = 0;
  std::size_t bytes = 0, data_at = 0, next = 0;
};

// The tags of the first three subelements of a v5 variable (array flags, dimensions, name), read
// from its miMATRIX tag at p (n bytes available). Returns how many of them the n bytes hold
// whole (their data may still run past n).
int v5_header_subelements(const unsigned char* p, std::size_t n, const U32Reader& u32, std::array<V5Subelement, 3>& out) {
  std::size_t at = 8;  // past the miMATRIX tag
  int count = 0;
  for (; count < 3 && at + 8 <= n; ++count) {
    const std::uint32_t type = u32(p + at);
    V5Subelement& e = out[static_cast<std::size_t>(count)];
    if ((type >> 16) != 0) {  // small element: byte count in the upper half, data in the tag
      e.type = type & 0xffffu;
      e.bytes = type >> 16;
      e.data_at = at + 4;
      e.next = at + 8;
    } else {
      e.type = type;
      e.bytes = u32(p + at + 4);
      e.data_at = at + 8;
      e.next = e.data_at + (e.bytes + 7) / 8 * 8;
    }
    at = e.next;
  }
  return count;
}

// The name of a v5 variable from the start of its (inflated) miMATRIX element: tag, array
// flags, dimensions, then the name (a small or a normal miINT8 element). "" when cut short.
std::string v5_variable_name(const unsigned char* p, std::size_t n, const U32Reader& u32) {
  std::array<V5Subelement, 3> e;
  if (v5_header_subelements(p, n, u32, e) < 3) return "";
  const V5Subelement& name = e[2];
  if (name.bytes > 63 || name.data_at + name.bytes > n) return "";
  return std::string(reinterpret_cast<const char*>(p + name.data_at), name.bytes);
}

// The first three subelements of a v5 variable (array flags, dimensions, name), from its miMATRIX
// tag at p (n bytes available): matio (1.5.23) allocates the dimensions and the name by the
// sizes their tags declare, before anything else is read, so a damaged tag (a name declaring
// 3 GB) would be allocated as it stands. Each must fit in the variable (`element_bytes`, its
// declared size), the flags take 8 bytes, the dimensions at most 64 (4-byte) values and the name
// at most 4096 characters (MATLAB's own limit is 63). Each must also be of the format's type
// (flags miUINT32, dimensions miINT32 in whole 4-byte values, name miINT8): matio walks a header
// of another type by other rules than the format's and can then read a name tag where the data
// are (a 728-byte file had it allocate 4 GB). Returns the problem, or "" (also when the n bytes
// end before the three tags: the later checks then speak).
std::string v5_matrix_header_problem(const unsigned char* p, std::size_t n, std::size_t element_bytes, const U32Reader& u32) {
  constexpr std::uint32_t kMiMatrix = 14;
  if (n < 8 || u32(p) != kMiMatrix) return "";
  const char* what[3] = {"array flags", "dimensions", "name"};
  const std::size_t most[3] = {8, 4 * 64, 4096};
  std::array<V5Subelement, 3> e;
  const int count = v5_header_subelements(p, n, u32, e);
  for (int k = 0; k < count; ++k) {
    const V5Subelement& s = e[static_cast<std::size_t>(k)];
    if (s.bytes > most[k] || s.next > 8 + element_bytes)
      return "the tag of its " + std::string(what[k]) + " declares " + std::to_string(s.bytes) +
             " bytes, more than the variable holds or than " + std::to_string(most[k]) + " (corrupt header)";
    constexpr std::uint32_t kMiInt8 = 1, kMiInt32 = 5, kMiUint32 = 6;
    const std::uint32_t type[3] = {kMiUint32, kMiInt32, kMiInt8};
    const char* type_name[3] = {"miUINT32", "miINT32", "miINT8"};
    if (s.type != type[k] || (k == 1 && s.bytes % 4 != 0))
      return "the tag of its " + std::string(what[k]) + " declares data type " + std::to_string(s.type) + " and " +
             std::to_string(s.bytes) + " bytes; expected " + type_name[k] + (k == 1 ? " values (4 bytes each)" : "") +
             " (corrupt header)";
  }
  return "";
}

// The first inflated bytes of a compressed v5 variable (at most `want`; fewer when the stream
// ends or is damaged: check_compressed reports that).
std::vector<unsigned char> inflate_head(const std::vector<unsigned char>& in, std::size_t want) {
  std::vector<unsigned char> out(want);
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return {};
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  while (z.avail_out > 0 && inflate(&z, Z_NO_FLUSH) == Z_OK) {
  }
  out.resize(want - z.avail_out);
  inflateEnd(&z);
  return out;
}

// Inflates a compressed v5 variable to its end with zlib: the zlib stream must end where the
// element does, with a matching adler32 checksum (matio 1.5.23 reads a stream with flipped bytes
// without a word). Returns "" when it does, else what is wrong; `name` gets the variable's name
// when the start of the stream can be read. The slow path of check_compressed: it tells how a
// stream is damaged (truncated, corrupt with zlib's own reason, trailing bytes).
std::string diagnose_compressed(const std::vector<unsigned char>& in, const U32Reader& u32, std::string& name) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return "zlib cannot start";
  std::vector<unsigned char> head;  // the first bytes inflated: the variable's header
  std::vector<unsigned char> out(1 << 16);
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = out.data();
    z.avail_out = static_cast<uInt>(out.size());
    rc = inflate(&z, Z_NO_FLUSH);
    const std::size_t got = out.size() - z.avail_out;
    if (head.size() < 256) head.insert(head.end(), out.begin(), out.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(got, 256 - head.size())));
    if (rc == Z_BUF_ERROR && z.avail_in == 0) break;  // input used up before the stream's end
  }
  const std::string zmsg = z.msg != nullptr ? z.msg : "";
  const std::size_t z_left = z.avail_in;
  inflateEnd(&z);
  name = v5_variable_name(head.data(), head.size(), u32);
  // A stream that ends well short of its element (more than alignment padding) was cut by damage.
  if (rc == Z_STREAM_END && z_left > kMaxStreamPadding) return "its zlib stream ends " + std::to_string(z_left) + " bytes before its data does (corrupt)";
  if (rc == Z_STREAM_END) return "";
  if (rc == Z_DATA_ERROR) return "its compressed data is corrupt (zlib: " + (zmsg.empty() ? std::string("data error") : zmsg) + ")";
  if (rc == Z_BUF_ERROR || rc == Z_OK) return "its compressed data ends before the zlib stream does (truncated)";
  return "its compressed data cannot be inflated (zlib error " + std::to_string(rc) + (zmsg.empty() ? "" : ": " + zmsg) + ")";
}

struct DecompressorFreer {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};
using Decompressor = std::unique_ptr<libdeflate_decompressor, DecompressorFreer>;

// Checks a compressed v5 variable's zlib stream as diagnose_compressed does, and returns the
// same. The common case, a sound stream, is decided by libdeflate in one whole-buffer call into
// `out` (`out_bytes` long: the inflated size the variable's miMATRIX tag declares): it verifies
// the adler32 checksum and reports how many input bytes the stream took, at about twice zlib's
// speed. libdeflate tells only "bad data", not whether the stream is truncated or corrupt (nor
// zlib's reason), so any stream it does not accept as sound (also one that inflates to more than
// its tag declares, which zlib accepts) is handed to diagnose_compressed, whose verdict and
// message are the reader's. A stream both accept is the same bytes to both (the checksum).
std::string check_compressed(libdeflate_decompressor* decompressor, const std::vector<unsigned char>& in,
                             unsigned char* out, std::size_t out_bytes, const U32Reader& u32, std::string& name) {
  std::size_t in_used = 0, out_used = 0;
  if (decompressor != nullptr &&
      libdeflate_zlib_decompress_ex(decompressor, in.data(), in.size(), out, out_bytes, &in_used, &out_used) == LIBDEFLATE_SUCCESS &&
      in.size() - in_used <= kMaxStreamPadding) {
    name = v5_variable_name(out, out_used, u32);
    return "";
  }
  return diagnose_compressed(in, u32, name);
}

// A compressed variable found by walk_v5: its number among the file's data elements, where its
// element starts, its compressed bytes and the inflated size its miMATRIX tag declares (bounded
// by zlib's largest ratio; 0 when the stream's first 8 bytes cannot be inflated).
struct V5Compressed {
  int variable = 0;
  std::size_t at = 0, bytes = 0, inflated = 0;
};

// What walk_v5 found: a problem of the file's structure ("" when none), whether it is a
// little-endian v5 file, and its compressed variables.
struct V5Walk {
  std::string problem;
  bool little_endian = true;
  std::vector<V5Compressed> compressed;
};

// A walk that found `problem` (and lists nothing).
V5Walk refused(std::string problem) {
  V5Walk walk;
  walk.problem = std::move(problem);
  return walk;
}

// A reader of the file's 4-byte unsigned integers in its byte order.
U32Reader u32_reader(bool little_endian) {
  return [little_endian](const unsigned char* p) {
    return little_endian ? std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24
                         : std::uint32_t(p[3]) | std::uint32_t(p[2]) << 8 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[0]) << 24;
  };
}

// matio (1.5.23) inflates a truncated or corrupt compressed v5 variable without reporting it,
// so the element structure of a v5 file is walked first: 128-byte header, then data elements
// each with an 8-byte tag (type, byte count; small elements pack both into 8 bytes). An element
// reaching past the end of the file means the file is truncated; each variable's header tags are
// checked (v5_matrix_header_problem) before matio allocates by them, and the compressed ones are
// listed for check_v5_streams. v7.3 (HDF5) files are left to HDF5 (nothing listed).
V5Walk walk_v5(const std::string& path) {
  V5Walk walk;
  // Only the header and the element tags are read (seeking past each element's data).
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return refused("cannot be opened for reading");
  const std::size_t size = static_cast<std::size_t>(in.tellg());
  if (size < 128) return refused("shorter than the 128-byte MAT-file header");
  unsigned char header[128];
  in.seekg(0);
  in.read(reinterpret_cast<char*>(header), 128);
  const unsigned char* b = header;
  const bool big_endian_file = b[126] == 'M' && b[127] == 'I';
  const bool little_endian_file = b[126] == 'I' && b[127] == 'M';
  if (!big_endian_file && !little_endian_file) return refused("no MAT-file endian indicator");
  walk.little_endian = little_endian_file;
  const U32Reader u32 = u32_reader(little_endian_file);
  const std::uint32_t version = little_endian_file ? (std::uint32_t(b[125]) << 8 | b[124]) : (std::uint32_t(b[124]) << 8 | b[125]);
  if (version != 0x0100) return walk;  // v7.3: HDF5 checks its own structure
  constexpr std::uint32_t kMiCompressed = 15, kMiMatrix = 14;
  std::size_t at = 128;
  unsigned char tag[8];
  int variable = 0;
  std::vector<unsigned char> element;
  while (at < size) {
    if (at + 8 > size) return refused("truncated: a data element tag at byte " + std::to_string(at) + " is cut off");
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(tag), 8)) return refused("read error at byte " + std::to_string(at));
    const std::uint32_t type = u32(tag);
    if ((type >> 16) != 0) {  // small data element: 4 bytes of tag, up to 4 of data
      at += 8;
      continue;
    }
    const std::uint32_t bytes = u32(tag + 4);
    std::size_t n = bytes;
    if (type != kMiCompressed && n % 8 != 0) n += 8 - n % 8;
    if (at + 8 + bytes > size) {
      return refused("truncated: the data element at byte " + std::to_string(at) + " needs " + std::to_string(bytes) +
                    " bytes but the file has " + std::to_string(size) + " in all");
    }
    ++variable;
    if (type == kMiMatrix || type == kMiCompressed) {
      // The variable's header tags, before matio allocates by them (v5_matrix_header_problem).
      element.resize(std::min<std::size_t>(bytes, type == kMiCompressed ? bytes : 504));
      if (!in.read(reinterpret_cast<char*>(element.data()), static_cast<std::streamsize>(element.size())))
        return refused("read error at byte " + std::to_string(at + 8));
      std::vector<unsigned char> head;
      std::size_t declared = bytes;
      if (type == kMiCompressed) {
        head = inflate_head(element, 512);
        // zlib inflates at most 1032 to 1: a larger declared size is damage too.
        declared = head.size() >= 8 ? std::min<std::size_t>(u32(head.data() + 4), 1032 * std::size_t{bytes}) : 0;
        walk.compressed.push_back({variable, at, bytes, head.size() >= 8 ? 8 + declared : 0});
      } else {
        head.resize(8 + element.size());
        std::copy(tag, tag + 8, head.begin());
        std::copy(element.begin(), element.end(), head.begin() + 8);
      }
      if (const std::string problem = v5_matrix_header_problem(head.data(), head.size(), declared, u32); !problem.empty())
        return refused("variable " + std::to_string(variable) + " at byte " + std::to_string(at) + ": " + problem);
    }
    at += 8 + n;
  }
  return walk;
}

// Inflates each compressed variable walk_v5 listed to its end (check_compressed): the first
// damaged one's problem, or "". The inflated bytes go to one buffer as long as the largest
// variable's declared size, reused for each.
std::string check_v5_streams(const std::string& path, const V5Walk& walk) {
  if (walk.compressed.empty()) return "";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot be opened for reading";
  const U32Reader u32 = u32_reader(walk.little_endian);
  std::size_t largest = 0;
  for (const V5Compressed& c : walk.compressed) largest = std::max(largest, c.inflated);
  std::vector<unsigned char> inflated(std::max<std::size_t>(largest, 1));
  unsigned char* const out = inflated.data();
  const Decompressor decompressor(libdeflate_alloc_decompressor());  // null when out of memory: zlib checks alone
  std::vector<unsigned char> element;
  for (const V5Compressed& c : walk.compressed) {
    element.resize(c.bytes);
    in.seekg(static_cast<std::streamoff>(c.at + 8));
    if (!in.read(reinterpret_cast<char*>(element.data()), static_cast<std::streamsize>(c.bytes)))
      return "read error at byte " + std::to_string(c.at + 8);
    std::string name;
    if (const std::string problem = check_compressed(decompressor.get(), element, out, c.inflated, u32, name); !problem.empty()) {
      const std::string which = name.empty() ? "variable " + std::to_string(c.variable) + " (its name is unreadable)"
                                             : "variable '" + name + "'";
      return which + ", compressed at byte " + std::to_string(c.at) + ": " + problem +
             "; the file is damaged (refused rather than read with wrong values)";
    }
  }
  return "";
}

}  // namespace

Dataset read_mat(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(errc::data_file_unreadable, path + ": no such MAT file (or not a regular file)", {.file = path});
  }
  // Hash first: it also proves the file is readable.
  Dataset data;
  data.file = path;
  data.sha256 = sha256_file(path);

  // matio's messages, once this reader holds the lock (before that, there are none of its own).
  const std::string* matio_messages = nullptr;
  const auto fail = [&](const std::string& what) {
    std::string msg = path + ": " + what;
    if (matio_messages != nullptr && !matio_messages->empty()) msg += " (matio: " + *matio_messages + ")";
    if (matio_messages != nullptr) g_matio_log.clear();
    throw InputError(errc::data_format, msg, {.file = path});
  };

  // The v5 structure and every compressed variable's stream are checked before matio opens the
  // file, without matio's lock (they do not call matio): batches reading on several threads
  // inflate in parallel. A damaged stream is reported after matio's size check below, so that a
  // header declaring more than the file holds is reported as that.
  const V5Walk walk = walk_v5(path);
  if (!walk.problem.empty()) fail("not a valid MATLAB MAT file: " + walk.problem);
  const std::string stream_problem = check_v5_streams(path, walk);

  const std::lock_guard matio_lock(g_matio_mutex);  // one reader in matio at a time (see above)
  detail::matio_library().LogInitFunc("frictionlab", &matio_log);
  g_matio_log.clear();
  g_matio_error = false;
  matio_messages = &g_matio_log;
  MatPtr mat(detail::matio_library().Open(path.c_str(), MAT_ACC_RDONLY));
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
  for (VarPtr info(detail::matio_library().VarReadNextInfo(mat.get())); info; info.reset(detail::matio_library().VarReadNextInfo(mat.get()))) {
    ++declared_count;
    double bytes = static_cast<double>(detail::matio_library().SizeOfClass(info->class_type));
    std::string shape;
    for (int d = 0; d < info->rank && info->dims != nullptr; ++d) {
      bytes *= static_cast<double>(info->dims[d]);
      shape += (d ? " x " : "") + std::to_string(info->dims[d]);
    }
    if (bytes > kMaxInflateRatio * file_bytes) {
      if (info->rank > 3) shape = "rank-" + std::to_string(info->rank) + " array of";
      const std::string gigabytes = format_number(bytes / 1e9, 3);  // may be far beyond any integer
      fail("variable " + (info->name != nullptr ? "'" + std::string(info->name) + "'" : std::to_string(declared_count) + " (no name)") +
           " declares " + shape + " values (" + gigabytes + " GB) but the file has " + std::to_string(file_size) +
           " bytes: corrupt file");
    }
  }
  detail::matio_library().Rewind(mat.get());
  g_matio_log.clear();
  if (!stream_problem.empty()) fail("not a valid MATLAB MAT file: " + stream_problem);

  // One pass over the variables, each read in full and checked by variable_problem.
  std::vector<std::string> names;
  std::vector<std::pair<std::string, Eigen::VectorXd>> vectors;
  Eigen::Index longest = 0;
  while (true) {
    g_matio_log.clear();
    g_matio_error = false;
    VarPtr var(detail::matio_library().VarReadNext(mat.get()));
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
    if (const std::string problem = variable_problem(*var); !problem.empty()) {
      data.unusable[name] = problem;
      continue;
    }
    Eigen::VectorXd values = numeric_values(*var);
    if (values.size() == 1) {
      data.scalars[name] = values(0);
    } else {
      longest = std::max(longest, values.size());
      vectors.emplace_back(name, std::move(values));
    }
  }
  // Columns share one length: the longest vectors'. Shorter ones are named with their length.
  for (auto& [name, values] : vectors) {
    if (values.size() == longest) data.add_column(name, std::move(values));
    else data.unusable[name] = "a vector of " + std::to_string(values.size()) + " samples, shorter than the other columns (" +
                               std::to_string(longest) + ")";
  }
  if (data.rows() == 0) {
    // matio (1.5.23) opens a v7.3 file whose HDF5 part HDF5 cannot open (truncated, corrupt) and
    // then reports no variables and no error: say so rather than "no numeric vector".
    if (names.empty() && detail::matio_library().GetVersion(mat.get()) == MAT_FT_MAT73)
      fail("cannot read the MAT v7.3 (HDF5) file: no variable could be read (corrupt, truncated or empty file)");
    std::string listed;
    for (const auto& n : names) {
      const auto it = data.unusable.find(n);
      listed += (listed.empty() ? "" : ", ") + n + (it != data.unusable.end() ? " (" + it->second + ")" : data.has_scalar(n) ? " (a scalar)" : "");
    }
    fail("no real numeric vector variable (expected time series saved as 1xN or Nx1 arrays); variables: " +
         (listed.empty() ? std::string("(none)") : listed));
  }
  g_matio_log.clear();
  return data;
}

}  // namespace frictionlab

// MATLAB v7.3 (HDF5) MAT files: written at test time with matio (Debian's libmatio is built with
// HDF5), read back through read_mat; corrupt v7.3 files give an error naming the file.

#include <gtest/gtest.h>
#include <matio.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "temp_dir.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/mat.hpp"

namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;


struct Variable {
  std::string name;
  std::vector<double> values;
  std::size_t rows, cols;  // MATLAB shape: 1xN row vector, Nx1 column vector, 1x1 scalar
};

// Writes `vars` as doubles into a v7.3 file at `path`; false when matio cannot create one (a
// matio built without HDF5 returns no file for MAT_FT_MAT73).
bool write_mat73(const std::string& path, const std::vector<Variable>& vars) {
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT73);
  if (mat == nullptr) return false;
  bool ok = Mat_GetVersion(mat) == MAT_FT_MAT73;
  for (const auto& v : vars) {
    std::size_t dims[2] = {v.rows, v.cols};
    // matio does not write through the data pointer; the cast only meets its C signature.
    matvar_t* var = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                  const_cast<double*>(v.values.data()), MAT_F_DONT_COPY_DATA);
    ok = ok && var != nullptr && Mat_VarWrite(mat, var, MAT_COMPRESSION_NONE) == 0;
    Mat_VarFree(var);
  }
  Mat_Close(mat);
  return ok;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A small rig recording: 1 kHz time stamps, a position ramp, a current-to-torque gain.
constexpr std::size_t kSamples = 50;
constexpr double kGain = 35.15065188;

std::vector<Variable> rig_variables() {
  Variable t{"t", {}, 1, kSamples}, q{"qm", {}, kSamples, 1};  // one row, one column vector
  for (std::size_t k = 0; k < kSamples; ++k) {
    t.values.push_back(1e-3 * static_cast<double>(k));
    q.values.push_back(0.25 * static_cast<double>(k) - 1.0);
  }
  return {t, q, {"gtau", {kGain}, 1, 1}};
}

}  // namespace

TEST(MatV73, ReadsColumnsAndScalarsWrittenByMatio) {
  TempDir d;
  const std::string p = d.file("rig_v73.mat");
  ASSERT_TRUE(write_mat73(p, rig_variables())) << "matio cannot write MAT v7.3 (built without HDF5?)";
  // The MATLAB header says 7.3 and HDF5's signature follows at byte 512: a real v7.3 file.
  const std::string bytes = read_bytes(p);
  ASSERT_GT(bytes.size(), 520u);
  EXPECT_EQ(bytes.substr(0, 19), "MATLAB 7.3 MAT-file");
  EXPECT_EQ(bytes.substr(513, 3), "HDF");

  const fl::Dataset data = fl::read_mat(p);
  ASSERT_EQ(data.rows(), static_cast<Eigen::Index>(kSamples));
  // HDF5 lists a group's variables by name, not in the order they were written.
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"qm", "t"}));
  // Doubles stored and read back unchanged: exact comparison.
  for (std::size_t k = 0; k < kSamples; ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    EXPECT_EQ(data.column("t")(i), 1e-3 * static_cast<double>(k)) << k;
    EXPECT_EQ(data.column("qm")(i), 0.25 * static_cast<double>(k) - 1.0) << k;
  }
  ASSERT_TRUE(data.has_scalar("gtau"));
  EXPECT_EQ(data.scalars.at("gtau"), kGain);
  EXPECT_EQ(fl::resolve_constant(data, "gtau", "--gain"), kGain);
  EXPECT_EQ(data.file, p);
  EXPECT_EQ(data.sha256.size(), 64u);

  // A missing variable is named, with the ones the file has.
  const std::string msg = error_of([&] { fl::select_column(data, "vir", "--input"); });
  EXPECT_NE(msg.find("no column 'vir'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("qm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("gtau"), std::string::npos) << msg;
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
}

TEST(MatV73, CorruptFilesGiveAnErrorNamingTheFile) {
  TempDir d;
  const std::string good = d.file("good_v73.mat");
  ASSERT_TRUE(write_mat73(good, rig_variables()));
  const std::string bytes = read_bytes(good);
  constexpr std::size_t kMatlabHeader = 512;  // v7.3: 512-byte user block before the HDF5 file
  ASSERT_GT(bytes.size(), 2 * kMatlabHeader);

  // Each damaged copy must give an error that names the file and says it is damaged (matio
  // itself opens such files and reports no variables, which read_mat must not pass on as "no
  // numeric vector").
  const auto expect_corrupt_error = [&](const std::string& name, const std::string& content) {
    const std::string p = d.file(name);
    write_bytes(p, content);
    const std::string msg = error_of([&] { fl::read_mat(p); });
    EXPECT_NE(msg.find(p), std::string::npos) << msg;
    EXPECT_NE(msg.find("v7.3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("corrupt"), std::string::npos) << msg;
  };
  // Cut off in the middle: HDF5 finds the end of file short of what its superblock records.
  expect_corrupt_error("truncated_v73.mat", bytes.substr(0, bytes.size() / 2));
  // Only the MATLAB header survives.
  expect_corrupt_error("header_only_v73.mat", bytes.substr(0, kMatlabHeader));
  // A v7.3 header followed by bytes that are not HDF5.
  expect_corrupt_error("garbage_v73.mat", bytes.substr(0, kMatlabHeader) + std::string(bytes.size() - kMatlabHeader, '\x5a'));
  // The HDF5 superblock damaged just after its signature.
  std::string damaged = bytes;
  for (std::size_t k = kMatlabHeader + 8; k < kMatlabHeader + 88; ++k) damaged[k] = static_cast<char>(~damaged[k]);
  expect_corrupt_error("superblock_v73.mat", damaged);
}

// Data as it comes off a rig: headerless CSV logs with jittered time, other delimiters, BOM,
// CRLF, quoted headers, extreme numbers, resampling through a Dataset; MAT files with corrupt
// compressed variables or variables of the wrong shape or type.

#include <gtest/gtest.h>
#include <matio.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "error_message.hpp"
#include "property_cases.hpp"
#include "temp_dir.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/io/mat.hpp"

namespace fl = frictionlab;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

const std::string kEmps = std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

fl::CsvOptions detect() {
  fl::CsvOptions o;
  o.header = fl::CsvHeader::detect;
  return o;
}

// A robot controller's joint log: no header row, 31 columns (time; six positions, six
// velocities, six currents in A; twelve more channels), 100 Hz nominal with stamps 10 to 12 ms
// apart. Joint 1 moves (a 0.5 Hz sine of 1 rad); encoder quantisation, current noise and offset.
struct RobotLog {
  std::string text;
  std::vector<double> time, q1;
};

constexpr double kJointAmplitude = 1.0;  // rad
constexpr double kJointOmega = M_PI;     // rad/s (0.5 Hz)
constexpr double kEncoderStep = 2 * M_PI / 131072;  // 17-bit encoder, rad

RobotLog robot_log(int rows, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> step(0.010, 0.012);
  std::normal_distribution<double> noise(0.0, 0.02);  // A
  RobotLog log;
  std::ostringstream out;
  out.precision(9);
  double t = 3.217;  // controllers start their clocks anywhere
  for (int k = 0; k < rows; ++k) {
    if (k > 0) t += step(rng);
    const double q = std::round(kJointAmplitude * std::sin(kJointOmega * t) / kEncoderStep) * kEncoderStep;
    log.time.push_back(t);
    log.q1.push_back(q);
    out << t;
    for (int j = 0; j < 6; ++j) out << "," << (j == 0 ? q : 0.1 * j);                       // positions, rad
    for (int j = 0; j < 6; ++j) out << "," << (j == 0 ? kJointAmplitude * kJointOmega * std::cos(kJointOmega * t) : 0.0);
    for (int j = 0; j < 6; ++j) out << "," << 0.3 + (j == 0 ? 0.8 * std::cos(kJointOmega * t) : 0.0) + noise(rng);
    for (int j = 0; j < 12; ++j) out << "," << 40 + j;                                       // temperatures, ...
    out << "\n";
  }
  log.text = out.str();
  return log;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(CsvRealLogs, HeaderlessJitteredRobotLogIsReadResampledAndChecked) {
  TempDir d;
  constexpr int kRows = 1500;
  const RobotLog log = robot_log(kRows, 2024);
  const std::string p = d.file("joints.csv", log.text);
  fl::Dataset data = fl::read_csv(p, detect());
  ASSERT_EQ(data.rows(), kRows);
  ASSERT_EQ(data.column_names().size(), 31u);
  EXPECT_EQ(data.column_names().front(), "c1");
  EXPECT_EQ(data.column_names().back(), "c31");
  EXPECT_FALSE(data.header_row);
  EXPECT_EQ(data.row_label(0), "line 1");  // the first row is data

  // A missing column lists the 31 and says the file has no header row.
  const std::string missing = error_of([&] { fl::select_column(data, "time", "--time"); });
  EXPECT_TRUE(contains(missing, "no column 'time' (--time)")) << missing;
  EXPECT_TRUE(contains(missing, "c1, c2, c3")) << missing;
  EXPECT_TRUE(contains(missing, "c31")) << missing;
  EXPECT_TRUE(contains(missing, "no header row")) << missing;

  // Refused as irregular, naming a line of the file and the step range.
  const std::string irregular = error_of([&] { fl::check_time(data, data.column("c1")); });
  EXPECT_TRUE(contains(irregular, p + ": line ")) << irregular;
  EXPECT_TRUE(contains(irregular, "differs from the median step")) << irregular;

  fl::resample_dataset(data, "c1");
  ASSERT_TRUE(data.resampling.has_value());
  const fl::ResampleReport& r = *data.resampling;
  EXPECT_GE(r.dt_min, 0.010 - 1e-9);  // printed with 9 digits: 1e-9 s of slack
  EXPECT_LE(r.dt_max, 0.012 + 1e-9);
  constexpr double kMedianTol = 2e-4;  // median of 1499 uniform draws on [10, 12] ms: 11 ms +- ~0.05 ms
  EXPECT_NEAR(r.dt_median, 0.011, kMedianTol);
  EXPECT_EQ(r.dt, r.dt_median);
  EXPECT_EQ(r.samples_in, kRows);
  const double span = log.time.back() - log.time.front();
  EXPECT_EQ(r.samples_out, static_cast<Eigen::Index>(std::floor(span / r.dt + 1e-9)) + 1);
  EXPECT_EQ(data.rows(), r.samples_out);
  EXPECT_TRUE(data.lines.empty());
  EXPECT_EQ(data.row_label(4), "sample 5 of the resampled grid");
  constexpr double kStepRel = 1e-9;  // grid built as t0 + i dt
  EXPECT_NEAR(fl::check_time(data, data.column("c1")), r.dt, kStepRel * r.dt);

  // Joint 1 on the grid: the sine within interpolation error (h^2 w^2 A / 8 with h <= 12 ms)
  // plus the encoder's quantisation (one step).
  const Eigen::VectorXd& t = data.column("c1");
  const Eigen::VectorXd& q = data.column("c2");
  const double kInterpTol = 0.012 * 0.012 * kJointOmega * kJointOmega * kJointAmplitude / 8 + kEncoderStep;
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    ASSERT_NEAR(q(k), kJointAmplitude * std::sin(kJointOmega * t(k)), kInterpTol) << "grid sample " << k;
  }
}

TEST(CsvRealLogs, NamesNameTheColumnsOfAHeaderlessFile) {
  TempDir d;
  const std::string p = d.file("log.csv", "0,1,2,3\n0.01,1,2,3\n");
  fl::CsvOptions o = detect();
  o.names = {"t", " q1 "};  // fewer names than columns: the others keep c<k>
  fl::Dataset data = fl::read_csv(p, o);
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"t", "q1", "c3", "c4"}));
  o.names_option = "--names";
  o.names = {"a", "b", "c", "d", "e"};
  std::string msg = error_of([&] { fl::read_csv(p, o); });
  EXPECT_TRUE(contains(msg, "--names gives 5 names but the file has 4 columns")) << msg;
  o.names = {"a", "", "c"};
  msg = error_of([&] { fl::read_csv(p, o); });
  EXPECT_TRUE(contains(msg, "--names: name 2 is empty")) << msg;
  o.names = {"a", "a"};
  msg = error_of([&] { fl::read_csv(p, o); });
  EXPECT_TRUE(contains(msg, "--names: 'a' names two columns")) << msg;
  o.names = {"c4"};  // would clash with the fourth column's generated name
  EXPECT_TRUE(contains(error_of([&] { fl::read_csv(p, o); }), "'c4'"));
  // With a header row, names replace the header's names.
  const std::string h = d.file("header.csv", "Time [s],Joint 1 [rad]\n0,1\n0.01,2\n");
  o.names = {"t", "q"};
  data = fl::read_csv(h, o);
  EXPECT_TRUE(data.header_row);
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"t", "q"}));
  EXPECT_EQ(data.rows(), 2);
}

TEST(CsvRealLogs, DelimitersAreDetected) {
  TempDir d;
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"semicolon.csv", "t;x;y\n0;1.5;-2\n0.01;2.5;-3\n"},
           {"tab.csv", "t\tx\ty\n0\t1.5\t-2\n0.01\t2.5\t-3\n"},
           {"spaces.csv", "  t    x  y\n0   1.5   -2\n  0.01 2.5 -3   \n"},
           {"comma_spaces.csv", "t, x, y\n0, 1.5, -2\n0.01, 2.5, -3\n"}}) {
    const fl::Dataset data = fl::read_csv(d.file(name, text), detect());
    EXPECT_EQ(data.column_names(), (std::vector<std::string>{"t", "x", "y"})) << name;
    ASSERT_EQ(data.rows(), 2) << name;
    EXPECT_EQ(data.column("x")(1), 2.5) << name;
    EXPECT_EQ(data.column("y")(0), -2.0) << name;
  }
  // Headerless and space separated, as many loggers write.
  const fl::Dataset blank = fl::read_csv(d.file("blank.csv", "0.000 1 2\n0.001 3 4\n"), detect());
  EXPECT_EQ(blank.column_names(), (std::vector<std::string>{"c1", "c2", "c3"}));
  EXPECT_EQ(blank.column("c3")(1), 4.0);
  // A decimal comma in a semicolon file is pointed out.
  const std::string msg = error_of([&] { fl::read_csv(d.file("eu.csv", "t;x\n0;1,5\n"), detect()); });
  EXPECT_TRUE(contains(msg, "line 2, column 2 'x': expected a number, got '1,5' (a decimal comma?")) << msg;
  // Wrong cell count names the separator.
  const std::string count = error_of([&] { fl::read_csv(d.file("ragged.csv", "0;1\n0.1;2;3\n"), detect()); });
  EXPECT_TRUE(contains(count, "line 2: 3 cells; expected 2 like the first row (separator ';')")) << count;
}

TEST(CsvRealLogs, BomCrlfQuotedHeaderAndComments) {
  TempDir d;
  const std::string p = d.file(
      "excel.csv", "\xEF\xBB\xBF# exported\r\n\"time\";\"motor; current\";\"pos \"\"deg\"\"\"\r\n0;1.5;2\r\n\r\n0.01;\"2.5\";3\r\n");
  const fl::Dataset data = fl::read_csv(p, detect());
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"time", "motor; current", "pos \"deg\""}));
  ASSERT_EQ(data.rows(), 2);
  EXPECT_EQ(data.column("motor; current")(1), 2.5);
  EXPECT_EQ(data.row_label(1), "line 5");
  const std::string open = error_of([&] { fl::read_csv(d.file("open.csv", "\"t,x\n0,1\n"), detect()); });
  EXPECT_TRUE(contains(open, "line 1: a quoted cell is not closed")) << open;
}

TEST(CsvRealLogs, ExtremeNumbers) {
  TempDir d;
  const fl::Dataset data = fl::read_csv(d.file("tiny.csv", "t,x\n0,1e-400\n1,-2.5e-310\n2,+1e-5000\n"), detect());
  EXPECT_EQ(data.column("x")(0), 0.0);  // below the smallest subnormal: 0
  EXPECT_EQ(data.column("x")(1), -2.5e-310);  // a subnormal, kept
  EXPECT_EQ(data.column("x")(2), 0.0);
  const std::string msg = error_of([&] { fl::read_csv(d.file("huge.csv", "t,x\n0,1\n1,1e400\n"), detect()); });
  EXPECT_TRUE(contains(msg, "line 3, column 2 'x': '1e400' is out of the range of a double")) << msg;
  EXPECT_FALSE(contains(msg, "not a finite number")) << msg;
}

TEST(CsvRealLogs, FirstRowMixingNumbersAndTextIsNamed) {
  TempDir d;
  const std::string msg = error_of([&] { fl::read_csv(d.file("mixed.csv", "0,abc,2\n1,2,3\n"), detect()); });
  EXPECT_TRUE(contains(msg, "line 1: the first row mixes numbers and text (column 1 '0', column 2 'abc')")) << msg;
  // Without detection a first row of numbers is still refused (the library's default).
  EXPECT_TRUE(contains(error_of([&] { fl::read_csv(d.file("n.csv", "1,2\n3,4\n")); }), "header row"));
}

TEST(ResampleDataset, RepeatedStampsGapsAndMaxGapThroughTheFile) {
  TempDir d;
  // 10 ms log; line 5 repeats line 4's stamp; a 0.2 s hole after line 9.
  const std::string p = d.file("holes.csv",
                               "time,f\n0,0\n0.01,1\n0.02,2\n0.02,4\n0.03,3\n0.04,4\n0.05,5\n0.06,6\n0.26,26\n0.27,27\n");
  fl::Dataset data = fl::read_csv(p, detect());
  const std::string gap = error_of([&] { fl::Dataset copy = data; fl::resample_dataset(copy, "time"); });
  EXPECT_TRUE(contains(gap, p + ": line 9 to line 10: a gap of 0.2 s")) << gap;
  EXPECT_TRUE(contains(gap, "20 median steps")) << gap;
  EXPECT_TRUE(contains(gap, "max_gap 0.202")) << gap;
  fl::ResampleOptions o;
  o.max_gap = 0.25;
  fl::resample_dataset(data, "time", o);
  ASSERT_TRUE(data.resampling);
  EXPECT_EQ(data.resampling->merged, 1);
  EXPECT_EQ(data.resampling->samples_out, 28);
  ASSERT_EQ(data.warnings.size(), 1u);
  EXPECT_TRUE(contains(data.warnings[0], p + ": 1 row(s) repeat the time stamp")) << data.warnings[0];
  EXPECT_TRUE(contains(data.warnings[0], "line 5")) << data.warnings[0];
  constexpr double kTol = 1e-9;  // a line through integers at decimal time stamps
  EXPECT_NEAR(data.column("f")(2), 3.0, kTol);   // mean of 2 and 4 at 0.02 s
  EXPECT_NEAR(data.column("f")(16), 16.0, kTol);  // across the allowed hole: the straight line
}

// ---- MAT files ----------------------------------------------------------------------------

namespace {

// Byte offset and size of each top-level data element of a v5 MAT file (after the 128-byte
// header), read from the element tags (little-endian files, as MATLAB writes on x86).
std::vector<std::pair<std::size_t, std::size_t>> v5_elements(const std::string& bytes) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t at = 128;
  while (at + 8 <= bytes.size()) {
    std::uint32_t size = 0;
    for (int i = 3; i >= 0; --i) size = size << 8 | static_cast<unsigned char>(bytes[at + 4 + static_cast<std::size_t>(i)]);
    out.emplace_back(at, size);
    at += 8 + size;
  }
  return out;
}

}  // namespace

TEST(MatDamage, FlippedBytesInACompressedVariableAreRefusedNamingIt) {
  TempDir d;
  const std::string bytes = read_bytes(kEmps);
  const auto elements = v5_elements(bytes);
  ASSERT_EQ(elements.size(), 7u);  // gtau, kp, kv, qg, qm, t, vir, each compressed
  const auto [qm_at, qm_size] = elements[4];

  // A few bytes flipped in the middle of qm's deflate stream.
  std::string flipped = bytes;
  for (std::size_t k = 0; k < 4; ++k) flipped[qm_at + 8 + qm_size / 2 + 7 * k] ^= 0x5a;
  const std::string p = d.file("flipped.mat", flipped);
  const std::string msg = error_of([&] { fl::read_mat(p); });
  EXPECT_TRUE(contains(msg, p + ": ")) << msg;
  EXPECT_TRUE(contains(msg, "variable 'qm'")) << msg;
  EXPECT_TRUE(contains(msg, "corrupt")) << msg;

  // Only the adler32 checksum at the end of the stream is wrong: the data inflate fine.
  std::string checksum = bytes;
  checksum[qm_at + 8 + qm_size - 1] ^= 0x01;
  const std::string q = d.file("checksum.mat", checksum);
  const std::string msg2 = error_of([&] { fl::read_mat(q); });
  EXPECT_TRUE(contains(msg2, "variable 'qm'")) << msg2;
  EXPECT_TRUE(contains(msg2, "incorrect data check")) << msg2;

  // The untouched copy reads as before.
  EXPECT_EQ(fl::read_mat(d.file("copy.mat", bytes)).rows(), 24841);
}

namespace {

// `bytes` (a little-endian v5 file) with element `k`'s data replaced by `data` and its tag's byte
// count set to match.
std::string with_element_data(const std::string& bytes, std::size_t k, const std::string& data) {
  const auto [at, size] = v5_elements(bytes)[k];
  std::string tag = bytes.substr(at, 8);
  for (int i = 0; i < 4; ++i) tag[4 + static_cast<std::size_t>(i)] = static_cast<char>(data.size() >> (8 * i) & 0xff);
  return bytes.substr(0, at) + tag + data + bytes.substr(at + 8 + size);
}

// The zlib stream of the EMPS file's compressed variable qm (element 4), and the file's bytes.
struct EmpsQm {
  std::string bytes, stream;
  std::size_t at = 0;
};

EmpsQm emps_qm() {
  EmpsQm e;
  e.bytes = read_bytes(kEmps);
  const auto elements = v5_elements(e.bytes);
  EXPECT_EQ(elements.size(), 7u);  // gtau, kp, kv, qg, qm, t, vir, each compressed
  e.at = elements.at(4).first;
  e.stream = e.bytes.substr(e.at + 8, elements.at(4).second);
  return e;
}

}  // namespace

// The reader checks a sound stream with libdeflate and has zlib say how a damaged one is damaged:
// a stream cut short, one followed by more than padding, and one whose data inflate to more than
// the variable's tag declares are each told as zlib tells them.
TEST(MatDamage, CutLongAndPaddedStreamsAreToldApart) {
  TempDir d;
  const EmpsQm e = emps_qm();
  const Eigen::VectorXd qm = fl::read_mat(kEmps).column("qm");

  // The element holds only the first half of the stream: truncated, not corrupt.
  const std::string cut = d.file("cut.mat", with_element_data(e.bytes, 4, e.stream.substr(0, e.stream.size() / 2)));
  const std::string msg = error_of([&] { fl::read_mat(cut); });
  EXPECT_TRUE(contains(msg, cut + ": not a valid MATLAB MAT file: variable 'qm', compressed at byte " + std::to_string(e.at) +
                                ": its compressed data ends before the zlib stream does (truncated); the file is damaged")) << msg;

  // 16 bytes after the stream's end, inside the element: more than alignment padding.
  const std::string tail = d.file("tail.mat", with_element_data(e.bytes, 4, e.stream + std::string(16, '\0')));
  const std::string msg2 = error_of([&] { fl::read_mat(tail); });
  EXPECT_TRUE(contains(msg2, "variable 'qm', compressed at byte " + std::to_string(e.at) +
                                 ": its zlib stream ends 16 bytes before its data does (corrupt)")) << msg2;

  // 7 bytes are padding: read, with the same values.
  const fl::Dataset padded = fl::read_mat(d.file("padded.mat", with_element_data(e.bytes, 4, e.stream + std::string(7, '\0'))));
  EXPECT_EQ(padded.column("qm"), qm);

  // The stream inflates to 16 bytes more than qm's tag declares (its element is whole before
  // them): zlib accepts that, and so does the reader, with the same values.
  std::string inflated(8 + 200000, '\0');
  uLongf inflated_size = static_cast<uLongf>(inflated.size());
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(inflated.data()), &inflated_size,
                       reinterpret_cast<const Bytef*>(e.stream.data()), static_cast<uLong>(e.stream.size())), Z_OK);
  inflated.resize(inflated_size);
  inflated += std::string(16, '\0');
  std::string longer(compressBound(static_cast<uLong>(inflated.size())), '\0');
  uLongf longer_size = static_cast<uLongf>(longer.size());
  ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(longer.data()), &longer_size, reinterpret_cast<const Bytef*>(inflated.data()),
                      static_cast<uLong>(inflated.size()), Z_BEST_SPEED), Z_OK);
  longer.resize(longer_size);
  EXPECT_EQ(fl::read_mat(d.file("longer.mat", with_element_data(e.bytes, 4, longer))).column("qm"), qm);
}

// Seeded damage to one compressed variable's deflate data (1 to 3 bytes changed anywhere between
// the zlib header and the last data byte, whose unused bits may not matter; or the stream cut at a
// random length): every damaged file is refused, naming the variable's element, never read.
TEST(MatDamage, RandomDamageToAStreamIsAlwaysRefused) {
  TempDir d;
  const EmpsQm e = emps_qm();
  // A file of qm alone (the 128-byte header and qm's element): each case reads one variable.
  const std::string alone = e.bytes.substr(0, 128) + e.bytes.substr(e.at, 8 + e.stream.size());
  constexpr std::size_t kQmAt = 128;
  ASSERT_EQ(fl::read_mat(d.file("alone.mat", alone)).rows(), 24841);
  std::mt19937 rng(13);
  std::uniform_int_distribution<std::size_t> where(2, e.stream.size() - 6), how_many(1, 3), length(0, e.stream.size() - 1);
  std::uniform_int_distribution<int> change(1, 255);
  const int cases = std::max(1, frictionlab::testing::property_cases() / 5);  // each case reads a file: a fifth
  int truncated = 0;
  for (int c = 0; c < cases; ++c) {
    std::string stream = e.stream;
    if (c % 4 == 3) {
      stream.resize(length(rng));
    } else {
      for (std::size_t k = how_many(rng); k > 0; --k) stream[where(rng)] ^= static_cast<char>(change(rng));
    }
    const std::string path = d.file("damaged.mat", with_element_data(alone, 0, stream));
    const std::string msg = error_of([&] { fl::read_mat(path); });
    const bool named = contains(msg, "compressed at byte " + std::to_string(kQmAt) + ": ") ||  // the stream check
                       contains(msg, "variable 1 at byte " + std::to_string(kQmAt) + ": ") ||  // its header tags
                       contains(msg, "variable 'qm' declares");                                // its dimensions
    ASSERT_TRUE(named && (contains(msg, "corrupt") || contains(msg, "truncated"))) << "case " << c << ": " << msg;
    truncated += contains(msg, "(truncated)");
  }
  EXPECT_GT(truncated, 0);  // the cut streams are told apart from the corrupt ones
}

namespace {

constexpr std::size_t kN = 20;

// Writes a MAT v5 file (compressed) with good columns t, qm and one variable of each wrong
// kind; false when matio cannot.
bool write_odd_variables(const std::string& path) {
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  if (mat == nullptr) return false;
  bool ok = true;
  const auto write = [&](matvar_t* v) {
    ok = ok && v != nullptr && Mat_VarWrite(mat, v, MAT_COMPRESSION_ZLIB) == 0;
    Mat_VarFree(v);
  };
  std::vector<double> t(kN), qm(kN), matrix(12, 1.0), shorter(5, 0.0), re(kN, 1.0), im(kN, 2.0);
  for (std::size_t k = 0; k < kN; ++k) t[k] = 1e-3 * static_cast<double>(k), qm[k] = static_cast<double>(k);
  std::size_t vec[2] = {kN, 1}, m34[2] = {3, 4}, short_dims[2] = {1, 5}, one[2] = {1, 1};
  write(Mat_VarCreate("t", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, vec, t.data(), MAT_F_DONT_COPY_DATA));
  write(Mat_VarCreate("qm", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, vec, qm.data(), MAT_F_DONT_COPY_DATA));
  write(Mat_VarCreate("matrix", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, m34, matrix.data(), MAT_F_DONT_COPY_DATA));
  write(Mat_VarCreate("shorter", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, short_dims, shorter.data(), MAT_F_DONT_COPY_DATA));
  char text[] = "rig 3";
  std::size_t text_dims[2] = {1, 5};
  write(Mat_VarCreate("label", MAT_C_CHAR, MAT_T_UINT8, 2, text_dims, text, MAT_F_DONT_COPY_DATA));
  mat_complex_split_t z{re.data(), im.data()};
  write(Mat_VarCreate("z", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, vec, &z, MAT_F_DONT_COPY_DATA | MAT_F_COMPLEX));
  std::vector<std::uint8_t> flags(kN, 1);
  write(Mat_VarCreate("flag", MAT_C_UINT8, MAT_T_UINT8, 2, vec, flags.data(), MAT_F_DONT_COPY_DATA | MAT_F_LOGICAL));
  // A struct with two fields, a cell with one element.
  const char* fields[2] = {"rate", "axis"};
  matvar_t* info = Mat_VarCreateStruct("info", 2, one, fields, 2);
  double rate = 100, axis = 1;
  Mat_VarSetStructFieldByName(info, "rate", 0, Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &rate, MAT_F_DONT_COPY_DATA));
  Mat_VarSetStructFieldByName(info, "axis", 0, Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &axis, MAT_F_DONT_COPY_DATA));
  write(info);
  matvar_t* cell = Mat_VarCreate("cellv", MAT_C_CELL, MAT_T_CELL, 2, one, nullptr, 0);
  Mat_VarSetCell(cell, 0, Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &rate, MAT_F_DONT_COPY_DATA));
  write(cell);
  // A 3x3 sparse identity.
  mat_uint32_t ir[3] = {0, 1, 2}, jc[4] = {0, 1, 2, 3};
  double diag[3] = {1, 1, 1};
  mat_sparse_t sparse{};
  sparse.nzmax = 3;
  sparse.ir = ir;
  sparse.nir = 3;
  sparse.jc = jc;
  sparse.njc = 4;
  sparse.ndata = 3;
  sparse.data = diag;
  std::size_t d33[2] = {3, 3};
  write(Mat_VarCreate("sp", MAT_C_SPARSE, MAT_T_DOUBLE, 2, d33, &sparse, MAT_F_DONT_COPY_DATA));
  Mat_Close(mat);
  return ok;
}

}  // namespace

TEST(MatShapes, WrongShapeOrTypeIsReportedAsWhatItIs) {
  TempDir d;
  const std::string p = d.file("odd.mat");
  ASSERT_TRUE(write_odd_variables(p)) << "matio could not write the test file";
  const fl::Dataset data = fl::read_mat(p);
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"t", "qm"}));
  const auto what = [&](const std::string& name) { return error_of([&] { fl::select_column(data, name, "--position"); }); };
  std::string msg = what("matrix");
  EXPECT_TRUE(contains(msg, p + ": variable 'matrix' (--position) is a 3x4 matrix; expected a real numeric vector")) << msg;
  EXPECT_TRUE(contains(msg, "of 20 samples")) << msg;
  EXPECT_TRUE(contains(what("shorter"), "is a vector of 5 samples, shorter than the other columns (20)"));
  EXPECT_TRUE(contains(what("label"), "is a 1x5 char array (text)"));
  EXPECT_TRUE(contains(what("z"), "is a 20x1 complex vector"));
  EXPECT_TRUE(contains(what("flag"), "is a 20x1 logical vector"));
  msg = what("info");
  EXPECT_TRUE(contains(msg, "is a 1x1 struct (fields: rate, axis)")) << msg;
  EXPECT_TRUE(contains(what("cellv"), "is a 1x1 cell array"));
  EXPECT_TRUE(contains(what("sp"), "is a 3x3 sparse matrix"));
  // A name the file does not have at all is still "no column", listing what there is.
  msg = what("qx");
  EXPECT_TRUE(contains(msg, "no column 'qx' (--position); the file has columns: t, qm")) << msg;
  EXPECT_TRUE(contains(msg, "matrix (a 3x4 matrix)")) << msg;
  // Dataset::column says the same as select_column.
  EXPECT_TRUE(contains(error_of([&] { data.column("info"); }), "variable 'info' is a 1x1 struct"));
}

TEST(MatShapes, ScalarAskedForAsAColumn) {
  const fl::Dataset data = fl::read_mat(kEmps);
  const std::string msg = error_of([&] { fl::select_column(data, "gtau", "--input"); });
  EXPECT_TRUE(contains(msg, "variable 'gtau' (--input) is a scalar (1x1); expected a real numeric vector")) << msg;
}

TEST(Columns, FiniteColumnNamesRowAndColumn) {
  TempDir d;
  fl::CsvOptions o = detect();
  o.drop_invalid = false;
  const fl::Dataset data = fl::read_csv(d.file("v.csv", "t,v\n0,1\n1,2\n"), o);
  EXPECT_EQ(fl::finite_column(data, "v", "--velocity")(1), 2.0);
  fl::Dataset bad = data;
  bad.column("v")(1) = std::nan("");
  EXPECT_TRUE(contains(error_of([&] { fl::finite_column(bad, "v"); }), "line 3, column 'v': value is not a finite number"));
}

// The structure walk and the stream check run outside matio's lock, each thread with its own
// buffers: files read on several threads at once give what one thread gives, and a damaged file
// read between them is still refused with its own message.
TEST(MatThreads, ReadsOnSeveralThreadsAgreeWithOne) {
  TempDir d;
  const EmpsQm e = emps_qm();
  const std::string cut = d.file("cut.mat", with_element_data(e.bytes, 4, e.stream.substr(0, e.stream.size() / 2)));
  const std::string pulses = std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS_PULSES.mat";
  const fl::Dataset one = fl::read_mat(kEmps), other = fl::read_mat(pulses);
  const std::string refused = error_of([&] { fl::read_mat(cut); });
  constexpr int kThreads = 4, kReads = 3;
  std::vector<std::string> problems(kThreads);
  std::vector<std::thread> threads;
  for (int k = 0; k < kThreads; ++k) {
    threads.emplace_back([&, k] {
      std::string& problem = problems[static_cast<std::size_t>(k)];
      for (int r = 0; r < kReads && problem.empty(); ++r) {
        const fl::Dataset a = fl::read_mat(k % 2 ? pulses : kEmps);
        const fl::Dataset& expected = k % 2 ? other : one;
        if (a.sha256 != expected.sha256 || a.column("qm") != expected.column("qm") || a.column("vir") != expected.column("vir"))
          problem = "thread " + std::to_string(k) + " read other values";
        if (const std::string msg = error_of([&] { fl::read_mat(cut); }); msg != refused)
          problem = "thread " + std::to_string(k) + ": " + msg;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (const std::string& problem : problems) EXPECT_EQ(problem, "");
  EXPECT_TRUE(contains(refused, "(truncated)")) << refused;
}

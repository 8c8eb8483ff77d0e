// Readers (CSV, MAT), digests, atomic writes and column helpers.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <fstream>
#include <stdexcept>
#include <string>

#include "error_message.hpp"
#include "temp_dir.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/io/mat.hpp"
#include "io/sha256.hpp"

namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

const std::string kEmps = std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat";
const std::string kPulses = std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS_PULSES.mat";



}  // namespace

TEST(Sha256, KnownDigests) {
  // FIPS 180-4 examples.
  EXPECT_EQ(fl::sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(fl::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(fl::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(fl::sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // The EMPS README's digests.
  EXPECT_EQ(fl::sha256_file(kEmps), "6cf6814ae14618795da0101aae2bb97ff0c6351b0501b5492751b02b07facf7e");
  EXPECT_EQ(fl::sha256_file(kPulses), "0eab75bb1f6b16228ee78791343a88bf9bfd9a51036ac9807d7b5fc11c0e1704");
  EXPECT_THROW(fl::sha256_file("/nonexistent/file"), std::invalid_argument);
}

TEST(Csv, ReadsColumnsAndLineNumbers) {
  TempDir d;
  const auto p = d.file("a.csv", "# comment\ntime, \"position\",force\n0,1.5,2\n\n0.001,1.25e-1,-3\n");
  const fl::Dataset data = fl::read_csv(p);
  ASSERT_EQ(data.rows(), 2);
  EXPECT_EQ(data.column_names(), (std::vector<std::string>{"time", "position", "force"}));
  EXPECT_DOUBLE_EQ(data.column("position")(1), 0.125);
  EXPECT_EQ(data.row_label(1), "line 5");
  EXPECT_EQ(data.sha256.size(), 64u);
  EXPECT_EQ(data.file, p);
}

TEST(Csv, NanAndEmptyCellsNameRowAndColumn) {
  TempDir d;
  const auto p = d.file("nan.csv", "time,force\n0,1\n0.001,NaN\n0.002,\n0.003,4\n");
  const std::string msg = error_of([&] { fl::read_csv(p); });
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("column 2 'force'"), std::string::npos) << msg;
  fl::CsvOptions o;
  o.drop_invalid = true;
  const fl::Dataset data = fl::read_csv(p, o);
  ASSERT_EQ(data.rows(), 2);
  EXPECT_EQ(data.row_label(1), "line 5");
  // Text is always an error, even with drop_invalid.
  const auto q = d.file("text.csv", "time,force\n0,1\n0.001,abc\n");
  const std::string text_msg = error_of([&] { fl::read_csv(q, o); });
  EXPECT_NE(text_msg.find("line 3, column 2 'force': expected a number, got 'abc'"), std::string::npos) << text_msg;
}


// A robot log's column the command does not use (a status text, a sensor that dropped out) must not
// refuse the file: with defer_invalid the bad cell is refused only when its column is used, with
// the message the reader would have given, also after resampling.
TEST(Csv, DeferredCellsAreRefusedOnlyWhenTheirColumnIsUsed) {
  TempDir d;
  const auto p = d.file("robot.csv", "time,force,status,temp\n0,1,OK,20\n0.001,2,OK,nan\n0.002,3,FAULT,\n0.003,4,OK,21\n");
  fl::CsvOptions o;
  o.defer_invalid = true;
  fl::Dataset data = fl::read_csv(p, o);
  ASSERT_EQ(data.rows(), 4);
  EXPECT_EQ(fl::finite_column(data, "force", "--force")[3], 4.0);
  EXPECT_EQ(error_of([&] { fl::finite_column(data, "status", "--load"); }),
            p + ": line 2, column 3 'status': expected a number, got 'OK'");
  EXPECT_EQ(error_of([&] { fl::select_column(data, "temp", "--temperature"); }),
            p + ": line 3, column 4 'temp': 'nan'; expected a finite number (use drop_invalid to skip such rows)");
  fl::ResampleOptions r;
  fl::resample_dataset(data, "time", r);
  EXPECT_EQ(fl::finite_column(data, "force")[2], 3.0);
  EXPECT_EQ(error_of([&] { fl::finite_column(data, "temp"); }),
            p + ": line 3, column 4 'temp': 'nan'; expected a finite number (use drop_invalid to skip such rows)");
  // Without defer_invalid the file is refused at its first bad cell, as before.
  EXPECT_EQ(error_of([&] { fl::read_csv(p); }), p + ": line 2, column 3 'status': expected a number, got 'OK'");
}
TEST(Csv, WrongCellCountAndHeaderProblems) {
  TempDir d;
  EXPECT_NE(error_of([&] { fl::read_csv(d.file("n.csv", "a,b\n1,2\n3\n")); }).find("line 3: 1 cells; expected 2"),
            std::string::npos);
  EXPECT_NE(error_of([&] { fl::read_csv(d.file("h.csv", "1,2\n3,4\n")); }).find("header"), std::string::npos);
  EXPECT_NE(error_of([&] { fl::read_csv(d.file("dup.csv", "a,a\n1,2\n")); }).find("duplicate"), std::string::npos);
  EXPECT_NE(error_of([&] { fl::read_csv(d.file("e.csv", "")); }).find("empty"), std::string::npos);
  EXPECT_NE(error_of([&] { fl::read_csv("/nonexistent.csv"); }).find("/nonexistent.csv"), std::string::npos);
}

TEST(Mat, ReadsEmpsVariables) {
  const fl::Dataset data = fl::read_mat(kEmps);
  constexpr Eigen::Index kSamples = 24841;  // README: 24841 samples each
  EXPECT_EQ(data.rows(), kSamples);
  for (const char* c : {"t", "qm", "qg", "vir"}) EXPECT_TRUE(data.has_column(c)) << c;
  ASSERT_TRUE(data.has_scalar("gtau"));
  constexpr double kPrintedDigits = 1e-8;  // the README prints gtau to 10 significant digits
  EXPECT_NEAR(data.scalars.at("gtau"), 35.15065188, kPrintedDigits);
  EXPECT_TRUE(data.has_scalar("kp"));
  EXPECT_EQ(data.sha256, "6cf6814ae14618795da0101aae2bb97ff0c6351b0501b5492751b02b07facf7e");
  EXPECT_EQ(data.row_label(4), "sample 5");
  const fl::Dataset pulses = fl::load_dataset(kPulses);
  EXPECT_TRUE(pulses.has_column("pulses_N"));
}

TEST(Mat, CorruptFilesGiveAnErrorNamingTheFile) {
  TempDir d;
  const auto garbage = d.file("garbage.mat", std::string(4096, '\x5a') + "not a mat file");
  const std::string msg = error_of([&] { fl::read_mat(garbage); });
  EXPECT_NE(msg.find(garbage), std::string::npos) << msg;

  // A real header with the data cut off.
  std::ifstream in(kEmps, std::ios::binary);
  std::string head(2000, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const auto truncated = d.file("truncated.mat", head);
  const std::string msg2 = error_of([&] { fl::read_mat(truncated); });
  EXPECT_NE(msg2.find("truncated"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find(truncated), std::string::npos) << msg2;

  const auto empty = d.file("empty.mat", "");
  EXPECT_NE(error_of([&] { fl::read_mat(empty); }).find(empty), std::string::npos);
  EXPECT_NE(error_of([&] { fl::read_mat("/nonexistent.mat"); }).find("/nonexistent.mat"), std::string::npos);
}

TEST(Load, ChoosesByExtension) {
  TempDir d;
  const auto p = d.file("UPPER.CSV", "t,x\n0,1\n1,2\n");
  EXPECT_EQ(fl::load_dataset(p).rows(), 2);
  // .tsv and .txt are tables by their extension; another name is read with the format given.
  EXPECT_EQ(fl::load_dataset(d.file("data.txt", "t x\n0 1\n1 2\n")).rows(), 2);
  EXPECT_EQ(fl::load_dataset(d.file("data.tsv", "t\tx\n0\t1\n")).rows(), 1);
  const auto q = d.file("robot.log", "t,x\n0,1\n1,2\n");
  const std::string msg = error_of([&] { fl::load_dataset(q); });
  EXPECT_NE(msg.find("unknown data file type '.log'"), std::string::npos) << msg;
  EXPECT_NE(msg.find(".csv"), std::string::npos) << msg;
  EXPECT_NE(msg.find(".mat"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--format csv"), std::string::npos) << msg;
  EXPECT_EQ(fl::load_dataset(q, {}, fl::DataFormat::csv).rows(), 2);
  EXPECT_NE(error_of([&] { fl::load_dataset(q, {}, fl::DataFormat::mat); }).find(q), std::string::npos);
  EXPECT_EQ(fl::parse_data_format("csv", "--format"), fl::DataFormat::csv);
  EXPECT_EQ(fl::parse_data_format("auto", "--format"), fl::DataFormat::by_extension);
  EXPECT_NE(error_of([&] { fl::parse_data_format("xls", "--format"); }).find("--format 'xls': expected csv"),
            std::string::npos);
}

TEST(Columns, MissingColumnListsTheAvailableOnes) {
  const fl::Dataset data = fl::read_mat(kEmps);
  const std::string msg = error_of([&] { fl::select_column(data, "position", "--position"); });
  EXPECT_NE(msg.find("no column 'position'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("qm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vir"), std::string::npos) << msg;
  EXPECT_NE(msg.find("gtau"), std::string::npos) << msg;
  EXPECT_NE(msg.find(kEmps), std::string::npos) << msg;
}

TEST(Columns, ConstantsAsNumbersOrScalarNames) {
  const fl::Dataset data = fl::read_mat(kEmps);
  EXPECT_DOUBLE_EQ(fl::resolve_constant(data, "35.15", "--gain"), 35.15);
  EXPECT_DOUBLE_EQ(fl::resolve_constant(data, "gtau", "--gain"), data.scalars.at("gtau"));
  const std::string msg = error_of([&] { fl::resolve_constant(data, "gain", "--gain"); });
  EXPECT_NE(msg.find("--gain"), std::string::npos) << msg;
  EXPECT_NE(msg.find("kv"), std::string::npos) << msg;
}

TEST(Columns, ScaleFactors) {
  TempDir d;
  fl::Dataset data = fl::read_csv(d.file("s.csv", "t,x\n0,1000\n1,2000\n"));
  fl::apply_scales(data, {"x=1e-3"});
  EXPECT_DOUBLE_EQ(data.column("x")(1), 2.0);
  EXPECT_THROW(fl::apply_scales(data, {"x=abc"}), std::invalid_argument);
  EXPECT_NE(error_of([&] { fl::apply_scales(data, {"y=2"}); }).find("columns: t, x"), std::string::npos);
}

TEST(Columns, TimeMustIncreaseAndBeRegular) {
  TempDir d;
  const fl::Dataset ok = fl::read_csv(d.file("ok.csv", "t\n0\n0.1\n0.2\n0.3\n"));
  constexpr double kStepTol = 1e-12;  // mean of exact-ish decimal steps
  EXPECT_NEAR(fl::check_time(ok, ok.column("t")), 0.1, kStepTol);
  const fl::Dataset back = fl::read_csv(d.file("back.csv", "t\n0\n0.1\n0.1\n0.3\n"));
  const std::string msg = error_of([&] { fl::check_time(back, back.column("t")); });
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("strictly increasing"), std::string::npos) << msg;
  const fl::Dataset gap = fl::read_csv(d.file("gap.csv", "t\n0\n0.1\n0.2\n0.5\n0.6\n"));
  EXPECT_NE(error_of([&] { fl::check_time(gap, gap.column("t")); }).find("line 5"), std::string::npos);
}

TEST(AtomicWrite, WritesAndRefusesToOverwrite) {
  TempDir d;
  const std::string p = (d.path() / "out.json").string();
  fl::write_file_atomic(p, "first");
  const std::string msg = error_of([&] { fl::write_file_atomic(p, "second"); });
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
  EXPECT_NE(msg.find("--overwrite"), std::string::npos) << msg;
  std::ifstream in(p);
  std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(content, "first");
  fl::write_file_atomic(p, "second", {true});
  std::ifstream in2(p);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in2)), {}), "second");
  // Nothing but the target is left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(d.path()), fs::directory_iterator()), 1);
  EXPECT_THROW(fl::write_file_atomic((d.path() / "no/such/dir/x").string(), "x"), std::runtime_error);
}

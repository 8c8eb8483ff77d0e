// Typed errors (frictionlab/error.hpp): the readers, the column checks, the scenario and law
// readers and the output checks throw InputError with a stable code and the fields that locate
// the fault; any other invalid_argument maps to input.invalid; JSON text stays valid UTF-8.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "frictionlab/error.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "temp_dir.hpp"

namespace fl = frictionlab;
using frictionlab::testing::TempDir;

namespace {

// The InputError `f` throws (fails the test when it throws something else or nothing).
std::optional<fl::InputError> input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fl::InputError& e) {
    return e;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got: " << e.what();
    return std::nullopt;
  }
  ADD_FAILURE() << "expected an InputError, nothing was thrown";
  return std::nullopt;
}

}  // namespace

TEST(Errors, InputErrorIsAnInvalidArgumentWithCodeAndFields) {
  const fl::InputError e(fl::errc::data_column_missing, "d.csv: no column 'v'", {.file = "d.csv", .column = "v"});
  const std::invalid_argument& base = e;
  EXPECT_STREQ(base.what(), "d.csv: no column 'v'");
  EXPECT_EQ(e.code(), "data.column_missing");
  EXPECT_EQ(fl::error_code(e), "data.column_missing");
  EXPECT_EQ(e.fields().file, "d.csv");
  EXPECT_EQ(e.fields().column, "v");
  EXPECT_FALSE(e.fields().row.has_value());
  const auto items = e.fields().items();
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0], (std::pair<std::string, std::string>{"file", "d.csv"}));
  EXPECT_EQ(items[1], (std::pair<std::string, std::string>{"column", "v"}));
}

TEST(Errors, OtherExceptionsGetTheGenericCodes) {
  EXPECT_EQ(fl::error_code(std::invalid_argument("x")), "input.invalid");
  EXPECT_EQ(fl::error_code(std::runtime_error("x")), "internal");
  const fl::InternalError internal(fl::errc::output_write_failed, "o.csv: write failed", {.file = "o.csv"});
  const std::runtime_error& base = internal;
  EXPECT_STREQ(base.what(), "o.csv: write failed");
  EXPECT_EQ(fl::error_code(internal), "output.write_failed");
  EXPECT_EQ(fl::error_fields(internal).file, "o.csv");
  EXPECT_TRUE(fl::error_fields(std::invalid_argument("x")).items().empty());
}

TEST(Errors, CsvReaderCodesAndFields) {
  TempDir d;
  const std::string text = d.file("text.csv", "time,position\n0,0\n0.001,abc\n");
  auto e = input_error_of([&] { fl::read_csv(text); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.not_a_number");
  EXPECT_EQ(e->fields().file, text);
  EXPECT_EQ(e->fields().row, 3u);
  EXPECT_EQ(e->fields().column, "position");
  EXPECT_EQ(e->fields().value, "abc");

  const std::string hole = d.file("hole.csv", "time,position\n0,0\n0.001,\n");
  e = input_error_of([&] { fl::read_csv(hole); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.not_finite");
  EXPECT_EQ(e->fields().row, 3u);
  EXPECT_EQ(e->fields().column, "position");

  const std::string huge = d.file("huge.csv", "time,position\n0,1e999\n");
  e = input_error_of([&] { fl::read_csv(huge); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.not_finite");
  EXPECT_EQ(e->fields().value, "1e999");

  const std::string cells = d.file("cells.csv", "time,position\n0,0\n0.001,1,2\n");
  e = input_error_of([&] { fl::read_csv(cells); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.format");
  EXPECT_EQ(e->fields().row, 3u);

  const std::string twice = d.file("twice.csv", "time,time\n0,0\n");
  e = input_error_of([&] { fl::read_csv(twice); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.column_duplicate");
  EXPECT_EQ(e->fields().column, "time");
  EXPECT_EQ(e->fields().row, 1u);

  e = input_error_of([&] { fl::read_csv(d.file("missing.csv")); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.file_unreadable");
  EXPECT_EQ(e->fields().file, d.file("missing.csv"));

  const std::string empty = d.file("empty.csv", "");
  e = input_error_of([&] { fl::read_csv(empty); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.format");
}

TEST(Errors, LoadAndMatCodes) {
  TempDir d;
  const std::string txt = d.file("data.log", "time\n0\n");
  auto e = input_error_of([&] { fl::load_dataset(txt); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.file_type");
  EXPECT_EQ(e->fields().value, ".log");

  e = input_error_of([&] { fl::load_dataset(d.file("none.mat")); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.file_unreadable");

  const std::string junk = d.file("junk.mat", std::string(300, 'x'));
  e = input_error_of([&] { fl::load_dataset(junk); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.format");
  EXPECT_EQ(e->fields().file, junk);
}

TEST(Errors, ColumnChecksCodesAndFields) {
  TempDir d;
  const std::string clean = d.file("clean.csv", "time,position\n0,0\n0.001,1\n");
  const fl::Dataset data = fl::read_csv(clean);
  auto e = input_error_of([&] { fl::select_column(data, "velocity", "--velocity"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.column_missing");
  EXPECT_EQ(e->fields().file, clean);
  EXPECT_EQ(e->fields().column, "velocity");
  EXPECT_EQ(e->fields().option, "--velocity");

  e = input_error_of([&] { fl::parse_scale("position", "--scale"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "option.invalid");
  EXPECT_EQ(e->fields().option, "--scale");
  EXPECT_EQ(e->fields().value, "position");

  e = input_error_of([&] { fl::resolve_constant(data, "gain", "--gain"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "option.invalid");
  EXPECT_EQ(e->fields().option, "--gain");

  fl::Dataset with_nan = data;
  Eigen::VectorXd v(2);
  v << 0.0, std::numeric_limits<double>::quiet_NaN();
  with_nan.add_column("velocity", v);
  e = input_error_of([&] { fl::finite_column(with_nan, "velocity", "--velocity"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "data.not_finite");
  EXPECT_EQ(e->fields().row, 3u);  // the file's line of the second sample
  EXPECT_EQ(e->fields().column, "velocity");
}

TEST(Errors, ScenarioAndLawFileCodesAndFields) {
  TempDir d;
  const std::string unknown = d.file("s.yaml",
                                     "plant: {type: pendulum, m: 1, l: 1, colour: red}\n"
                                     "friction: {law: coulomb, Fc: 0.1}\n"
                                     "duration: 1\n");
  auto e = input_error_of([&] { fl::load_scenario(unknown); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.key_unknown") << e->what();
  EXPECT_EQ(e->fields().file, unknown);
  EXPECT_EQ(e->fields().key, "plant.colour");

  const std::string missing = d.file("m.yaml", "friction: {law: coulomb, Fc: 0.1}\nduration: 1\n");
  e = input_error_of([&] { fl::load_scenario(missing); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.key_missing") << e->what();
  EXPECT_EQ(e->fields().key, "plant");

  const std::string text = d.file("t.yaml",
                                  "plant: {type: pendulum, m: heavy, l: 1}\n"
                                  "friction: {law: coulomb, Fc: 0.1}\n"
                                  "duration: 1\n");
  e = input_error_of([&] { fl::load_scenario(text); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.value") << e->what();
  EXPECT_EQ(e->fields().key, "plant.m");
  EXPECT_EQ(e->fields().value, "heavy");

  const std::string twice = d.file("k.yaml", "plant: {type: pendulum}\nplant: {type: pendulum}\n");
  e = input_error_of([&] { fl::load_scenario(twice); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.key_duplicate") << e->what();
  EXPECT_EQ(e->fields().row, 2u);

  const std::string law = d.file("law.json", "{\"law\": \"coulomb\", \"Fc\": \"one\"}");
  e = input_error_of([&] { fl::load_law(law); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.value") << e->what();
  EXPECT_EQ(e->fields().file, law);
  EXPECT_EQ(e->fields().key, "Fc");

  const std::string broken = d.file("broken.json", "{\"law\": ");
  e = input_error_of([&] { fl::load_law(broken); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "scenario.format");
  EXPECT_EQ(e->fields().file, broken);
}

TEST(Errors, OutputPathCodes) {
  TempDir d;
  const std::string there = d.file("there.json", "{}");
  auto e = input_error_of([&] { fl::check_output_path(there, false); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "output.exists");
  EXPECT_EQ(e->fields().file, there);
  e = input_error_of([&] { fl::check_output_path(d.path().string(), true); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "output.not_writable");
}

TEST(AtomicWrite, DanglingLinkIsReplacedOnlyWithOverwrite) {
  TempDir d;
  const std::string link = d.file("link.json");
  std::filesystem::create_symlink(d.file("nowhere/target.json"), link);
  auto e = input_error_of([&] { fl::write_file_atomic(link, "{}\n"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code(), "output.exists");
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  fl::AtomicWriteOptions w;
  w.overwrite = true;
  fl::write_file_atomic(link, "{}\n", w);
  EXPECT_FALSE(std::filesystem::is_symlink(link));
  EXPECT_TRUE(std::filesystem::is_regular_file(link));
}

TEST(AtomicWrite, LeavesNoTemporaryNames) {
  TempDir d;
  const std::string out = d.file("out.csv");
  fl::write_file_atomic(out, "a\n");
  fl::AtomicWriteOptions w;
  w.overwrite = true;
  fl::write_file_atomic(out, "b\n", w);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(d.path())) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "out.csv");
  }
  EXPECT_EQ(files, 1u);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "b");
}

TEST(JsonText, BytesThatAreNotUtf8AreEscaped) {
  EXPECT_EQ(fl::valid_utf8("plain"), "plain");
  EXPECT_EQ(fl::valid_utf8("caf\xC3\xA9"), "caf\xC3\xA9");  // valid UTF-8 unchanged
  EXPECT_EQ(fl::valid_utf8("caf\xE9"), "caf\\xE9");          // Latin-1 byte escaped
  EXPECT_EQ(fl::valid_utf8("\xC0\xAF"), "\\xC0\\xAF");       // overlong form
  nlohmann::json j = {{"file", "d\xFF.csv"}, {"columns", {"t", "pos\xE9"}}};
  j["k\xFE"] = 1;
  std::string text;
  ASSERT_NO_THROW(text = fl::json_text(j));
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back["file"], "d\\xFF.csv");
  EXPECT_EQ(back["columns"][1], "pos\\xE9");
  EXPECT_EQ(back["k\\xFE"], 1);
}

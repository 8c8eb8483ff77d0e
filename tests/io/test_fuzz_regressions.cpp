// The inputs the fuzzers of tests/fuzz found (tests/fuzz/regressions/<target>/), read by the same
// readers in the ordinary build: each must read, or be refused with std::invalid_argument naming
// the file; never another exception. (make test also replays them under ASan and UBSan.)

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "temp_dir.hpp"
#include "../fuzz/scenario_data.hpp"
#include "frictionlab/io/csv.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/xy_table.hpp"

namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

const fs::path kFuzzDir = fs::path(FRICTIONLAB_SOURCE_DIR) / "tests" / "fuzz";

std::vector<fs::path> regressions(const std::string& target) {
  std::vector<fs::path> out;
  const fs::path dir = kFuzzDir / "regressions" / target;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  return out;
}

// Copies `input` to `name` in `dir`, runs `read` on it; fails the test on any exception other than
// std::invalid_argument, or on one whose message does not name the file.
void expect_read_or_refused(const fs::path& input, const TempDir& dir, const std::string& name,
                            const std::function<void(const std::string&)>& read) {
  const std::string path = dir.file(name);
  fs::copy_file(input, path, fs::copy_options::overwrite_existing);
  try {
    read(path);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << input << ": the message does not name the file: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << input << ": not std::invalid_argument: " << e.what();
  }
}

// The types of the compensators a scenario's plant runs ("x: lugre-observer, y: none" on an
// xy-table), "" when it runs none.
std::string compensations(const fl::Plant& plant) {
  auto type_of = [](const fl::Compensator* c) { return c ? c->type() : std::string(); };
  if (const auto* loop = dynamic_cast<const fl::ClosedLoop*>(&plant)) return type_of(loop->compensator());
  if (const auto* loop = dynamic_cast<const fl::EmpsPdLoop*>(&plant)) return type_of(loop->compensator());
  if (const auto* xy = dynamic_cast<const fl::XyTable*>(&plant)) {
    const std::string x = type_of(xy->axis(0).compensator.get()), y = type_of(xy->axis(1).compensator.get());
    return x.empty() && y.empty() ? "" : "x: " + (x.empty() ? "none" : x) + ", y: " + (y.empty() ? "none" : y);
  }
  return "";
}

}  // namespace

TEST(FuzzRegressions, CsvInputsReadOrAreRefused) {
  TempDir dir;
  for (const fs::path& input : regressions("fuzz_csv")) {
    expect_read_or_refused(input, dir, "data.csv", [](const std::string& p) { (void)fl::load_dataset(p); });
    fl::CsvOptions lenient;
    lenient.drop_invalid = true;
    expect_read_or_refused(input, dir, "data.csv", [&](const std::string& p) { (void)fl::read_csv(p, lenient); });
  }
}

TEST(FuzzRegressions, MatInputsReadOrAreRefused) {
  TempDir dir;
  const std::vector<fs::path> inputs = regressions("fuzz_mat");
  EXPECT_FALSE(inputs.empty());  // the huge-variable files below are kept there
  for (const fs::path& input : inputs)
    expect_read_or_refused(input, dir, "data.mat", [](const std::string& p) { (void)fl::load_dataset(p); });
}

// 1 kB files whose compressed variable declares 16 x 2^28 (34 GB) and 16 x 50533889 (6.5 GB)
// doubles: refused as corrupt before matio allocates (it used to end the variables there
// silently, or hand 6.5 GB of zeros to the reader). The zlib stream check or the declared-size
// check, whichever comes first, names the file.
TEST(FuzzRegressions, MatVariableLargerThanTheFileCouldHoldIsRefused) {
  TempDir dir;
  for (const char* name : {"huge_variable_32GB.mat", "huge_matrix_6GB.mat"}) {
    const std::string path = dir.file(name);
    fs::copy_file(kFuzzDir / "regressions" / "fuzz_mat" / name, path);
    const std::string message = error_of([&] { (void)fl::load_dataset(path); });
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("corrupt"), std::string::npos) << message;
  }
}

// A 728-byte file whose dimensions tag is of data type 2048: matio read a name tag inside the
// data and allocated 4.2 GB for it. Refused by the header-tag check before matio opens the file.
TEST(FuzzRegressions, MatHeaderTagOfAnotherTypeIsRefused) {
  TempDir dir;
  const std::string path = dir.file("dims.mat");
  fs::copy_file(kFuzzDir / "regressions" / "fuzz_mat" / "dims_tag_of_another_type_4GB_name.mat", path);
  const std::string message = error_of([&] { (void)fl::load_dataset(path); });
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("variable 2"), std::string::npos) << message;
  EXPECT_NE(message.find("dimensions declares data type 2048 and 5 bytes; expected miINT32"), std::string::npos) << message;
}

TEST(FuzzRegressions, ScenarioInputsReadOrAreRefused) {
  TempDir dir;
  for (const auto& [name, text] : fl::fuzz::kScenarioTextFiles) std::ofstream(dir.file(name)) << text;
  fs::copy_file(kFuzzDir / fl::fuzz::kScenarioMat, dir.file("data.mat"));
  for (const fs::path& input : regressions("fuzz_scenario"))
    expect_read_or_refused(input, dir, "scenario.yaml", [](const std::string& p) { (void)fl::load_scenario(p); });
}

// The hand-made seeds of fuzz_scenario (the corpus files with an extension) are scenarios the
// parser accepts, beside the same data and model files as the fuzzer's: a seed refused at its first
// key would leave the fuzzer to find the deeper readers (an xy-table's axes, a compensation's model
// file) by chance. The xy-table and compensation seeds build what they name.
TEST(FuzzSeeds, ScenarioSeedsLoad) {
  TempDir dir;
  for (const auto& [name, text] : fl::fuzz::kScenarioTextFiles) std::ofstream(dir.file(name)) << text;
  fs::copy_file(kFuzzDir / fl::fuzz::kScenarioMat, dir.file("data.mat"));
  int seeds = 0;
  for (const auto& e : fs::directory_iterator(kFuzzDir / "corpus" / "fuzz_scenario")) {
    if (!e.path().has_extension()) continue;  // inputs the fuzzer kept: any input may be refused
    const std::string path = dir.file("scenario.yaml");
    fs::copy_file(e.path(), path, fs::copy_options::overwrite_existing);
    ++seeds;
    try {
      const fl::Scenario sc = fl::load_scenario(path);
      const std::string file = e.path().filename().string();
      if (file.rfind("xy_", 0) == 0) {
        ASSERT_TRUE(sc.plant) << file;
        EXPECT_EQ(sc.plant->type(), "xy-table") << file;
        EXPECT_EQ(sc.inputs.size(), 2u) << file;
      }
      const std::string built = compensations(*sc.plant);
      if (file == "xy_axis_compensations.yaml") {
        EXPECT_EQ(built, "x: lugre-observer, y: disturbance-observer");
      } else if (file == "xy_shared_feedback.yaml") {
        EXPECT_EQ(built, "x: feedback, y: none");  // y says `compensation: none`
      } else if (file == "xy_circle_compensated.yaml") {
        EXPECT_EQ(built, "x: feedforward, y: feedforward");
      } else if (file.find("compensat") != std::string::npos) {
        EXPECT_NE(built, "") << file << ": no compensation built";
      }
    } catch (const std::exception& e2) {
      ADD_FAILURE() << e.path() << ": a seed the parser refuses: " << e2.what();
    }
  }
  EXPECT_GE(seeds, 20);  // the 14 single-axis seeds and the xy-table and compensation ones
}

TEST(FuzzRegressions, LawInputsReadOrAreRefused) {
  TempDir dir;
  for (const fs::path& input : regressions("fuzz_law")) {
    expect_read_or_refused(input, dir, "law.json", [](const std::string& p) { (void)fl::load_law(p); });
    expect_read_or_refused(input, dir, "law.yaml", [](const std::string& p) { (void)fl::load_law(p); });
  }
}

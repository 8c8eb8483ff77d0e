// The library side of the bad-input contract (docs/guarantees.md): how outputs are written
// (directories refused, devices and FIFOs written through, never replaced), scenario files whose
// output would not fit in memory, keys given twice, and the one MODEL.json reader.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "error_message.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "temp_dir.hpp"

namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(OutputPath, DirectoryIsRefusedWithOrWithoutOverwrite) {
  TempDir d;
  const std::string dir = d.path().string();
  for (bool overwrite : {false, true}) {
    EXPECT_EQ(error_of([&] { fl::check_output_path(dir, overwrite); }), dir + " is a directory; expected a file name");
    EXPECT_EQ(error_of([&] { fl::write_file_atomic(dir, "x", {overwrite}); }), dir + " is a directory; expected a file name");
  }
  EXPECT_TRUE(fs::is_directory(d.path()));
}

TEST(OutputPath, KindsOfTarget) {
  TempDir d;
  const fs::path file = d.path() / "out.json";
  EXPECT_EQ(fl::check_output_path(file.string(), false), fl::OutputKind::create);
  write(file, "old");
  EXPECT_EQ(error_of([&] { fl::check_output_path(file.string(), false); }),
            file.string() + " exists; pass --overwrite to replace it");
  EXPECT_EQ(fl::check_output_path(file.string(), true), fl::OutputKind::replace);
  EXPECT_EQ(fl::check_output_path("/dev/null", false), fl::OutputKind::write_through);
  const std::string nodir = (d.path() / "no" / "x.json").string();
  EXPECT_EQ(error_of([&] { fl::check_output_path(nodir, false); }),
            nodir + ": directory " + (d.path() / "no").string() + " does not exist");
  EXPECT_EQ(error_of([&] { fl::check_output_path("/dev/frictionlab-no-such-node", true); }),
            "/dev/frictionlab-no-such-node: no such file under /dev or /proc (frictionlab creates no files there)");
}

TEST(OutputPath, SymbolicLinkKeepsTheLinkAndReplacesItsTarget) {
  TempDir d;
  const fs::path target = d.path() / "model-v1.json", link = d.path() / "model.json";
  write(target, "old");
  fs::create_symlink(target, link);
  fl::write_file_atomic(link.string(), "new", {true});
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(slurp(target), "new");
}

TEST(OutputPath, FifoIsWrittenThroughNeverReplaced) {
  TempDir d;
  const fs::path fifo = d.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (bool overwrite : {false, true}) {
    std::string got;
    std::thread reader([&] { got = slurp(fifo); });
    fl::write_file_atomic(fifo.string(), "through the pipe\n", {overwrite});
    reader.join();
    EXPECT_EQ(got, "through the pipe\n");
    EXPECT_TRUE(fs::is_fifo(fifo)) << "overwrite " << overwrite;
  }
  EXPECT_EQ(fl::check_output_path(fifo.string(), false), fl::OutputKind::write_through);
}

TEST(OutputPath, CharacterDeviceIsWrittenThroughNeverReplaced) {
  TempDir d;
  const fs::path null = d.path() / "null";
  // A private copy of /dev/null (needs root, as CI runs): a regression must not replace the real one.
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs root";
  for (bool overwrite : {false, true}) {
    fl::write_file_atomic(null.string(), "discarded", {overwrite});
    EXPECT_TRUE(fs::is_character_file(null)) << "overwrite " << overwrite;
  }
  EXPECT_FALSE(fs::exists(null.string() + ".tmp")) << "no temporary left";
  for (const auto& e : fs::directory_iterator(d.path())) EXPECT_EQ(e.path(), null) << "left behind: " << e.path();
}

// ---------------------------------------------------------------------------------------------

const std::string kPendulum = std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/craig_pendulum_coulomb.yaml";

YAML::Node pendulum() { return YAML::LoadFile(kPendulum); }

TEST(ScenarioSize, OutputLargerThanMemoryIsRefusedNamingTheKey) {
  YAML::Node y = pendulum();
  y["duration"] = 1e9;
  const std::string msg = error_of([&] { fl::scenario_from_yaml(y, "s.yaml"); });
  EXPECT_EQ(msg.rfind("s.yaml: duration and output_rate: 1000000000 s at 200 Hz gives 2e+11 output rows (shorten duration or lower output_rate): that needs ", 0), 0u)
      << msg;
  EXPECT_NE(msg.find("of memory; the memory budget is "), std::string::npos) << msg;
  EXPECT_NE(msg.find("this process may use; raise it with --budget FACTOR, in Python frictionlab.set_budget_factor(FACTOR))"), std::string::npos) << msg;
  y.remove("output_rate");
  y["duration"] = 1e9;
  const std::string dflt = error_of([&] { fl::scenario_from_yaml(y, "s.yaml"); });
  EXPECT_NE(dflt.find("s.yaml: duration: 1000000000 s at 100 Hz (the default output_rate) gives 1e+11 output rows"),
            std::string::npos)
      << dflt;
}

TEST(ScenarioSize, SimulateRefusesBeforeAllocating) {
  fl::Scenario sc = fl::load_scenario(kPendulum);
  sc.options.output_rate = 1e300;
  const std::string msg = error_of([&] { fl::simulate(sc); });
  EXPECT_NE(msg.find("output_rate = 1e+300 Hz give"), std::string::npos) << msg;
  // time and 9 columns of 8 bytes per row: the figure the message reports.
  sc.options.output_rate = 100;
  sc.options.duration = 10;
  EXPECT_DOUBLE_EQ(fl::output_rows(sc.options), 1001.0);
  EXPECT_DOUBLE_EQ(fl::output_bytes(sc.options), 1001.0 * 10 * 8);
  EXPECT_EQ(fl::format_bytes(14.4e12), "14.4 TB");
  EXPECT_EQ(fl::format_bytes(512), "512 bytes");
}

TEST(ScenarioKeys, KeyGivenTwiceIsRefusedWithItsLine) {
  const std::string text = "plant: {type: pendulum, m: 1, l: 1}\nfriction:\n  law: coulomb\n  Fc: 0.1\n  Fc: 0.2\nduration: 1\n";
  EXPECT_EQ(error_of([&] { fl::scenario_from_yaml(YAML::Load(text), "s.yaml"); }),
            "s.yaml: line 5: key 'Fc' given twice (first on line 4); give each key once");
  const std::string top = "duration: 1\nplant: {type: pendulum, m: 1, l: 1}\nfriction: {law: coulomb, Fc: 0.1}\nduration: 2\n";
  EXPECT_EQ(error_of([&] { fl::scenario_from_yaml(YAML::Load(top), "s.yaml"); }),
            "s.yaml: line 4: key 'duration' given twice (first on line 1); give each key once");
}

TEST(ScenarioKeys, DefaultsComeFromTheParameterStructs) {
  YAML::Node y = pendulum();
  y["plant"].remove("g");
  const fl::Scenario sc = fl::scenario_from_yaml(y, "s.yaml");
  EXPECT_EQ(sc.options.output_rate, 200.0);
  y.remove("output_rate");
  EXPECT_EQ(fl::scenario_from_yaml(y, "s.yaml").options.output_rate, fl::SimulationOptions{}.output_rate);
}

TEST(ScenarioKeys, ValueOfTheWrongKindIsBadInput) {
  YAML::Node y = pendulum();
  y["friction"]["law"] = std::vector<std::string>{"coulomb"};
  EXPECT_EQ(error_of([&] { fl::scenario_from_yaml(y, "s.yaml"); }), "s.yaml: friction.law: expected a name");
}

TEST(ScenarioKeys, ModelValuesAreBlamedOnTheModelFile) {
  const std::string text = "plant: {type: axis}\nduration: 1\n";
  fl::ScenarioOptions o;
  o.law = fl::FrictionLaw::from_spec({"coulomb", {{"Fc", 1.0}}, {}, {}});
  o.axis = fl::AxisParams{};
  o.axis->M = -1;
  o.model_source = "model.json";
  const std::string msg = error_of([&] { fl::scenario_from_yaml(YAML::Load(text), "s.yaml", o); });
  EXPECT_EQ(msg.rfind("model.json: parameters: ", 0), 0u) << msg;
  EXPECT_EQ(msg.find("s.yaml"), std::string::npos) << msg;
}

// ---------------------------------------------------------------------------------------------

TEST(ModelFile, OneStrictReader) {
  TempDir d;
  const std::string ok = R"({"schema": 1, "status": "ok", "law": {"law": "coulomb", "Fc": 1.5}})";
  write(d.path() / "ok.json", ok + "\n");
  EXPECT_EQ(fl::load_law((d.path() / "ok.json").string()).name(), "coulomb");

  const std::string garbage = (d.path() / "garbage.json").string();
  write(garbage, ok + "\n}\n");
  const std::string g = error_of([&] { fl::load_law(garbage); });
  EXPECT_EQ(g.rfind(garbage + ": not valid JSON (", 0), 0u) << g;
  EXPECT_NE(g.find("line 2"), std::string::npos) << g;
  EXPECT_EQ(error_of([&] { fl::read_model_json(garbage); }), g);

  const std::string failed = (d.path() / "failed.json").string();
  write(failed, R"({"schema": 1, "status": "error", "message": "no excitation", "method": "idim"})");
  EXPECT_EQ(error_of([&] { fl::load_law(failed); }),
            failed + ": the identification failed (status \"error\": no excitation); it holds no model to use");

  const std::string dir = d.path().string();
  EXPECT_EQ(error_of([&] { fl::read_model_json(dir); }),
            dir + " is a directory; expected a JSON model file (MODEL.json of frictionlab identify --json)");
}

TEST(LawFile, KeyGivenTwiceIsRefused) {
  TempDir d;
  const std::string p = (d.path() / "law.yaml").string();
  write(p, "law: coulomb\nFc: 1\nFc: 2\n");
  EXPECT_EQ(error_of([&] { fl::load_law(p); }), p + ": line 3: key 'Fc' given twice (first on line 2); give each key once");
}

}  // namespace

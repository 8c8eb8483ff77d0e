// The work and memory budget (frictionlab/budget.hpp, docs/guarantees.md): its factor, the memory
// it is a share of, an output estimate that covers what a run allocates, and input files read
// within it (a device refused at once, a FIFO read as a stream, once).

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include "error_message.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "io/input_file.hpp"
#include "temp_dir.hpp"

namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

// Restores the factor 1 whatever a test did.
struct FactorGuard {
  ~FactorGuard() { fl::set_budget_factor(1.0); }
};

std::string code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fl::InputError& e) {
    return e.code();
  }
  return "(none)";
}

TEST(Budget, FactorScalesWorkAndMemoryAndIsChecked) {
  FactorGuard guard;
  EXPECT_EQ(fl::work_budget(), fl::kDefaultWorkBudget);
  EXPECT_EQ(fl::memory_budget(), 0.5 * fl::memory_available());
  fl::set_budget_factor(4);
  EXPECT_EQ(fl::work_budget(), 4 * fl::kDefaultWorkBudget);
  EXPECT_EQ(fl::memory_budget(), fl::memory_available()) << "never beyond all the memory the process may use";
  fl::set_budget_factor(1e-3);
  EXPECT_EQ(fl::memory_budget(), 0.5e-3 * fl::memory_available());
  for (double bad : {0.0, -1.0, 1e-9, double(NAN), double(INFINITY)})
    EXPECT_EQ(code_of([&] { fl::set_budget_factor(bad); }), "option.out_of_range") << bad;
  EXPECT_EQ(fl::budget_factor(), 1e-3) << "a refused factor leaves the one in effect";
}

TEST(Budget, MemoryIsTheCgroupLimitOrThePhysicalMemory) {
  const double physical = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  EXPECT_GT(fl::memory_available(), 0.0);
  EXPECT_LE(fl::memory_available(), physical);
  std::ifstream in("/sys/fs/cgroup/memory.max");  // the root cgroup of a v2 system (a container's own)
  std::string limit;
  if (in >> limit && limit != "max") {
    EXPECT_LE(fl::memory_available(), std::stod(limit));
  }
}

TEST(Budget, ChecksNameWhatAndTheSize) {
  const std::string m = error_of([] { fl::check_memory(1e30, "s.yaml: duration: 1e30 s", {.file = "s.yaml"}); });
  EXPECT_EQ(m.rfind("s.yaml: duration: 1e30 s: that needs 1e+12 EB of memory; the memory budget is ", 0), 0u) << m;
  EXPECT_NE(m.find("raise it with --budget FACTOR"), std::string::npos) << m;
  EXPECT_EQ(code_of([] { fl::check_memory(NAN, "x"); }), "budget.memory") << "NaN is never within the budget";
  EXPECT_EQ(code_of([] { fl::check_work(INFINITY, "runs", "x"); }), "budget.work");
  EXPECT_EQ(error_of([] { fl::check_work(2e9, "runs", "--runs 2000000000"); }),
            "--runs 2000000000: that is 2e+09 runs; the work budget is 1e+09 work units (the default; raise it with --budget FACTOR, "
            "in Python frictionlab.set_budget_factor(FACTOR))");
  EXPECT_NO_THROW(fl::check_work(fl::kDefaultWorkBudget, "runs", "x")) << "the budget itself is within it";
}

// The output estimate covers every column a run reserves (it was 9 columns short of time and
// the environment's load and temperature): the columns' capacity, in bytes, never exceeds it.
double column_bytes(const fl::Trajectory& tr) {
  double bytes = 0;
  const auto add = [&](const fl::ContactColumns& c) {
    for (const auto* col : {&c.position, &c.velocity, &c.friction, &c.applied, &c.current, &c.voltage, &c.reference,
                            &c.stuck, &c.drive, &c.load, &c.temperature})
      bytes += 8.0 * static_cast<double>(col->capacity());
    for (const auto& z : c.law_state) bytes += 8.0 * static_cast<double>(z.capacity());
  };
  bytes += 8.0 * static_cast<double>(tr.time.capacity());
  add(tr);
  for (const auto& o : tr.others) add(o);
  return bytes;
}

TEST(Budget, OutputEstimateCoversTheRunsColumns) {
  for (const char* file : {"craig_pendulum_coulomb.yaml", "canudas_presliding.yaml"}) {
    const fl::Scenario sc = fl::load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + file);
    const fl::Trajectory tr = fl::simulate(sc);
    const int states = sc.law.is_dynamic() ? sc.law.num_states() : 0;
    EXPECT_LE(column_bytes(tr), fl::output_bytes(sc.options, states)) << file;
    EXPECT_GE(column_bytes(tr), 0.9 * fl::output_bytes(sc.options, states)) << file << ": the estimate is not loose either";
  }
}

TEST(InputFile, DevicesAreRefusedAtOnceAndFifosReadAsStreams) {
  TempDir d;
  const fs::path zero = d.path() / "zero.csv";
  fs::create_symlink("/dev/zero", zero);
  EXPECT_EQ(error_of([&] { fl::read_input_file(zero.string(), "CSV file", fl::errc::data_file_unreadable); }),
            zero.string() + " is a character device; expected the CSV file as a regular file or a pipe");
  EXPECT_EQ(code_of([&] { fl::read_input_file(d.path().string(), "scenario file", fl::errc::scenario_format); }),
            "scenario.format");
  const fs::path fifo = d.path() / "in.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << "t,x\n0,1\n1,2\n"; });
  EXPECT_EQ(fl::read_input_file(fifo.string(), "CSV file", fl::errc::data_file_unreadable), "t,x\n0,1\n1,2\n");
  writer.join();
  // A stream past the budget is refused naming the file and what was read.
  FactorGuard guard;
  fl::set_budget_factor(1e-6);
  std::signal(SIGPIPE, SIG_IGN);
  std::thread endless([&] {
    std::ofstream out(fifo);
    const std::string block(1 << 16, '1');
    while (out << block) {
    }
  });
  const std::string m = error_of([&] { fl::read_input_file(fifo.string(), "CSV file", fl::errc::data_file_unreadable); });
  EXPECT_NE(m.find("in.csv: the CSV file ("), std::string::npos) << m;
  EXPECT_NE(m.find("read from a pipe so far)"), std::string::npos) << m;
  // The writer ends when the reader has closed the pipe (SIGPIPE is ignored: the write fails).
  endless.join();
}

}  // namespace

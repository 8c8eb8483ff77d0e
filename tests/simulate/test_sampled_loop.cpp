// The EMPS discrete PD loop (simulate/emps_pd_loop.hpp) in the engine, and the `data` input of
// scenario files.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "frictionlab/io/mat.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "temp_dir.hpp"

namespace fl = frictionlab;

namespace {

fl::Scenario emps(double duration, fl::SolverMode mode) {
  fl::ScenarioOptions so;
  so.data = std::make_shared<const fl::Dataset>(fl::read_mat(std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat"));
  fl::Scenario sc = fl::load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/emps_closed_loop.yaml", so);
  sc.options.duration = duration;
  sc.options.mode = mode;
  sc.options.dt = 1e-6;
  return sc;
}

}  // namespace

// The hybrid engine integrates the plant exactly between samples (the controller output is held,
// stick/slip events located by root finding). A fine fixed step converges to it at O(dt): with
// dt = 1 us the two agree to well below the micrometre the closed loop turns into newtons
// (kp kv gtau = 1.4e6 N/m): 2.5e-8 m observed over 2 s (the fixed step's O(dt) error); 1e-7 m
// leaves margin for libm differences, and is 1/30 of the 3.5e-6 m rms error against the
// measurement.
TEST(SampledLoop, HybridAgreesWithFineFixedStep) {
  constexpr double kPositionTol = 1e-7;  // m
  const fl::Trajectory a = fl::simulate(emps(2.0, fl::SolverMode::hybrid));
  const fl::Trajectory b = fl::simulate(emps(2.0, fl::SolverMode::fixed_step));
  ASSERT_EQ(a.rows(), b.rows());
  double worst = 0;
  for (std::size_t k = 0; k < a.rows(); ++k) worst = std::max(worst, std::abs(a.position[k] - b.position[k]));
  std::printf("max |q_hybrid - q_fixed(1 us)| over 2 s = %.3g m\n", worst);
  EXPECT_LT(worst, kPositionTol);
}

// The recorded voltage is the controller's own formula on the simulated samples.
TEST(SampledLoop, VoltageFollowsTheControlLaw) {
  fl::Scenario sc = emps(0.5, fl::SolverMode::automatic);
  const auto& p = dynamic_cast<const fl::EmpsPdLoop&>(*sc.plant).params();
  const fl::Trajectory tr = fl::simulate(sc);
  const auto qg = fl::read_mat(std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat").column("qg");
  constexpr double kTol = 1e-9;  // V: rounding of the formula only
  for (std::size_t k = 2; k < tr.rows(); ++k) {
    const double qf = 0.5 * tr.position[k] + 0.5 * tr.position[k - 1];
    const double qf1 = 0.5 * tr.position[k - 1] + 0.5 * tr.position[k - 2];
    const double v = std::clamp(p.kp * p.kv * (qg[static_cast<Eigen::Index>(k)] - tr.position[k]) - p.kv * (qf - qf1) / p.dt, -p.limit, p.limit);
    ASSERT_NEAR(tr.voltage[k], v, kTol) << "sample " << k << " stuck " << tr.stuck[k] << " " << tr.stuck[k - 1] << " v " << tr.velocity[k];
  }
}

TEST(DataInput, ReadsAColumnOnARegularGrid) {
  const frictionlab::testing::TempDir tmp;
  const auto& dir = tmp.path();
  {
    std::ofstream f(dir / "in.csv");
    f << "time,u\n1.0,0\n1.5,2\n2.0,4\n";
  }
  const YAML::Node root = YAML::Load(
      "plant: {type: axis, M: 1}\nfriction: {law: viscous, Fv: 1}\n"
      "input: {type: data, file: in.csv, column: u, scale: 0.5}\n");
  fl::ScenarioOptions so;
  so.base_dir = dir.string();
  const fl::Scenario sc = fl::scenario_from_yaml(root, "test.yaml", so);
  EXPECT_DOUBLE_EQ(sc.options.duration, 1.0);  // the data's span
  EXPECT_DOUBLE_EQ(sc.input.at(0.25).value, 0.5);  // linear, scaled, from t = 0
  const YAML::Node bad = YAML::Load("plant: {type: axis, M: 1}\nfriction: {law: viscous, Fv: 1}\n"
                                    "input: {type: data, file: in.csv, column: qg}\n");
  try {
    fl::scenario_from_yaml(bad, "test.yaml", so);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no column 'qg'"), std::string::npos) << e.what();
  }
}

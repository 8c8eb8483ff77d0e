// IDIM-IV (identify/idim.hpp, IdimIvOptions) on the EMPS benchmark (data/emps: the record is
// taken in the benchmark's PD position loop, control/emps_pd.hpp) and its refusals: no
// controller, no reference, a reference of the wrong length, terms it cannot simulate, and an
// iteration that does not converge. The controller from a scenario (idim_iv_scenario) with the
// options over it, and the scenarios it cannot simulate.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <variant>
#include <vector>
#include <string>

#include "frictionlab/error.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/idim_record.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "frictionlab/io/mat.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "../temp_dir.hpp"

namespace fl = frictionlab;

namespace {

struct Emps {
  fl::IdimData data;
  fl::EmpsPdParams controller;
};

// The identification record with its reference qg, and the benchmark's controller with the
// gains of the file (kp 1/s, kv V/(m/s), gtau N/V), +-10 V, applied one sample later.
Emps load_emps() {
  const fl::Dataset d = fl::read_mat(std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat");
  Emps e;
  e.data = fl::idim_record(d, {"t", "qm", "vir", "gtau"});
  e.data.reference = d.column("qg");
  e.controller.kp = d.scalars.at("kp");
  e.controller.kv = d.scalars.at("kv");
  e.controller.gtau = d.scalars.at("gtau");
  e.controller.limit = 10;
  e.controller.delay = 1;
  return e;
}

fl::IdimOptions iv_options(const Emps& e) {
  fl::IdimOptions o;
  o.iv.enabled = true;
  o.iv.controller = e.controller;
  o.iv.sample_at_record_rate = true;
  return o;
}

// The published IDIM-LS figures (data/emps/README.md; Janot, Gautier, Brunot 2019).
constexpr double kPublishedM = 95.1089, kPublishedFv = 203.5034, kPublishedFc = 20.3935;

}  // namespace

TEST(IdimIv, EmpsConvergesNearTheLeastSquaresEstimate) {
  const Emps e = load_emps();
  const fl::Result ls = fl::identify_idim(e.data);
  const fl::Result iv = fl::identify_idim(e.data, iv_options(e));
  ASSERT_TRUE(ls.ok()) << ls.message;
  ASSERT_TRUE(iv.ok()) << iv.message;
  EXPECT_EQ(iv.diagnostics.texts.at("estimator"), "idim-iv");
  const double iterations = iv.diagnostics.numbers.at("iv_iterations");
  // Measured: see docs/identify.md. The model's loop tracks the record closely, so the
  // instruments are strong and the iteration settles in a few steps.
  constexpr int kFewIterations = 10;
  EXPECT_GE(iterations, 1);
  EXPECT_LE(iterations, kFewIterations);
  EXPECT_LE(iv.diagnostics.numbers.at("iv_relative_change"), 1e-4);
  // Measured (docs/identify.md): IV moves M, Fv and Fc by 0.03, 0.12 and 0.12 % from IDIM-LS
  // (2 iterations); 0.5 % (the band the published figures are checked to in test_idim_emps.cpp)
  // leaves room for the simulation's rounding on other platforms and fails on instruments that
  // are not the loop's. The published IDIM-LS values are met to the same band.
  constexpr double kIvNearLs = 5e-3, kNearPublished = 5e-3;
  for (const char* name : {"M", "Fv", "Fc"})
    EXPECT_NEAR(iv.value(name), ls.value(name), kIvNearLs * std::abs(ls.value(name))) << name;
  EXPECT_NEAR(iv.value("M"), kPublishedM, kNearPublished * kPublishedM);
  EXPECT_NEAR(iv.value("Fv"), kPublishedFv, kNearPublished * kPublishedFv);
  EXPECT_NEAR(iv.value("Fc"), kPublishedFc, kNearPublished * kPublishedFc);
  // The least-squares values are kept for comparison; the std are the IV sandwich's.
  EXPECT_DOUBLE_EQ(iv.diagnostics.groups.at("ls_estimate").at("M"), ls.value("M"));
  for (const auto& p : iv.parameters) {
    EXPECT_TRUE(std::isfinite(p.std) && p.std > 0) << p.name;
    ASSERT_TRUE(p.std_ols.has_value()) << p.name;
    EXPECT_GT(*p.std_ols, 0) << p.name;
  }
  // Strong instruments: the simulated loop moves like the record.
  const double relevance = iv.diagnostics.numbers.at("iv_min_canonical_correlation");
  EXPECT_GT(relevance, 0.9);
  EXPECT_LE(relevance, 1.0 + 1e-12);
  EXPECT_GT(iv.diagnostics.groups.at("iv_instrument_correlation").at("M"), 0.9);
  EXPECT_TRUE(iv.law.has_value());
}

TEST(IdimIv, WithoutAControllerIsRefusedNamingWhatToGive) {
  Emps e = load_emps();
  fl::IdimOptions o;
  o.iv.enabled = true;
  try {
    (void)fl::identify_idim(e.data, o);
    FAIL() << "no error";
  } catch (const fl::InputError& err) {
    EXPECT_EQ(err.code(), "option.invalid");
    const std::string m = err.what();
    for (const char* want : {"--controller", "--kp", "--kv", "--drive-gain"}) EXPECT_NE(m.find(want), std::string::npos) << m;
  }
  o = iv_options(e);
  e.data.reference.resize(0);
  try {
    (void)fl::identify_idim(e.data, o);
    FAIL() << "no error";
  } catch (const fl::InputError& err) {
    EXPECT_NE(std::string(err.what()).find("--reference COLUMN"), std::string::npos) << err.what();
  }
}

TEST(IdimIv, AReferenceOfTheWrongLengthOrNotFiniteIsRefused) {
  Emps e = load_emps();
  const fl::IdimOptions o = iv_options(e);
  e.data.reference.conservativeResize(e.data.reference.size() - 1);
  try {
    (void)fl::identify_idim(e.data, o);
    FAIL() << "no error";
  } catch (const fl::InputError& err) {
    EXPECT_EQ(err.code(), "data.column_length");
    EXPECT_NE(std::string(err.what()).find("reference"), std::string::npos) << err.what();
  }
  e = load_emps();
  e.data.reference(7) = std::nan("");
  try {
    (void)fl::identify_idim(e.data, o);
    FAIL() << "no error";
  } catch (const fl::InputError& err) {
    EXPECT_EQ(err.code(), "data.not_finite");
    EXPECT_NE(std::string(err.what()).find("sample 8"), std::string::npos) << err.what();
  }
}

TEST(IdimIv, TermsThatMakeNoSimulableModelAreRefused) {
  const Emps e = load_emps();
  fl::IdimOptions o = iv_options(e);
  o.terms = {"inertia", "viscous", "coulomb", "offset", "ripple"};
  o.ripple_period = 0.01;
  EXPECT_THROW((void)fl::identify_idim(e.data, o), fl::InputError);
  o.terms = {"viscous", "coulomb"};
  EXPECT_THROW((void)fl::identify_idim(e.data, o), fl::InputError);
}

TEST(IdimIv, NotConvergedIsAStatusErrorNamingTheOption) {
  const Emps e = load_emps();
  fl::IdimOptions o = iv_options(e);
  o.iv.max_iterations = 1;
  o.iv.tolerance = 1e-15;  // below what one step from least squares can reach
  const fl::Result r = fl::identify_idim(e.data, o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("did not converge in 1 iterations"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("--iv-iterations"), std::string::npos) << r.message;
  EXPECT_TRUE(r.parameters.empty());
}

TEST(IdimIv, ARunawayLoopIsAStatusErrorNotNumbers) {
  Emps e = load_emps();
  fl::IdimOptions o = iv_options(e);
  // A controller that is not the experiment's: a velocity gain 4000 times EMPS's, without
  // saturation, makes the sampled loop unstable (kv gtau dt / M is about 370, far above 2): the
  // model's simulated loop runs away and IDIM-IV must refuse, not report numbers.
  fl::EmpsPdParams wild = e.controller;
  wild.kv = 1e6;
  wild.limit = 1e9;
  o.iv.controller = wild;
  const fl::Result r = fl::identify_idim(e.data, o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("IDIM-IV, iteration 1"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("diverged"), std::string::npos) << r.message;
  EXPECT_TRUE(r.parameters.empty());
}

TEST(IdimIv, TheIvSandwichWithTheRegressorsAsInstrumentsIsTheLeastSquaresOne) {
  // With Z = W the IV estimate is least squares, so its two std must be the least-squares
  // sandwich's and ordinary figure (identify/uncertainty.hpp); seeded regressors and meat.
  std::srand(7);
  const Eigen::MatrixXd W = Eigen::MatrixXd::Random(200, 3) + Eigen::MatrixXd::Constant(200, 3, 0.3);
  const Eigen::MatrixXd S = Eigen::MatrixXd::Random(200, 3);
  const Eigen::MatrixXd meat = S.transpose() * S;  // positive semi-definite
  const std::vector<std::string> names = {"a", "b", "c"};
  fl::Result ls, iv;
  for (const auto& n : names) {
    ls.parameters.push_back({n, 1.0, 0.0, "N", ""});
    iv.parameters.push_back({n, 1.0, 0.0, "N", ""});
  }
  const Eigen::MatrixXd A = W.transpose() * W;
  constexpr double kS2 = 0.7;  // N^2
  fl::set_uncertainty_from_sandwich(ls, names, A, meat, kS2);
  fl::set_uncertainty_from_iv(iv, names, A, A, A, meat, kS2);
  constexpr double kRounding = 1e-10;  // the same algebra through another inverse: rounding only
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_NEAR(iv.parameters[i].std, ls.parameters[i].std, kRounding * ls.parameters[i].std) << names[i];
    EXPECT_NEAR(*iv.parameters[i].std_ols, *ls.parameters[i].std_ols, kRounding * *ls.parameters[i].std_ols) << names[i];
  }
}

// The controller from a scenario (identify idim --iv --scenario): the EMPS example's controller
// section read by the scenario reader, its data file replaced by the record as validate does.
namespace {

fl::IdimIvScenario emps_scenario(fl::Axis axis = fl::Axis::linear) {
  fl::ScenarioOptions so;
  so.data = std::make_shared<const fl::Dataset>(fl::read_mat(std::string(FRICTIONLAB_DATA_DIR) + "/emps/DATA_EMPS.mat"));
  so.law = fl::FrictionLaw();
  so.axis = fl::AxisParams{};
  const std::string path = std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/emps_closed_loop.yaml";
  return fl::idim_iv_scenario(fl::load_scenario(path, so), "emps_closed_loop.yaml", axis);
}

fl::OptionValues iv_values() {
  fl::OptionValues v = fl::method_info(fl::MethodId::idim).values();
  v.set("iv", true, "--iv");
  return v;
}

// The InputError `f` throws (fails the test when it throws none).
template <class F>
fl::InputError input_error(F&& f) {
  try {
    f();
  } catch (const fl::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return fl::InputError("none", "none");
}

}  // namespace

TEST(IdimIvScenario, TheScenarioGivesTheControllerAndTheOptionsOverrideIt) {
  const fl::IdimIvScenario s = emps_scenario();
  const Emps e = load_emps();
  const auto* c = std::get_if<fl::EmpsPdParams>(&s.controller);
  ASSERT_NE(c, nullptr);
  // The example names the file's scalars kp, kv, gtau: the very numbers load_emps reads.
  EXPECT_EQ(c->kp, e.controller.kp);
  EXPECT_EQ(c->kv, e.controller.kv);
  EXPECT_EQ(c->gtau, e.controller.gtau);
  EXPECT_EQ(c->limit, 10);
  EXPECT_EQ(c->delay, 1);

  fl::IdimOptions o = fl::make_idim_options(iv_values(), &s);
  EXPECT_EQ(std::get<fl::EmpsPdParams>(*o.iv.controller).kv, e.controller.kv);
  EXPECT_EQ(o.iv.sources.at("controller"), "scenario emps_closed_loop.yaml: controller.type");
  EXPECT_EQ(o.iv.sources.at("kp"), "scenario emps_closed_loop.yaml: controller.kp");
  EXPECT_EQ(o.iv.sources.at("drive-gain"), "scenario emps_closed_loop.yaml: controller.gtau");

  fl::OptionValues v = iv_values();
  v.set("kp", 100.0, "--kp");
  v.set("control-delay", 0LL, "--control-delay");
  o = fl::make_idim_options(v, &s);
  const auto& over = std::get<fl::EmpsPdParams>(*o.iv.controller);
  EXPECT_EQ(over.kp, 100.0);
  EXPECT_EQ(over.delay, 0);
  EXPECT_EQ(over.kv, e.controller.kv);  // not given: the scenario's
  EXPECT_EQ(o.iv.sources.at("kp"), "--kp");
  EXPECT_EQ(o.iv.sources.at("control-delay"), "--control-delay");
  EXPECT_EQ(o.iv.sources.at("kv"), "scenario emps_closed_loop.yaml: controller.kv");
}

TEST(IdimIvScenario, TheIvResultWithTheScenarioIsTheOneWithTheNumbers) {
  const Emps e = load_emps();
  const fl::IdimIvScenario s = emps_scenario();
  const fl::Result by_numbers = fl::identify_idim(e.data, iv_options(e));
  const fl::Result by_scenario = fl::identify_idim(e.data, fl::make_idim_options(iv_values(), &s));
  ASSERT_TRUE(by_numbers.ok()) << by_numbers.message;
  ASSERT_TRUE(by_scenario.ok()) << by_scenario.message;
  // The same controller, the same simulation: the same numbers to the bit.
  for (const char* name : {"M", "Fv", "Fc", "offset"}) {
    EXPECT_EQ(by_scenario.value(name), by_numbers.value(name)) << name;
    EXPECT_EQ(by_scenario.find(name)->std, by_numbers.find(name)->std) << name;
  }
  EXPECT_EQ(by_scenario.diagnostics.texts.at("iv_controller_type"), "emps-pd");
  EXPECT_EQ(by_scenario.diagnostics.texts.at("iv_source_kv"), "scenario emps_closed_loop.yaml: controller.kv");
  EXPECT_EQ(by_scenario.diagnostics.groups.at("iv_controller").at("kv"), e.controller.kv);
  EXPECT_EQ(by_scenario.diagnostics.groups.at("iv_controller").at("sample_period"), by_numbers.diagnostics.groups.at("iv_controller").at("sample_period"));
}

TEST(IdimIvScenario, ConflictsWithTheOptionsNameTheFileAndKey) {
  const fl::IdimIvScenario s = emps_scenario();
  fl::OptionValues v = iv_values();
  v.set("controller", std::string("pid"), "--controller");
  fl::InputError e = input_error([&] { (void)fl::make_idim_options(v, &s); });
  EXPECT_EQ(e.code(), fl::errc::option_conflict);
  EXPECT_EQ(e.fields().key, "controller.type");
  EXPECT_EQ(e.fields().file, "emps_closed_loop.yaml");
  EXPECT_NE(std::string(e.what()).find("contradicts the scenario emps_closed_loop.yaml"), std::string::npos) << e.what();
  fl::OptionValues kd = iv_values();
  kd.set("kd", 3.0, "--kd");
  e = input_error([&] { (void)fl::make_idim_options(kd, &s); });
  EXPECT_NE(std::string(e.what()).find("--kd belongs to --controller pid"), std::string::npos) << e.what();
  // A scenario without --iv.
  const fl::OptionValues no_iv = fl::method_info(fl::MethodId::idim).values();
  e = input_error([&] { (void)fl::make_idim_options(no_iv, &s); });
  EXPECT_NE(std::string(e.what()).find("iv=True is not given"), std::string::npos) << e.what();
  // A rotary identification with the scenario's linear axis.
  e = input_error([&] { (void)emps_scenario(fl::Axis::rotary); });
  EXPECT_EQ(e.fields().key, "plant.type");
  EXPECT_NE(std::string(e.what()).find("moves linear (m, N), but the identification is rotary"), std::string::npos) << e.what();
}

TEST(IdimIvScenario, ScenariosItCannotSimulateAreRefusedNamingTheKey) {
  fl::testing::TempDir dir;
  const std::string head = "plant: {type: axis, M: 2}\nfriction: {law: coulomb-viscous, Fc: 1, Fv: 2}\n"
                           "input: {type: constant, value: 0}\nduration: 1\n";
  const auto refused = [&](const std::string& name, const std::string& yaml, fl::Axis axis = fl::Axis::linear) {
    const std::string path = dir.file(name, yaml);
    return input_error([&] { (void)fl::idim_iv_scenario(fl::load_scenario(path), path, axis); });
  };
  fl::InputError e = refused("none.yaml", head);
  EXPECT_EQ(e.fields().key, "controller");
  EXPECT_NE(std::string(e.what()).find("none.yaml: controller: missing"), std::string::npos) << e.what();
  e = refused("velocity.yaml", head + "controller: {loop: velocity, Kp: 10}\n");
  EXPECT_EQ(e.fields().key, "controller.loop");
  e = refused("compensated.yaml", head + "controller: {Kp: 1e4, Kd: 100, compensation: {type: feedforward}}\n");
  EXPECT_EQ(e.fields().key, "controller.compensation");
  EXPECT_NE(std::string(e.what()).find("--feedforward COLUMN"), std::string::npos) << e.what();
  const std::string pendulum = "plant: {type: pendulum, m: 1, l: 0.5}\nfriction: {law: coulomb, Fc: 0.1}\n"
                               "input: {type: constant, value: 0}\nduration: 1\ncontroller: {Kp: 10, Kd: 1}\n";
  e = refused("pendulum.yaml", pendulum);
  EXPECT_EQ(e.fields().key, "plant.type");
  EXPECT_NE(std::string(e.what()).find("moves rotary"), std::string::npos) << e.what();
  e = refused("pendulum_rotary.yaml", pendulum, fl::Axis::rotary);
  EXPECT_EQ(e.fields().key, "plant.type");
  EXPECT_NE(std::string(e.what()).find("expected axis"), std::string::npos) << e.what();
  // A PID it can simulate: its gains, the position loop.
  const std::string ok = dir.file("pid.yaml", head + "controller: {Kp: 4e4, Kd: 400, limit: 50}\n");
  const fl::IdimIvScenario s = fl::idim_iv_scenario(fl::load_scenario(ok), ok, fl::Axis::linear);
  const auto& pid = std::get<fl::PidParams>(s.controller);
  EXPECT_EQ(pid.Kp, 4e4);
  EXPECT_EQ(pid.Kd, 400);
  EXPECT_EQ(pid.limit, 50);
  fl::OptionValues v = iv_values();
  v.set("kd", 300.0, "--kd");
  const fl::IdimOptions o = fl::make_idim_options(v, &s);
  EXPECT_EQ(std::get<fl::PidParams>(*o.iv.controller).Kd, 300);
  EXPECT_EQ(std::get<fl::PidParams>(*o.iv.controller).Kp, 4e4);
  EXPECT_EQ(o.iv.sources.at("kp"), "scenario " + ok + ": controller.Kp");
}

TEST(IdimIvScenario, AGainLeftAsAScalarNameIsRefusedWithoutTheFile) {
  fl::OptionValues v = iv_values();
  v.set("controller", std::string("emps-pd"), "--controller");
  v.set("kp", std::string("kp"), "--kp");
  const fl::InputError e = input_error([&] { (void)fl::make_idim_options(v); });
  EXPECT_EQ(e.fields().option, "--kp");
  EXPECT_NE(std::string(e.what()).find("needs the data file"), std::string::npos) << e.what();
}

// The MJCF that `frictionlab export --mjcf` writes (export/mjcf_export.hpp), loaded and run by
// MuJoCo's own C library (Debian libmujoco-dev 2.2.2): the file loads, mjModel holds the model's
// values, and MuJoCo's motion under a constant force is compared with the library's exact engine
// (simulate/simulate.hpp, hybrid stick/slip) with the same Coulomb and viscous law:
//  - below Fc (0.5 Fc) the exact engine stays at rest, velocity exactly 0; MuJoCo's friction loss
//    is a soft constraint and creeps. The creep is printed (docs/export.md quotes it; run
//    `ctest -R export.mujoco -V`) and checked against the creep MuJoCo's constraint model
//    predicts (see creep_velocity below);
//  - above Fc (2 Fc) both accelerate at (F - Fc - Fv v) / M: the velocities agree after the
//    transient.
// mju_user_error and mju_user_warning are set so that a MuJoCo error throws (the test fails
// with MuJoCo's message) instead of ending the process, and a warning fails the test.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/export/mjcf_export.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/model_file.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "io/atomic_write.hpp"
#include "temp_dir.hpp"

namespace frictionlab {
namespace {

using testing::TempDir;

std::vector<std::string>& mujoco_warnings() {
  static std::vector<std::string> w;
  return w;
}

struct MujocoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Installed once for the whole program, before any MuJoCo call.
const bool kHandlersSet = [] {
  mju_user_error = [](const char* msg) { throw MujocoError(std::string("MuJoCo error: ") + msg); };
  mju_user_warning = [](const char* msg) { mujoco_warnings().push_back(msg); };
  return true;
}();

// Owns an mjModel and its mjData.
struct Mujoco {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  explicit Mujoco(const std::string& path) {
    char error[1000] = "";
    m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
    if (!m) throw MujocoError("mj_loadXML(" + path + "): " + error);
    d = mj_makeData(m);
  }
  ~Mujoco() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
  Mujoco(const Mujoco&) = delete;
  Mujoco& operator=(const Mujoco&) = delete;

  // From rest at 0, ctrl = force for `duration` seconds; returns {position, velocity} at the end.
  std::pair<double, double> run(double force, double duration) {
    mj_resetData(m, d);
    d->ctrl[0] = force;
    const long steps = std::lround(duration / m->opt.timestep);
    for (long i = 0; i < steps; ++i) mj_step(m, d);
    return {d->qpos[0], d->qvel[0]};
  }
};

// The text round trip of a number: the file holds the shortest text that reads back to the same
// double, and MuJoCo parses it with the C library's correctly rounded strtod, so the value comes
// back exactly; 4 ulp (1e-15 relative) allows a parser that rounds a little differently.
constexpr double kParseTol = 1e-15;

// A MODEL.json as `identify idim --json` writes it (the parts export reads), written with the
// library's own law_to_json and atomic write, read back with read_model_file as the CLI reads it.
ModelFile model_json(const TempDir& dir, const FrictionLaw& law, double M, const std::string& axis) {
  const nlohmann::json j = {{"schema", 1},
                            {"status", "ok"},
                            {"message", ""},
                            {"method", "idim"},
                            {"model", law.name()},
                            {"axis", axis},
                            {"law", law_to_json(law)},
                            {"parameters", {{"M", {{"value", M}, {"std", 0.01}, {"unit", axis == "rotary" ? "kg m^2" : "kg"}}}}}};
  const std::string path = dir.file("model.json");
  write_file_atomic(path, j.dump(1), {.overwrite = true});
  return read_model_file(path);
}

std::string write_mjcf(const TempDir& dir, const ModelFile& model, double armature) {
  MjcfOptions o;
  o.axis = model.axis.value();
  o.inertia = model.inertia.value();
  o.armature = armature;
  o.source = "model.json";
  const std::string path = dir.file("axis.xml");
  write_file_atomic(path, mjcf_model(model.law, o).xml, {.overwrite = true});
  return path;
}

// MuJoCo's steady creep velocity under a constant force F below Fc. The friction loss is a
// constraint on the joint velocity with impedance d and reference acceleration aref = -b v
// (MuJoCo's soft-constraint model, "Computation" chapter of its documentation): its force solves
// f = -(J a0 - aref) / (A + R) with A = 1/M (the joint's inverse inertia), R = A (1 - d) / d and
// a0 = F / M. Steady creep (a = a0 + A f = 0) gives v = (1 - d) / d * F / (M b). For the file's
// solimpfriction "0.9 0.95 0.001 0.5 2" the impedance at zero violation is d = dmin = 0.9, and for
// solreffriction "0.02 1" (time constant tc = 0.02 s, damping ratio 1) b = 2 / (dmax tc) with
// dmax = 0.95. The viscous term Fv v is 2e-4 of F at that speed and is left out.
double creep_velocity(double F, double M) {
  const double d = 0.9, dmax = 0.95, tc = 0.02;
  const double b = 2.0 / (dmax * tc);
  return (1.0 - d) / d * F / (M * b);
}

InputSignal constant(double F) {
  InputSignal u;
  u.value = F;
  return u;
}

struct Case {
  const char* axis;
  double M, armature;
};

class MjcfInMujoco : public ::testing::TestWithParam<Case> {};

TEST_P(MjcfInMujoco, LoadsWithTheModelsValues) {
  ASSERT_TRUE(kHandlersSet);
  const Case c = GetParam();
  TempDir dir;
  const FrictionLaw law = CoulombViscous{.Fc = 1.3, .Fv = 0.4};
  const ModelFile model = model_json(dir, law, c.M, c.axis);
  Mujoco mj(write_mjcf(dir, model, c.armature));
  const mjModel* m = mj.m;
  ASSERT_EQ(m->njnt, 1);
  ASSERT_EQ(m->nv, 1);
  ASSERT_EQ(m->nu, 1);
  const bool rotary = std::string(c.axis) == "rotary";
  EXPECT_EQ(m->jnt_type[0], rotary ? mjJNT_HINGE : mjJNT_SLIDE);
  EXPECT_NEAR(m->dof_frictionloss[0], 1.3, kParseTol * 1.3);
  EXPECT_NEAR(m->dof_damping[0], 0.4, kParseTol * 0.4);
  EXPECT_NEAR(m->dof_armature[0], c.armature, kParseTol * c.M);
  const double body = c.M - c.armature;
  if (rotary) {
    EXPECT_NEAR(m->body_inertia[3 * 1 + 2], body, kParseTol * c.M);  // body 1, about z: the hinge's axis
  } else {
    EXPECT_NEAR(m->body_mass[1], body, kParseTol * c.M);
  }
  // The joint's whole inertia as MuJoCo computes it (mass matrix at q = 0) is the model's M.
  mj_forward(m, mj.d);
  EXPECT_NEAR(mj.d->qM[0], c.M, kParseTol * c.M * 4);
  EXPECT_EQ(m->opt.integrator, mjINT_EULER);
  EXPECT_EQ(m->opt.timestep, 0.002);
  EXPECT_EQ(m->dof_solref[0], 0.02);
  EXPECT_EQ(m->dof_solimp[0], 0.9);
  EXPECT_EQ(m->actuator_trntype[0], mjTRN_JOINT);
  EXPECT_EQ(m->actuator_gear[0], 1.0);
  EXPECT_TRUE(mujoco_warnings().empty()) << mujoco_warnings().front();
}

TEST_P(MjcfInMujoco, BelowFcMujocoCreepsWhereTheExactEngineSticks) {
  const Case c = GetParam();
  TempDir dir;
  const double Fc = 1.3, Fv = 0.4, F = 0.5 * Fc, duration = 1.0;
  const FrictionLaw law = CoulombViscous{.Fc = Fc, .Fv = Fv};
  const ModelFile model = model_json(dir, law, c.M, c.axis);
  Mujoco mj(write_mjcf(dir, model, c.armature));
  const auto [x, v] = mj.run(F, duration);

  SimulationOptions so;
  so.duration = duration;
  const Trajectory exact = simulate(RigidAxis({.M = c.M}), law, constant(F), so);
  for (std::size_t i = 0; i < exact.rows(); ++i) {
    ASSERT_EQ(exact.velocity[i], 0.0) << "the exact engine moved at t = " << exact.time[i];
    ASSERT_EQ(exact.position[i], 0.0);
  }

  const double vc = creep_velocity(F, c.M);
  const char* unit = std::string(c.axis) == "rotary" ? "rad" : "m";
  std::printf("MuJoCo %d.%d.%d, %s axis (Euler, timestep 0.002 s, solreffriction 0.02 1, solimpfriction 0.9 0.95 0.001 0.5 2):\n"
              "  M = %g, Fc = %g, F = 0.5 Fc = %g held %g s from rest: creep %.4g %s, velocity %.4g %s/s\n"
              "  (predicted steady creep velocity (1 - d) / d F / (M b) = %.4g %s/s); exact engine: 0 and 0\n",
              mj_version() / 100, mj_version() / 10 % 10, mj_version() % 10, c.axis, c.M, Fc, F, duration, x, unit, v, unit, vc, unit);
  // MuJoCo creeps (a test that it does not would mean the file is not MuJoCo's soft friction) in
  // the direction of the force, at the predicted steady velocity. The creep reaches that speed at
  // the rate d b = 95 /s (same derivation), so the position at 1 s lags vc t by about vc / (d b):
  // 1.1 % (0.8 % measured); the velocity is steady by then (0.1 % measured, Euler's discretisation).
  // 2 % bounds both; a file with another M, solref or solimp is off by far more (the creep scales
  // with 1 / M and with (1 - d) / d: 0.95 instead of 0.9 halves it).
  constexpr double kCreepTol = 0.02;
  EXPECT_GT(x, 0.0);
  EXPECT_NEAR(v, vc, kCreepTol * vc);
  EXPECT_NEAR(x, vc * duration, kCreepTol * vc * duration);
  EXPECT_TRUE(mujoco_warnings().empty()) << mujoco_warnings().front();
}

TEST_P(MjcfInMujoco, AboveFcMujocoSlidesLikeTheExactEngine) {
  const Case c = GetParam();
  TempDir dir;
  const double Fc = 1.3, Fv = 0.4, F = 2.0 * Fc, duration = 1.0;
  const FrictionLaw law = CoulombViscous{.Fc = Fc, .Fv = Fv};
  const ModelFile model = model_json(dir, law, c.M, c.axis);
  Mujoco mj(write_mjcf(dir, model, c.armature));
  const auto [x, v] = mj.run(F, duration);

  SimulationOptions so;
  so.duration = duration;
  const Trajectory exact = simulate(RigidAxis({.M = c.M}), law, constant(F), so);
  const double v_exact = exact.velocity.back(), x_exact = exact.position.back();
  // The exact solution of M dv/dt = F - Fc - Fv v from rest: the engine itself is right.
  const double tau = c.M / Fv, v_inf = (F - Fc) / Fv;
  ASSERT_NEAR(v_exact, v_inf * (1 - std::exp(-duration / tau)), 1e-6 * v_inf);

  std::printf("MuJoCo %s: F = 2 Fc = %g for %g s from rest: velocity %.6g (exact %.6g, rel. diff %.2e), "
              "position %.6g (exact %.6g)\n",
              c.axis, F, duration, v, v_exact, (v - v_exact) / v_exact, x, x_exact);
  // MuJoCo's Euler step (semi-implicit, damping implicit) is first order: its error in v is about
  // dt / (2 tau) of v with tau = M / Fv: 1.6e-4 (linear) and 5e-4 (rotary; 1.5e-4 and 3.9e-4
  // measured). 2e-3 bounds that with margin; a wrong mass, level or damping in the file is off by
  // far more (Fc 1 % off moves v by 1 %). The position leads by the semi-implicit step's v dt / 2,
  // about 1.9e-3 of x here (1.8e-3 and 1.4e-3 measured): 5e-3.
  constexpr double kSlideTol = 2e-3, kSlidePositionTol = 5e-3;
  EXPECT_NEAR(v, v_exact, kSlideTol * v_exact);
  EXPECT_NEAR(x, x_exact, kSlidePositionTol * x_exact);
  EXPECT_TRUE(mujoco_warnings().empty()) << mujoco_warnings().front();
}

// A linear axis as identify idim gives it; a rotary one with a rotor's share in the armature
// (the total inertia must still be M).
INSTANTIATE_TEST_SUITE_P(Axes, MjcfInMujoco,
                         ::testing::Values(Case{"linear", 2.5, 0.0}, Case{"rotary", 0.8, 0.2}),
                         [](const auto& info) { return std::string(info.param.axis); });

// Every law with a Coulomb level gives a file MuJoCo loads, with Fc (or the mean of the two
// directions' levels) as frictionloss; laws without one are refused by the exporter.
TEST(MjcfEveryLaw, LoadsInMujoco) {
  TempDir dir;
  const std::vector<nlohmann::json> laws = {
      {{"law", "coulomb"}, {"Fc", 1.0}},
      {{"law", "coulomb-viscous"}, {"Fc", 1.0}, {"Fv", 0.2}},
      {{"law", "static-coulomb-viscous"}, {"Fc", 1.0}, {"Fs", 1.4}, {"Fv", 0.2}},
      {{"law", "stribeck"}, {"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.001}, {"Fv", 0.4}},
      {{"law", "stribeck-asymmetric"}, {"Fc_pos", 1.1}, {"Fs_pos", 1.6}, {"vs_pos", 0.002}, {"Fv_pos", 0.35},
       {"Fc_neg", 0.8}, {"Fs_neg", 1.3}, {"vs_neg", 0.001}, {"Fv_neg", 0.45}},
      {{"law", "lugre"}, {"sigma0", 1e5}, {"sigma1", 316.2}, {"sigma2", 0.4}, {"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.001}},
      {{"law", "dahl"}, {"sigma0", 1e5}, {"Fc", 1.0}},
  };
  for (const auto& j : laws) {
    const FrictionLaw law = law_from_json(j, "law");
    MjcfOptions o;
    o.inertia = 2.0;
    const std::string path = dir.file("law.xml");
    write_file_atomic(path, mjcf_model(law, o).xml, {.overwrite = true});
    Mujoco mj(path);
    const double fc = mjcf_coulomb_level(law).value();
    EXPECT_NEAR(mj.m->dof_frictionloss[0], fc, kParseTol * fc) << law.name();
  }
  EXPECT_TRUE(mujoco_warnings().empty()) << mujoco_warnings().front();
}

// A MuJoCo error reaches the test as an exception, not the end of the process: the handler works.
TEST(MjcfEveryLaw, MujocoErrorsAreReportedNotFatal) {
  TempDir dir;
  const std::string bad = dir.file("bad.xml", "<mujoco><worldbody><body><joint type=\"slide\"/></body></worldbody></mujoco>\n");
  EXPECT_THROW(Mujoco{bad}, MujocoError);  // a moving body without mass: MuJoCo refuses it
  EXPECT_THROW(mju_error("raised by the test"), MujocoError);
}

}  // namespace
}  // namespace frictionlab

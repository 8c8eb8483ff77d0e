// The two-axis table's analytic Jacobian (XyTable::jacobian): against central differences of its
// right-hand side at seeded random states (static laws: the plant's own partials; dynamic laws: the
// stiff engine's whole Newton matrix), with and without compensators, continuous and sampled; and
// the stiff engine using it on a circular test with LuGre on both axes: the same contour as with
// CVODE's difference quotients, with fewer right-hand sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedback.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/core/contour_input.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "simulate/stiff_system.hpp"
#include "property_cases.hpp"
#include "xy_loop.hpp"

using namespace frictionlab;
using frictionlab::testing::gains_for;
using frictionlab::testing::property_cases;
using frictionlab::testing::relative_difference;

namespace {

// Seeded: a failure reproduces. property_cases() random states per configuration (a quarter of
// them for the whole Newton matrix); FRICTIONLAB_PROPERTY_CASES sets it (default 1000).
constexpr unsigned kSeed = 20261127;

// Central differences step h_j = kStep * scale_j: truncation O(h^2) and rounding O(eps / h) both
// stay near 1e-10 of an entry's row; 1e-6 relative to the row leaves room for the curvature of the
// Stribeck curve and of the observers' nonlinear terms without hiding a wrong entry (a missing or
// wrong term is O(1) of its row: a gain, 1/M, a compensator's slope).
constexpr double kStep = 1e-6;
constexpr double kJacobianTolerance = 1e-6;

XyAxis axis_of(double mass, FrictionLaw law, double limit, std::shared_ptr<const Compensator> comp = nullptr) {
  XyAxis a;
  a.mass = mass;
  a.law = std::move(law);
  a.gains = gains_for(mass, limit);
  a.compensator = std::move(comp);
  return a;
}

// LuGre scaled to a ball-screw carriage (N, m/s): sigma1 = 2 sqrt(sigma0 M) damps the bristle mode.
LuGre carriage_lugre(double Fc, double Fs, double M) {
  LuGre l;
  l.sigma0 = 1e6;
  l.sigma1 = 2.0 * std::sqrt(1e6 * M);
  l.sigma2 = 150.0;
  l.Fc = Fc;
  l.Fs = Fs;
  l.vs = 0.002;
  return l;
}

// Largest entry difference relative to the largest entry of its row (rows mix gains of 1e6 N/m
// with 1/M), over an n x m matrix stored with element (i, j) at a[index(i, j)].
template <class Index>
double max_row_relative_error(const std::vector<double>& a, const std::vector<double>& b, std::size_t n,
                              std::size_t m, Index index) {
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double row = 0.0;
    for (std::size_t j = 0; j < m; ++j) row = std::max(row, std::abs(b[index(i, j)]));
    if (row == 0.0) row = 1.0;  // an all-zero row: compare absolutely
    for (std::size_t j = 0; j < m; ++j) worst = std::max(worst, std::abs(a[index(i, j)] - b[index(i, j)]) / row);
  }
  return worst;
}

// A random state of `plant` around a circular test of R ~ 5 cm: positions, velocities, the PID
// integrals, held commands (sampled) and each compensator's states from its own initial_states at
// the random measurement, continuous ones (an observer's) then moved by up to their own size.
struct RandomState {
  std::vector<double> x;
  std::vector<InputValue> u;
  std::vector<double> friction;
};

RandomState random_state(const XyTable& plant, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RandomState s;
  s.x.assign(static_cast<std::size_t>(plant.num_states()), 0.0);
  s.u.resize(2);
  s.friction.resize(2);
  const bool sampled = plant.sample_period() > 0;
  std::size_t block = 4;
  for (int i = 0; i < 2; ++i) {
    const auto p = static_cast<std::size_t>(2 * i);
    s.x[p] = 0.05 * unit(rng);     // m
    s.x[p + 1] = 0.1 * unit(rng);  // m/s
    s.u[static_cast<std::size_t>(i)] = InputValue{s.x[p] + 1e-3 * unit(rng), 0.1 * unit(rng), 2.0 * unit(rng)};
    s.friction[static_cast<std::size_t>(i)] = 30.0 * unit(rng);  // N
    s.x[block] = 1e-4 * unit(rng);                              // m s
    std::size_t own = 1;
    if (sampled) {
      s.x[block + 1] = 300.0 * unit(rng);  // N, applied
      s.x[block + 2] = 300.0 * unit(rng);  // N, computed
      own = 3;
    }
    if (const Compensator* comp = plant.axis(i).compensator.get()) {
      CompensatorInput in;
      in.position = s.x[p];
      in.velocity = s.x[p + 1];
      const InputValue& r = s.u[static_cast<std::size_t>(i)];
      in.reference = r.value;
      in.reference_rate = r.rate;
      in.reference_accel = r.accel;
      const auto nz = static_cast<std::size_t>(comp->num_states());
      const std::span<double> z(s.x.data() + block + own, nz);
      comp->initial_states(in, z);
      // Band compensations keep their discrete region; observers' states move off their start.
      if (comp->type() == "lugre-observer" || comp->type() == "disturbance-observer")
        for (double& zj : z) zj += (std::abs(zj) + 1e-5) * unit(rng);
      own += nz;
    }
    block += own;
  }
  return s;
}

// The scale of each state for the difference step: positions 1 cm, velocities 1 cm/s, the rest
// their own size (at least a floor that keeps h above rounding).
std::vector<double> scales_of(const std::vector<double>& x) {
  std::vector<double> scale(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) scale[j] = j < 4 ? 0.01 : std::max(std::abs(x[j]), 1e-5);
  return scale;
}

// The plant's dfdx and dfdF against central differences of XyTable::derivatives in x and in F.
void expect_plant_partials_match(const XyTable& plant, const RandomState& s, const std::string& what) {
  const auto n = static_cast<std::size_t>(plant.num_states());
  constexpr std::size_t nc = 2;
  std::vector<double> dfdx(n * n, -7.0), dfdF(n * nc, -7.0);
  ASSERT_TRUE(plant.jacobian(0.3, s.x, s.u, s.friction, dfdx, dfdF)) << what;
  const std::vector<double> scale = scales_of(s.x);
  std::vector<double> fd_x(n * n), fd_F(n * nc), fp(n), fm(n);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> xp = s.x, xm = s.x;
    const double h = kStep * scale[j];
    xp[j] += h;
    xm[j] -= h;
    plant.derivatives(0.3, xp, s.u, s.friction, fp);
    plant.derivatives(0.3, xm, s.u, s.friction, fm);
    for (std::size_t i = 0; i < n; ++i) fd_x[i * n + j] = (fp[i] - fm[i]) / (2 * h);
  }
  for (std::size_t k = 0; k < nc; ++k) {
    std::vector<double> Fp = s.friction, Fm = s.friction;
    const double h = kStep * 30.0;
    Fp[k] += h;
    Fm[k] -= h;
    plant.derivatives(0.3, s.x, s.u, Fp, fp);
    plant.derivatives(0.3, s.x, s.u, Fm, fm);
    for (std::size_t i = 0; i < n; ++i) fd_F[i * nc + k] = (fp[i] - fm[i]) / (2 * h);
  }
  EXPECT_LT(max_row_relative_error(dfdx, fd_x, n, n, [n](std::size_t i, std::size_t j) { return i * n + j; }),
            kJacobianTolerance)
      << what << ": d f / d x";
  EXPECT_LT(max_row_relative_error(dfdF, fd_F, n, nc, [](std::size_t i, std::size_t k) { return i * nc + k; }),
            kJacobianTolerance)
      << what << ": d f / d F";
}

// The stiff engine's Newton matrix (plant, laws, compensators) against central differences of its
// right-hand side; law states start at their steady state for the random velocity, moved by up to
// half of it.
void expect_newton_matrix_matches(const XyTable& plant, const RandomState& s, std::mt19937& rng, const std::string& what) {
  const FrictionLaw unused = LuGre{};  // every contact has its own law
  StiffSystem sys(plant, unused);
  ASSERT_TRUE(sys.has_jacobian()) << what;
  const auto np = static_cast<std::size_t>(plant.num_states()), n = static_cast<std::size_t>(sys.size());
  std::vector<double> y(n), scale(n);
  std::copy(s.x.begin(), s.x.end(), y.begin());
  const std::vector<double> plant_scale = scales_of(s.x);
  std::copy(plant_scale.begin(), plant_scale.end(), scale.begin());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t z = np;
  for (int i = 0; i < 2; ++i) {
    const FrictionLaw& law = *plant.contact(i).law;
    const auto nz = static_cast<std::size_t>(law.num_states());
    std::span<double> zs(y.data() + z, nz);
    law.steady_state(y[static_cast<std::size_t>(2 * i + 1)], zs);
    for (std::size_t j = 0; j < nz; ++j) {
      zs[j] *= 1.0 + 0.5 * unit(rng);
      scale[z + j] = std::max(std::abs(zs[j]), 1e-7);  // m: bristle deflections ~ Fc / sigma0
    }
    z += nz;
  }
  std::vector<double> jac(n * n);
  sys.jacobian(0.3, y, s.u, jac);
  std::vector<double> fd(n * n), fp(n), fm(n);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> yp = y, ym = y;
    const double h = kStep * scale[j];
    yp[j] += h;
    ym[j] -= h;
    sys.rhs(0.3, yp, s.u, fp);
    sys.rhs(0.3, ym, s.u, fm);
    for (std::size_t i = 0; i < n; ++i) fd[i + j * n] = (fp[i] - fm[i]) / (2 * h);
  }
  EXPECT_LT(max_row_relative_error(jac, fd, n, n, [n](std::size_t i, std::size_t j) { return i + j * n; }),
            kJacobianTolerance)
      << what;
}

std::shared_ptr<const Compensator> lugre_observer(double Fc, double Fs, double M) {
  return std::make_shared<LuGreObserver>(FrictionLaw(carriage_lugre(Fc, Fs, M)), LuGreObserverParams{5.0});
}
std::shared_ptr<const Compensator> disturbance_observer(double M) {
  DisturbanceObserverParams p;
  p.bandwidth = 200.0;
  p.inertia = 0.9 * M;  // a nominal model 10 % off: its terms must not cancel
  return std::make_shared<DisturbanceObserver>(p);
}
std::shared_ptr<const Compensator> feedback(FrictionLaw law) {
  return std::make_shared<FeedbackCompensation>(std::move(law), FeedbackParams{1e-3});
}
std::shared_ptr<const Compensator> feedforward(FrictionLaw law) {
  return std::make_shared<FeedforwardCompensation>(std::move(law), FeedforwardParams{0.01});
}

// The plant configurations of the property tests: each compensator on each axis, the saturation
// reached (a low limit on x), continuous and sampled with either delay.
struct TableCase {
  std::string name;
  XyAxis x, y;
  XyTiming timing;
};

std::vector<TableCase> table_cases(const FrictionLaw& law_x, const FrictionLaw& law_y) {
  const double Mx = 26.84, My = 13.9;  // kg: examples/xy_circle.yaml's equivalent masses
  std::vector<TableCase> out;
  out.push_back({"continuous", axis_of(Mx, law_x, 1500.0), axis_of(My, law_y, 0.0), {}});
  out.push_back({"continuous, x saturating", axis_of(Mx, law_x, 200.0), axis_of(My, law_y, 800.0), {}});
  out.push_back({"lugre-observer on x, disturbance-observer on y",
                 axis_of(Mx, law_x, 1500.0, lugre_observer(25.0, 40.0, Mx)),
                 axis_of(My, law_y, 800.0, disturbance_observer(My)),
                 {}});
  out.push_back({"disturbance-observer on x (saturating), lugre-observer on y",
                 axis_of(Mx, law_x, 300.0, disturbance_observer(Mx)),
                 axis_of(My, law_y, 0.0, lugre_observer(15.0, 25.0, My)),
                 {}});
  out.push_back({"feedforward on both", axis_of(Mx, law_x, 1500.0, feedforward(Stribeck{25.0, 40.0, 0.002, 2.0, 150.0})),
                 axis_of(My, law_y, 800.0, feedforward(FrictionLaw(carriage_lugre(15.0, 25.0, My)))),
                 {}});
  out.push_back({"feedback (static law, 10 % over) on x, feedback (static law) on y",
                 axis_of(Mx, law_x, 1500.0, feedback(Stribeck{27.5, 44.0, 0.002, 2.0, 165.0})),
                 axis_of(My, law_y, 800.0, feedback(StaticCoulombViscous{25.0, 15.0, 100.0})),
                 {}});
  out.push_back({"sampled, delay 0, lugre-observer on x", axis_of(Mx, law_x, 1500.0, lugre_observer(25.0, 40.0, Mx)),
                 axis_of(My, law_y, 800.0), XyTiming{2.5e-4, 0}});
  out.push_back({"sampled, delay 1, disturbance-observer on y", axis_of(Mx, law_x, 1500.0),
                 axis_of(My, law_y, 800.0, disturbance_observer(My)), XyTiming{2.5e-4, 1}});
  return out;
}

// Every plant state's derivative and the saturation state of the x command, counted over the
// random states so a test knows both sides of the saturation were seen.
struct Seen {
  int saturated = 0, unsaturated = 0;
};

void count_saturation(const XyTable& plant, const RandomState& s, Seen& seen) {
  const double limit = plant.axis(0).gains.limit;
  if (limit <= 0 || plant.sample_period() > 0) return;
  const double drive = plant.command(0, 0.3, s.x, s.u[0]);
  (std::abs(drive) >= limit ? seen.saturated : seen.unsaturated) += 1;
}

// The plant without its analytic Jacobian: every call forwarded but jacobian(), which says there is
// none, so the engine builds its Newton matrices by difference quotients (the run before
// XyTable::jacobian existed).
class WithoutJacobian : public Plant {
 public:
  explicit WithoutJacobian(const Plant& p) : p_(p) {}
  std::string type() const override { return p_.type(); }
  int num_states() const override { return p_.num_states(); }
  int num_inputs() const override { return p_.num_inputs(); }
  int num_contacts() const override { return p_.num_contacts(); }
  Contact contact(int i) const override { return p_.contact(i); }
  double inertia(int i) const override { return p_.inertia(i); }
  bool kinematic() const override { return p_.kinematic(); }
  void initial_extras(std::span<double> x) const override { p_.initial_extras(x); }
  void initial_extras(std::span<double> x, Inputs u) const override { p_.initial_extras(x, u); }
  void applied(double t, std::span<const double> x, Inputs u, std::span<double> f) const override {
    p_.applied(t, x, u, f);
  }
  void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> F,
                   std::span<double> dx) const override {
    p_.derivatives(t, x, u, F, dx);
  }
  bool jacobian(double, std::span<const double>, Inputs, std::span<const double>, std::span<double>,
                std::span<double>) const override {
    return false;
  }
  void signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const override {
    p_.signals(t, x, u, out);
  }
  double sample_period() const override { return p_.sample_period(); }
  void sample(double t, std::span<double> x, Inputs u) const override { p_.sample(t, x, u); }
  int num_events() const override { return p_.num_events(); }
  void events(double t, std::span<const double> x, Inputs u, std::span<double> g) const override {
    p_.events(t, x, u, g);
  }
  void on_event(double t, std::span<double> x, Inputs u, int k) const override { p_.on_event(t, x, u, k); }
  bool has_fixed_step_update() const override { return p_.has_fixed_step_update(); }
  void fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before, std::span<double> x,
                         Inputs u) const override {
    p_.fixed_step_update(t, dt, before, u_before, x, u);
  }

 private:
  const Plant& p_;
};

}  // namespace

TEST(XyTableJacobian, StaticLawsPlantPartialsMatchCentralDifferences) {
  // The plant's partials do not read the laws: static laws with stiction on both axes (what the
  // hybrid engine runs them with), each its own.
  const FrictionLaw law_x = Stribeck{25.0, 40.0, 0.002, 2.0, 150.0};
  const FrictionLaw law_y = StaticCoulombViscous{25.0, 15.0, 100.0};
  std::mt19937 rng(kSeed);
  Seen seen;
  for (const TableCase& tc : table_cases(law_x, law_y)) {
    const XyTable plant(tc.x, tc.y, tc.timing);
    for (int k = 0; k < property_cases(); ++k) {
      const RandomState s = random_state(plant, rng);
      if (tc.name == "continuous, x saturating") count_saturation(plant, s, seen);
      expect_plant_partials_match(plant, s, tc.name + ", state " + std::to_string(k));
    }
  }
  // Both sides of the saturation were checked (x: 200 N limit against up to 1e6 N/m x 5 cm).
  EXPECT_GT(seen.saturated, 0);
  EXPECT_GT(seen.unsaturated, 0);
}

TEST(XyTableJacobian, DynamicLawsNewtonMatrixMatchesCentralDifferences) {
  // Each axis its own dynamic law, both ways round: LuGre (Stribeck level, bristle damping),
  // Dahl, elasto-plastic (a presliding regime) and a GMS with two elements.
  const double Mx = 26.84, My = 13.9;
  Dahl dahl;
  dahl.sigma0 = 1e6;
  dahl.Fc = 15.0;
  ElastoPlastic ep;
  ep.sigma0 = 1e6;
  ep.sigma1 = 2.0 * std::sqrt(1e6 * Mx);
  ep.sigma2 = 150.0;
  ep.Fc = 25.0;
  ep.Fs = 40.0;
  ep.vs = 0.002;
  ep.zba = 1.5e-5;  // m, < Fc / sigma0 = 2.5e-5
  const std::vector<std::pair<FrictionLaw, FrictionLaw>> pairs = {
      {carriage_lugre(25.0, 40.0, Mx), carriage_lugre(15.0, 25.0, My)},
      {carriage_lugre(25.0, 40.0, Mx), dahl},
      {ep, carriage_lugre(15.0, 25.0, My)},
  };
  std::mt19937 rng(kSeed + 1);
  for (const auto& [law_x, law_y] : pairs) {
    for (const TableCase& tc : table_cases(law_x, law_y)) {
      const XyTable plant(tc.x, tc.y, tc.timing);
      for (int k = 0; k < std::max(property_cases() / 4, 1); ++k) {
        const RandomState s = random_state(plant, rng);
        expect_newton_matrix_matches(plant, s, rng,
                                     law_x.name() + "/" + law_y.name() + ", " + tc.name + ", state " + std::to_string(k));
      }
    }
  }
}

TEST(XyTableJacobian, AxesDoNotCouple) {
  // No entry links x's block to y's: the Newton matrix is block diagonal per axis.
  const double Mx = 26.84, My = 13.9;
  const XyTable plant(axis_of(Mx, carriage_lugre(25.0, 40.0, Mx), 1500.0, lugre_observer(25.0, 40.0, Mx)),
                      axis_of(My, carriage_lugre(15.0, 25.0, My), 800.0, disturbance_observer(My)));
  std::mt19937 rng(kSeed + 2);
  const RandomState s = random_state(plant, rng);
  const auto n = static_cast<std::size_t>(plant.num_states());
  std::vector<double> dfdx(n * n), dfdF(n * 2);
  ASSERT_TRUE(plant.jacobian(0.0, s.x, s.u, s.friction, dfdx, dfdF));
  // x owns states 0, 1 and 4 .. 5 (integral, observer); y owns 2, 3 and 6 .. 7.
  auto owner = [](std::size_t j) { return j < 4 ? (j < 2 ? 0 : 1) : (j < 6 ? 0 : 1); };
  int checked = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (owner(i) != owner(j)) {
        EXPECT_EQ(dfdx[i * n + j], 0.0) << "row " << i << ", column " << j;
        ++checked;
      }
  EXPECT_EQ(checked, 32);  // 2 x 4 x 4 cross entries
  EXPECT_EQ(dfdF[1 * 2 + 1], 0.0);
  EXPECT_EQ(dfdF[3 * 2 + 0], 0.0);
  EXPECT_DOUBLE_EQ(dfdF[1 * 2 + 0], -1.0 / Mx);
  EXPECT_DOUBLE_EQ(dfdF[3 * 2 + 1], -1.0 / My);
}

TEST(XyTableJacobian, CompensatorWithoutPartialsLeavesDifferenceQuotients) {
  // The feedback compensation of a dynamic law has no analytic partials (its output is the law's
  // steady-state force: Compensator::jacobian returns false): the table then has none either,
  // writes nothing, and the engine builds its Newton matrices by difference quotients. Sampled,
  // its states are discrete and the table has its partials.
  const double Mx = 26.84, My = 13.9;
  auto feedback = std::make_shared<FeedbackCompensation>(FrictionLaw(carriage_lugre(25.0, 40.0, Mx)));
  const XyAxis x = axis_of(Mx, carriage_lugre(25.0, 40.0, Mx), 1500.0, feedback);
  const XyAxis y = axis_of(My, carriage_lugre(15.0, 25.0, My), 800.0);
  const XyTable continuous(x, y);
  std::mt19937 rng(kSeed + 3);
  const RandomState s = random_state(continuous, rng);
  const auto n = static_cast<std::size_t>(continuous.num_states());
  std::vector<double> dfdx(n * n, -7.0), dfdF(n * 2, -7.0);
  EXPECT_FALSE(continuous.jacobian(0.0, s.x, s.u, s.friction, dfdx, dfdF));
  EXPECT_TRUE(std::all_of(dfdx.begin(), dfdx.end(), [](double d) { return d == -7.0; }));
  const FrictionLaw unused = LuGre{};  // every contact has its own law
  EXPECT_FALSE(StiffSystem(continuous, unused).has_jacobian());
  const XyTable sampled(x, y, XyTiming{2.5e-4, 1});
  EXPECT_TRUE(StiffSystem(sampled, unused).has_jacobian());
}

TEST(XyTableJacobian, StiffCircleRunMatchesDifferenceQuotientsWithFewerRightHandSides) {
  // The circular test of examples/xy_circle.yaml with LuGre on both axes and a continuous loop,
  // one turn through all four reversals, run with the analytic Jacobian and with CVODE's difference
  // quotients (the plant wrapped without its Jacobian: the run before XyTable::jacobian); without
  // compensation, and with a LuGre observer on x and a disturbance observer on y.
  const double Mx = 26.84, My = 13.9;
  const XyTable plain(axis_of(Mx, carriage_lugre(25.0, 40.0, Mx), 1500.0),
                      axis_of(My, carriage_lugre(15.0, 25.0, My), 800.0));
  const XyTable observed(axis_of(Mx, carriage_lugre(25.0, 40.0, Mx), 1500.0, lugre_observer(25.0, 40.0, Mx)),
                         axis_of(My, carriage_lugre(15.0, 25.0, My), 800.0, disturbance_observer(My)));
  CircleContour c;
  c.radius = 0.01;  // m
  c.feed = 0.02;    // m/s
  c.turns = 1.0;
  c.start_angle = std::numbers::pi / 4;
  const auto inputs = c.inputs();
  SimulationOptions o;
  o.duration = c.duration();  // s: 2 pi R / F = 3.14 s
  o.output_rate = 1000.0;
  o.mode = SolverMode::stiff;
  o.initial_positions = {inputs[0].at(0.0).value, inputs[1].at(0.0).value};
  const FrictionLaw unused = LuGre{};  // every contact has its own law
  for (const XyTable* plant : {&plain, &observed}) {
    const char* what = plant == &plain ? "no compensation" : "lugre-observer on x, disturbance-observer on y";
    SCOPED_TRACE(what);
    const Trajectory a = simulate(*plant, unused, inputs, o);
    const Trajectory b = simulate(WithoutJacobian(*plant), unused, inputs, o);
    ASSERT_STREQ(a.stats.solver, "stiff");
    ASSERT_STREQ(b.stats.solver, "stiff");
    // Both runs hold rtol = 1e-8 per step, on different step sequences (measured: positions agree
    // to 7e-9 of the largest, velocities and friction to 6e-7). 1e-7 of the radius is 1 nm, far
    // below the quadrant glitches (tens of um); velocity and friction, a derivative and a force
    // through the bristles' stiffness (sigma0 = 1e6 N/m), get 100 times that.
    constexpr double kPositionRelTol = 1e-7;
    constexpr double kRateRelTol = 1e-5;
    for (int k = 0; k < 2; ++k) {
      const ContactColumns& ca = k == 0 ? static_cast<const ContactColumns&>(a) : a.others[0];
      const ContactColumns& cb = k == 0 ? static_cast<const ContactColumns&>(b) : b.others[0];
      const double dp = relative_difference(ca.position, cb.position), dv = relative_difference(ca.velocity, cb.velocity),
                   df = relative_difference(ca.friction, cb.friction), dd = relative_difference(ca.drive, cb.drive);
      EXPECT_LT(dp, kPositionRelTol) << "axis " << k;
      EXPECT_LT(dv, kRateRelTol) << "axis " << k;
      EXPECT_LT(df, kRateRelTol) << "axis " << k;
      EXPECT_LT(dd, kRateRelTol) << "axis " << k;
      std::printf("%s, axis %d: relative differences position %.2g, velocity %.2g, friction %.2g, drive %.2g\n", what, k, dp,
                  dv, df, dd);
    }
    // The analytic run builds no Newton matrix by difference quotients; the other spends one
    // right-hand side per state on each. In all, fewer right-hand sides.
    EXPECT_EQ(a.stats.jacobian_rhs_evaluations, 0);
    EXPECT_GT(b.stats.jacobian_rhs_evaluations, 0);
    const long total_a = a.stats.rhs_evaluations + a.stats.jacobian_rhs_evaluations;
    const long total_b = b.stats.rhs_evaluations + b.stats.jacobian_rhs_evaluations;
    EXPECT_LT(total_a, total_b);
    std::printf("%s: analytic Jacobian %ld steps, %ld rhs; difference quotients %ld steps, %ld + %ld rhs\n", what,
                a.stats.steps, a.stats.rhs_evaluations, b.stats.steps, b.stats.rhs_evaluations,
                b.stats.jacobian_rhs_evaluations);
  }
}

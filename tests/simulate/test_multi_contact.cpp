// Plants with several friction contacts: each contact has its own mode, switches and columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/multi_axis.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

// Identical axes in one MultiAxis are the 1-DOF system repeated. Fixed-step runs do the 1-DOF
// arithmetic exactly (measured difference 0). Hybrid runs take the 1-DOF run's steps: CVODE's error
// and convergence norms (root mean squares over the states) are those of one axis up to the
// rounding of their sums, its dense LU of the block-diagonal Newton matrix does the 1-DOF
// eliminations (the other blocks' multipliers are exact zeros), all contacts' roots fall on the
// same step, and every switch restarts the integrator, so the rounding of the norms cannot build
// up (measured: 0 with 2 axes, 6e-13 with 3).
constexpr double kSameRunRelTol = 1e-12;
// A stiff run never restarts: the last-bit differences of those norms move step sizes, the runs
// then take different steps, and agree only to their integration error. At rtol = 1e-10 the
// measured worst is 6.5e-8 of the friction scale (LuGre's presliding slope sigma0 = 1e5 N/m turns a
// timing difference into a large force difference), 3e-9 of the positions; 1e-6 leaves a margin of 15.
constexpr double kStiffSameRunRelTol = 1e-6;

// Column a equals column b to rel relative to the column's scale (its largest magnitude, at least 1e-300).
void expect_same_column(const std::vector<double>& a, const std::vector<double>& b, double rel, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 1e-300;
  for (double v : b) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_NEAR(a[i], b[i], rel * scale) << what << " row " << i;
  }
}

void expect_contact_is_run(const Trajectory& multi, int k, const Trajectory& single, double rel) {
  const ContactColumns& c = multi.contact(k);
  const std::string who = multi.contact_names[static_cast<std::size_t>(k)];
  expect_same_column(multi.time, single.time, rel, "time");
  expect_same_column(c.position, single.position, rel, who + ".position");
  expect_same_column(c.velocity, single.velocity, rel, who + ".velocity");
  expect_same_column(c.friction, single.friction, rel, who + ".friction");
  expect_same_column(c.applied, single.applied, rel, who + ".applied");
  expect_same_column(c.drive, single.drive, rel, who + ".drive");
  EXPECT_EQ(c.stuck, single.stuck) << who;
  ASSERT_EQ(c.law_state.size(), single.law_state.size()) << who;
  for (std::size_t i = 0; i < c.law_state.size(); ++i)
    expect_same_column(c.law_state[i], single.law_state[i], rel, who + ".law_state");
  std::vector<ModeSwitch> mine;
  for (const ModeSwitch& s : multi.switches)
    if (s.contact == k) mine.push_back(s);
  ASSERT_EQ(mine.size(), single.switches.size()) << who;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    EXPECT_NEAR(mine[i].time, single.switches[i].time, rel * std::max(1.0, single.switches[i].time)) << who << " switch " << i;
    EXPECT_EQ(mine[i].kind, single.switches[i].kind) << who << " switch " << i;
    EXPECT_EQ(mine[i].direction, single.switches[i].direction) << who << " switch " << i;
    double scale = 1e-300;  // of the positions: a stick at x ~ 0 is compared on the motion's scale
    for (double v : single.position) scale = std::max(scale, std::abs(v));
    EXPECT_NEAR(mine[i].position, single.switches[i].position, rel * scale) << who << " switch " << i;
  }
}

std::vector<NamedAxis> same_axes(int n, double M) {
  std::vector<NamedAxis> axes;
  const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < n; ++k) axes.push_back({names[k], AxisParams{M, 0.0}, std::nullopt});
  return axes;
}

InputSignal sine(double amplitude, double omega) {
  InputSignal in;
  in.shape = InputShape::sine;
  in.amplitude = amplitude;
  in.omega = omega;
  return in;
}

}  // namespace

// (a) Identical axes: each one is the 1-DOF run, in every solver mode, with its switches tagged.
TEST(MultiContact, IdenticalAxesEachGiveTheOneDofRunInEveryMode) {
  const double M = 2.0;
  struct Case {
    const char* what;
    FrictionLaw law;
    SolverMode mode;
    double rel;
    double rtol;  // the solver's (CVODE modes)
  };
  const std::vector<Case> cases = {
      {"hybrid", StaticCoulombViscous{1.5, 1.0, 0.1}, SolverMode::hybrid, kSameRunRelTol, 1e-8},
      {"stiff lugre", LuGre{}, SolverMode::stiff, kStiffSameRunRelTol, 1e-10},
      {"fixed-step", StaticCoulombViscous{1.5, 1.0, 0.1}, SolverMode::fixed_step, kSameRunRelTol, 1e-8},
  };
  const InputSignal in = sine(2.0, 3.0);  // pushes past the breakaway level both ways: stick, slip, reversal
  for (const Case& c : cases) {
    SimulationOptions o;
    o.duration = 4.0;
    o.output_rate = 200.0;
    o.mode = c.mode;
    o.dt = 1e-4;
    o.rtol = c.rtol;
    o.atol = 1e-2 * c.rtol;
    const Trajectory one = simulate(RigidAxis(AxisParams{M, 0.0}), c.law, in, o);
    if (c.mode == SolverMode::hybrid) {
      ASSERT_GT(one.switches.size(), 4u) << "the case must exercise the switches";
    }
    for (int n : {2, 3}) {
      const MultiAxis plant(same_axes(n, M));
      const std::vector<InputSignal> inputs(static_cast<std::size_t>(n), in);
      const Trajectory multi = simulate(plant, c.law, inputs, o);
      ASSERT_EQ(multi.num_contacts(), n);
      EXPECT_STREQ(multi.stats.solver, one.stats.solver) << c.what;
      for (int k = 0; k < n; ++k) {
        SCOPED_TRACE(std::string(c.what) + ", " + std::to_string(n) + " axes, axis " + std::to_string(k));
        expect_contact_is_run(multi, k, one, c.rel);
      }
    }
  }
}

// (a) Different axes, each with its own law, inertia and input, in fixed-step mode: each axis's
// arithmetic is the 1-DOF run's (no adaptive step couples them), so the match is exact.
TEST(MultiContact, DifferentAxesWithTheirOwnLawsGiveTheirOneDofRunsInFixedStepMode) {
  std::vector<NamedAxis> axes = {{"x", AxisParams{1.0, 0.0}, FrictionLaw(StaticCoulombViscous{1.5, 1.0, 0.1})},
                                 {"y", AxisParams{3.0, 0.2}, FrictionLaw(LuGre{})},
                                 {"z", AxisParams{0.5, 0.0}, std::nullopt}};
  const FrictionLaw shared = Coulomb{0.4};
  const std::vector<InputSignal> inputs = {sine(2.0, 3.0), sine(1.7, 5.0), sine(0.6, 2.0)};
  const MultiAxis plant(axes);
  SimulationOptions o;
  o.duration = 3.0;
  o.mode = SolverMode::fixed_step;
  o.dt = 1e-4;
  const Trajectory multi = simulate(plant, shared, inputs, o);
  for (int k = 0; k < 3; ++k) {
    const auto& a = axes[static_cast<std::size_t>(k)];
    const Trajectory one = simulate(RigidAxis(a.params), a.law ? *a.law : shared, inputs[static_cast<std::size_t>(k)], o);
    SCOPED_TRACE("axis " + a.name);
    expect_contact_is_run(multi, k, one, kSameRunRelTol);
  }
}

namespace {

// Two masses joined by a spring, each on its own contact: the input force u pushes mass a, the
// spring k (x_a - x_b) pulls b along. States: x_a, v_a, x_b, v_b.
class TwoMasses : public Plant {
 public:
  TwoMasses(double ma, double mb, double k, FrictionLaw la, FrictionLaw lb) : ma_(ma), mb_(mb), k_(k), la_(la), lb_(lb) {}
  std::string type() const override { return "two-masses"; }
  int num_states() const override { return 4; }
  int num_contacts() const override { return 2; }
  Contact contact(int i) const override { return i == 0 ? Contact{"a", 0, 1, &la_} : Contact{"b", 2, 3, &lb_}; }
  double inertia(int i) const override { return i == 0 ? ma_ : mb_; }
  void applied(double, std::span<const double> x, Inputs u, std::span<double> force) const override {
    const double spring = k_ * (x[0] - x[2]);
    force[0] = u[0].value - spring;
    force[1] = spring;
  }
  void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                   std::span<double> dx) const override {
    double a[2];
    applied(t, x, u, a);
    dx[0] = x[1];
    dx[1] = (a[0] - friction[0]) / ma_;
    dx[2] = x[3];
    dx[3] = (a[1] - friction[1]) / mb_;
  }
  double energy(double xa, double va, double xb, double vb) const {
    return 0.5 * ma_ * va * va + 0.5 * mb_ * vb * vb + 0.5 * k_ * (xa - xb) * (xa - xb);
  }

 private:
  double ma_, mb_, k_;
  FrictionLaw la_, lb_;
};

InputSignal ramp(double rate) {
  InputSignal in;
  in.shape = InputShape::ramp;
  in.rate = rate;
  return in;
}

}  // namespace

// (b) Mass a breaks away under a force ramp while b stays stuck; the stretched spring then breaks
// b loose. Each contact decides from its own applied force.
TEST(MultiContact, CoupledMassesOneStuckWhileTheOtherSlides) {
  const double k = 10.0, Fs_a = 1.0, Fs_b = 3.0, rate = 1.0;  // N/m, N, N, N/s
  const TwoMasses plant(1.0, 1.0, k, StaticCoulombViscous{Fs_a, 0.8, 0.0}, StaticCoulombViscous{Fs_b, 2.5, 0.0});
  SimulationOptions o;
  o.duration = 6.0;
  o.output_rate = 1000.0;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Trajectory tr = simulate(plant, Coulomb{}, ramp(rate), o);
  ASSERT_EQ(tr.num_contacts(), 2);
  ASSERT_GE(tr.switches.size(), 2u);
  // a breaks away first, when u = rate t reaches Fs_a (the spring is still relaxed).
  const ModeSwitch& first = tr.switches[0];
  EXPECT_EQ(first.contact, 0);
  EXPECT_EQ(first.kind, SwitchKind::breakaway);
  constexpr double kEventTimeTol = 1e-9;  // s; CVODE locates a root to ~100 roundoffs of t, the state error moves it less
  EXPECT_NEAR(first.time, Fs_a / rate, kEventTimeTol);
  // b breaks away when the spring force reaches Fs_b: the root is located on the applied force.
  auto b_break = std::find_if(tr.switches.begin(), tr.switches.end(),
                              [](const ModeSwitch& s) { return s.contact == 1 && s.kind == SwitchKind::breakaway; });
  ASSERT_NE(b_break, tr.switches.end()) << "the spring never broke b loose";
  constexpr double kForceRelTol = 1e-9;  // the applied force at a located root, relative to the level
  EXPECT_NEAR(b_break->applied, Fs_b, kForceRelTol * Fs_b);
  EXPECT_EQ(b_break->position, 0.0) << "b breaks away where it was stuck";
  const ContactColumns& a = tr.contact(0);
  const ContactColumns& b = tr.contact(1);
  bool seen_one_sliding = false;
  for (std::size_t r = 0; r < tr.rows(); ++r) {
    if (tr.time[r] >= b_break->time) break;
    ASSERT_EQ(b.stuck[r], 1.0) << "row " << r;
    EXPECT_EQ(b.position[r], 0.0) << "row " << r;
    EXPECT_EQ(b.velocity[r], 0.0) << "row " << r;
    EXPECT_NEAR(b.friction[r], b.applied[r], kForceRelTol * Fs_b) << "a stuck contact's friction balances its applied force, row " << r;
    seen_one_sliding = seen_one_sliding || (a.stuck[r] == 0.0 && a.velocity[r] > 0.0);
  }
  EXPECT_TRUE(seen_one_sliding) << "a never slid while b was stuck";
  // Momentum: d/dt (ma va + mb vb) = u - F_a - F_b; trapezoid integral over the 1 kHz rows.
  double p_int = 0.0, worst = 0.0;
  for (std::size_t r = 1; r < tr.rows(); ++r) {
    const double dt = tr.time[r] - tr.time[r - 1];
    auto net = [&](std::size_t i) { return a.reference[i] - a.friction[i] - b.friction[i]; };
    p_int += 0.5 * dt * (net(r) + net(r - 1));
    worst = std::max(worst, std::abs(p_int - (a.velocity[r] + b.velocity[r])));
  }
  // The trapezoid rule errs by dt^2/12 |d2 net/dt2| per unit time, and by dt |jump| at each of the
  // few switches inside a row (friction jumps Fs - Fc and at reversals): a few 1e-4 N s.
  constexpr double kMomentumAbsTol = 2e-3;  // N s, against a momentum of ~10 N s at the end
  EXPECT_LT(worst, kMomentumAbsTol);
}

// (b) Unforced and symmetric: a stretched spring between equal masses on equal contacts. The
// masses move mirror-wise (zero total momentum), stick at the same instant, and the energy never grows.
TEST(MultiContact, SymmetricMassesKeepZeroMomentumAndLoseEnergy) {
  const double k = 50.0;
  const FrictionLaw law = StaticCoulombViscous{1.2, 1.0, 0.0};
  const TwoMasses plant(1.0, 1.0, k, law, law);
  SimulationOptions o;
  o.duration = 5.0;  // ~10 half cycles of 0.31 s until the swing is inside Fs / (2 k)
  o.output_rate = 1000.0;
  o.initial_positions = {0.2, -0.2};
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Trajectory tr = simulate(plant, Coulomb{}, InputSignal{}, o);
  const ContactColumns& a = tr.contact(0);
  const ContactColumns& b = tr.contact(1);
  ASSERT_FALSE(tr.switches.empty());
  const double e0 = plant.energy(a.position[0], a.velocity[0], b.position[0], b.velocity[0]);
  constexpr double kMirrorRelTol = 1e-12;  // the two halves do the same arithmetic with opposite signs
  constexpr double kEnergyRelTol = 1e-8;   // energy may rise by the integration error only (rtol 1e-10, with margin)
  double e_prev = e0;
  for (std::size_t r = 0; r < tr.rows(); ++r) {
    EXPECT_NEAR(a.velocity[r] + b.velocity[r], 0.0, kMirrorRelTol * 10.0) << "momentum, row " << r;
    EXPECT_NEAR(a.position[r] + b.position[r], 0.0, kMirrorRelTol) << "row " << r;
    const double e = plant.energy(a.position[r], a.velocity[r], b.position[r], b.velocity[r]);
    EXPECT_LE(e, e_prev + kEnergyRelTol * e0) << "energy grew at row " << r;
    e_prev = e;
  }
  EXPECT_LT(e_prev, 0.5 * e0) << "friction dissipated energy";
  EXPECT_EQ(a.stuck.back(), 1.0);
  EXPECT_EQ(b.stuck.back(), 1.0);
  // Switches come in mirrored pairs at the same instant, one per contact.
  ASSERT_EQ(tr.switches.size() % 2, 0u);
  for (std::size_t i = 0; i + 1 < tr.switches.size(); i += 2) {
    EXPECT_EQ(tr.switches[i].time, tr.switches[i + 1].time);
    EXPECT_NE(tr.switches[i].contact, tr.switches[i + 1].contact);
    EXPECT_EQ(tr.switches[i].kind, tr.switches[i + 1].kind);
  }
}

namespace {

// A 1-DOF plant with an event function of its own: the force F0 s on a mass, where the sign s is a
// discrete state flipped each time x crosses 0.5 (a bang-bang position switch). States: x, v, s.
class SwitchedForce : public SingleContactPlant {
 public:
  std::string type() const override { return "switched-force"; }
  int num_states() const override { return 3; }
  double inertia(int = 0) const override { return 1.0; }
  void initial_extras(std::span<double> x) const override { x[2] = 1.0; }
  double applied(double, std::span<const double> x, const InputValue&) const override { return kF0 * x[2]; }
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override {
    dx[0] = x[1];
    dx[1] = applied(t, x, u) - friction;
    dx[2] = 0.0;
  }
  int num_events() const override { return 1; }
  void events(double, std::span<const double> x, Inputs, std::span<double> g) const override { g[0] = x[0] - 0.5; }
  void on_event(double, std::span<double> x, Inputs, int k) const override {
    if (k == 0) x[2] = -x[2];
  }
  static constexpr double kF0 = 1.0;  // N
};

}  // namespace

// (c) The engine stops on the plant's own event, calls on_event and goes on with the flipped force.
TEST(MultiContact, PlantEventFunctionIsLocatedAndFlipsTheForce) {
  const double Fc = 0.2, F0 = SwitchedForce::kF0;  // N; unit mass
  const SwitchedForce plant;
  SimulationOptions o;
  o.duration = 4.0;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Trajectory tr = simulate(plant, Coulomb{Fc}, InputSignal{}, o);
  // Closed form: accelerate at F0 - Fc to x = 0.5 (event 1), decelerate at F0 + Fc to rest
  // (reversal: |F0| > Fc), come back at F0 - Fc to x = 0.5 (event 2).
  const double a1 = F0 - Fc, t1 = std::sqrt(2 * 0.5 / a1), v1 = a1 * t1;
  const double t2 = t1 + v1 / (F0 + Fc), x2 = 0.5 + v1 * v1 / (2 * (F0 + Fc));
  const double t3 = t2 + std::sqrt(2 * (x2 - 0.5) / a1);
  ASSERT_GE(tr.plant_events.size(), 2u);
  constexpr double kEventTimeTol = 1e-9;  // s; root location (~100 roundoffs) plus the state error at rtol 1e-10
  EXPECT_NEAR(tr.plant_events[0].time, t1, kEventTimeTol);
  EXPECT_EQ(tr.plant_events[0].index, 0);
  EXPECT_NEAR(tr.plant_events[1].time, t3, kEventTimeTol);
  ASSERT_FALSE(tr.switches.empty());
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::reversal);
  EXPECT_NEAR(tr.switches[0].time, t2, kEventTimeTol);
  constexpr double kPositionTol = 1e-9;  // m; the state error at rtol 1e-10 over a 0.5 m swing, with margin
  EXPECT_NEAR(tr.switches[0].position, x2, kPositionTol);
  // Between the events the applied force is -F0.
  for (std::size_t r = 0; r < tr.rows(); ++r) {
    if (tr.time[r] > t1 + 1e-6 && tr.time[r] < t3 - 1e-6) {
      EXPECT_EQ(tr.applied[r], -F0) << "t = " << tr.time[r];
    }
  }
}

// (c) The same event without stiction: a viscous law runs stiff (no contact root functions, and
// no rows read from the step's polynomial past an event), and the event is located all the same.
TEST(MultiContact, PlantEventIsLocatedInAStiffRunToo) {
  const double Fv = 0.7, F0 = SwitchedForce::kF0;  // N s/m, N; unit mass
  SimulationOptions o;
  o.duration = 2.0;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Trajectory tr = simulate(SwitchedForce{}, Viscous{Fv}, InputSignal{}, o);
  EXPECT_STREQ(tr.stats.solver, "stiff");
  // x(t) = (F0/Fv) (t - (1 - exp(-Fv t)) / Fv) reaches 0.5 at the root of x(t) - 0.5 (Newton).
  auto x = [&](double t) { return F0 / Fv * (t - (1 - std::exp(-Fv * t)) / Fv); };
  auto v = [&](double t) { return F0 / Fv * (1 - std::exp(-Fv * t)); };
  double t1 = 1.0;
  for (int i = 0; i < 50; ++i) t1 -= (x(t1) - 0.5) / v(t1);
  ASSERT_FALSE(tr.plant_events.empty());
  constexpr double kEventTimeTol = 1e-9;  // s; as above
  EXPECT_NEAR(tr.plant_events[0].time, t1, kEventTimeTol);
  // After the event the force is -F0: the velocity falls faster than viscous decay alone.
  const std::size_t r = static_cast<std::size_t>(std::ceil((t1 + 0.1) * o.output_rate));
  EXPECT_EQ(tr.applied[r], -F0);
}

// (d) Input counts are checked, naming the plant type and both counts.
TEST(MultiContact, InputCountErrorsNameThePlantAndTheCounts) {
  const MultiAxis plant(same_axes(3, 1.0));
  SimulationOptions o;
  o.duration = 0.1;
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no std::invalid_argument");
  };
  const std::string one = message([&] { simulate(plant, Coulomb{}, InputSignal{}, o); });
  EXPECT_NE(one.find("'multi-axis' takes 3 inputs; 1 given"), std::string::npos) << one;
  const std::vector<InputSignal> two(2);
  const std::string span = message([&] { simulate(plant, Coulomb{}, std::span<const InputSignal>(two), o); });
  EXPECT_NE(span.find("'multi-axis' takes 3 inputs; 2 given"), std::string::npos) << span;
  Scenario s;
  s.plant = std::make_shared<MultiAxis>(same_axes(3, 1.0));
  s.options = o;
  s.inputs.resize(4);
  const std::string sc = message([&] { simulate(s); });
  EXPECT_NE(sc.find("'multi-axis' takes 3 inputs; scenario.inputs has 4"), std::string::npos) << sc;
  s.inputs.clear();
  const std::string none = message([&] { simulate(s); });
  EXPECT_NE(none.find("takes 3 inputs; 1 given"), std::string::npos) << none;
  s.inputs.resize(3);
  EXPECT_NO_THROW(simulate(s));
  const std::string opts = message([&] {
    SimulationOptions bad = o;
    bad.initial_positions = {0.0, 1.0};
    simulate(plant, Coulomb{}, std::span<const InputSignal>(s.inputs), bad);
  });
  EXPECT_NE(opts.find("initial_positions has 2 entries; plant 'multi-axis' has 3 contacts"), std::string::npos) << opts;
}

// (e) An N-contact trajectory names its columns by contact; a 1-DOF one keeps today's names.
TEST(MultiContact, CsvHeaderOfATwoContactRunNamesEachContactsColumns) {
  const MultiAxis plant(same_axes(2, 1.0));
  SimulationOptions o;
  o.duration = 0.05;
  const std::vector<InputSignal> inputs(2);
  const Trajectory tr = simulate(plant, Coulomb{}, inputs, o);
  const std::string csv = tr.to_csv();
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "time,x.position,x.velocity,x.friction,x.applied,x.current,x.voltage,x.reference,x.stuck,x.drive,"
            "y.position,y.velocity,y.friction,y.applied,y.current,y.voltage,y.reference,y.stuck,y.drive");
  EXPECT_EQ(&tr.column("y.velocity"), &tr.contact(1).velocity);
  EXPECT_EQ(&tr.column("x.stuck"), &tr.stuck);
  EXPECT_THROW(tr.column("position"), std::invalid_argument);
  EXPECT_EQ(tr.names().size(), 19u);
  const Trajectory one = simulate(RigidAxis(AxisParams{}), Coulomb{}, InputSignal{}, o);
  const std::string csv1 = one.to_csv();
  EXPECT_EQ(csv1.substr(0, csv1.find('\n')), "time,position,velocity,friction,applied,current,voltage,reference,stuck");
  EXPECT_EQ(one.names(), Trajectory::column_names());
}

// Static (memoryless) friction laws: known values computed by hand, odd symmetry, the stiction
// rule of friction_force at v = 0, and one validation test per rule with its exact message.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/validation_cases.hpp"
#include "frictionlab/models/asymmetric.hpp"
#include "frictionlab/models/coulomb.hpp"
#include "frictionlab/models/coulomb_viscous.hpp"
#include "frictionlab/models/karnopp.hpp"
#include "frictionlab/models/smooth.hpp"
#include "frictionlab/models/static_coulomb_viscous.hpp"
#include "frictionlab/models/static_law.hpp"
#include "frictionlab/models/stribeck.hpp"
#include "frictionlab/models/viscous.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using testing::RuleCase;
using testing::with;

// The expected values below are the law's formula evaluated by hand in a different order of
// operations (and with exp/tanh/atan of the same arguments): they agree to a few ulps.
constexpr double kRelTol = 1e-13;

void expect_rel(double got, double want) { EXPECT_NEAR(got, want, kRelTol * std::abs(want)) << "want " << want; }

// Velocities used for symmetry checks: both small (inside the Stribeck dip) and large.
const std::vector<double> kVelocities = {1e-6, 3e-4, 1e-3, 2.5e-3, 0.1, 1.0, 37.0, 1e3};

template <class Law>
void expect_odd(const Law& law) {
  for (double v : kVelocities) EXPECT_EQ(law.sliding(-v), -law.sliding(v)) << Law::kName << " at v = " << v;
  EXPECT_EQ(law.sliding(0.0), 0.0);
  EXPECT_EQ(law.breakaway_positive(), law.breakaway_negative());
}

// At v = 0 friction balances the applied force up to the breakaway level, then saturates there.
template <class Law>
void expect_stiction(const Law& law, double Fs_pos, double Fs_neg) {
  EXPECT_EQ(law.breakaway_positive(), Fs_pos);
  EXPECT_EQ(law.breakaway_negative(), Fs_neg);
  for (double frac : {0.0, 0.25, 0.5, 0.999, 1.0}) {
    EXPECT_EQ(friction_force(law, 0.0, frac * Fs_pos), frac * Fs_pos) << "holds " << frac << " of Fs+";
    EXPECT_EQ(friction_force(law, 0.0, -frac * Fs_neg), -frac * Fs_neg) << "holds " << frac << " of Fs-";
  }
  for (double over : {1.001, 2.0, 100.0}) {
    EXPECT_EQ(friction_force(law, 0.0, over * Fs_pos + 1e-9), Fs_pos) << "saturates at Fs+";
    EXPECT_EQ(friction_force(law, 0.0, -over * Fs_neg - 1e-9), -Fs_neg) << "saturates at Fs-";
  }
  // While sliding, the applied force does not matter.
  EXPECT_EQ(friction_force(law, 0.2, 1e6), law.sliding(0.2));
  EXPECT_EQ(friction_force(law, -0.2, 1e6), law.sliding(-0.2));
}

// ---------------------------------------------------------------------------------------------
// Known values

TEST(Coulomb, KnownValues) {
  const Coulomb law{2.0};
  EXPECT_EQ(law.sliding(0.5), 2.0);    // Fc sign(v) = 2
  EXPECT_EQ(law.sliding(-3.0), -2.0);  // Fc sign(v) = -2
  EXPECT_EQ(law.sliding(1e-300), 2.0);
  EXPECT_EQ(law.sliding(0.0), 0.0);
}

TEST(Coulomb, OddAndStiction) {
  const Coulomb law{2.0};
  expect_odd(law);
  expect_stiction(law, 2.0, 2.0);
}

TEST(Viscous, KnownValues) {
  const Viscous law{0.3};
  expect_rel(law.sliding(2.0), 0.6);     // Fv v = 0.3 * 2
  expect_rel(law.sliding(-0.5), -0.15);  // 0.3 * -0.5
}

TEST(Viscous, OddAndHoldsNothingAtRest) {
  const Viscous law{0.3};
  expect_odd(law);
  expect_stiction(law, 0.0, 0.0);
  EXPECT_EQ(friction_force(law, 0.0, 5.0), 0.0);  // a viscous contact holds no force
}

TEST(CoulombViscous, KnownValues) {
  const CoulombViscous law{1.0, 0.5};
  expect_rel(law.sliding(2.0), 2.0);     // Fc + Fv v = 1 + 0.5 * 2
  expect_rel(law.sliding(-0.1), -1.05);  // -1 + 0.5 * -0.1
}

TEST(CoulombViscous, OddAndStiction) {
  const CoulombViscous law{1.0, 0.5};
  expect_odd(law);
  expect_stiction(law, 1.0, 1.0);
}

TEST(StaticCoulombViscous, KnownValues) {
  const StaticCoulombViscous law{1.5, 1.0, 0.1};
  expect_rel(law.sliding(0.5), 1.05);  // Fc + Fv v = 1 + 0.1 * 0.5
  expect_rel(law.sliding(-2.0), -1.2);  // -1 + 0.1 * -2
}

TEST(StaticCoulombViscous, OddAndStictionUpToFs) {
  const StaticCoulombViscous law{1.5, 1.0, 0.1};
  expect_odd(law);
  expect_stiction(law, 1.5, 1.5);  // holds up to Fs, not Fc
}

TEST(Stribeck, KnownValuesGaussian) {
  const Stribeck law{1.0, 1.5, 0.01, 2.0, 0.4};
  // v = vs: Fc + (Fs - Fc) exp(-1) + Fv v = 1 + 0.5 e^-1 + 0.004
  expect_rel(law.sliding(0.01), 1.0 + 0.5 * std::exp(-1.0) + 0.004);
  // v = -2 vs: -(1 + 0.5 e^-4) - 0.008
  expect_rel(law.sliding(-0.02), -(1.0 + 0.5 * std::exp(-4.0)) - 0.008);
  // level without sign or viscous part at v = 0.5 vs: 1 + 0.5 e^-0.25
  expect_rel(law.level(0.005), 1.0 + 0.5 * std::exp(-0.25));
  expect_rel(law.level(0.0), 1.5);  // at rest the level is Fs
}

TEST(Stribeck, KnownValuesOtherExponents) {
  const Stribeck exp1{1.0, 1.5, 0.01, 1.0, 0.4};
  // delta = 1, v = 2 vs: 1 + 0.5 e^-2 + 0.4 * 0.02
  expect_rel(exp1.sliding(0.02), 1.0 + 0.5 * std::exp(-2.0) + 0.008);
  const Stribeck half{2.0, 3.0, 0.01, 0.5, 0.0};
  // delta = 0.5, v = 4 vs: |4|^0.5 = 2: 2 + 1 e^-2
  expect_rel(half.sliding(0.04), 2.0 + std::exp(-2.0));
  // Far above vs only Coulomb + viscous remain: 1 + 0.4 * 10
  expect_rel(exp1.sliding(10.0), 1.0 + 4.0);
}

TEST(Stribeck, OddAndStictionUpToFs) {
  const Stribeck law{1.0, 1.5, 0.01, 2.0, 0.4};
  expect_odd(law);
  expect_stiction(law, 1.5, 1.5);
}

TEST(Karnopp, KnownValuesOutsideTheBand) {
  const Karnopp law{1.5, 1.0, 0.1, 1e-3};
  expect_rel(law.sliding(0.5), 1.05);                  // Fc + Fv v
  expect_rel(law.force(0.5, 100.0), 1.05);             // outside |v| < dv it slides whatever is applied
  expect_rel(law.force(-2e-3, 0.0), -(1.0 + 2e-4));    // -Fc + Fv v
  expect_rel(friction_force(law, 1e-3, 0.0), 1.0001);  // |v| = dv is outside the band: 1 + 0.1e-3
}

TEST(Karnopp, BandBalancesAppliedUpToFs) {
  const Karnopp law{1.5, 1.0, 0.1, 1e-3};
  for (double v : {0.0, 5e-4, -9.99e-4}) {
    EXPECT_EQ(law.force(v, 0.7), 0.7) << v;
    EXPECT_EQ(law.force(v, -1.5), -1.5) << v;
    EXPECT_EQ(law.force(v, 2.0), 1.5) << v;
    EXPECT_EQ(law.force(v, -2.0), -1.5) << v;
    EXPECT_EQ(friction_force(law, v, 0.7), 0.7) << "friction_force uses Karnopp's own rule at v = " << v;
  }
}

TEST(Karnopp, OddAndStictionAtZero) {
  const Karnopp law{1.5, 1.0, 0.1, 1e-3};
  expect_odd(law);
  expect_stiction(law, 1.5, 1.5);
  for (double v : {5e-4, 2e-3, 1.0})
    for (double a : {0.3, 1.0, 3.0}) EXPECT_EQ(law.force(-v, -a), -law.force(v, a));
}

TEST(Smooth, KnownValuesTanh) {
  Smooth law{1.0, 1.5, 0.01, 2.0, 0.2, 1e-3, SmoothShape::tanh};
  // v = 2 vt: tanh(2) (Fc + (Fs - Fc) exp(-(0.002/0.01)^2)) + Fv v
  expect_rel(law.sliding(0.002), std::tanh(2.0) * (1.0 + 0.5 * std::exp(-0.04)) + 0.2 * 0.002);
  // v = -0.03: tanh(-30) ~ -1: -(1 + 0.5 e^-9) - 0.006
  expect_rel(law.sliding(-0.03), std::tanh(-30.0) * (1.0 + 0.5 * std::exp(-9.0)) - 0.006);
}

TEST(Smooth, KnownValuesAtan) {
  Smooth law{1.0, 1.5, 0.01, 2.0, 0.2, 1e-3, SmoothShape::atan};
  // v = 2 vt: (2/pi) atan(2) (1 + 0.5 exp(-0.04)) + 0.2 * 0.002
  expect_rel(law.sliding(0.002), 2.0 / std::numbers::pi * std::atan(2.0) * (1.0 + 0.5 * std::exp(-0.04)) + 0.0004);
}

TEST(Smooth, DefaultIsSmoothedCoulomb) {
  const Smooth law;  // Fc = Fs = 1, Fv = 0, vt = 1e-3
  expect_rel(law.sliding(1e-3), std::tanh(1.0));  // tanh(v/vt) Fc
  expect_rel(law.sliding(1.0), std::tanh(1000.0));
}

TEST(Smooth, OddAndNoStiction) {
  for (SmoothShape shape : {SmoothShape::tanh, SmoothShape::atan}) {
    Smooth law{1.0, 1.5, 0.01, 2.0, 0.2, 1e-3, shape};
    expect_odd(law);
    expect_stiction(law, 0.0, 0.0);  // continuous law: holds nothing at v = 0
  }
}

// ---------------------------------------------------------------------------------------------
// Direction-asymmetric forms: `pos` for v > 0 (and pushes in +), `neg` for v < 0.

TEST(Asymmetric, Coulomb) {
  const Asymmetric<Coulomb> law{Coulomb{2.0}, Coulomb{1.0}};
  EXPECT_EQ(Asymmetric<Coulomb>::name(), "coulomb-asymmetric");
  EXPECT_EQ(law.sliding(0.3), 2.0);    // Fc_pos
  EXPECT_EQ(law.sliding(-0.3), -1.0);  // -Fc_neg
  expect_stiction(law, 2.0, 1.0);
}

TEST(Asymmetric, Viscous) {
  const Asymmetric<Viscous> law{Viscous{0.3}, Viscous{0.5}};
  expect_rel(law.sliding(2.0), 0.6);    // Fv_pos v
  expect_rel(law.sliding(-2.0), -1.0);  // Fv_neg v
  expect_stiction(law, 0.0, 0.0);
}

TEST(Asymmetric, CoulombViscous) {
  const Asymmetric<CoulombViscous> law{CoulombViscous{1.0, 0.5}, CoulombViscous{0.8, 0.2}};
  expect_rel(law.sliding(2.0), 2.0);    // 1 + 0.5 * 2
  expect_rel(law.sliding(-2.0), -1.2);  // -0.8 + 0.2 * -2
  expect_stiction(law, 1.0, 0.8);
}

TEST(Asymmetric, StaticCoulombViscous) {
  const Asymmetric<StaticCoulombViscous> law{StaticCoulombViscous{1.5, 1.0, 0.1}, StaticCoulombViscous{2.5, 2.0, 0.3}};
  expect_rel(law.sliding(1.0), 1.1);    // 1 + 0.1 * 1
  expect_rel(law.sliding(-1.0), -2.3);  // -2 + 0.3 * -1
  expect_stiction(law, 1.5, 2.5);
}

TEST(Asymmetric, Stribeck) {
  const Asymmetric<Stribeck> law{Stribeck{1.0, 1.5, 0.01, 2.0, 0.4}, Stribeck{2.0, 3.0, 0.02, 1.0, 0.1}};
  // v = 0.01: 1 + 0.5 e^-1 + 0.4 * 0.01
  expect_rel(law.sliding(0.01), 1.0 + 0.5 * std::exp(-1.0) + 0.004);
  // v = -0.01: -(2 + 1 e^-0.5) + 0.1 * -0.01
  expect_rel(law.sliding(-0.01), -(2.0 + std::exp(-0.5)) - 0.001);
  expect_stiction(law, 1.5, 3.0);
}

TEST(Asymmetric, EqualSidesIsTheSymmetricLaw) {
  const Stribeck s{1.0, 1.5, 0.01, 2.0, 0.4};
  const Asymmetric<Stribeck> law{s, s};
  for (double v : kVelocities) {
    EXPECT_EQ(law.sliding(v), s.sliding(v));
    EXPECT_EQ(law.sliding(-v), s.sliding(-v));
  }
}

// ---------------------------------------------------------------------------------------------
// Validation: one case per rule, with the exact message (law, parameter, value, rule).




class StaticValidation : public ::testing::TestWithParam<RuleCase> {};

TEST_P(StaticValidation, MessageNamesLawParameterValueAndRule) {
  EXPECT_EQ(error_of(GetParam().validate), GetParam().message);
}

const double kNaN = std::nan("");
const double kInf = INFINITY;

INSTANTIATE_TEST_SUITE_P(
    Rules, StaticValidation,
    ::testing::Values(
        RuleCase{"coulomb_Fc_negative", with<Coulomb>([](auto& l) { l.Fc = -1; }), "coulomb: Fc = -1 must be >= 0 (N or N m)"},
        RuleCase{"coulomb_Fc_nan", with<Coulomb>([](auto& l) { l.Fc = kNaN; }), "coulomb: Fc = nan must be >= 0 (N or N m)"},
        RuleCase{"viscous_Fv_negative", with<Viscous>([](auto& l) { l.Fv = -0.5; }),
                 "viscous: Fv = -0.5 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"viscous_Fv_inf", with<Viscous>([](auto& l) { l.Fv = kInf; }),
                 "viscous: Fv = inf must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"coulomb_viscous_Fc", with<CoulombViscous>([](auto& l) { l.Fc = -2; }),
                 "coulomb-viscous: Fc = -2 must be >= 0 (N or N m)"},
        RuleCase{"coulomb_viscous_Fv", with<CoulombViscous>([](auto& l) { l.Fv = -0.1; }),
                 "coulomb-viscous: Fv = -0.1 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"scv_Fc", with<StaticCoulombViscous>([](auto& l) { l.Fc = -1; }),
                 "static-coulomb-viscous: Fc = -1 must be >= 0 (N or N m)"},
        RuleCase{"scv_Fs_below_Fc", with<StaticCoulombViscous>([](auto& l) { l.Fs = 0.5; }),
                 "static-coulomb-viscous: Fs = 0.5 must be >= Fc = 1 (N or N m)"},
        RuleCase{"scv_Fv", with<StaticCoulombViscous>([](auto& l) { l.Fv = -3; }),
                 "static-coulomb-viscous: Fv = -3 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"stribeck_Fc", with<Stribeck>([](auto& l) { l.Fc = -1; }), "stribeck: Fc = -1 must be >= 0 (N or N m)"},
        RuleCase{"stribeck_Fs", with<Stribeck>([](auto& l) { l.Fs = 0.25; }),
                 "stribeck: Fs = 0.25 must be >= Fc = 1 (N or N m)"},
        RuleCase{"stribeck_vs", with<Stribeck>([](auto& l) { l.vs = -1; }), "stribeck: vs = -1 must be > 0 (m/s or rad/s)"},
        RuleCase{"stribeck_vs_zero", with<Stribeck>([](auto& l) { l.vs = 0; }), "stribeck: vs = 0 must be > 0 (m/s or rad/s)"},
        RuleCase{"stribeck_delta", with<Stribeck>([](auto& l) { l.delta = 0; }), "stribeck: delta = 0 must be > 0"},
        RuleCase{"stribeck_Fv", with<Stribeck>([](auto& l) { l.Fv = -0.4; }),
                 "stribeck: Fv = -0.4 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"karnopp_Fc", with<Karnopp>([](auto& l) { l.Fc = -1; }), "karnopp: Fc = -1 must be >= 0 (N or N m)"},
        RuleCase{"karnopp_Fs", with<Karnopp>([](auto& l) { l.Fs = 0.9; }), "karnopp: Fs = 0.9 must be >= Fc = 1 (N or N m)"},
        RuleCase{"karnopp_Fv", with<Karnopp>([](auto& l) { l.Fv = -1; }),
                 "karnopp: Fv = -1 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"karnopp_dv", with<Karnopp>([](auto& l) { l.dv = 0; }), "karnopp: dv = 0 must be > 0 (m/s or rad/s)"},
        RuleCase{"smooth_Fc", with<Smooth>([](auto& l) { l.Fc = -1; }), "smooth: Fc = -1 must be >= 0 (N or N m)"},
        RuleCase{"smooth_Fs", with<Smooth>([](auto& l) { l.Fs = 0.5; }), "smooth: Fs = 0.5 must be >= Fc = 1 (N or N m)"},
        RuleCase{"smooth_vs", with<Smooth>([](auto& l) { l.vs = -0.001; }),
                 "smooth: vs = -0.001 must be > 0 (m/s or rad/s)"},
        RuleCase{"smooth_delta", with<Smooth>([](auto& l) { l.delta = -2; }), "smooth: delta = -2 must be > 0"},
        RuleCase{"smooth_Fv", with<Smooth>([](auto& l) { l.Fv = -1; }),
                 "smooth: Fv = -1 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"smooth_vt", with<Smooth>([](auto& l) { l.vt = 0; }), "smooth: vt = 0 must be > 0 (m/s or rad/s)"},
        // Asymmetric forms: the law name gets -asymmetric, the parameter its direction suffix,
        // and a rule that refers to another parameter names the same side's one.
        RuleCase{"asym_coulomb_Fc_neg", with<Asymmetric<Coulomb>>([](auto& l) { l.neg.Fc = -1; }),
                 "coulomb-asymmetric: Fc_neg = -1 must be >= 0 (N or N m)"},
        RuleCase{"asym_viscous_Fv_pos", with<Asymmetric<Viscous>>([](auto& l) { l.pos.Fv = -1; }),
                 "viscous-asymmetric: Fv_pos = -1 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"asym_cv_Fv_neg", with<Asymmetric<CoulombViscous>>([](auto& l) { l.neg.Fv = -1; }),
                 "coulomb-viscous-asymmetric: Fv_neg = -1 must be >= 0 (N s/m or N m s/rad)"},
        RuleCase{"asym_scv_Fs_pos", with<Asymmetric<StaticCoulombViscous>>([](auto& l) { l.pos.Fs = 0.5; }),
                 "static-coulomb-viscous-asymmetric: Fs_pos = 0.5 must be >= Fc_pos = 1 (N or N m)"},
        RuleCase{"asym_stribeck_vs_neg", with<Asymmetric<Stribeck>>([](auto& l) { l.neg.vs = -1; }),
                 "stribeck-asymmetric: vs_neg = -1 must be > 0 (m/s or rad/s)"},
        RuleCase{"asym_stribeck_Fs_neg", with<Asymmetric<Stribeck>>([](auto& l) { l.neg.Fs = 0.5; }),
                 "stribeck-asymmetric: Fs_neg = 0.5 must be >= Fc_neg = 1 (N or N m)"}),
    [](const ::testing::TestParamInfo<RuleCase>& info) { return info.param.name; });

TEST(StaticValidation, DefaultsAreValid) {
  EXPECT_NO_THROW(Coulomb{}.validate());
  EXPECT_NO_THROW(Viscous{}.validate());
  EXPECT_NO_THROW(CoulombViscous{}.validate());
  EXPECT_NO_THROW(StaticCoulombViscous{}.validate());
  EXPECT_NO_THROW(Stribeck{}.validate());
  EXPECT_NO_THROW(Karnopp{}.validate());
  EXPECT_NO_THROW(Smooth{}.validate());
  EXPECT_NO_THROW(Asymmetric<Stribeck>{}.validate());
  // Boundary values that the rules allow: Fc = 0, Fs = Fc, Fv = 0.
  EXPECT_NO_THROW((Stribeck{0.0, 0.0, 1e-3, 2.0, 0.0}.validate()));
}

}  // namespace
}  // namespace frictionlab

// Decay identification on analytic free oscillations (exact solutions, no simulator involved).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "frictionlab/identify/decay.hpp"

namespace fl = frictionlab;

namespace {
// Sampled at 1 kHz, a period of ~2 s: central differences and parabolic peaks are accurate to
// about 1e-6 relative; the energy balance then recovers the levels to better than 1e-3.
constexpr double kDecayRelTol = 1e-3;
constexpr double kDt = 1e-3;

// Spring-mass with Coulomb friction: each half cycle is a harmonic swing about +-Fc/k.
fl::DecayData coulomb_oscillator(double M, double k, double Fc, double A0) {
  const double w = std::sqrt(k / M), c = Fc / k;
  // Duration: until the turning point falls inside the dead band |x| <= Fc/k, plus a margin.
  double t0 = 0;
  for (double A = A0; std::abs(A) > c; A = 2 * (A > 0 ? c : -c) - A) t0 += std::numbers::pi / w;
  fl::DecayData d;
  const int n = static_cast<int>(t0 / kDt) + 200;
  d.time.resize(n);
  d.position.resize(n);
  double Ah = A0;
  double start = 0;
  for (int i = 0; i < n; ++i) {
    const double ti = i * kDt;
    while (ti >= start + std::numbers::pi / w && std::abs(Ah) > c) {
      const double centre = Ah > 0 ? c : -c;
      Ah = 2 * centre - Ah;
      start += std::numbers::pi / w;
    }
    d.time[i] = ti;
    if (std::abs(Ah) <= c) {
      d.position[i] = Ah;  // stuck at the last turning point
    } else {
      const double centre = Ah > 0 ? c : -c;
      d.position[i] = centre + (Ah - centre) * std::cos(w * (ti - start));
    }
  }
  return d;
}

fl::DecayData viscous_oscillator(double M, double k, double Fv, double A0, double duration) {
  const double wn = std::sqrt(k / M), zeta = Fv / (2 * M * wn), wd = wn * std::sqrt(1 - zeta * zeta);
  const int n = static_cast<int>(duration / kDt);
  fl::DecayData d;
  d.time.resize(n);
  d.position.resize(n);
  for (int i = 0; i < n; ++i) {
    const double t = i * kDt;
    d.time[i] = t;
    // x(0) = A0, v(0) = 0
    d.position[i] = A0 * std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t));
  }
  return d;
}
}  // namespace

TEST(Decay, CoulombOscillatorGivesFcAndNoViscous) {
  const double M = 1.0, k = 9.81, Fc = 0.16;
  fl::DecayOptions o;
  o.stiffness = k;
  const auto r = fl::identify_decay(coulomb_oscillator(M, k, Fc, 0.5), o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.value("Fc"), Fc, kDecayRelTol * Fc);
  const auto* fv = r.find("Fv");
  EXPECT_LE(std::abs(fv->value), std::max(2 * fv->std, 1e-6)) << "absent viscous friction must be zero within its std";
}

TEST(Decay, ViscousOscillatorGivesFvAndNoCoulomb) {
  const double M = 1.0, k = 9.81, Fv = 0.5;
  fl::DecayOptions o;
  o.stiffness = k;
  const auto r = fl::identify_decay(viscous_oscillator(M, k, Fv, 0.5, 20.0), o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.value("Fv"), Fv, kDecayRelTol * Fv);
  const auto* fc = r.find("Fc");
  EXPECT_LE(std::abs(fc->value), std::max(2 * fc->std, 1e-6 * Fv)) << "absent Coulomb friction must be zero within its std";
}

TEST(Decay, NaturalFrequencyAloneGivesRelativeFigures) {
  const double M = 2.0, k = 50.0, Fv = 0.8;
  fl::DecayOptions o;
  o.natural_frequency = std::sqrt(k / M);
  const auto r = fl::identify_decay(viscous_oscillator(M, k, Fv, 0.01, 15.0), o);
  ASSERT_TRUE(r.ok()) << r.message;
  const double zeta = Fv / (2 * std::sqrt(k * M));
  EXPECT_NEAR(r.value("zeta"), zeta, kDecayRelTol * zeta);
  EXPECT_EQ(r.find("zeta")->unit, "");
  EXPECT_EQ(r.find("Fc_over_k")->unit, "m");
}

TEST(Decay, TooShortARecordIsAnErrorStatus) {
  fl::DecayOptions o;
  o.stiffness = 9.81;
  const auto r = fl::identify_decay(viscous_oscillator(1, 9.81, 0.5, 0.5, 1.2), o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("half cycles found"), std::string::npos) << r.message;
}

TEST(Decay, MissingStiffnessIsNamed) {
  try {
    fl::identify_decay(viscous_oscillator(1, 9.81, 0.5, 0.5, 5), {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "decay: give --stiffness (N/m or N m/rad; m g l for a pendulum) or --natural-frequency (rad/s)");
  }
}

// Derivatives from ceres::Jet against central finite differences, for every law: the same
// templated formula serves simulation (double) and fitting (Jets), so the Jet derivatives must be
// the derivatives of the double function. Evaluation points are away from the kinks (v != 0,
// not at the elasto-plastic zone edges or a GMS element's stick/slip switch, not at table points).

#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/models/asymmetric.hpp"
#include "frictionlab/models/coulomb.hpp"
#include "frictionlab/models/coulomb_viscous.hpp"
#include "frictionlab/models/dahl.hpp"
#include "frictionlab/models/elastoplastic.hpp"
#include "frictionlab/models/gms.hpp"
#include "frictionlab/models/karnopp.hpp"
#include "frictionlab/models/lugre.hpp"
#include "frictionlab/models/smooth.hpp"
#include "frictionlab/models/static_coulomb_viscous.hpp"
#include "frictionlab/models/stribeck.hpp"
#include "frictionlab/models/table.hpp"
#include "frictionlab/models/viscous.hpp"

namespace frictionlab {
namespace {

// Central difference with a step h = kFdStep |x|: truncation error ~ (h/L)^2 f' where L is the
// scale over which the function bends (here never much shorter than |x|): ~1e-10 relative;
// round-off ~ eps |f| / h ~ 2e-11 |f|/|x|. kRelTol leaves four orders of margin for the
// shortest scales (the elasto-plastic transition zone is about |z| wide).
constexpr double kFdStep = 1e-5;
constexpr double kRelTol = 1e-6;

// |jet - fd| <= kRelTol (|jet| + |F| / |x|): relative to the derivative, or, where the derivative
// is (near) zero, to the natural scale of the output over the input.
void expect_derivative(double jet, double fd, double out, double x, const std::string& what) {
  EXPECT_NEAR(jet, fd, kRelTol * (std::abs(jet) + std::abs(out) / std::abs(x))) << what;
}

template <class Law>
std::vector<double> params_of(const Law& law) {
  std::vector<double> out;
  Law::visit(law, [&](const auto&, Quantity, const double& x) { out.push_back(x); });
  return out;
}

template <class Law>
std::vector<std::string> param_names(const Law& law) {
  std::vector<std::string> out;
  Law::visit(law, [&](const auto& name, Quantity, const double&) { out.push_back(std::string(name)); });
  return out;
}

template <class Law>
Law with_param(Law law, std::size_t i, double value) {
  std::size_t j = 0;
  Law::visit(law, [&](const auto&, Quantity, double& x) {
    if (j++ == i) x = value;
  });
  return law;
}

template <class J, class JLaw>
void set_jet_params(JLaw& law, const std::vector<double>& values, int first_index) {
  std::size_t j = 0;
  JLaw::visit(law, [&](const auto&, Quantity, J& x) {
    x = J(values[j], first_index + static_cast<int>(j));
    ++j;
  });
}

// d sliding / d v and d sliding / d each parameter.
template <int N, class Law, class JLaw>
void check_static(const Law& law, JLaw jlaw, double v) {
  using J = ceres::Jet<double, N>;
  const auto values = params_of(law);
  const auto names = param_names(law);
  ASSERT_EQ(values.size() + 1, static_cast<std::size_t>(N));
  set_jet_params<J>(jlaw, values, 1);
  const J f = jlaw.sliding(J(v, 0));
  const double f0 = law.sliding(v);
  EXPECT_NEAR(f.a, f0, kRelTol * std::abs(f0));
  const double hv = kFdStep * std::abs(v);
  expect_derivative(f.v[0], (law.sliding(v + hv) - law.sliding(v - hv)) / (2 * hv), f0, v, "d/dv at v = " + std::to_string(v));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double x = values[i];
    if (x == 0.0) continue;  // a zero parameter has no relative step (none chosen below)
    const double h = kFdStep * std::abs(x);
    const double fd = (with_param(law, i, x + h).sliding(v) - with_param(law, i, x - h).sliding(v)) / (2 * h);
    expect_derivative(f.v[i + 1], fd, f0, x, "d/d" + names[i] + " at v = " + std::to_string(v));
  }
}

TEST(Jacobians, Coulomb) {
  for (double v : {0.3, -2.0}) check_static<2>(Coulomb{2.0}, CoulombT<ceres::Jet<double, 2>>{}, v);
}

TEST(Jacobians, Viscous) {
  for (double v : {0.3, -2.0}) check_static<2>(Viscous{0.3}, ViscousT<ceres::Jet<double, 2>>{}, v);
}

TEST(Jacobians, CoulombViscous) {
  for (double v : {0.3, -2.0}) check_static<3>(CoulombViscous{1.0, 0.5}, CoulombViscousT<ceres::Jet<double, 3>>{}, v);
}

TEST(Jacobians, StaticCoulombViscous) {
  for (double v : {0.3, -2.0})
    check_static<4>(StaticCoulombViscous{1.5, 1.0, 0.5}, StaticCoulombViscousT<ceres::Jet<double, 4>>{}, v);
}

TEST(Jacobians, Stribeck) {
  using J = ceres::Jet<double, 6>;
  for (double delta : {0.7, 2.0})
    for (double v : {1.5e-3, -2.5e-3, 4e-4, 0.05}) check_static<6>(Stribeck{1.0, 1.5, 1e-3, delta, 0.4}, StribeckT<J>{}, v);
}

TEST(Jacobians, Karnopp) {
  using J = ceres::Jet<double, 5>;
  for (double v : {0.3, -2.0}) check_static<5>(Karnopp{1.5, 1.0, 0.5, 1e-3}, KarnoppT<J>{}, v);
}

TEST(Jacobians, Smooth) {
  using J = ceres::Jet<double, 7>;
  for (SmoothShape shape : {SmoothShape::tanh, SmoothShape::atan}) {
    for (double v : {1.5e-3, -2.5e-3, 4e-4}) {
      SmoothT<J> jl;
      jl.shape = shape;
      check_static<7>(Smooth{1.0, 1.5, 1e-3, 2.0, 0.4, 1e-3, shape}, jl, v);
    }
  }
}

TEST(Jacobians, AsymmetricForms) {
  for (double v : {1.5e-3, -2.5e-3, 0.2}) {
    check_static<3>(Asymmetric<Coulomb>{Coulomb{2.0}, Coulomb{1.0}}, Asymmetric<CoulombT<ceres::Jet<double, 3>>>{}, v);
    check_static<3>(Asymmetric<Viscous>{Viscous{0.3}, Viscous{0.5}}, Asymmetric<ViscousT<ceres::Jet<double, 3>>>{}, v);
    check_static<5>(Asymmetric<CoulombViscous>{CoulombViscous{1.0, 0.5}, CoulombViscous{0.8, 0.2}},
                    Asymmetric<CoulombViscousT<ceres::Jet<double, 5>>>{}, v);
    check_static<7>(Asymmetric<StaticCoulombViscous>{StaticCoulombViscous{1.5, 1.0, 0.1}, StaticCoulombViscous{2.5, 2.0, 0.3}},
                    Asymmetric<StaticCoulombViscousT<ceres::Jet<double, 7>>>{}, v);
    check_static<11>(Asymmetric<Stribeck>{Stribeck{1.0, 1.5, 1e-3, 2.0, 0.4}, Stribeck{2.0, 3.0, 2e-3, 1.0, 0.1}},
                     Asymmetric<StribeckT<ceres::Jet<double, 11>>>{}, v);
  }
}

TEST(Jacobians, TableWithRespectToVelocity) {
  using J = ceres::Jet<double, 1>;
  const Table t({-0.3, -0.1, 0.01, 0.1, 0.5, 1.0}, {-1.6, -1.2, 1.2, 0.9, 1.0, 1.3});
  // Inside segments, below the first point (held: slope 0) and beyond the last (extrapolated).
  for (double v : {0.05, 0.13, 0.7, 0.005, 2.0, -0.2, -0.05, -0.5}) {
    const J f = t.sliding(J(v, 0));
    const double h = kFdStep * std::abs(v);
    const double fd = (t.sliding(v + h) - t.sliding(v - h)) / (2 * h);
    EXPECT_EQ(f.a, t.sliding(v));
    expect_derivative(f.v[0], fd, f.a, v, "table d/dv at v = " + std::to_string(v));
  }
}

// Dynamic laws: d(dz/dt)/d z_i, d(dz/dt)/d v, d F/d z_i, d F/d v and both w.r.t. each parameter.
template <int N, class Law, class JLaw>
void check_dynamic(const Law& law, JLaw jlaw, const std::vector<double>& z, double v, const std::string& where) {
  using J = ceres::Jet<double, N>;
  const std::size_t ns = z.size();
  const auto values = params_of(law);
  const auto names = param_names(law);
  ASSERT_EQ(ns + 1 + values.size(), static_cast<std::size_t>(N));
  set_jet_params<J>(jlaw, values, static_cast<int>(ns) + 1);
  std::vector<J> zj(ns), dzj(ns);
  for (std::size_t i = 0; i < ns; ++i) zj[i] = J(z[i], static_cast<int>(i));
  const J vj(v, static_cast<int>(ns));
  jlaw.derivative(std::span<const J>(zj), vj, std::span<J>(dzj));
  const J fj = jlaw.force(std::span<const J>(zj), vj);

  // outputs: dz[0..ns-1], force
  auto outputs = [&](const Law& l, const std::vector<double>& zz, double vv) {
    std::vector<double> out(ns + 1);
    l.derivative(std::span<const double>(zz), vv, std::span<double>(out.data(), ns));
    out[ns] = l.force(std::span<const double>(zz), vv);
    return out;
  };
  const auto base = outputs(law, z, v);
  for (std::size_t o = 0; o <= ns; ++o) {
    const double jet_value = o < ns ? dzj[o].a : fj.a;
    EXPECT_NEAR(jet_value, base[o], kRelTol * std::abs(base[o])) << where << " value of output " << o;
  }
  auto compare = [&](int input, const std::vector<double>& plus, const std::vector<double>& minus, double h, double x,
                     const std::string& name) {
    for (std::size_t o = 0; o <= ns; ++o) {
      const double jet = o < ns ? dzj[o].v[input] : fj.v[input];
      const std::string out_name = o < ns ? "dz[" + std::to_string(o) + "]" : "F";
      expect_derivative(jet, (plus[o] - minus[o]) / (2 * h), base[o], x, where + ": d " + out_name + " / d " + name);
    }
  };
  for (std::size_t i = 0; i < ns; ++i) {
    const double h = kFdStep * std::abs(z[i]);
    auto zp = z, zm = z;
    zp[i] += h;
    zm[i] -= h;
    compare(static_cast<int>(i), outputs(law, zp, v), outputs(law, zm, v), h, z[i], "z[" + std::to_string(i) + "]");
  }
  {
    const double h = kFdStep * std::abs(v);
    compare(static_cast<int>(ns), outputs(law, z, v + h), outputs(law, z, v - h), h, v, "v");
  }
  for (std::size_t p = 0; p < values.size(); ++p) {
    const double x = values[p];
    if (x == 0.0) continue;
    const double h = kFdStep * std::abs(x);
    compare(static_cast<int>(ns + 1 + p), outputs(with_param(law, p, x + h), z, v), outputs(with_param(law, p, x - h), z, v),
            h, x, names[p]);
  }
}

TEST(Jacobians, Dahl) {
  using J = ceres::Jet<double, 5>;
  for (double alpha : {1.0, 1.5, 0.6}) {
    const Dahl law{1e5, 1.0, alpha};
    check_dynamic<5>(law, DahlT<J>{}, {3e-6}, 2e-3, "dahl, u = 0.7");
    check_dynamic<5>(law, DahlT<J>{}, {3e-6}, -2e-3, "dahl, against z");
    check_dynamic<5>(law, DahlT<J>{}, {1.4e-5}, 2e-3, "dahl, beyond the bound");
  }
}

TEST(Jacobians, LuGre) {
  using J = ceres::Jet<double, 10>;
  LuGre law;
  law.vd = 1e-2;  // exercise the velocity-dependent damping (vd = 0 is a switch, not a point to differentiate at)
  for (double v : {2e-3, -7e-4, 0.05}) {
    check_dynamic<10>(law, LuGreT<J>{}, {5e-6}, v, "lugre");
    check_dynamic<10>(law, LuGreT<J>{}, {-1.2e-5}, v, "lugre");
  }
}

TEST(Jacobians, ElastoPlastic) {
  using J = ceres::Jet<double, 10>;
  const ElastoPlastic law;  // zba = 5e-6; zmax = g(v)/sigma0 ~ 1.0e-5 .. 1.5e-5
  for (double v : {2e-3, -7e-4}) {
    const double s = v > 0 ? 1 : -1;
    check_dynamic<10>(law, ElastoPlasticT<J>{}, {s * 3e-6}, v, "elastoplastic, elastic zone");
    check_dynamic<10>(law, ElastoPlasticT<J>{}, {s * 8e-6}, v, "elastoplastic, transition zone");
    check_dynamic<10>(law, ElastoPlasticT<J>{}, {s * 2e-5}, v, "elastoplastic, above zmax");
    check_dynamic<10>(law, ElastoPlasticT<J>{}, {-s * 8e-6}, v, "elastoplastic, z against v");
  }
}

TEST(Jacobians, Gms) {
  using J = ceres::Jet<double, 10>;
  const Gms law;
  GmsT<J> jl;
  jl.k.clear();
  jl.alpha.clear();
  for (double k : law.k) jl.k.emplace_back(k);
  for (double a : law.alpha) jl.alpha.emplace_back(a);
  // Element 0 sticks (F0 = 0.2 < 0.5 s), element 1 slips (F1 = 0.4 > 0.3 s with v), element 2 opposes v.
  check_dynamic<10>(law, jl, {2e-6, 8e-6, -1e-5}, 1e-3, "gms");
  check_dynamic<10>(law, jl, {-2e-6, -8e-6, 1e-5}, -1e-3, "gms mirrored");
  check_dynamic<10>(law, jl, {2e-6, 8e-6, -1e-5}, 0.05, "gms fast");
}

}  // namespace
}  // namespace frictionlab

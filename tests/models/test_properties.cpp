// Seeded random property tests through FrictionLaw: for any valid parameters (random within
// physical ranges) and finite inputs, no law returns NaN or infinity, and dynamic states stay
// finite. The number of cases comes from FRICTIONLAB_PROPERTY_CASES (default 1000).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "property_cases.hpp"

namespace frictionlab {
namespace {

constexpr unsigned kSeed = 20240611;

using testing::property_cases;

class Random {
 public:
  explicit Random(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double log_uniform(double lo, double hi) { return std::pow(10.0, uniform(std::log10(lo), std::log10(hi))); }
  bool coin() { return uniform(0, 1) < 0.5; }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  // A velocity: 0 sometimes, otherwise any sign and magnitude from 1e-9 to 1e3 m/s.
  double velocity() {
    if (uniform(0, 1) < 0.05) return 0.0;
    return (coin() ? 1 : -1) * log_uniform(1e-9, 1e3);
  }

 private:
  std::mt19937 rng_;
};

// Default instances by name, from which the parameter names are taken.
FrictionLaw default_law(const std::string& name) {
  if (name == "table") return Table{};
  if (name == "gms") return Gms{};
  if (name == "smooth") return Smooth{};
  if (name == "dahl") return Dahl{};
  if (name == "lugre") return LuGre{};
  if (name == "elastoplastic") return ElastoPlastic{};
  if (name == "coulomb") return Coulomb{};
  if (name == "viscous") return Viscous{};
  if (name == "coulomb-viscous") return CoulombViscous{};
  if (name == "static-coulomb-viscous") return StaticCoulombViscous{};
  if (name == "stribeck") return Stribeck{};
  if (name == "karnopp") return Karnopp{};
  if (name == "coulomb-asymmetric") return Asymmetric<Coulomb>{};
  if (name == "viscous-asymmetric") return Asymmetric<Viscous>{};
  if (name == "coulomb-viscous-asymmetric") return Asymmetric<CoulombViscous>{};
  if (name == "static-coulomb-viscous-asymmetric") return Asymmetric<StaticCoulombViscous>{};
  if (name == "stribeck-asymmetric") return Asymmetric<Stribeck>{};
  ADD_FAILURE() << "no default for law " << name;
  return Coulomb{};
}

// The file form of a law with every parameter drawn at random within physical ranges.
LawSpec random_law(const std::string& name, Random& r) {
  LawSpec spec = default_law(name).to_spec();
  const double Fc = r.log_uniform(1e-3, 1e3);
  const double sigma0 = r.log_uniform(1e2, 1e9);
  double Fc_side[2] = {Fc, r.log_uniform(1e-3, 1e3)};
  for (auto& [p, value] : spec.scalars) {
    const auto us = p.find('_');
    const std::string base = p.substr(0, us);
    const int side = (us != std::string::npos && p.substr(us) == "_neg") ? 1 : 0;
    if (base == "Fc") value = Fc_side[side];
    else if (base == "Fv" || base == "sigma2") value = r.coin() ? 0.0 : r.log_uniform(1e-4, 1e2);
    else if (base == "vs" || base == "vt" || base == "dv") value = r.log_uniform(1e-6, 1.0);
    else if (base == "vd") value = r.coin() ? 0.0 : r.log_uniform(1e-6, 1.0);
    else if (base == "delta") value = r.uniform(0.3, 4.0);
    else if (base == "alpha") value = r.uniform(0.3, 3.0);  // Dahl exponent
    else if (base == "sigma0") value = sigma0;
    else if (base == "sigma1") value = r.coin() ? 0.0 : r.log_uniform(1e-2, 1e4);
    else if (base == "C") value = r.log_uniform(1e-2, 1e4);
    else if (base != "Fs" && base != "zba") ADD_FAILURE() << "no random range for parameter " << p;
  }
  // Parameters bounded by others, set after those.
  for (auto& [p, value] : spec.scalars) {
    const auto us = p.find('_');
    const std::string base = p.substr(0, us);
    const int side = (us != std::string::npos && p.substr(us) == "_neg") ? 1 : 0;
    if (base == "Fs") value = Fc_side[side] * (r.coin() ? 1.0 : r.uniform(1.0, 3.0));
    if (base == "zba") value = r.uniform(0.01, 0.99) * Fc / sigma0;
  }
  if (name == "gms") {
    const int n = r.integer(1, 10);
    std::vector<double> k(n), alpha(n);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      k[i] = r.log_uniform(1e2, 1e8);
      alpha[i] = r.uniform(0.05, 1.0);
      sum += alpha[i];
    }
    for (auto& a : alpha) a /= sum;
    spec.arrays["k"] = k;
    spec.arrays["alpha"] = alpha;
  }
  if (name == "table") {
    // 2..20 points per side, increasing |v|, positive forces.
    std::vector<double> v, f;
    const int nneg = r.coin() ? 0 : r.integer(2, 20), npos = r.integer(2, 20);
    std::vector<double> neg_v, neg_f;
    double x = 0;
    for (int i = 0; i < nneg; ++i) {
      x += r.log_uniform(1e-6, 10.0);
      neg_v.push_back(-x);
      neg_f.push_back(-r.log_uniform(1e-3, 1e3));
    }
    for (int i = nneg - 1; i >= 0; --i) {
      v.push_back(neg_v[i]);
      f.push_back(neg_f[i]);
    }
    x = 0;
    for (int i = 0; i < npos; ++i) {
      x += r.log_uniform(1e-6, 10.0);
      v.push_back(x);
      f.push_back(r.log_uniform(1e-3, 1e3));
    }
    spec.arrays["velocity"] = v;
    spec.arrays["force"] = f;
  }
  if (name == "smooth") spec.strings["shape"] = r.coin() ? "tanh" : "atan";
  return spec;
}

bool finite(double x) { return std::isfinite(x); }

TEST(Properties, NoNanOrInfinityForAnyValidLaw) {
  const int cases = property_cases();
  Random r(kSeed);
  int checked = 0;
  for (const auto& name : FrictionLaw::names()) {
    for (int c = 0; c < cases; ++c) {
      const LawSpec spec = random_law(name, r);
      FrictionLaw law;
      try {
        law = FrictionLaw::from_spec(spec);
      } catch (const std::exception& e) {
        FAIL() << name << " case " << c << ": random parameters rejected: " << e.what();
      }
      const std::string where = name + " case " + std::to_string(c);
      if (!law.is_dynamic()) {
        for (int k = 0; k < 8; ++k) {
          const double v = r.velocity();
          const double applied = (r.coin() ? 1 : -1) * r.log_uniform(1e-6, 1e4);
          const double s = law.sliding(v), f = law.force(v, applied);
          ASSERT_TRUE(finite(s)) << where << ": sliding(" << v << ") = " << s;
          ASSERT_TRUE(finite(f)) << where << ": force(" << v << ", " << applied << ") = " << f;
          ASSERT_TRUE(finite(law.breakaway_positive()) && finite(law.breakaway_negative())) << where;
        }
      } else {
        const std::size_t n = static_cast<std::size_t>(law.num_states());
        std::vector<double> z(n), dz(n);
        // Start anywhere a state can be: at rest, or steady at some velocity, or a random deflection.
        law.steady_state(r.velocity(), std::span<double>(z));
        for (auto& zi : z) zi *= r.uniform(-1.5, 1.5);
        for (int k = 0; k < 20; ++k) {
          const double v = r.velocity();
          const double dt = r.coin() ? r.log_uniform(1e-9, 1.0) : (r.coin() ? 1.0 : 0.0);  // up to 1 s, and 0
          law.derivative(std::span<const double>(z), v, std::span<double>(dz));
          for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(finite(dz[i])) << where << ": dz[" << i << "] at v = " << v;
          const double f0 = law.force(std::span<const double>(z), v);
          ASSERT_TRUE(finite(f0)) << where << ": force(z, " << v << ")";
          const double f1 = law.step(std::span<double>(z), v, dt);
          ASSERT_TRUE(finite(f1)) << where << ": step(z, " << v << ", " << dt << ") = " << f1;
          for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(finite(z[i])) << where << ": z[" << i << "] after step";
          ASSERT_TRUE(finite(law.sliding(v))) << where << ": sliding(" << v << ")";
        }
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, cases * static_cast<int>(FrictionLaw::names().size()));
}

}  // namespace
}  // namespace frictionlab

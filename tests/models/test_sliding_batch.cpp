// FrictionLaw::sliding over arrays against the scalar call, value by value: every law, the
// delta forms of the Stribeck decay, smooth shapes with and without the dip, velocities at the
// edges (zero of both signs, tiny, subnormal, huge, inf, NaN), and lengths that leave every tail
// of a 2-, 4- and 8-wide vector (the compiler may vectorise the loop). The array call runs the
// scalar formula, so every value must equal the scalar call's to the bit. Also the size check.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {
namespace {

using ::testing::HasSubstr;

// Laws and parameter sets, each with a label for the failure message.
std::vector<std::pair<std::string, FrictionLaw>> laws() {
  std::vector<std::pair<std::string, FrictionLaw>> out;
  // Every law of the variant with its default parameters: every name of FrictionLaw::names().
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (out.emplace_back("default", FrictionLaw(std::variant_alternative_t<I, FrictionLaw::Variant>{})), ...);
  }(std::make_index_sequence<std::variant_size_v<FrictionLaw::Variant>>());
  for (double delta : {1.0, 2.0, 1.5, 0.7, 3.3}) {
    out.emplace_back("delta " + std::to_string(delta), Stribeck{1.0, 1.5, 1e-3, delta, 0.4});
    out.emplace_back("Fc 0, Fv 0, delta " + std::to_string(delta), Stribeck{0.0, 2.0, 1e-2, delta, 0.0});
  }
  out.emplace_back("Fs = Fc", Stribeck{1.0, 1.0, 1e-3, 1.5, 0.4});
  out.emplace_back("same decay form", Asymmetric<Stribeck>{{1.0, 1.5, 1e-3, 1.5, 0.4}, {0.8, 1.1, 2e-3, 0.7, 0.3}});
  out.emplace_back("delta 1.5 / 2", Asymmetric<Stribeck>{{1.0, 1.5, 1e-3, 1.5, 0.4}, {0.8, 1.1, 2e-3, 2.0, 0.3}});
  out.emplace_back("delta 1 / Fs = Fc", Asymmetric<Stribeck>{{1.0, 1.5, 1e-3, 1.0, 0.4}, {0.8, 0.8, 2e-3, 2.0, 0.0}});
  for (SmoothShape shape : {SmoothShape::tanh, SmoothShape::atan}) {
    const std::string s = shape == SmoothShape::tanh ? "tanh" : "atan";
    out.emplace_back(s + " no dip", Smooth{1.0, 1.0, 1e-3, 2.0, 0.0, 1e-3, shape});
    out.emplace_back(s + " no dip, viscous", Smooth{1.0, 1.0, 1e-3, 2.0, 0.2, 1e-4, shape});
    for (double delta : {2.0, 1.0, 1.5})
      out.emplace_back(s + " dip, delta " + std::to_string(delta), Smooth{1.0, 1.5, 1e-3, delta, 0.2, 1e-3, shape});
  }
  out.emplace_back("8 points", Table({-1.0, -0.1, -0.01, -0.001, 0.001, 0.01, 0.1, 1.0},
                                     {-1.4, -1.0, -1.2, -1.5, 1.5, 1.2, 1.0, 1.4}));
  out.emplace_back("asymmetric", Asymmetric<CoulombViscous>{{1.0, 0.1}, {0.7, 0.3}});
  return out;
}

// Velocities (m/s): the edges first, then a seeded log-uniform spread of both signs.
std::vector<double> velocities() {
  const double inf = std::numeric_limits<double>::infinity();
  const double subnormal = std::numeric_limits<double>::denorm_min();
  std::vector<double> v = {0.0, -0.0, 1e-300, -1e-300, subnormal, -subnormal, 3e-310, -3e-310, 1e-12, -1e-12,
                           // around vs = 1e-3 and 1e-2, and the cut-off |v/vs|^delta = 40 of each delta
                           5e-4, -1e-3, 2e-3, -6.3e-3, 6.4e-3, -1.17e-2, 1.17e-2, 4e-2, -6e-2, 1.1e-1, -3e-1,
                           1e6, -1e6, inf, -inf, std::numeric_limits<double>::quiet_NaN(), 0.0, -0.0};
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> exponent(-9.0, 3.0);
  while (v.size() < 1100) v.push_back((rng() % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng)));
  return v;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// F against the scalar call at each v: the same bits (the sign of zero included), or NaN where
// the scalar gives NaN (of either sign: the sign of a NaN carries nothing).
void expect_matches_scalar(const FrictionLaw& law, std::span<const double> v, std::span<const double> F,
                           const std::string& label) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double want = law.sliding(v[i]);
    if (std::isnan(want)) {
      EXPECT_TRUE(std::isnan(F[i])) << label << ": v = " << v[i] << " gives " << F[i] << ", scalar NaN";
    } else {
      EXPECT_EQ(bits(F[i]), bits(want)) << label << ": v = " << v[i] << " (index " << i << ") gives " << F[i]
                                        << ", scalar " << want;
    }
  }
}

// Every length 0..17 (every tail of a vector of 4 or 8, with and without a whole vector before
// it) and 1001, each from offsets 0..7 of the velocities, so that every edge value lands in every
// lane of an 8-wide vector and in the tail.
template <class Evaluate>
void for_each_slice(Evaluate evaluate) {
  const std::vector<double> v = velocities();
  for (std::size_t n : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 1001})
    for (std::size_t offset = 0; offset < 8; ++offset) evaluate(std::span<const double>(v).subspan(offset, n));
}

TEST(SlidingBatch, MatchesTheScalarCallForEveryLaw) {
  for (const auto& [label, law] : laws()) {
    for_each_slice([&](std::span<const double> v) {
      std::vector<double> F(v.size(), -7.0);
      law.sliding(v, F);
      expect_matches_scalar(law, v, F, law.name() + " " + label + ", length " + std::to_string(v.size()));
    });
  }
}

TEST(SlidingBatch, DynamicLawsGiveTheSteadyStateAsTheScalarCall) {
  for (const FrictionLaw& law :
       {FrictionLaw(LuGre{}), FrictionLaw(Gms{}), FrictionLaw(Dahl{}), FrictionLaw(ElastoPlastic{})}) {
    const std::vector<double> v = {-2e-3, -1e-4, 0.0, 3e-4, 0.5};
    std::vector<double> F(v.size());
    law.sliding(v, F);
    for (std::size_t i = 0; i < v.size(); ++i)
      EXPECT_EQ(bits(F[i]), bits(law.sliding(v[i]))) << law.name() << " at v = " << v[i];
  }
}

TEST(SlidingBatch, SizeMismatchNamesBothSizes) {
  const FrictionLaw law = Stribeck{};
  const std::vector<double> v(5, 0.1);
  std::vector<double> F(4);
  EXPECT_EQ(testing::error_of([&] { law.sliding(v, F); }),
            "FrictionLaw::sliding: F (N or N m) has 4 values but v (m/s or rad/s) has 5; "
            "they must have the same length");
  EXPECT_THAT(F, ::testing::Each(0.0));  // nothing written
}

}  // namespace
}  // namespace frictionlab

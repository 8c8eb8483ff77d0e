// The stiff engine's analytic Jacobian (StiffSystem) against central differences of its
// right-hand side, and the engine using it against the same run with CVODE's difference quotients.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "simulate/stiff_system.hpp"

using namespace frictionlab;

namespace {

// Central differences with a step relative to each state's size: truncation error O(h^2) and
// rounding O(eps / h); with h = 1e-6 * scale both stay near 1e-10 of the entry's scale.
std::vector<double> central_jacobian(const StiffSystem& sys, double t, const std::vector<double>& y, const InputValue& u,
                                     const std::vector<double>& scale) {
  const auto n = static_cast<std::size_t>(sys.size());
  std::vector<double> jac(n * n), yp = y, ym = y, fp(n), fm(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double h = 1e-6 * scale[j];
    yp = y;
    ym = y;
    yp[j] += h;
    ym[j] -= h;
    sys.rhs(t, yp, u, fp);
    sys.rhs(t, ym, u, fm);
    for (std::size_t i = 0; i < n; ++i) jac[i + j * n] = (fp[i] - fm[i]) / (2 * h);
  }
  return jac;
}

// Largest entry difference relative to the largest entry of its row (rows mix 1 and 1e5 scales).
double max_row_relative_error(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double row = 0.0;
    for (std::size_t j = 0; j < n; ++j) row = std::max(row, std::abs(b[i + j * n]));
    for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, std::abs(a[i + j * n] - b[i + j * n]) / std::max(row, 1e-300));
  }
  return worst;
}

// Central differences reach about 1e-9 relative here (see central_jacobian); 1e-6 leaves room
// for the Stribeck curve's curvature at v ~ vs without hiding a wrong entry (those are O(1) off).
constexpr double kJacobianTolerance = 1e-6;

}  // namespace

TEST(StiffSystem, LuGreSpringBaseJacobianMatchesCentralDifferences) {
  SpringBaseParams p;
  p.m = 1.0;
  p.k = 2.0;
  p.c = 0.3;
  p.V0 = 0.1;
  const SpringBase plant(p);
  const FrictionLaw law = LuGre{};  // Table I of Canudas de Wit et al. 1995
  StiffSystem sys(plant, law);
  ASSERT_TRUE(sys.has_jacobian());
  const std::size_t n = 3;
  // States across the regimes of a stick-slip cycle: sticking (v ~ 0, both signs), the Stribeck
  // region (v ~ vs), sliding fast, and a bristle deflection above its steady state.
  for (const std::vector<double>& y : std::vector<std::vector<double>>{
           {0.01, 1e-5, 1.2e-5}, {0.02, -3e-4, -8e-6}, {0.05, 1e-3, 1.4e-5}, {0.3, 0.25, 1e-5}, {0.1, 0.002, 1.6e-5}}) {
    std::vector<double> jac(n * n);
    sys.jacobian(1.5, y, InputValue{}, jac);
    const std::vector<double> scale = {1.0, std::max(std::abs(y[1]), 1e-4), 1e-5};
    const auto fd = central_jacobian(sys, 1.5, y, InputValue{}, scale);
    EXPECT_LT(max_row_relative_error(jac, fd, n), kJacobianTolerance) << "at v = " << y[1];
  }
}

TEST(StiffSystem, OtherDynamicLawsOnAnAxisMatchCentralDifferences) {
  const RigidAxis plant(AxisParams{2.0, 0.1});
  Dahl dahl;
  ElastoPlastic ep;
  for (const FrictionLaw& law : {FrictionLaw(dahl), FrictionLaw(ep)}) {
    StiffSystem sys(plant, law);
    ASSERT_TRUE(sys.has_jacobian());
    const auto n = static_cast<std::size_t>(sys.size());
    std::vector<double> y(n, 0.0);
    y[1] = 0.02;
    for (std::size_t i = 2; i < n; ++i) y[i] = 3e-6;
    std::vector<double> jac(n * n);
    sys.jacobian(0.0, y, InputValue{0.5, 0.0}, jac);
    std::vector<double> scale(n, 1e-5);
    scale[0] = 1.0;
    scale[1] = 0.02;
    EXPECT_LT(max_row_relative_error(jac, central_jacobian(sys, 0.0, y, InputValue{0.5, 0.0}, scale), n), kJacobianTolerance)
        << law.name();
  }
}

TEST(StiffSystem, PlantsWithoutAnAnalyticJacobianSayso) {
  DcMotorParams p;
  const DcMotor motor(p);
  const StiffSystem sys(motor, FrictionLaw(LuGre{}));
  EXPECT_FALSE(sys.has_jacobian());
  EXPECT_THROW(StiffSystem(motor, FrictionLaw(Coulomb{})), std::invalid_argument);
}

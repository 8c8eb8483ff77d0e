#include "frictionlab/simulate/stiff_system.hpp"

#include <ceres/jet.h>

#include <array>
#include <stdexcept>
#include <string>
#include <variant>

namespace frictionlab {

namespace {

// One directional derivative at a time: the laws have at most a few states, and a Jet of fixed
// size 1 keeps the code free of a compile-time bound on the number of states.
using Dual = ceres::Jet<double, 1>;

// Up to this many law states the duals live on the stack; larger GMS models use heap scratch.
constexpr int kStackStates = 16;

// Partial derivatives of the law's dz/dt and force with respect to z_j (j < nz) or v (j = nz):
// dh[i * (nz + 1) + j] and dF[j].
void law_partials(const FrictionLaw& law, std::span<const double> z, double v, std::span<double> dh,
                  std::span<double> dF) {
  const int nz = static_cast<int>(z.size());
  std::visit(
      [&](const auto& l) {
        if constexpr (requires(std::span<const Dual> zc, std::span<Dual> dz, const Dual& w) {
                        l.template derivative<Dual>(zc, w, dz);
                        l.template force<Dual>(zc, w);
                      }) {
          std::array<Dual, kStackStates> zs_stack, dzs_stack;
          std::vector<Dual> zs_heap, dzs_heap;
          std::span<Dual> zs(zs_stack.data(), static_cast<std::size_t>(nz));
          std::span<Dual> dzs(dzs_stack.data(), static_cast<std::size_t>(nz));
          if (nz > kStackStates) {
            zs_heap.resize(static_cast<std::size_t>(nz));
            dzs_heap.resize(static_cast<std::size_t>(nz));
            zs = zs_heap;
            dzs = dzs_heap;
          }
          for (int j = 0; j <= nz; ++j) {
            // Seeds set by hand: Jet's two-argument constructor takes an index, not a derivative.
            for (int i = 0; i < nz; ++i) {
              zs[static_cast<std::size_t>(i)] = Dual(z[static_cast<std::size_t>(i)]);
              zs[static_cast<std::size_t>(i)].v[0] = i == j ? 1.0 : 0.0;
            }
            Dual w(v);
            w.v[0] = j == nz ? 1.0 : 0.0;
            l.template derivative<Dual>(std::span<const Dual>(zs), w, dzs);
            for (int i = 0; i < nz; ++i)
              dh[static_cast<std::size_t>(i * (nz + 1) + j)] = dzs[static_cast<std::size_t>(i)].v[0];
            dF[static_cast<std::size_t>(j)] = l.template force<Dual>(std::span<const Dual>(zs), w).v[0];
          }
        } else {
          throw std::logic_error("StiffSystem: law '" + law.name() + "' has no differentiable state equations");
        }
      },
      law.variant());
}

}  // namespace

StiffSystem::StiffSystem(const Plant& plant, const FrictionLaw& law) : plant_(plant), law_(law) {
  if (!law.is_dynamic()) throw std::invalid_argument("StiffSystem: law '" + law.name() + "' is not dynamic (no states)");
  np_ = plant.num_states();
  nz_ = law.num_states();
  const auto np = static_cast<std::size_t>(np_), nz = static_cast<std::size_t>(nz_);
  dfdx_.assign(np * np, 0.0);
  dfdF_.assign(np, 0.0);
  dh_.assign(nz * (nz + 1), 0.0);
  dF_.assign(nz + 1, 0.0);
  // Probe once: a plant either has an analytic Jacobian or not, whatever the state.
  std::vector<double> x(np, 0.0);
  const InputValue u0{};
  const double f0 = 0.0;
  has_jacobian_ = !plant.kinematic() && plant.jacobian(0.0, x, Inputs(&u0, 1), std::span<const double>(&f0, 1), dfdx_, dfdF_);
}

void StiffSystem::rhs(double t, std::span<const double> y, const InputValue& u, std::span<double> dy) const {
  const auto np = static_cast<std::size_t>(np_), nz = static_cast<std::size_t>(nz_);
  const std::span<const double> x = y.first(np), z = y.subspan(np, nz);
  const double f = law_.force(z, x[1]);
  plant_.derivatives(t, x, Inputs(&u, 1), std::span<const double>(&f, 1), dy.first(np));
  law_.derivative(z, x[1], dy.subspan(np, nz));
}

void StiffSystem::jacobian(double t, std::span<const double> y, const InputValue& u, std::span<double> jac) {
  if (!has_jacobian_) throw std::logic_error("StiffSystem::jacobian: plant '" + plant_.type() + "' has no analytic Jacobian");
  const int n = np_ + nz_;
  const auto np = static_cast<std::size_t>(np_), nz = static_cast<std::size_t>(nz_);
  const std::span<const double> x = y.first(np), z = y.subspan(np, nz);
  const double v = x[1];
  const double f = law_.force(z, v);
  plant_.jacobian(t, x, Inputs(&u, 1), std::span<const double>(&f, 1), dfdx_, dfdF_);
  law_partials(law_, z, v, dh_, dF_);
  auto at = [&](int i, int j) -> double& { return jac[static_cast<std::size_t>(i + j * n)]; };
  const double dFdv = dF_[nz];
  // Plant rows: d f / d x + d f / d F * (d F / d v in the velocity column, d F / d z in the law's).
  for (int i = 0; i < np_; ++i) {
    const double fF = dfdF_[static_cast<std::size_t>(i)];
    for (int j = 0; j < np_; ++j) at(i, j) = dfdx_[static_cast<std::size_t>(i * np_ + j)] + (j == 1 ? fF * dFdv : 0.0);
    for (int k = 0; k < nz_; ++k) at(i, np_ + k) = fF * dF_[static_cast<std::size_t>(k)];
  }
  // Law rows: the law's state depends on the plant only through v = x[1].
  for (int i = 0; i < nz_; ++i) {
    const auto row = static_cast<std::size_t>(i) * (nz + 1);
    for (int j = 0; j < np_; ++j) at(np_ + i, j) = j == 1 ? dh_[row + nz] : 0.0;
    for (int k = 0; k < nz_; ++k) at(np_ + i, np_ + k) = dh_[row + static_cast<std::size_t>(k)];
  }
}

}  // namespace frictionlab

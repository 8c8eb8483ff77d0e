#include "simulate/stiff_system.hpp"

#include <ceres/jet.h>

#include <algorithm>
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

StiffSystem::StiffSystem(const Plant& plant, const FrictionLaw& law) : plant_(plant) {
  np_ = plant.num_states();
  nc_ = plant.num_contacts();
  int z = np_, widest = 0;
  for (int k = 0; k < nc_; ++k) {
    const Contact c = plant.contact(k);
    const FrictionLaw* l = c.law ? c.law : &law;
    if (!l->is_dynamic()) throw std::invalid_argument("StiffSystem: law '" + l->name() + "' is not dynamic (no states)");
    parts_.push_back({l, c.velocity, z, l->num_states()});
    z += l->num_states();
    widest = std::max(widest, l->num_states());
  }
  n_ = z;
  const auto np = static_cast<std::size_t>(np_), nc = static_cast<std::size_t>(nc_), nz = static_cast<std::size_t>(widest);
  dfdx_.assign(np * np, 0.0);
  dfdF_.assign(np * nc, 0.0);
  force_.assign(nc, 0.0);
  dh_.assign(nz * (nz + 1), 0.0);
  dF_.assign(nz + 1, 0.0);
  // Probe once: a plant either has an analytic Jacobian or not, whatever the state.
  std::vector<double> x(np, 0.0);
  std::vector<InputValue> u(static_cast<std::size_t>(plant.num_inputs()));
  has_jacobian_ = !plant.kinematic() && plant.jacobian(0.0, x, u, force_, dfdx_, dfdF_);
}

void StiffSystem::rhs(double t, std::span<const double> y, Inputs u, std::span<double> dy) const {
  const auto np = static_cast<std::size_t>(np_);
  const std::span<const double> x = y.first(np);
  // Friction forces on the stack for up to 8 contacts (rhs is const and called at every step).
  std::array<double, 8> f_stack;
  std::vector<double> f_heap;
  std::span<double> f(f_stack.data(), parts_.size());
  if (parts_.size() > f_stack.size()) {
    f_heap.resize(parts_.size());
    f = f_heap;
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Part& p = parts_[k];
    const auto z = y.subspan(static_cast<std::size_t>(p.z), static_cast<std::size_t>(p.nz));
    const double v = x[static_cast<std::size_t>(p.velocity)];
    f[k] = p.law->force(z, v);
    p.law->derivative(z, v, dy.subspan(static_cast<std::size_t>(p.z), static_cast<std::size_t>(p.nz)));
  }
  plant_.derivatives(t, x, u, f, dy.first(np));
}

void StiffSystem::jacobian(double t, std::span<const double> y, Inputs u, std::span<double> jac) {
  if (!has_jacobian_) throw std::logic_error("StiffSystem::jacobian: plant '" + plant_.type() + "' has no analytic Jacobian");
  const int n = n_;
  const auto np = static_cast<std::size_t>(np_);
  const std::span<const double> x = y.first(np);
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Part& p = parts_[k];
    force_[k] = p.law->force(y.subspan(static_cast<std::size_t>(p.z), static_cast<std::size_t>(p.nz)),
                             x[static_cast<std::size_t>(p.velocity)]);
  }
  plant_.jacobian(t, x, u, force_, dfdx_, dfdF_);
  auto at = [&](int i, int j) -> double& { return jac[static_cast<std::size_t>(i + j * n)]; };
  for (std::size_t i = 0; i < jac.size(); ++i) jac[i] = 0.0;
  for (int i = 0; i < np_; ++i)
    for (int j = 0; j < np_; ++j) at(i, j) = dfdx_[static_cast<std::size_t>(i * np_ + j)];
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Part& p = parts_[k];
    const auto nz = static_cast<std::size_t>(p.nz);
    const auto z = y.subspan(static_cast<std::size_t>(p.z), nz);
    law_partials(*p.law, z, x[static_cast<std::size_t>(p.velocity)], dh_, dF_);
    const double dFdv = dF_[nz];
    // Plant rows: d f / d F_k * (d F_k / d v_k in v_k's column, d F_k / d z_k in the law's).
    for (int i = 0; i < np_; ++i) {
      const double fF = dfdF_[static_cast<std::size_t>(i * nc_) + k];
      at(i, p.velocity) += fF * dFdv;
      for (int m = 0; m < p.nz; ++m) at(i, p.z + m) = fF * dF_[static_cast<std::size_t>(m)];
    }
    // Law rows: contact k's law state depends on the plant only through v_k.
    for (int i = 0; i < p.nz; ++i) {
      const auto row = static_cast<std::size_t>(i) * (nz + 1);
      at(p.z + i, p.velocity) = dh_[row + nz];
      for (int m = 0; m < p.nz; ++m) at(p.z + i, p.z + m) = dh_[row + static_cast<std::size_t>(m)];
    }
  }
}

}  // namespace frictionlab

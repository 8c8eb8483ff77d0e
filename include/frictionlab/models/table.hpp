#pragma once
// Tabulated friction-velocity map, as a constant-velocity sweep produces it.

#include <string_view>
#include <vector>

#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Friction as a measured function of velocity, interpolated monotonically between the points
/// (piecewise cubic Hermite with Fritsch-Carlson slopes: no overshoot between measured points).
/// Positive and negative velocities are separate branches; a table with only positive
/// velocities is mirrored (odd symmetry). Below the smallest |v| of a branch the force is held
/// at that point's value (it is also the breakaway level); beyond the largest it continues
/// along the last segment's slope.
class Table {
 public:
  static constexpr std::string_view kName = "table";

  /// \param velocity  strictly increasing, nonzero velocities (m/s or rad/s), at least 2 per branch
  /// \param force     friction at each velocity (N or N m); the sign of v (|force| grows away from 0 is not required)
  /// \throws std::invalid_argument on unequal lengths, non-increasing or zero velocities,
  ///         a force whose sign differs from its velocity's, a branch with one point, or non-finite values.
  Table(std::vector<double> velocity, std::vector<double> force);
  Table() : Table({0.001, 1.0}, {1.0, 1.0}) {}

  const std::vector<double>& velocity() const { return velocity_; }
  const std::vector<double>& force() const { return force_; }

  /// Re-checks the table (the constructor already did). Throws std::invalid_argument.
  void validate() const;

  template <class T>
  T sliding(const T& v) const {
    const double x = value_of(v);
    if (x == 0.0) return T(0);
    const Branch& b = x > 0 ? pos_ : neg_;
    const double sign = x > 0 ? 1.0 : -1.0;
    const T a = sign * v;  // |v| with its derivative
    return T(sign) * b.evaluate(a);
  }
  double breakaway_positive() const { return pos_.f.front(); }
  double breakaway_negative() const { return neg_.f.front(); }

 private:
  // One direction, stored as |v| ascending and |F|, with Hermite slopes.
  struct Branch {
    std::vector<double> v, f, slope;
    template <class T>
    T evaluate(const T& a) const {
      const double x = value_of(a);
      if (x <= v.front()) return T(f.front());
      const std::size_t n = v.size();
      if (x >= v.back()) return T(f.back()) + T((f[n - 1] - f[n - 2]) / (v[n - 1] - v[n - 2])) * (a - T(v.back()));
      std::size_t k = 0;
      while (v[k + 1] < x) ++k;  // tables are short (tens of points): a linear scan is fastest
      const double h = v[k + 1] - v[k];
      const T t = (a - T(v[k])) / T(h);
      const T t2 = t * t, t3 = t2 * t;
      return (T(2) * t3 - T(3) * t2 + T(1)) * T(f[k]) + (t3 - T(2) * t2 + t) * T(h * slope[k]) +
             (T(-2) * t3 + T(3) * t2) * T(f[k + 1]) + (t3 - t2) * T(h * slope[k + 1]);
    }
  };
  static Branch make_branch(std::vector<double> v, std::vector<double> f);

  std::vector<double> velocity_, force_;
  Branch pos_, neg_;
};

}  // namespace frictionlab

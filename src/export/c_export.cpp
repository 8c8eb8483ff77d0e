#include "frictionlab/export/c_export.hpp"
#include "frictionlab/error.hpp"

#include <cmath>
#include <limits>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "frictionlab/format.hpp"
#include "frictionlab/version.hpp"
#include "../models/table_knots.hpp"

namespace frictionlab {
namespace {

// The C text is written from templates in which
//   @       stands for the prefix,                  REAL for double or float,
//   %       for the parameter side ("", "_pos" or "_neg" of an asymmetric law),
//   $exp(   for exp( or expf( (every math.h call is written so),
//   2.0_r   for a literal 2.0 or 2.0f,
// so that one template serves both precisions and every law's sides. The formulas follow the
// library's (models/*.hpp, control/*.cpp) operation by operation, so that in double the header
// rounds as the library does.
class Writer {
 public:
  Writer(std::string prefix, bool single) : prefix_(std::move(prefix)), single_(single) {}

  const std::string& prefix() const { return prefix_; }
  bool single() const { return single_; }

  /// A C literal of `x` with full round-trip precision (%.17g), as a float literal in float mode.
  /// \throws std::invalid_argument for a value the target type cannot hold: not finite (a
  /// band of 1e307 gives -inf), or beyond float's range in float mode (a C compiler refuses the
  /// literal with -Werror=overflow), or nonzero and below float's smallest magnitude in float
  /// mode (the literal would round to 0).
  /// `name` (the constant's, without the prefix) is named in the messages when given.
  std::string number(double x, const std::string& name = "") const {
    const std::string which = name.empty() ? "" : " (" + prefix_ + "_" + name + ")";
    if (!std::isfinite(x))
      throw InputError(errc::output_not_finite,
                       "export: a constant of the header would be " + std::string(std::isnan(x) ? "NaN" : x > 0 ? "inf" : "-inf") + which +
                           " (a parameter or option too large or too small for double arithmetic); expected finite values",
                       {.value = std::isnan(x) ? "NaN" : x > 0 ? "inf" : "-inf"});
    if (single_ && std::abs(x) > static_cast<double>(std::numeric_limits<float>::max())) {
      char v[40];
      std::snprintf(v, sizeof v, "%.6g", x);
      throw InputError(errc::output_not_finite,  // float would hold it as inf
                       std::string("--float: a constant of the header is ") + v + ", beyond float's range (3.4e+38)" + which +
                           "; export without --float (double)",
                       {.option = "--float", .value = v});
    }
    // Below float's smallest subnormal a literal rounds to 0 (a C compiler says so with
    // -Werror=overflow), and a 0 the law divides by (vs, a table's speed) would give inf.
    if (single_ && x != 0 && static_cast<float>(x) == 0.0f) {
      char v[40];
      std::snprintf(v, sizeof v, "%.6g", x);
      throw std::invalid_argument(std::string("--float: a constant of the header is ") + v +
                                  ", below float's smallest magnitude (1.4e-45)" + which +
                                  ": float holds it as 0; export without --float (double)");
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    std::string s = buf;
    if (single_) {
      if (s.find_first_of(".e") == std::string::npos) s += ".0";
      s += "f";
    }
    return s;
  }

  std::string expand(std::string_view tmpl, std::string_view side = "") const {
    std::string out;
    out.reserve(tmpl.size() + 64);
    for (std::size_t i = 0; i < tmpl.size(); ++i) {
      const char c = tmpl[i];
      if (c == '@') {
        out += prefix_;
      } else if (c == '%') {
        out += side;
      } else if (c == '$') {  // $name( -> name( or namef(
        std::size_t j = i + 1;
        while (j < tmpl.size() && std::isalnum(static_cast<unsigned char>(tmpl[j]))) ++j;
        out += tmpl.substr(i + 1, j - i - 1);
        if (single_) out += 'f';
        i = j - 1;
      } else if (c == '_' && i + 1 < tmpl.size() && tmpl[i + 1] == 'r' && i > 0 &&
                 (std::isdigit(static_cast<unsigned char>(tmpl[i - 1])) || tmpl[i - 1] == '.') &&
                 (i + 2 >= tmpl.size() || !std::isalnum(static_cast<unsigned char>(tmpl[i + 2])))) {
        if (single_) out += 'f';
        ++i;
      } else if (tmpl.compare(i, 4, "REAL") == 0) {
        out += single_ ? "float" : "double";
        i += 3;
      } else {
        out += c;
      }
    }
    return out;
  }

  void code(std::string_view tmpl, std::string_view side = "") { text_ += expand(tmpl, side); }
  void line(const std::string& s) { text_ += s + "\n"; }

  /// static const REAL PREFIX_name = value;  /* unit */
  void constant(const std::string& name, double value, const std::string& what) {
    text_ += "static const " + std::string(single_ ? "float" : "double") + " " + prefix_ + "_" + name + " = " +
             number(value, name) + ";" + (what.empty() ? "" : "  /* " + what + " */") + "\n";
  }
  void array(const std::string& name, const std::vector<double>& values, const std::string& what) {
    text_ += "static const " + std::string(single_ ? "float" : "double") + " " + prefix_ + "_" + name + "[" +
             std::to_string(values.size()) + "] = {";
    for (std::size_t i = 0; i < values.size(); ++i)
      text_ += (i ? ", " : "") + number(values[i], name + "[" + std::to_string(i) + "]");
    text_ += "};" + (what.empty() ? std::string() : "  /* " + what + " */") + "\n";
  }

  std::string take() { return std::move(text_); }

 private:
  std::string prefix_;
  bool single_;
  std::string text_;
};

std::string unit_text(Quantity q) {
  const std::string lin(unit(q, Axis::linear)), rot(unit(q, Axis::rotary));
  if (lin.empty()) return "dimensionless";
  return lin == rot ? lin : lin + " (" + rot + " on a rotary axis)";
}

// The parameters of a law with `visit` (every law but table), each side's names suffixed.
template <class Law>
void law_constants(Writer& w, const Law& law, const std::string& side) {
  Law::visit(law, [&](std::string_view name, Quantity q, const double& x) {
    w.constant(std::string(name) + side, x, unit_text(q));
  });
}

// exp(-|v/vs|^delta) as stribeck_decay (models/scalar.hpp): the delta = 2 and delta = 1 fast paths
// and the cut-off at an exponent of 40 are the library's, so the values match to the ulp.
constexpr std::string_view kDecay = R"(static inline REAL @_decay%(REAL v) {
  REAL x, u, e;
  if (@_delta% == 2.0_r) {
    REAL xx;
    x = v / @_vs%;
    xx = x * x;
    e = $exp(-(xx < 40.0_r ? xx : 40.0_r));
    return xx > 40.0_r ? 0.0_r : e;
  }
  x = $fabs(v / @_vs%);
  if (x == 0.0_r) return 1.0_r;
  u = @_delta% == 1.0_r ? x : $exp(@_delta% * $log(x));
  e = $exp(-(u < 40.0_r ? u : 40.0_r));
  return u > 40.0_r ? 0.0_r : e;
}
)";

constexpr std::string_view kSign = R"(static inline REAL @_sign(REAL x) { return x > 0.0_r ? 1.0_r : (x < 0.0_r ? -1.0_r : 0.0_r); }
)";

// Stribeck level g(v) = Fc + (Fs - Fc) exp(-|v/vs|^delta) (N or N m).
constexpr std::string_view kLevel = R"(static inline REAL @_level%(REAL v) { return @_Fc% + (@_Fs% - @_Fc%) * @_decay%(v); }
)";

// The sliding force of one side of a static law, `@_sliding%(v)`.
template <class Law>
void static_sliding(Writer& w, const Law& law, const std::string& side) {
  if constexpr (std::is_same_v<Law, Coulomb>) {
    w.code("static inline REAL @_sliding%(REAL v) { return @_Fc% * @_sign(v); }\n", side);
  } else if constexpr (std::is_same_v<Law, Viscous>) {
    w.code("static inline REAL @_sliding%(REAL v) { return @_Fv% * v; }\n", side);
  } else if constexpr (std::is_same_v<Law, CoulombViscous> || std::is_same_v<Law, StaticCoulombViscous> ||
                       std::is_same_v<Law, Karnopp>) {
    w.code("static inline REAL @_sliding%(REAL v) { return @_Fc% * @_sign(v) + @_Fv% * v; }\n", side);
  } else if constexpr (std::is_same_v<Law, Stribeck>) {
    w.code(kDecay, side);
    w.code(kLevel, side);
    w.code("static inline REAL @_sliding%(REAL v) { return @_sign(v) * @_level%(v) + @_Fv% * v; }\n", side);
  } else if constexpr (std::is_same_v<Law, Smooth>) {
    w.code(kDecay, side);
    if (law.shape == SmoothShape::atan) w.constant("two_over_pi", 2.0 / std::numbers::pi, "2/pi");
    // tanh|x| through expm1 as the library computes it (models/smooth.hpp); atan scaled by 2/pi.
    w.code(law.shape == SmoothShape::atan ? R"(static inline REAL @_sliding%(REAL v) {
  const REAL x = v / @_vt%;
  const REAL s = @_two_over_pi * $atan(x);
)"
                                          : R"(static inline REAL @_sliding%(REAL v) {
  const REAL x = v / @_vt%;
  const REAL a = 2.0_r * $fabs(x);
  const REAL m = $expm1(a < 40.0_r ? -a : -40.0_r);
  const REAL s = @_sign(x) * (-m / (2.0_r + m));
)",
           side);
    w.code(R"(  const REAL level = @_Fs% == @_Fc% ? @_Fc% : @_Fc% + (@_Fs% - @_Fc%) * @_decay%(v);
  return s * level + @_Fv% * v;
}
)",
           side);
  } else {
    static_assert(std::is_same_v<Law, Table>);
    (void)law;
  }
}

template <class Law>
void static_side(Writer& w, const Law& law, const std::string& side) {
  law_constants(w, law, side);
  static_sliding(w, law, side);
}

void table_branch(Writer& w, const detail::TableSide& k, const std::string& side) {
  const std::string n = std::to_string(k.speed.size());
  w.array("table" + side + "_speed", k.speed, "|v| ascending, m/s (rad/s on a rotary axis)");
  w.array("table" + side + "_level", k.level, "|F|, N (N m)");
  w.array("table" + side + "_slope", detail::monotone_slopes(k.speed, k.level),
          "monotone Hermite slopes d|F|/d|v|, N s/m (N m s/rad)");
  // Monotone cubic Hermite in |v|, held below the first point, linear past the last (models/table.hpp).
  w.code(R"(static inline REAL @_branch%(REAL a) {
  const REAL *v = @_table%_speed, *f = @_table%_level, *m = @_table%_slope;
  const int n = )" + n + R"(;
  int k = 0;
  REAL h, t, t2, t3;
  if (a <= v[0]) return f[0];
  if (a >= v[n - 1]) return f[n - 1] + ((f[n - 1] - f[n - 2]) / (v[n - 1] - v[n - 2])) * (a - v[n - 1]);
  while (v[k + 1] < a) ++k;
  h = v[k + 1] - v[k];
  t = (a - v[k]) / h;
  t2 = t * t;
  t3 = t2 * t;
  return (2.0_r * t3 - 3.0_r * t2 + 1.0_r) * f[k] + (t3 - 2.0_r * t2 + t) * (h * m[k]) +
         (-2.0_r * t3 + 3.0_r * t2) * f[k + 1] + (t3 - t2) * (h * m[k + 1]);
}
)",
         side);
}

// The breakaway level of one side of a static law as a C expression of its constants (a
// constant of its own would repeat Fs or Fc, and C has no constant that names another).
template <class Law>
std::string breakaway(const Law&, const std::string& side) {
  if constexpr (std::is_same_v<Law, Coulomb> || std::is_same_v<Law, CoulombViscous>) return "@_Fc" + side;
  else if constexpr (std::is_same_v<Law, Viscous> || std::is_same_v<Law, Smooth>) return "0.0_r";
  else return "@_Fs" + side;  // static-coulomb-viscous, karnopp, stribeck
}

// The sliding force of one side with its levels moved by dFc, dFs, dFv (models/law_effects.hpp:
// at_conditions moves Fc, Fs and Fv or sigma2 by these, then the law's own formula runs): the
// formula of static_sliding with the moved levels, `@_sliding_at%(v, dFc, dFs, dFv)`.
template <class Law>
void static_sliding_at(Writer& w, const Law& law, const std::string& side) {
  std::string head = "static inline REAL @_sliding_at%(REAL v, REAL dFc, REAL dFs, REAL dFv) {\n";
  std::string unused = "  (void)dFc; (void)dFs; (void)dFv;\n";
  if constexpr (std::is_same_v<Law, Coulomb>) {
    w.code(head + unused + "  return (@_Fc% + dFc) * @_sign(v);\n}\n", side);
  } else if constexpr (std::is_same_v<Law, Viscous>) {
    w.code(head + unused + "  return (@_Fv% + dFv) * v;\n}\n", side);
  } else if constexpr (std::is_same_v<Law, CoulombViscous> || std::is_same_v<Law, StaticCoulombViscous> ||
                       std::is_same_v<Law, Karnopp>) {
    w.code(head + unused + "  return (@_Fc% + dFc) * @_sign(v) + (@_Fv% + dFv) * v;\n}\n", side);
  } else if constexpr (std::is_same_v<Law, Stribeck>) {
    w.code(head + R"(  const REAL Fc = @_Fc% + dFc, Fs = @_Fs% + dFs, Fv = @_Fv% + dFv;
  return @_sign(v) * (Fc + (Fs - Fc) * @_decay%(v)) + Fv * v;
}
)",
           side);
  } else if constexpr (std::is_same_v<Law, Smooth>) {
    w.code(head + R"(  const REAL Fc = @_Fc% + dFc, Fs = @_Fs% + dFs, Fv = @_Fv% + dFv;
  const REAL x = v / @_vt%;
)" + (law.shape == SmoothShape::atan ? std::string("  const REAL s = @_two_over_pi * $atan(x);\n")
                                     : std::string(R"(  const REAL a = 2.0_r * $fabs(x);
  const REAL m = $expm1(a < 40.0_r ? -a : -40.0_r);
  const REAL s = @_sign(x) * (-m / (2.0_r + m));
)")) + R"(  const REAL level = Fs == Fc ? Fc : Fc + (Fs - Fc) * @_decay%(v);
  return s * level + Fv * v;
}
)",
           side);
  } else {
    (void)law;
  }
}

// The breakaway level of one side with its levels moved, as a C expression of dFc and dFs.
template <class Law>
std::string breakaway_at(const Law& law, const std::string& side) {
  const std::string b = breakaway(law, side);
  if (b == "@_Fc" + side) return "(@_Fc" + side + " + dFc)";
  if (b == "@_Fs" + side) return "(@_Fs" + side + " + dFs)";
  return b;
}

// Static laws: constants, @_friction(v) and @_friction_stuck(v, applied).
template <class Law>
void static_law(Writer& w, const Law& law, bool moves_levels) {
  std::string hi, lo;
  if constexpr (std::is_same_v<Law, Table>) {
    detail::TableSide pos, neg;  // the points and slopes the Table interpolates (models/table_knots.hpp)
    detail::table_sides(law.velocity(), law.force(), pos, neg);
    table_branch(w, pos, "_pos");
    table_branch(w, neg, "_neg");
    w.code(R"(/* Friction force (N or N m) at velocity v (m/s or rad/s); 0 at v = 0. */
static inline REAL @_friction(REAL v) {
  if (v == 0.0_r) return 0.0_r;
  return v > 0.0_r ? @_branch_pos(v) : -@_branch_neg(-v);
}
)");
    hi = "@_table_pos_level[0]";
    lo = "@_table_neg_level[0]";
  } else if constexpr (requires { law.pos; }) {
    static_side(w, law.pos, "_pos");
    static_side(w, law.neg, "_neg");
    w.code(R"(/* Friction force (N or N m) at velocity v (m/s or rad/s): the _pos parameters for v >= 0,
   the _neg ones for v < 0; 0 at v = 0. */
static inline REAL @_friction(REAL v) { return v >= 0.0_r ? @_sliding_pos(v) : @_sliding_neg(v); }
)");
    hi = breakaway(law.pos, "_pos");
    lo = breakaway(law.neg, "_neg");
    if (moves_levels) {
      static_sliding_at(w, law.pos, "_pos");
      static_sliding_at(w, law.neg, "_neg");
      w.code("static inline REAL @_friction_moved(REAL v, REAL dFc, REAL dFs, REAL dFv) {\n"
             "  return v >= 0.0_r ? @_sliding_at_pos(v, dFc, dFs, dFv) : @_sliding_at_neg(v, dFc, dFs, dFv);\n}\n");
      w.code("static inline REAL @_breakaway_moved_pos(REAL dFc, REAL dFs) { (void)dFc; (void)dFs; return " +
             breakaway_at(law.pos, "_pos") + "; }\n");
      w.code("static inline REAL @_breakaway_moved_neg(REAL dFc, REAL dFs) { (void)dFc; (void)dFs; return " +
             breakaway_at(law.neg, "_neg") + "; }\n");
    }
  } else {
    static_side(w, law, "");
    w.code(R"(/* Friction force (N or N m) at velocity v (m/s or rad/s); 0 at v = 0. */
static inline REAL @_friction(REAL v) { return @_sliding(v); }
)");
    hi = lo = breakaway(law, "");
    if (moves_levels) {
      static_sliding_at(w, law, "");
      w.code("static inline REAL @_friction_moved(REAL v, REAL dFc, REAL dFs, REAL dFv) {\n"
             "  return @_sliding_at(v, dFc, dFs, dFv);\n}\n");
      const std::string b = breakaway_at(law, "");
      w.code("static inline REAL @_breakaway_moved_pos(REAL dFc, REAL dFs) { (void)dFc; (void)dFs; return " + b + "; }\n");
      w.code("static inline REAL @_breakaway_moved_neg(REAL dFc, REAL dFs) { (void)dFc; (void)dFs; return " + b + "; }\n");
    }
  }
  w.code("/* Breakaway levels (N or N m): the largest force a stuck contact holds pushed in + and in -. */\n"
         "static inline REAL @_breakaway_pos(void) { return " + hi + "; }\n"
         "static inline REAL @_breakaway_neg(void) { return " + lo + "; }\n");
  if constexpr (std::is_same_v<Law, Karnopp>) {
    w.code(R"(/* Friction with Karnopp's band (N or N m): inside |v| < dv it balances `applied` (the net force
   that would accelerate the body without friction, N or N m) up to Fs; outside it slides. */
static inline REAL @_friction_stuck(REAL v, REAL applied) {
  if ($fabs(v) < @_dv) {
    if (applied > @_breakaway_pos()) return @_breakaway_pos();
    if (applied < -@_breakaway_neg()) return -@_breakaway_neg();
    return applied;
  }
  return @_friction(v);
}
)");
  } else {
    w.code(R"(/* Friction with stiction (N or N m): the sliding force for v != 0; at v == 0 it balances
   `applied` (the net force that would accelerate the body without friction, N or N m) up to the
   breakaway level of the direction it pushes. */
static inline REAL @_friction_stuck(REAL v, REAL applied) {
  if (v != 0.0_r) return @_friction(v);
  if (applied > @_breakaway_pos()) return @_breakaway_pos();
  if (applied < -@_breakaway_neg()) return -@_breakaway_neg();
  return applied;
}
)");
  }
}

constexpr std::string_view kInitDoc =
    "/* The state at the start of a run: relaxed (zero deflection), as a body that has rested. */\n";
constexpr std::string_view kUpdateDoc =
    R"(/* Advances the state over dt seconds (>= 0) at constant velocity v (m/s or rad/s) and returns the
   friction force (N or N m) at the end of the step. Stable for any dt. */
)";

void lugre_law(Writer& w, const LuGre& law) {
  law_constants(w, law, "");
  w.code(kDecay);
  w.code(kLevel);
  w.code(R"(/* Bristle damping sigma1(v) (N s/m or N m s/rad): constant when vd = 0. */
static inline REAL @_damping(REAL v) {
  REAL r;
  if (@_vd == 0.0_r) return @_sigma1;
  r = v / @_vd;
  return @_sigma1 * $exp(-r * r);
}
/* Force at bristle deflection z (m or rad) and velocity v. */
static inline REAL @_force(REAL z, REAL v) {
  const REAL zdot = v - @_sigma0 * $fabs(v) * z / @_level(v);
  return @_sigma0 * z + @_damping(v) * zdot + @_sigma2 * v;
}
/* Steady-state friction force (N or N m) at constant velocity v (m/s or rad/s). */
static inline REAL @_friction(REAL v) { return @_force(@_sign(v) * @_level(v) / @_sigma0, v); }
typedef struct { REAL z[1]; } @_state; /* bristle deflection, m or rad */
)");
  w.code(kInitDoc);
  w.code("static inline void @_init(@_state *s) { s->z[0] = 0.0_r; }\n");
  w.code(kUpdateDoc);
  // Exact relaxation at frozen v (LuGreT::step).
  w.code(R"(static inline REAL @_update(@_state *s, REAL v, REAL dt) {
  const REAL g = @_level(v);
  const REAL rate = @_sigma0 * $fabs(v) / g;
  REAL zdot;
  if (v != 0.0_r) {
    const REAL zss = (v > 0.0_r ? g : -g) / @_sigma0;
    s->z[0] = zss + (s->z[0] - zss) * $exp(-rate * dt);
  }
  zdot = v - rate * s->z[0];
  return @_sigma0 * s->z[0] + @_damping(v) * zdot + @_sigma2 * v;
}
)");
}

void dahl_law(Writer& w, const Dahl& law) {
  law_constants(w, law, "");
  w.code(R"(/* Steady-state friction force (N or N m) at constant velocity v (m/s or rad/s). */
static inline REAL @_friction(REAL v) { return @_sigma0 * (@_sign(v) * @_Fc / @_sigma0); }
typedef struct { REAL z[1]; } @_state; /* deflection, m or rad */
)");
  w.code(kInitDoc);
  w.code("static inline void @_init(@_state *s) { s->z[0] = 0.0_r; }\n");
  w.code(kUpdateDoc);
  // Closed form in the travelled distance |v| dt (DahlT::step).
  w.code(R"(static inline REAL @_update(@_state *s, REAL v, REAL dt) {
  REAL sg, dx, k, u0, a, b, u;
  if (v == 0.0_r || dt <= 0.0_r) return @_sigma0 * s->z[0];
  sg = v > 0.0_r ? 1.0_r : -1.0_r;
  dx = $fabs(v) * dt;
  k = @_sigma0 / @_Fc;
  u0 = 1.0_r - k * s->z[0] * sg;
  a = $fabs(u0);
  if (@_alpha == 1.0_r) {
    b = a * $exp(-k * dx);
  } else {
    const REAL w = $pow(a, 1.0_r - @_alpha) + (@_alpha - 1.0_r) * k * dx;
    b = (@_alpha < 1.0_r && w <= 0.0_r) ? 0.0_r : $pow(w, 1.0_r / (1.0_r - @_alpha));
    if (@_alpha > 1.0_r && a == 0.0_r) b = 0.0_r;
  }
  u = u0 < 0.0_r ? -b : b;
  s->z[0] = (1.0_r - u) * sg / k;
  return @_sigma0 * s->z[0];
}
)");
}

void elastoplastic_law(Writer& w, const ElastoPlastic& law) {
  law_constants(w, law, "");
  // The Newton search's stopping rules, relative to zmax: the library's in double (a few ulps);
  // in float a few of float's ulps, which double's 1e-14 would never meet (60 iterations each step).
  w.constant("ep_step_tol", w.single() ? 5e-7 : 1e-14, "Newton step tolerance, relative to zmax");
  w.constant("ep_bracket_tol", w.single() ? 1e-7 : 1e-15, "bracket width tolerance, relative to zmax");
  w.constant("pi", std::numbers::pi, "");
  w.code(kDecay);
  w.code(kLevel);
  w.code(R"(/* Plasticity weight a(z, v) in [0, 1]. */
static inline REAL @_weight(REAL z, REAL v) {
  const REAL az = $fabs(z);
  REAL zmax;
  if (z * v <= 0.0_r) return 0.0_r;
  zmax = @_level(v) / @_sigma0;
  if (az <= @_zba) return 0.0_r;
  if (az >= zmax) return 1.0_r;
  return 0.5_r * $sin(@_pi * (az - (zmax + @_zba) / 2.0_r) / (zmax - @_zba)) + 0.5_r;
}
/* Force at deflection z (m or rad) and velocity v. */
static inline REAL @_force(REAL z, REAL v) {
  const REAL zdot = v - @_weight(z, v) * @_sigma0 * $fabs(v) * z / @_level(v);
  return @_sigma0 * z + @_sigma1 * zdot + @_sigma2 * v;
}
/* Steady-state friction force (N or N m) at constant velocity v (m/s or rad/s). */
static inline REAL @_friction(REAL v) { return @_force(@_sign(v) * @_level(v) / @_sigma0, v); }
typedef struct { REAL z[1]; } @_state; /* deflection, m or rad */
/* One implicit Euler step over the travelled distance h in the transition zone, solved by Newton's
   method kept inside a bracket (ElastoPlasticT::step). */
static inline REAL @_transition(REAL w, REAL h, REAL zmax) {
  const REAL k = @_pi / (zmax - @_zba), mid = (zmax + @_zba) / 2.0_r;
  REAL lo = w, hi = zmax, y, slope, f, newton, a, da;
  int it;
  a = lo >= zmax ? 1.0_r : 0.0_r;
  if (lo > @_zba && lo < zmax) a = 0.5_r * $sin(k * (lo - mid)) + 0.5_r;
  if (lo - w - h * (1.0_r - a * lo / zmax) >= 0.0_r) return lo;
  y = w + h < zmax ? w + h : zmax;
  for (it = 0; it < 60 && hi - lo > @_ep_bracket_tol * zmax; ++it) {
    a = y >= zmax ? 1.0_r : 0.0_r;
    da = 0.0_r;
    if (y > @_zba && y < zmax) {
      a = 0.5_r * $sin(k * (y - mid)) + 0.5_r;
      da = 0.5_r * k * $cos(k * (y - mid));
    }
    slope = 1.0_r + h * (da * y + a) / zmax;
    f = y - w - h * (1.0_r - a * y / zmax);
    if (f > 0.0_r) hi = y; else lo = y;
    newton = y - f / slope;
    if ($fabs(newton - y) < @_ep_step_tol * zmax) return newton < lo ? lo : (hi < newton ? hi : newton);
    y = newton > lo && newton < hi ? newton : 0.5_r * (lo + hi);
  }
  return y;
}
)");
  w.code(kInitDoc);
  w.code("static inline void @_init(@_state *s) { s->z[0] = 0.0_r; }\n");
  w.code(kUpdateDoc);
  w.code(R"(static inline REAL @_update(@_state *s, REAL v, REAL dt) {
  REAL sg, x, wd, zmax, elastic, room;
  if (v == 0.0_r || dt <= 0.0_r) return @_force(s->z[0], v);
  sg = v > 0.0_r ? 1.0_r : -1.0_r;
  x = $fabs(v) * dt;
  wd = s->z[0] * sg;
  zmax = @_level(v) / @_sigma0;
  if (wd > zmax) {
    wd = zmax + (wd - zmax) * $exp(-x / zmax);
  } else {
    room = @_zba - wd;
    if (room < 0.0_r) room = 0.0_r;
    elastic = x < room ? x : room;
    wd += elastic;
    x -= elastic;
    if (x > 0.0_r) wd = @_transition(wd, x, zmax);
  }
  s->z[0] = wd * sg;
  return @_force(s->z[0], v);
}
)");
}

void gms_law(Writer& w, const Gms& law) {
  law_constants(w, law, "");
  w.array("k", law.k, "element stiffnesses, N/m (N m/rad)");
  w.array("alpha", law.alpha, "element fractions of the Stribeck level");
  const std::string n = std::to_string(law.k.size());
  w.code(kDecay);
  w.code(kLevel);
  w.code(R"(typedef struct { REAL z[)" + n + R"(]; } @_state; /* element deflections, m or rad */
/* Force at element deflections z (m or rad) and velocity v. */
static inline REAL @_force(const REAL *z, REAL v) {
  REAL f = @_sigma2 * v;
  int i;
  for (i = 0; i < )" + n + R"(; ++i) f += @_k[i] * z[i];
  return f;
}
/* Steady-state friction force (N or N m) at constant velocity v (m/s or rad/s). */
static inline REAL @_friction(REAL v) {
  @_state st;
  const REAL s = @_level(v);
  int i;
  for (i = 0; i < )" + n + R"(; ++i) st.z[i] = @_sign(v) * @_alpha[i] * s / @_k[i];
  return @_force(st.z, v);
}
)");
  w.code(kInitDoc);
  w.code("static inline void @_init(@_state *s) {\n  int i;\n  for (i = 0; i < " + n +
         "; ++i) s->z[i] = 0.0_r;\n}\n");
  w.code(kUpdateDoc);
  // Each element moves with v, clamped at its slip level; above it, exact relaxation (GmsT::step).
  w.code(R"(static inline REAL @_update(@_state *s, REAL v, REAL dt) {
  if (dt > 0.0_r && v != 0.0_r) {
    const REAL lv = @_level(v);
    const REAL sg = v > 0.0_r ? 1.0_r : -1.0_r;
    const REAL decay = $exp(-@_C * dt / lv);
    int i;
    for (i = 0; i < )" + n + R"(; ++i) {
      const REAL bound = @_alpha[i] * lv / @_k[i];
      const REAL wd = s->z[i] * sg;
      REAL w1;
      if (wd > bound) {
        w1 = bound + (wd - bound) * decay;
      } else {
        const REAL moved = wd + $fabs(v) * dt;
        w1 = bound < moved ? bound : moved;
      }
      s->z[i] = w1 * sg;
    }
  }
  return @_force(s->z, v);
}
)");
}

// --- compensations (control/*.cpp, their update()) ---

struct ConditionArgs;
void feedforward_at(Writer& w, const ConditionArgs& a);
void feedback_at(Writer& w, const ConditionArgs& a);
bool moves(const ConditionArgs& a);
bool compensation_at(const ConditionArgs& a);

void feedforward(Writer& w, const FrictionLaw& law, const FeedforwardParams& p, const ConditionArgs& a) {
  const FeedforwardCompensation check(law, p);  // validates the band
  w.line("\n/* Feedforward compensation (control/feedforward.hpp): the law at the reference velocity. */");
  w.constant("ff_band", p.band, "half-width of the smoothing band, m/s (rad/s)");
  w.constant("ff_at_plus", law.sliding(p.band), "F(+band), N (N m)");
  w.constant("ff_at_minus", law.sliding(-p.band), "F(-band), N (N m)");
  w.code(R"(/* Compensation force (N or N m) to add to the drive's command at reference velocity vr (m/s or
   rad/s): F(vr) outside |vr| <= band, a straight line from F(-band) to F(+band) inside. */
static inline REAL @_feedforward(REAL vr) {
  if (vr > @_ff_band || vr < -@_ff_band) return @_friction(vr);
  const REAL t = 0.5_r + 0.5_r * (vr / @_ff_band);
  return @_ff_at_minus * (1.0_r - t) + @_ff_at_plus * t;
}
)");
  if (compensation_at(a)) feedforward_at(w, a);
}

void feedback(Writer& w, const FrictionLaw& law, const FeedbackParams& p, const ConditionArgs& a) {
  const FeedbackCompensation check(law, p);
  w.line("\n/* Feedback compensation (control/feedback.hpp): the law at the measured velocity. */");
  w.constant("fb_dead_band", p.dead_band, "half-width of the dead band, m/s (rad/s)");
  w.code(R"(/* Compensation force (N or N m) to add to the drive's command at measured velocity v (m/s or
   rad/s): F(v) outside |v| <= dead band, 0 inside. */
static inline REAL @_feedback(REAL v) {
  if (v > @_fb_dead_band || v < -@_fb_dead_band) return @_friction(v);
  return 0.0_r;
}
)");
  if (compensation_at(a)) feedback_at(w, a);
}

void lugre_observer(Writer& w, const FrictionLaw& law, const LuGreObserverParams& p) {
  const LuGreObserver check(law, p);  // refuses a law that is not LuGre, a bad gain
  const bool ripple = law.effects().ripple.has_value();
  w.line("\n/* LuGre observer (control/lugre_observer.hpp; Canudas de Wit et al. 1995, section V). */");
  w.constant("obs_gain", p.gain, "observer gain k, 1/s");
  w.code(R"(typedef struct { REAL z; } @_lugre_observer_state; /* estimated bristle deflection, m or rad */
/* The observer's start: the law's steady state at the first measured velocity v (m/s or rad/s). */
static inline void @_lugre_observer_init(@_lugre_observer_state *s, REAL v) {
  s->z = @_sign(v) * @_level(v) / @_sigma0;
}
/* Advances the observer over the step of dt seconds just ended, holding the measured position x
   (m or rad), velocity v (m/s or rad/s) and reference position r (m or rad), and returns the
   compensation force (N or N m) to add to the drive's command)" +
         std::string(ripple ? ", the ripple r(x) at the measured position included" : "") +
         R"(. Exact at frozen v: stable for any dt. */
static inline REAL @_lugre_observer_update(@_lugre_observer_state *s, REAL x, REAL v, REAL r, REAL dt) {
  const REAL rate = @_sigma0 * $fabs(v) / @_level(v);
  const REAL c = v - @_obs_gain * (x - r);
  REAL dz;
  if (rate > 0.0_r) {
    const REAL zss = c / rate;
    s->z = zss + (s->z - zss) * $exp(-rate * dt);
  } else {
    s->z += c * dt;
  }
  dz = c - rate * s->z;
  return @_sigma0 * s->z + @_damping(v) * dz + @_sigma2 * v)" +
         std::string(ripple ? " + @_ripple(x)" : "") + R"(;
}
)");
}

void disturbance_observer(Writer& w, const DisturbanceObserverParams& p) {
  const DisturbanceObserver check(p);
  w.line("\n/* Disturbance observer (control/disturbance_observer.hpp): low-pass inverse model. */");
  w.constant("dob_bandwidth", p.bandwidth, "low-pass bandwidth w, rad/s");
  w.constant("dob_inertia", p.inertia, "nominal inertia M, kg (kg m^2)");
  w.code(R"(typedef struct { REAL p; } @_disturbance_observer_state; /* d^ + w M v, N or N m */
/* The observer's start at the first measured velocity v (m/s or rad/s): estimate 0. */
static inline void @_disturbance_observer_init(@_disturbance_observer_state *s, REAL v) {
  s->p = @_dob_bandwidth * @_dob_inertia * v;
}
/* Advances the observer over the step of dt seconds just ended, holding the measured velocity v
   (m/s or rad/s) and the force `drive` (N or N m, this compensation included) applied over it, and
   returns the estimated disturbance (N or N m) to add to the drive's command. Exact: stable for any dt. */
static inline REAL @_disturbance_observer_update(@_disturbance_observer_state *s, REAL v, REAL drive, REAL dt) {
  const REAL pss = drive + @_dob_bandwidth * @_dob_inertia * v;
  s->p = pss + (s->p - pss) * $exp(-@_dob_bandwidth * dt);
  return s->p - @_dob_bandwidth * @_dob_inertia * v;
}
)");
}

std::string upper(std::string s);

// The position ripple (models/position_ripple.hpp: PositionRipple::force, the same operations in
// the same order) and the friction with it at a position: PREFIX_ripple(q), PREFIX_friction_at(v, q).
void ripple_table(Writer& w, const PositionRipple& r);
void ripple_harmonics(Writer& w, const PositionRipple& r);

void ripple(Writer& w, const PositionRipple& r, bool with_friction_at) {
  if (r.is_table()) {
    ripple_table(w, r);
  } else {
    ripple_harmonics(w, r);
  }
  if (with_friction_at)
    w.code(R"(
/* The sliding friction at velocity v and position q: friction(v) + r(q), N or N m. */
static inline REAL @_friction_at(REAL v, REAL q) { return @_friction(v) + @_ripple(q); }
)");
}

// A ripple given as a table over one period (PositionRipple::segment and force: the position
// wrapped into [q_0, q_0 + P) by fmod, the first row past it found by bisection, as
// std::upper_bound finds it, and the same linear interpolation).
void ripple_table(Writer& w, const PositionRipple& r) {
  const std::size_t n = r.table_position.size();
  w.line("\n/* Position ripple r(q) by table: " + std::to_string(n) +
         " rows of force against position over one period P, periodic, linear between rows (N or N m), q in m or "
         "rad; it adds to the friction whether the contact slides or sticks. */");
  w.constant("ripple_period", r.period, "P, m (rad on a rotary axis)");
  w.array("ripple_q", r.table_position, "positions q_0 < ... < q_n = q_0 + P, m (rad)");
  w.array("ripple_r", r.table_force, "ripple force at them, N (N m); r_n = r_0");
  const std::string points = upper(w.prefix()) + "_RIPPLE_POINTS";
  w.line("#define " + points + " " + std::to_string(n));
  w.code(R"(
/* r(q), N or N m, at position q (m or rad). */
static inline REAL @_ripple(REAL q) {
  REAL u = $fmod(q - @_ripple_q[0], @_ripple_period);
  REAL x, t;
  int lo = 0, hi = )" + points + R"(, k;
  if (u < 0.0_r) u += @_ripple_period;
  x = @_ripple_q[0] + u;
  while (lo < hi) { /* the first row whose position exceeds x */
    const int mid = (lo + hi) / 2;
    if (@_ripple_q[mid] > x) hi = mid; else lo = mid + 1;
  }
  k = lo < 1 ? 1 : (lo > )" + points + R"( - 1 ? )" + points + R"( - 1 : lo);
  t = (x - @_ripple_q[k - 1]) / (@_ripple_q[k] - @_ripple_q[k - 1]);
  return @_ripple_r[k - 1] + t * (@_ripple_r[k] - @_ripple_r[k - 1]);
}
)");
}

void ripple_harmonics(Writer& w, const PositionRipple& r) {
  const std::size_t K = r.harmonics();
  std::vector<double> a(r.a), b(r.b);
  a.resize(K, 0.0);
  b.resize(K, 0.0);
  w.line("\n/* Position ripple r(q) = sum_k a_k sin(2 pi k q / P) + b_k cos(2 pi k q / P), k = 1.." + std::to_string(K) +
         " (N or N m), q in m or rad; it adds to the friction whether the contact slides or sticks. */");
  w.constant("ripple_period", r.period, "P, m (rad on a rotary axis)");
  w.constant("ripple_pi", std::numbers::pi, "pi, as the library's std::numbers::pi");
  w.array("ripple_a", a, "sine amplitudes a_k, N (N m)");
  w.array("ripple_b", b, "cosine amplitudes b_k, N (N m)");
  w.line("#define " + upper(w.prefix()) + "_RIPPLE_HARMONICS " + std::to_string(K));
  w.code(R"(
/* r(q), N or N m, at position q (m or rad). */
static inline REAL @_ripple(REAL q) {
  const REAL w = 2.0_r * @_ripple_pi * q / @_ripple_period;
  REAL r = 0.0_r;
  int k;
  for (k = 0; k < )" + upper(w.prefix()) + R"(_RIPPLE_HARMONICS; ++k) {
    const REAL kw = (REAL)(k + 1) * w;
    r += @_ripple_a[k] * $sin(kw);
    r += @_ripple_b[k] * $cos(kw);
  }
  return r;
}
)");
}

// The load and temperature terms of a static law (models/law_effects.hpp: at_conditions), the
// friction and breakaway levels at given conditions. The arguments of the public functions are
// the terms the law has: (v[, q][, load][, T]).
struct ConditionArgs {
  bool ripple = false, load = false, temperature = false;
  std::string decl() const {  // ", REAL load, REAL T" for the terms present
    return std::string(load ? ", REAL load" : "") + (temperature ? ", REAL T" : "");
  }
  std::string pass() const {  // the arguments of @_level_shifts
    return std::string(load ? "load" : "0.0_r") + ", " + (temperature ? "T" : "0.0_r");
  }
};

void conditions(Writer& w, const LawEffects& e, const ConditionArgs& a) {
  std::string units;
  if (e.load) {
    w.line("\n/* Load term: Fc + mu_load_coulomb |load|, Fs + mu_load_static |load|; `load` in N (N m on a rotary axis). */");
    w.constant("mu_load_static", e.load->mu_static, "dimensionless: N of friction per N of load");
    w.constant("mu_load_coulomb", e.load->mu_coulomb, "dimensionless: N of friction per N of load");
  }
  if (const auto& t = e.temperature) {
    w.line("\n/* Temperature term: Fc, Fs + Fc_per_K (T - T_ref), Fv + Fv_per_K (T - T_ref); `T` in degC or K, the scale\n"
           "   of T_ref. The library refuses a temperature outside [T_min, T_max]; the header clamps T to it. */");
    w.constant("T_ref", t->T_ref, "degC or K: the law's own Fc, Fv hold here");
    w.constant("Fc_per_K", t->Fc_per_K, "N/K (N m/K)");
    w.constant("Fv_per_K", t->Fv_per_K, "N s/(m K) (N m s/(rad K))");
    if (t->T_min) w.constant("T_min", *t->T_min, "degC or K");
    if (t->T_max) w.constant("T_max", *t->T_max, "degC or K");
  }
  std::string body = "static inline void @_level_shifts(REAL load, REAL T, REAL *dFc, REAL *dFs, REAL *dFv) {\n"
                     "  (void)load; (void)T;\n  *dFc = 0.0_r; *dFs = 0.0_r; *dFv = 0.0_r;\n";
  if (e.load)
    body += "  *dFc += @_mu_load_coulomb * $fabs(load);\n  *dFs += @_mu_load_static * $fabs(load);\n";
  if (const auto& t = e.temperature) {
    if (t->T_min) body += "  if (T < @_T_min) T = @_T_min;\n";
    if (t->T_max) body += "  if (T > @_T_max) T = @_T_max;\n";
    body += "  *dFc += @_Fc_per_K * (T - @_T_ref);\n  *dFs += @_Fc_per_K * (T - @_T_ref);\n"
            "  *dFv += @_Fv_per_K * (T - @_T_ref);\n";
  }
  body += "}\n";
  w.code("/* The moves of the levels Fc, Fs and Fv (N, N, N s/m; N m, N m, N m s/rad) at load and temperature T. */\n" + body);
  const std::string args = std::string(a.ripple ? ", q (m or rad)" : "") + (a.load ? ", load (N or N m)" : "") +
                           (a.temperature ? ", T (degC or K)" : "");
  w.code("\n/* The sliding friction (N or N m) at velocity v (m/s or rad/s)" + args +
         ": the law with its levels moved" + (a.ripple ? ", plus the ripple r(q)" : "") + ". */\n" +
         "static inline REAL @_friction_at(REAL v" + (a.ripple ? ", REAL q" : "") + a.decl() + ") {\n" +
         "  REAL dFc, dFs, dFv;\n  @_level_shifts(" + a.pass() + ", &dFc, &dFs, &dFv);\n" +
         "  return @_friction_moved(v, dFc, dFs, dFv)" + (a.ripple ? " + @_ripple(q)" : "") + ";\n}\n");
  if (a.load || a.temperature) {
    const std::string decl = a.decl().substr(2);  // without the leading ", "
    for (const char* dir : {"pos", "neg"})
      w.code(std::string("/* Breakaway level pushed in ") + (dir[0] == 'p' ? "+" : "-") + " (N or N m) at" +
             (a.load ? " load (N or N m)" : "") + (a.load && a.temperature ? "," : "") + (a.temperature ? " T (degC or K)" : "") +
             " */\nstatic inline REAL @_breakaway_" + dir + "_at(" + decl + ") {\n" +
             "  REAL dFc, dFs, dFv;\n  @_level_shifts(" + a.pass() + ", &dFc, &dFs, &dFv);\n  (void)dFv;\n" +
             "  return @_breakaway_moved_" + dir + "(dFc, dFs);\n}\n");
  }
}

bool moves(const ConditionArgs& a) { return a.load || a.temperature; }
// A compensation gets its form at the conditions (PREFIX_feedforward_at, _feedback_at) when the law
// has a term that takes an argument: load, temperature or the ripple's position.
bool compensation_at(const ConditionArgs& a) { return moves(a) || a.ripple; }

// The comment over a compensation at the conditions: which arguments it takes, in which units.
// `position` names the position the ripple is taken at (the reference's or the measured one).
std::string conditions_comment(const std::string& what, const ConditionArgs& a, const std::string& position) {
  std::string s = "/* The " + what;
  if (moves(a))
    s += " at load" + std::string(a.load ? " `load` (N or N m, measured or estimated)" : " 0") +
         (a.temperature ? " and temperature `T` (degC or K, measured; pass T_ref when none is measured)" : "") +
         ": the law with its levels moved";
  if (a.ripple)
    s += std::string(moves(a) ? ",\n   plus" : ": the compensation plus") + " the ripple r(q) at the " + position +
         " `q` (m or rad), inside the band as outside it";
  return s + ". */\n";
}

// The compensation's value f at the conditions, then the ripple at q added to it, as the library
// adds law.ripple(q) to the band's force (control/band_compensation.cpp): the same operations.
std::string compensation_return(const ConditionArgs& a) { return a.ripple ? "  return f + @_ripple(q);\n}\n" : "  return f;\n}\n"; }

// The compensations at the measured (or estimated) load and temperature (control/feedforward.cpp,
// feedback.cpp with CompensatorInput::load, ::temperature): the band's ends move with the levels.
void feedforward_at(Writer& w, const ConditionArgs& a) {
  std::string body;
  if (moves(a))
    body = "  REAL dFc, dFs, dFv, plus, minus, t, f;\n  @_level_shifts(" + a.pass() + ", &dFc, &dFs, &dFv);\n"
           "  if (vr > @_ff_band || vr < -@_ff_band) {\n    f = @_friction_moved(vr, dFc, dFs, dFv);\n  } else {\n"
           "    plus = @_friction_moved(@_ff_band, dFc, dFs, dFv);\n"
           "    minus = @_friction_moved(-@_ff_band, dFc, dFs, dFv);\n"
           "    t = 0.5_r + 0.5_r * (vr / @_ff_band);\n    f = minus * (1.0_r - t) + plus * t;\n  }\n";
  else
    body = "  const REAL f = @_feedforward(vr);\n";
  w.code(conditions_comment("feedforward", a, "reference position") + "static inline REAL @_feedforward_at(REAL vr" +
         (a.ripple ? ", REAL q" : "") + a.decl() + ") {\n" + body + compensation_return(a));
}

void feedback_at(Writer& w, const ConditionArgs& a) {
  std::string body;
  if (moves(a))
    body = "  REAL dFc, dFs, dFv, f = 0.0_r;\n  @_level_shifts(" + a.pass() + ", &dFc, &dFs, &dFv);\n"
           "  if (v > @_fb_dead_band || v < -@_fb_dead_band) f = @_friction_moved(v, dFc, dFs, dFv);\n";
  else
    body = "  const REAL f = @_feedback(v);\n";
  w.code(conditions_comment("feedback", a, "measured position") + "static inline REAL @_feedback_at(REAL v" +
         (a.ripple ? ", REAL q" : "") + a.decl() + ") {\n" + body + compensation_return(a));
}

void check_prefix(const std::string& prefix) {
  bool ok = !prefix.empty() && prefix.size() <= 40 && std::isalpha(static_cast<unsigned char>(prefix[0]));
  for (char c : prefix) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok)
    throw std::invalid_argument("prefix '" + prefix +
                                "' is not a C identifier; expected a letter, then letters, digits or _ "
                                "(at most 40 characters)");
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string c_header(const FrictionLaw& law, const CExportOptions& options) {
  check_prefix(options.prefix);
  // The C form moves a static law's levels with load and temperature (PREFIX_friction_at); a
  // dynamic law's state update in the header runs on fixed levels, so its terms are refused.
  const LawEffects& effects = law.effects();
  if (effects.moves_levels() && law.is_dynamic())
    throw InputError(errc::law_parameter,
                     "export: law '" + law.name() + "' is dynamic and carries " +
                         (effects.load ? "a load term (mu_load)" : "a temperature term (Fv_per_K, Fc_per_K)") +
                         ": the header's state update runs on fixed levels and does not move them with the load or "
                         "temperature; export the law without them, or a static law (stribeck, ...) with them",
                     {.key = effects.load ? "mu_load" : "T_ref"});
  // A position ripple goes into the feedforward and feedback as PREFIX_feedforward_at(vr, q, ...),
  // PREFIX_feedback_at(v, q, ...); the observers run as the library's do (see their comments).
  const std::optional<PositionRipple> ripple_effect = law.effects().ripple;
  // The float form of the library's rule for bristle laws (FrictionLaw::validate: sigma0 / Fc at
  // most 1e150 in double): the rate sigma0 |v| / Fc overflows float at a finite speed when
  // sigma0 / Fc is far beyond 1e15 (sigma0 = 2.1e38 gave -inf friction at 10 m/s in a float
  // header). Real contacts are 1e2 to 1e9 per unit of Fc.
  if (options.single_precision) {
    double sigma0 = NAN, Fc = NAN;
    for (const Parameter& p : law.parameters()) {
      if (p.name == "sigma0") sigma0 = p.value;
      if (p.name == "Fc") Fc = p.value;
    }
    constexpr double kMaxFloatStiffnessRatio = 1e15;
    if (std::isfinite(sigma0) && !(sigma0 / Fc <= kMaxFloatStiffnessRatio))
      throw InputError(errc::output_not_finite,
                       "--float: sigma0 / Fc = " + format_number(sigma0 / Fc) +
                           " (1/m or 1/rad) exceeds 1e+15, where the bristle rate sigma0 |v| / Fc leaves "
                           "float's range at a finite speed; export without --float (double)",
                       {.key = "sigma0", .option = "--float", .value = format_number(sigma0)});
  }
  Writer w(options.prefix, options.single_precision);
  const std::string type = compensation_type(options.compensation);
  const std::string guard = upper(options.prefix) + "_FRICTION_H";
  std::ostringstream head;
  head << "/* Friction law '" << law.name() << "'" << (type.empty() ? "" : " with " + type + " compensation")
       << ", written by frictionlab " << kVersion << (options.source.empty() ? "" : " from " + options.source)
       << ".\n"
       << R"( * One C99 header: static inline functions, no allocation, nothing beyond math.h (link with -lm).
 * Units: SI. Linear axis: N, m, m/s, N s/m, N/m; rotary axis: N m, rad, rad/s, N m s/rad, N m/rad; time in s.
 * Sign: friction F has the sign of the velocity and is subtracted (M a = drive - F); a compensation
 * estimates F and is ADDED to the drive's command.
 * Precision: )"
       << (options.single_precision ? "float (agrees with frictionlab to float's precision)."
                                    : "double (the same formulas as frictionlab, in the same order).")
       << R"(
 * In a sampled loop of period dt (s), per sample:)"
       << (law.is_dynamic() ? "\n *   F = " + options.prefix + "_update(&state, v, dt);   after " + options.prefix +
                                  "_init(&state) once"
                            : "\n *   F = " + options.prefix + "_friction(v);")
       << "\n */\n";
  w.line(head.str() + "#ifndef " + guard + "\n#define " + guard + "\n\n#include <math.h>\n");
  w.code(kSign);
  std::visit(
      [&](const auto& l) {
        using Law = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<Law, LuGre>) {
          lugre_law(w, l);
        } else if constexpr (std::is_same_v<Law, Dahl>) {
          dahl_law(w, l);
        } else if constexpr (std::is_same_v<Law, ElastoPlastic>) {
          elastoplastic_law(w, l);
        } else if constexpr (std::is_same_v<Law, Gms>) {
          gms_law(w, l);
        } else {
          static_law(w, l, effects.moves_levels());
        }
      },
      law.variant());
  const ConditionArgs cargs{.ripple = ripple_effect.has_value(), .load = effects.load.has_value(),
                            .temperature = effects.temperature.has_value()};
  if (ripple_effect) ripple(w, *ripple_effect, !law.is_dynamic() && !effects.moves_levels());
  if (effects.moves_levels()) conditions(w, effects, cargs);
  std::visit(
      [&](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, FeedforwardParams>) feedforward(w, law, p, cargs);
        else if constexpr (std::is_same_v<P, FeedbackParams>) feedback(w, law, p, cargs);
        else if constexpr (std::is_same_v<P, LuGreObserverParams>) lugre_observer(w, law, p);
        else if constexpr (std::is_same_v<P, DisturbanceObserverParams>) disturbance_observer(w, p);
      },
      options.compensation);
  w.line("\n#endif /* " + guard + " */");
  return w.take();
}

}  // namespace frictionlab

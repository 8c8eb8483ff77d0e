#include "frictionlab/models/friction_law.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>

#include "frictionlab/error.hpp"

namespace frictionlab {
namespace {

template <class Law>
std::string law_name() {
  if constexpr (requires { Law::name(); }) {
    return Law::name();
  } else {
    return std::string(Law::kName);
  }
}

template <class Law>
constexpr bool kIsDynamic = DynamicLaw<Law>;

// The force (N or N m) of `law` sliding steadily at v (m/s or rad/s): a dynamic law's at its
// steady state.
template <class Law>
double steady_sliding(const Law& law, double v) {
  if constexpr (kIsDynamic<Law>) {
    std::vector<double> z(static_cast<std::size_t>(law.num_states()));
    law.steady_state(v, z);
    return law.force(std::span<const double>(z), v);
  } else {
    return law.sliding(v);
  }
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// Parameters a file may leave out, with the value a demanding user expects.
bool is_optional(const std::string& law, const std::string& param) {
  static const std::set<std::string> everywhere = {"delta", "delta_pos", "delta_neg", "vd"};
  if (everywhere.count(param)) return true;
  if (law == "dahl" && param == "alpha") return true;
  if (law == "smooth" && (param == "Fs" || param == "vs" || param == "Fv")) return true;
  return false;
}

template <class Law>
Law build(const LawSpec& spec) {
  Law law{};
  const std::string name = law_name<Law>();
  std::vector<std::string> known;
  std::set<std::string> used;
  std::string missing;
  Law::visit(law, [&](const std::string& p, Quantity, double& x) {
    known.push_back(p);
    if (auto it = spec.scalars.find(p); it != spec.scalars.end()) {
      x = it->second;
      used.insert(p);
    } else if (!is_optional(name, p) && missing.empty()) {
      missing = p;
    }
  });
  std::vector<std::string> arrays;
  if constexpr (std::is_same_v<Law, Gms>) arrays = {"k", "alpha"};
  for (const auto& [key, value] : spec.scalars) {
    if (!used.count(key))
      throw std::invalid_argument(name + ": unknown parameter '" + key + "'; " + name + " has " + join(known) +
                                  (arrays.empty() ? "" : ", " + join(arrays)));
  }
  // A parameter of one number given as a list (Fc: [1.0]) is that, not a missing parameter.
  for (const auto& [key, value] : spec.arrays)
    if (std::find(known.begin(), known.end(), key) != known.end())
      throw std::invalid_argument(name + ": parameter '" + key + "' is a list of " + std::to_string(value.size()) +
                                  " numbers; expected one number");
  if (!missing.empty())
    throw std::invalid_argument(name + ": missing parameter '" + missing + "' (" + name + " needs " + join(known) +
                                (arrays.empty() ? "" : ", " + join(arrays)) + ")");
  auto array = [&](const std::string& key) {
    auto it = spec.arrays.find(key);
    if (it == spec.arrays.end()) throw std::invalid_argument(name + ": missing parameter '" + key + "' (a list of numbers)");
    return it->second;
  };
  if constexpr (std::is_same_v<Law, Gms>) {
    law.k = array("k");
    law.alpha = array("alpha");
  }
  if constexpr (std::is_same_v<Law, Smooth>) {
    if (!spec.scalars.count("Fs")) law.Fs = law.Fc;
    if (auto it = spec.strings.find("shape"); it != spec.strings.end()) {
      if (it->second == "tanh") law.shape = SmoothShape::tanh;
      else if (it->second == "atan") law.shape = SmoothShape::atan;
      else throw std::invalid_argument("smooth: shape '" + it->second + "' is not valid; expected tanh or atan");
    }
  }
  return law;
}

template <>
Table build<Table>(const LawSpec& spec) {
  for (const auto& [key, value] : spec.scalars)
    throw std::invalid_argument("table: unknown parameter '" + key + "'; table has velocity, force (lists of numbers)");
  auto array = [&](const std::string& key) {
    auto it = spec.arrays.find(key);
    if (it == spec.arrays.end())
      throw std::invalid_argument("table: missing parameter '" + key + "' (a list of numbers, " +
                                  (key == "velocity" ? "m/s or rad/s)" : "N or N m)"));
    return it->second;
  };
  return Table(array("velocity"), array("force"));
}

template <class Variant, std::size_t... I>
FrictionLaw from_name(const LawSpec& spec, std::index_sequence<I...>) {
  std::optional<FrictionLaw> out;
  (void)((law_name<std::variant_alternative_t<I, Variant>>() == spec.name
              ? (out.emplace(build<std::variant_alternative_t<I, Variant>>(spec)), true)
              : false) ||
         ...);
  if (!out) throw std::invalid_argument("unknown friction law '" + spec.name + "'; valid laws: " + join(FrictionLaw::names()));
  return *out;
}

template <class Variant, std::size_t... I>
std::vector<std::string> all_names(std::index_sequence<I...>) {
  return {law_name<std::variant_alternative_t<I, Variant>>()...};
}

}  // namespace

namespace {
// Takes the effects' keys out of `spec` (law_effects.hpp): what is left is the velocity law's.
LawEffects take_effects(LawSpec& spec) {
  LawEffects e;
  auto take = [&](const char* key) -> std::optional<double> {
    auto it = spec.scalars.find(key);
    if (it == spec.scalars.end()) return std::nullopt;
    const double v = it->second;
    spec.scalars.erase(it);
    return v;
  };
  auto take_list = [&](const char* key) -> std::optional<std::vector<double>> {
    auto it = spec.arrays.find(key);
    if (it == spec.arrays.end()) {
      if (auto one = take(key)) return std::vector<double>{*one};  // one harmonic written as a number
      return std::nullopt;
    }
    std::vector<double> v = std::move(it->second);
    spec.arrays.erase(it);
    return v;
  };
  auto refuse = [](const char* key, const std::string& why, std::optional<double> v = std::nullopt) {
    throw InputError(errc::law_parameter, std::string(key) + ": " + why,
                     {.key = key, .value = v ? detail::format_value(*v) : std::string()});
  };
  const auto mu = take("mu_load"), mu_s = take("mu_load_static"), mu_c = take("mu_load_coulomb");
  if (mu && (mu_s || mu_c)) refuse("mu_load", "give mu_load alone (both levels) or mu_load_static with mu_load_coulomb, not both forms");
  if (mu) {
    if (!(std::isfinite(*mu) && *mu >= 0))
      refuse("mu_load", detail::format_value(*mu) + " must be >= 0 (dimensionless: N of friction per N of load)", *mu);
    e.load = LoadDependence{*mu, *mu};
  } else if (mu_s || mu_c) {
    if (!mu_s) refuse("mu_load_static", "missing: mu_load_coulomb needs mu_load_static (or give one mu_load for both levels)");
    if (!mu_c) refuse("mu_load_coulomb", "missing: mu_load_static needs mu_load_coulomb (or give one mu_load for both levels)");
    e.load = LoadDependence{*mu_s, *mu_c};
  }
  const auto T_ref = take("T_ref"), Fc_K = take("Fc_per_K"), Fv_K = take("Fv_per_K"), T_min = take("T_min"), T_max = take("T_max");
  if (Fc_K || Fv_K || T_min || T_max || T_ref) {
    if (!T_ref) refuse("T_ref", "missing: the temperature at which the law's Fc and Fv hold (degC or K) is needed with Fc_per_K, Fv_per_K, T_min, T_max");
    if (!Fc_K && !Fv_K) refuse("Fv_per_K", "missing: T_ref needs Fv_per_K or Fc_per_K (the slopes per K)");
    TemperatureDependence t;
    t.T_ref = *T_ref;
    t.Fc_per_K = Fc_K.value_or(0.0);
    t.Fv_per_K = Fv_K.value_or(0.0);
    t.T_min = T_min;
    t.T_max = T_max;
    e.temperature = t;
  }
  const auto P = take("ripple_period");
  auto a = take_list("ripple_a"), b = take_list("ripple_b");
  auto tq = take_list("ripple_position"), tf = take_list("ripple_force");
  if (P || a || b || tq || tf) {
    if (!P)
      refuse("ripple_period", "missing: the ripple's period P (m or rad) is needed with ripple_a, ripple_b (or "
                              "ripple_position, ripple_force)");
    if ((tq || tf) && !(tq && tf))
      refuse(tq ? "ripple_force" : "ripple_position",
             std::string("missing: a ripple table needs both ripple_position (m or rad) and ripple_force (N or N m); ") +
                 (tq ? "ripple_position" : "ripple_force") + " was given alone");
    PositionRipple r;
    r.period = *P;
    r.a = a.value_or(std::vector<double>{});
    r.b = b.value_or(std::vector<double>{});
    r.table_position = tq.value_or(std::vector<double>{});
    r.table_force = tf.value_or(std::vector<double>{});
    e.ripple = std::move(r);
  }
  return e;
}

void put_effects(const LawEffects& e, LawSpec& spec) {
  if (e.load) {
    if (e.load->mu_static == e.load->mu_coulomb) {
      spec.scalars["mu_load"] = e.load->mu_static;
    } else {
      spec.scalars["mu_load_static"] = e.load->mu_static;
      spec.scalars["mu_load_coulomb"] = e.load->mu_coulomb;
    }
  }
  if (const auto& t = e.temperature) {
    spec.scalars["T_ref"] = t->T_ref;
    spec.scalars["Fc_per_K"] = t->Fc_per_K;
    spec.scalars["Fv_per_K"] = t->Fv_per_K;
    if (t->T_min) spec.scalars["T_min"] = *t->T_min;
    if (t->T_max) spec.scalars["T_max"] = *t->T_max;
  }
  if (const auto& r = e.ripple) {
    spec.scalars["ripple_period"] = r->period;
    if (!r->a.empty()) spec.arrays["ripple_a"] = r->a;
    if (!r->b.empty()) spec.arrays["ripple_b"] = r->b;
    if (r->is_table()) {
      spec.arrays["ripple_position"] = r->table_position;
      spec.arrays["ripple_force"] = r->table_force;
    }
  }
}
}  // namespace

FrictionLaw FrictionLaw::from_spec(const LawSpec& spec) {
  LawSpec plain = spec;
  const LawEffects effects = take_effects(plain);
  FrictionLaw law = from_name<Variant>(plain, std::make_index_sequence<std::variant_size_v<Variant>>());
  if (effects.empty()) return law;
  try {
    return law.with_effects(effects);
  } catch (const InputError& e) {
    // "stribeck: mu_load: ..." as the law's own messages read
    throw InputError(e.code(), law.name() + ": " + e.what(), e.fields());
  }
}

FrictionLaw FrictionLaw::with_effects(LawEffects effects) const {
  std::visit([&](const auto& law) { check_effects(law, effects, law_name<std::decay_t<decltype(law)>>()); }, law_);
  FrictionLaw out = *this;
  out.effects_ = std::move(effects);
  return out;
}

FrictionLaw FrictionLaw::without_effects() const {
  FrictionLaw out = *this;
  out.effects_ = LawEffects{};
  return out;
}

double FrictionLaw::sliding(double v, const Conditions& c) const {
  if (!effects_.moves_levels()) return sliding(v);
  return std::visit([&](const auto& plain) { return steady_sliding(at_conditions(plain, effects_, c), v); }, law_);
}

namespace {
// A static law's breakaway level (`level`: its breakaway_positive or breakaway_negative) with its
// levels moved to the conditions; 0 for a dynamic law, whose bristles hold no level.
template <class Level>
double breakaway_at(const FrictionLaw::Variant& law, const LawEffects& effects, const Conditions& c, Level level) {
  return std::visit(
      [&](const auto& plain) -> double {
        using Law = std::decay_t<decltype(plain)>;
        if constexpr (kIsDynamic<Law>) return 0.0;
        else return level(at_conditions(plain, effects, c));
      },
      law);
}
}  // namespace

double FrictionLaw::breakaway_positive(const Conditions& c) const {
  if (!effects_.moves_levels()) return breakaway_positive();
  return breakaway_at(law_, effects_, c, [](const auto& law) { return law.breakaway_positive(); });
}

double FrictionLaw::breakaway_negative(const Conditions& c) const {
  if (!effects_.moves_levels()) return breakaway_negative();
  return breakaway_at(law_, effects_, c, [](const auto& law) { return law.breakaway_negative(); });
}

const std::vector<std::string>& FrictionLaw::names() {
  static const std::vector<std::string> list = all_names<Variant>(std::make_index_sequence<std::variant_size_v<Variant>>());
  return list;
}

LawSpec FrictionLaw::to_spec() const {
  LawSpec spec;
  spec.name = name();
  for (const auto& p : parameters()) spec.scalars[p.name] = p.value;
  put_effects(effects_, spec);
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, Table>) {
          spec.arrays["velocity"] = law.velocity();
          spec.arrays["force"] = law.force();
        } else if constexpr (std::is_same_v<Law, Gms>) {
          spec.arrays["k"] = law.k;
          spec.arrays["alpha"] = law.alpha;
        } else if constexpr (std::is_same_v<Law, Smooth>) {
          spec.strings["shape"] = law.shape == SmoothShape::tanh ? "tanh" : "atan";
        }
      },
      law_);
  return spec;
}

std::string FrictionLaw::name() const {
  return std::visit([](const auto& law) { return law_name<std::decay_t<decltype(law)>>(); }, law_);
}

bool FrictionLaw::is_dynamic() const {
  return std::visit([](const auto& law) { return kIsDynamic<std::decay_t<decltype(law)>>; }, law_);
}

int FrictionLaw::num_states() const {
  return std::visit(
      [](const auto& law) -> int {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          return law.num_states();
        } else {
          return 0;
        }
      },
      law_);
}

std::vector<Parameter> FrictionLaw::parameters() const {
  std::vector<Parameter> out;
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (!std::is_same_v<Law, Table>) {
          Law::visit(law, [&](const std::string& n, Quantity q, const double& x) { out.push_back({n, x, q}); });
        }
      },
      law_);
  return out;
}

void FrictionLaw::validate() const {
  std::visit(
      [](const auto& law) {
        law.validate();
        // A bristle law (lugre, dahl, elastoplastic) relaxes at the rate sigma0 |v| / Fc toward a
        // deflection Fc / sigma0: with sigma0 / Fc beyond 1e150 (1/m or 1/rad) the deflection is
        // below 1e-150 and the rate overflows a double at a finite speed (a LuGre law with sigma0
        // 1e308 gave -inf friction at 10 m/s). Real contacts are 1e2 to 1e9 per unit of Fc.
        if constexpr (requires { law.sigma0; law.Fc; }) {
          constexpr double kMaxStiffnessRatio = 1e150;
          const double ratio = law.sigma0 / law.Fc;
          if (!(ratio <= kMaxStiffnessRatio))
            throw std::invalid_argument(
                std::string(std::decay_t<decltype(law)>::kName) + ": sigma0 = " + format_number(law.sigma0) +
                " (N/m or N m/rad) is too stiff for Fc = " + format_number(law.Fc) +
                " (N or N m): sigma0 / Fc = " + format_number(ratio) +
                " exceeds 1e+150 (1/m or 1/rad), where the bristle deflection Fc / sigma0 and the rate sigma0 |v| / Fc "
                "leave the range of a double; expected the stiffness of a real contact (e.g. sigma0 = 1e5 N/m for Fc = "
                "1 N)");
        }
      },
      law_);
}

double FrictionLaw::sliding(double v) const {
  return std::visit([&](const auto& law) { return steady_sliding(law, v); }, law_);
}

double FrictionLaw::breakaway_positive() const {
  return std::visit(
      [](const auto& law) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          return 0.0;
        } else {
          return law.breakaway_positive();
        }
      },
      law_);
}

double FrictionLaw::breakaway_negative() const {
  return std::visit(
      [](const auto& law) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          return 0.0;
        } else {
          return law.breakaway_negative();
        }
      },
      law_);
}

namespace {
[[noreturn]] void wrong_kind(const FrictionLaw& law, const char* call) {
  throw std::logic_error(std::string("friction law '") + law.name() + "' is " + (law.is_dynamic() ? "dynamic" : "static") +
                         "; " + call + " is for " + (law.is_dynamic() ? "static" : "dynamic") + " laws");
}
}  // namespace

double FrictionLaw::force(double v, double applied) const {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          wrong_kind(*this, "force(v, applied)");
        } else {
          return friction_force(law, v, applied);
        }
      },
      law_);
}

void FrictionLaw::derivative(std::span<const double> z, double v, std::span<double> dz) const {
  std::visit(
      [&](const auto& law) {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          law.derivative(z, v, dz);
        } else {
          wrong_kind(*this, "derivative(z, v, dz)");
        }
      },
      law_);
}

double FrictionLaw::force(std::span<const double> z, double v) const {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          return law.force(z, v);
        } else {
          wrong_kind(*this, "force(z, v)");
        }
      },
      law_);
}

double FrictionLaw::step(std::span<double> z, double v, double dt) const {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          return law.step(z, v, dt);
        } else {
          wrong_kind(*this, "step(z, v, dt)");
        }
      },
      law_);
}

void FrictionLaw::steady_state(double v, std::span<double> z) const {
  std::visit(
      [&](const auto& law) {
        if constexpr (kIsDynamic<std::decay_t<decltype(law)>>) {
          law.steady_state(v, z);
        } else {
          wrong_kind(*this, "steady_state(v, z)");
        }
      },
      law_);
}

double FrictionLaw::force(double v, double applied, const Conditions& c) const {
  const double r = ripple(c.position);
  return std::visit(
             [&](const auto& plain) -> double {
               using Law = std::decay_t<decltype(plain)>;
               if constexpr (kIsDynamic<Law>) {
                 wrong_kind(*this, "force(v, applied, conditions)");
               } else {
                 return friction_force(at_conditions(plain, effects_, c), v, applied - r);
               }
             },
             law_) +
         r;
}

void FrictionLaw::derivative(std::span<const double> z, double v, std::span<double> dz, const Conditions& c) const {
  if (!effects_.moves_levels()) return derivative(z, v, dz);
  std::visit(
      [&](const auto& plain) {
        if constexpr (kIsDynamic<std::decay_t<decltype(plain)>>) {
          at_conditions(plain, effects_, c).derivative(z, v, dz);
        } else {
          wrong_kind(*this, "derivative(z, v, dz, conditions)");
        }
      },
      law_);
}

double FrictionLaw::force(std::span<const double> z, double v, const Conditions& c) const {
  if (!effects_.moves_levels()) return force(z, v);
  return std::visit(
      [&](const auto& plain) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(plain)>>) {
          return at_conditions(plain, effects_, c).force(z, v);
        } else {
          wrong_kind(*this, "force(z, v, conditions)");
        }
      },
      law_);
}

double FrictionLaw::step(std::span<double> z, double v, double dt, const Conditions& c) const {
  if (!effects_.moves_levels()) return step(z, v, dt);
  return std::visit(
      [&](const auto& plain) -> double {
        if constexpr (kIsDynamic<std::decay_t<decltype(plain)>>) {
          return at_conditions(plain, effects_, c).step(z, v, dt);
        } else {
          wrong_kind(*this, "step(z, v, dt, conditions)");
        }
      },
      law_);
}

}  // namespace frictionlab

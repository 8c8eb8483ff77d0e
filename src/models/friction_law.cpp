#include "frictionlab/models/friction_law.hpp"

#include <set>
#include <stdexcept>
#include <utility>

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

FrictionLaw FrictionLaw::from_spec(const LawSpec& spec) {
  return from_name<Variant>(spec, std::make_index_sequence<std::variant_size_v<Variant>>());
}

const std::vector<std::string>& FrictionLaw::names() {
  static const std::vector<std::string> list = all_names<Variant>(std::make_index_sequence<std::variant_size_v<Variant>>());
  return list;
}

LawSpec FrictionLaw::to_spec() const {
  LawSpec spec;
  spec.name = name();
  for (const auto& p : parameters()) spec.scalars[p.name] = p.value;
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
  std::visit([](const auto& law) { law.validate(); }, law_);
}

double FrictionLaw::sliding(double v) const {
  return std::visit(
      [&](const auto& law) -> double {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (kIsDynamic<Law>) {
          std::vector<double> z(static_cast<std::size_t>(law.num_states()));
          law.steady_state(v, z);
          return law.force(std::span<const double>(z), v);
        } else {
          return law.sliding(v);
        }
      },
      law_);
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

}  // namespace frictionlab

#pragma once
// A friction law chosen at run time by name (CLI, scenario files, Python): one type that
// holds any of the laws in this folder.

#include <map>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "frictionlab/models/asymmetric.hpp"
#include "frictionlab/models/coulomb.hpp"
#include "frictionlab/models/coulomb_viscous.hpp"
#include "frictionlab/models/dynamic_law.hpp"
#include "frictionlab/models/dahl.hpp"
#include "frictionlab/models/elastoplastic.hpp"
#include "frictionlab/models/gms.hpp"
#include "frictionlab/models/karnopp.hpp"
#include "frictionlab/models/law_effects.hpp"
#include "frictionlab/models/lugre.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/smooth.hpp"
#include "frictionlab/models/static_coulomb_viscous.hpp"
#include "frictionlab/models/static_law.hpp"
#include "frictionlab/models/stribeck.hpp"
#include "frictionlab/models/table.hpp"
#include "frictionlab/models/viscous.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A law as written in a file: its name and named values. Scalars are parameters (SI units);
/// arrays serve `table` (velocity, force), `gms` (k, alpha) and the ripple (ripple_a, ripple_b);
/// strings serve `smooth` (shape). The effects' keys (mu_load, mu_load_static, mu_load_coulomb,
/// T_ref, Fc_per_K, Fv_per_K, T_min, T_max, ripple_period, ripple_a, ripple_b; see
/// law_effects.hpp) may accompany any law's own parameters.
struct LawSpec {
  std::string name;
  std::map<std::string, double> scalars;
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, std::string> strings;
};

/// Any friction law of frictionlab, selected by name. Static laws answer `force(v, applied)`;
/// dynamic laws (`is_dynamic()`) answer the state-based calls. Calling a call of the other kind
/// throws std::logic_error naming the law.
class FrictionLaw {
 public:
  using Variant = std::variant<Coulomb, Viscous, CoulombViscous, StaticCoulombViscous, Stribeck, Karnopp, Table, Smooth,
                               Asymmetric<Coulomb>, Asymmetric<Viscous>, Asymmetric<CoulombViscous>,
                               Asymmetric<StaticCoulombViscous>, Asymmetric<Stribeck>, Dahl, LuGre, ElastoPlastic, Gms>;

  /// Wraps a law after validating it (throws std::invalid_argument from the law's validate()).
  template <class Law>
  FrictionLaw(Law law) : law_(std::move(law)) {  // NOLINT: implicit on purpose, any law converts
    validate();
  }
  FrictionLaw() : FrictionLaw(Coulomb{}) {}

  /// Builds a law from its file form. Throws std::invalid_argument for an unknown name (listing
  /// the valid names), an unknown parameter (listing the law's parameters), a missing required
  /// parameter (naming it), or a value that breaks the law's rules.
  static FrictionLaw from_spec(const LawSpec& spec);
  /// The file form of this law (inverse of from_spec).
  LawSpec to_spec() const;

  /// Every name from_spec accepts, in a fixed order.
  static const std::vector<std::string>& names();

  std::string name() const;
  bool is_dynamic() const;
  /// Number of internal states: 0 for static laws.
  int num_states() const;
  /// Scalar parameters in the law's order (arrays of table and gms are in to_spec()).
  /// Each with its value and quantity (std 0, unit empty: see Parameter::with_unit).
  std::vector<Parameter> parameters() const;
  void validate() const;

  // Static laws.
  /// Force for v != 0 (N or N m). For dynamic laws: the steady-state (Stribeck) force at v.
  double sliding(double v) const;
  /// The same over an array, F[i] = sliding(v[i]): v in m/s or rad/s, F in N or N m, both of one
  /// length. The law's type is resolved once per call, not per value; each value is exactly the
  /// scalar call's, on every CPU. For dynamic laws: the steady-state force at each v, as sliding(v).
  /// \throws std::invalid_argument naming both sizes when F.size() != v.size().
  void sliding(std::span<const double> v, std::span<double> F) const;
  /// Largest applied force a stuck contact holds, pushed in + / - (N or N m); 0 for dynamic laws.
  double breakaway_positive() const;
  double breakaway_negative() const;
  /// Static law force with stiction (see friction_force in static_law.hpp).
  double force(double v, double applied) const;

  // Dynamic laws (state z has num_states() entries, m or rad).
  void derivative(std::span<const double> z, double v, std::span<double> dz) const;
  double force(std::span<const double> z, double v) const;
  double step(std::span<double> z, double v, double dt) const;
  void steady_state(double v, std::span<double> z) const;

  const Variant& variant() const { return law_; }

  // Load, temperature and position effects (law_effects.hpp), composed with the velocity law.
  /// The effects this law carries (empty() for a plain velocity law).
  const LawEffects& effects() const { return effects_; }
  bool has_effects() const { return !effects_.empty(); }
  /// This law with `effects` (replacing any it had).
  /// \throws InputError (law.parameter) naming the effect's parameter when the law lacks what an
  ///         effect moves, or an effect's parameter breaks its rule (see check_effects).
  FrictionLaw with_effects(LawEffects effects) const;
  /// The velocity law alone, without effects.
  FrictionLaw without_effects() const;

  /// The conditioned calls: the law with its levels moved to `c` (load, temperature). The ripple
  /// r(c.position) is NOT included except in force(v, applied, c); add ripple(q) for the total.
  /// Without effects they equal the plain calls. \throws InputError (law.parameter) when the
  /// temperature makes a coefficient negative or leaves [T_min, T_max].
  double sliding(double v, const Conditions& c) const;
  double breakaway_positive(const Conditions& c) const;
  double breakaway_negative(const Conditions& c) const;
  /// The ripple force r(q) (N or N m) at position q (m or rad); 0 without a ripple.
  double ripple(double q) const { return effects_.ripple_force(q); }
  /// Total friction of a static law at conditions c, ripple included (N or N m): sliding(v, c) +
  /// r(q) for v != 0; at v == 0 it balances `applied` while -breakaway_negative(c) <= applied - r(q)
  /// <= breakaway_positive(c), else it is r(q) plus the level opposing the push.
  double force(double v, double applied, const Conditions& c) const;
  void derivative(std::span<const double> z, double v, std::span<double> dz, const Conditions& c) const;
  /// Dynamic law's force at conditions c, ripple not included (N or N m).
  double force(std::span<const double> z, double v, const Conditions& c) const;
  double step(std::span<double> z, double v, double dt, const Conditions& c) const;

 private:
  Variant law_;
  LawEffects effects_;
};

}  // namespace frictionlab

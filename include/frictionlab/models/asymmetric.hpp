#pragma once
// Direction-dependent friction: one parameter set for positive velocity, another for negative.
// Parameter names get the suffixes _pos and _neg (Fc_pos, Fc_neg, Fv_pos, ...).

#include <string>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Direction-asymmetric form of a symmetric static law `Law`: `pos` acts for v > 0 (and a stuck
/// contact pushed in +), `neg` for v < 0. Both are stored with positive levels.
template <class Law>
struct Asymmetric {
  Law pos{};
  Law neg{};

  static std::string name() { return std::string(Law::kName) + "-asymmetric"; }

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    Law::visit(self.pos, [&](std::string_view n, Quantity q, auto& x) { visit(std::string(n) + "_pos", q, x); });
    Law::visit(self.neg, [&](std::string_view n, Quantity q, auto& x) { visit(std::string(n) + "_neg", q, x); });
  }

  /// Throws std::invalid_argument naming the law, the direction-suffixed parameter and its rule.
  void validate() const {
    validate_side(pos, "_pos");
    validate_side(neg, "_neg");
  }

  template <class T>
  T sliding(const T& v) const {
    return value_of(v) >= 0.0 ? pos.sliding(v) : neg.sliding(v);
  }
  auto breakaway_positive() const { return pos.breakaway_positive(); }
  auto breakaway_negative() const { return neg.breakaway_negative(); }

 private:
  static void validate_side(const Law& side, std::string_view suffix) {
    try {
      side.validate();
    } catch (const std::invalid_argument& e) {
      // "stribeck: Fs = 0.5 must be >= Fc = 1 ..." -> "stribeck-asymmetric: Fs_pos = 0.5 must be >= Fc_pos = 1 ..."
      std::string msg = e.what();
      const std::string head = std::string(Law::kName) + ": ";
      std::string rest = msg.substr(head.size());
      const auto eq = rest.find(" = ");
      std::string rule = rest.substr(eq);
      // A rule that refers to another parameter of the same side names it with the suffix too.
      if (const auto ref = rule.find(" Fc = "); ref != std::string::npos) rule.insert(ref + 3, suffix);
      throw std::invalid_argument(name() + ": " + rest.substr(0, eq) + std::string(suffix) + rule);
    }
  }
};

}  // namespace frictionlab

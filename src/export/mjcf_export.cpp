// The MJCF model of an axis: see include/frictionlab/export/mjcf_export.hpp.
#include "frictionlab/export/mjcf_export.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

// MuJoCo's defaults for a joint's friction-loss constraint (MJCF reference, joint:
// solreffriction "0.02 1", solimpfriction "0.9 0.95 0.001 0.5 2"), written out so the file says
// what MuJoCo uses. The creep measured in docs/export.md is for these values.
constexpr const char* kSolrefFriction = "0.02 1";
constexpr const char* kSolimpFriction = "0.9 0.95 0.001 0.5 2";
// The slide body's shape for its rotational inertia (which a slide joint never moves): a cube of
// this edge (m), also drawn as its box.
constexpr double kCubeEdge = 0.1;

// A number in the file: the shortest text that reads back to the same double.
std::string num(double x) { return format_exact(x); }

// The same number for people (messages, comments).
std::string show(double x) { return format_number(x, 10); }

std::string strip_direction(const std::string& name) {
  for (const char* suffix : {"_pos", "_neg"}) {
    const std::string s = suffix;
    if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0)
      return name.substr(0, name.size() - s.size());
  }
  return name;
}

std::string reason_for(const std::string& base) {
  if (base == "Fs")
    return "static (breakaway) level above Fc: MuJoCo's frictionloss is one level for sticking and sliding, so the "
           "joint breaks away at Fc";
  if (base == "vs" || base == "delta")
    return "Stribeck curve (the fall from Fs to Fc with speed): MuJoCo's friction loss does not depend on speed";
  if (base == "sigma0" || base == "sigma1" || base == "vd" || base == "alpha" || base == "zba" || base == "C")
    return "presliding (bristle) dynamics: a MuJoCo joint has no friction state";
  if (base == "dv")
    return "Karnopp's stick band: MuJoCo's stick is its soft friction-loss constraint (solreffriction, solimpfriction)";
  if (base == "vt")
    return "smoothing of sign(v): MuJoCo regularises the friction loss by its own solver parameters instead";
  return "MJCF has no term for it";
}

// XML comments may not hold "--" (nor end in "-"): a file name could.
std::string comment_safe(std::string s) {
  for (std::size_t at = s.find("--"); at != std::string::npos; at = s.find("--", at)) s.replace(at, 2, "- -");
  return s;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("mjcf: " + what);
}

}  // namespace

std::optional<double> mjcf_coulomb_level(const FrictionLaw& law) {
  std::map<std::string, double> p;
  for (const auto& q : law.parameters()) p[q.name] = q.value;
  if (p.count("Fc")) return p["Fc"];
  if (p.count("Fc_pos") && p.count("Fc_neg")) return 0.5 * (p["Fc_pos"] + p["Fc_neg"]);
  return std::nullopt;
}

MjcfModel mjcf_model(const FrictionLaw& law, const MjcfOptions& o) {
  const std::optional<double> fc = mjcf_coulomb_level(law);
  if (!fc)
    throw std::invalid_argument("law " + law.name() +
                                " has no Coulomb level Fc (nor Fc_pos and Fc_neg): MuJoCo's frictionloss needs one");
  require(std::isfinite(o.inertia) && o.inertia > 0, "inertia = " + show(o.inertia) + " must be > 0 (kg or kg m^2)");
  require(std::isfinite(o.armature) && o.armature >= 0 && o.armature < o.inertia,
          "armature = " + show(o.armature) + " must be >= 0 and < the inertia " + show(o.inertia) + " (kg or kg m^2)");
  require(std::isfinite(o.timestep) && o.timestep > 0, "timestep = " + show(o.timestep) + " must be > 0 (s)");
  require(std::isfinite(o.offset), "offset = " + show(o.offset) + " must be finite (N or N m)");

  const bool rotary = o.axis == Axis::rotary;
  MjcfModel m;
  m.joint_type = rotary ? "hinge" : "slide";
  m.frictionloss = *fc;
  m.armature = o.armature;
  m.body_inertia = o.inertia - o.armature;

  // Which parameters the file carries: Fc, and one viscous coefficient (Fv or sigma2), each
  // direction-dependent pair as its mean (the pair is listed when its two values differ).
  const std::vector<Parameter> params = law.parameters();
  std::map<std::string, double> value;
  for (const auto& q : params) value[q.name] = q.value;
  const char* viscous = value.count("Fv") || value.count("Fv_pos") ? "Fv" : (value.count("sigma2") ? "sigma2" : nullptr);
  if (viscous) {
    const std::string v = viscous;
    m.damping = value.count(v) ? value[v] : 0.5 * (value[v + "_pos"] + value[v + "_neg"]);
  }
  for (const auto& q : params) {
    const std::string base = strip_direction(q.name);
    const bool mapped = base == "Fc" || (viscous && base == viscous);
    const std::string unit(frictionlab::unit(q.quantity, o.axis));
    if (!mapped) {
      m.left_out.push_back({q.name, q.value, unit, reason_for(base)});
    } else if (base != q.name && value[base + "_pos"] != value[base + "_neg"]) {
      m.left_out.push_back({q.name, q.value, unit,
                            "direction-dependent level: MuJoCo's " +
                                std::string(base == "Fc" ? "frictionloss" : "damping") +
                                " is one value for both directions; the file has the mean of _pos and _neg"});
    }
  }
  if (law.is_dynamic())
    m.left_out.push_back({"states", static_cast<double>(law.num_states()), "",
                          "the law's internal state (bristle deflection, m or rad): a MuJoCo joint has no friction "
                          "state, so presliding displacement and hysteresis are lost"});
  if (o.offset != 0)
    m.left_out.push_back({"offset", o.offset, std::string(frictionlab::unit(Quantity::force, o.axis)),
                          "constant force of the identified u = M a + F + offset (gravity on a vertical axis): MJCF has "
                          "no constant joint force; subtract it from the actuator's ctrl"});

  const std::string force_unit(frictionlab::unit(Quantity::force, o.axis));
  const std::string viscous_unit(frictionlab::unit(Quantity::viscous, o.axis));
  const std::string inertia_unit = rotary ? "kg m^2" : "kg";
  std::string x;
  x += "<!-- frictionlab " + comment_safe(law.name()) + " law" +
       (o.source.empty() ? std::string() : " of " + comment_safe(o.source)) + " as a MuJoCo model (MJCF), " +
       (rotary ? "rotary axis: hinge joint about z, N m, rad, kg m^2" : "linear axis: slide joint along x, N, m, kg") +
       ".\n";
  x += "     frictionloss = Fc = " + show(m.frictionloss) + " " + force_unit + "; damping = " +
       (viscous ? std::string(viscous) : std::string("0 (no viscous term)")) +
       (viscous ? " = " + show(m.damping) + " " + viscous_unit : std::string()) + ";\n";
  x += "     M = " + show(o.inertia) + " " + inertia_unit + " = body " + show(m.body_inertia) + " + armature " +
       show(m.armature) + ". Actuator \"drive\": ctrl is the force (" + force_unit + ").\n";
  x += "     MuJoCo's friction loss is a soft constraint (solreffriction, solimpfriction): below Fc the joint\n"
       "     creeps slowly instead of staying at rest (frictionlab docs/export.md gives the measured creep). -->\n";
  if (!m.left_out.empty()) {
    x += "<!-- Left out (MuJoCo cannot express them):\n";
    std::string lines = mjcf_left_out_text(m.left_out);
    std::size_t start = 0;
    while (start < lines.size()) {
      const std::size_t end = lines.find('\n', start);
      x += "     " + comment_safe(lines.substr(start, end - start)) + "\n";
      start = end == std::string::npos ? lines.size() : end + 1;
    }
    x += "-->\n";
  }
  x += "<mujoco model=\"frictionlab\">\n";
  x += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  x += "  <option timestep=\"" + num(o.timestep) + "\" integrator=\"Euler\" gravity=\"0 0 0\"/>\n";
  x += "  <worldbody>\n";
  x += "    <body name=\"axis\" pos=\"0 0 0\">\n";
  x += "      <joint name=\"axis\" type=\"" + m.joint_type + "\" axis=\"" + (rotary ? "0 0 1" : "1 0 0") +
       "\" frictionloss=\"" + num(m.frictionloss) + "\" damping=\"" + num(m.damping) + "\" armature=\"" +
       num(m.armature) + "\"\n             solreffriction=\"" + kSolrefFriction + "\" solimpfriction=\"" +
       kSolimpFriction + "\"/>\n";
  if (rotary) {
    // Mass on the axis: it does not act on the hinge, but MuJoCo needs one > 0.
    const std::string i = num(m.body_inertia);
    x += "      <inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"" + i + " " + i + " " + i + "\"/>\n";
    x += "      <geom type=\"cylinder\" size=\"0.05 0.01\" contype=\"0\" conaffinity=\"0\"/>\n";
  } else {
    const std::string i = num(m.body_inertia * kCubeEdge * kCubeEdge / 6.0);  // a cube: m a^2 / 6
    x += "      <inertial pos=\"0 0 0\" mass=\"" + num(m.body_inertia) + "\" diaginertia=\"" + i + " " + i + " " + i +
         "\"/>\n";
    x += "      <geom type=\"box\" size=\"" + num(kCubeEdge / 2) + " " + num(kCubeEdge / 2) + " " + num(kCubeEdge / 2) +
         "\" contype=\"0\" conaffinity=\"0\"/>\n";
  }
  x += "    </body>\n";
  x += "  </worldbody>\n";
  x += "  <actuator>\n";
  x += "    <motor name=\"drive\" joint=\"axis\" gear=\"1\"/>\n";
  x += "  </actuator>\n";
  x += "</mujoco>\n";
  m.xml = std::move(x);
  return m;
}

std::string mjcf_left_out_text(const std::vector<MjcfLeftOut>& left_out) {
  std::string s;
  for (const auto& l : left_out)
    s += l.name + " = " + show(l.value) + (l.unit.empty() ? "" : " " + l.unit) + ": " + l.reason + "\n";
  return s;
}

}  // namespace frictionlab

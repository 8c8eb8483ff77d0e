#pragma once
// A model for MuJoCo: the identified axis as one MJCF file (MuJoCo's XML model format) that
// MuJoCo loads as it is. Pure text: the library does not link MuJoCo.
//
// What the file holds (SI units; N, m, kg on a linear axis; N m, rad, kg m^2 on a rotary one):
//   <option timestep=... integrator="Euler" gravity="0 0 0"/>   MuJoCo's defaults, written out
//   one body on one joint: a slide joint along x (linear axis) or a hinge about z (rotary axis),
//     frictionloss = Fc                     the Coulomb level (N or N m)
//     damping      = Fv                     the viscous coefficient (N s/m or N m s/rad; 0 if none)
//     armature     = options.armature       the part of M the joint carries (kg or kg m^2)
//     solreffriction, solimpfriction        MuJoCo's defaults for the friction-loss constraint
//   the body's <inertial>: slide: mass = M - armature (kg), the rotational inertia of a 0.1 m
//     cube of that mass; hinge: inertia about z = M - armature (kg m^2), mass 1 kg on the axis
//     (MuJoCo refuses a moving body without mass; on the axis it does not act)
//   a motor actuator "drive" on the joint, gear 1: ctrl is the force (N) or torque (N m)
//   the terms MuJoCo cannot express, in an XML comment (and in MjcfModel::left_out)
//
// The mapping of a law's parameters:
//   Fc (or the mean of Fc_pos and Fc_neg)          -> frictionloss
//   Fv, LuGre's and GMS's sigma2 (or the mean of _pos and _neg) -> damping
//   everything else (Fs, vs, delta, the bristle parameters sigma0, sigma1, the laws' internal
//   states, Karnopp's band dv, a direction-dependent level's asymmetry, a model's offset) is
//   left out and listed.
// MuJoCo's friction loss is a soft constraint: below Fc the joint does not stay exactly at rest
// as the library's engine keeps it, it creeps (docs/export.md gives the measured creep).

#include <optional>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of mjcf_model.
struct MjcfOptions {
  /// The axis: linear gives a slide joint (N, m, kg), rotary a hinge joint (N m, rad, kg m^2).
  /// Default linear.
  Axis axis = Axis::linear;
  /// The axis' identified inertia M (kg or kg m^2), > 0: the body's mass (slide) or its inertia
  /// about the hinge's axis, together with `armature`. Required (no default: a MuJoCo body
  /// without mass cannot move, and a made-up mass would make a wrong model).
  double inertia = 0.0;
  /// The part of `inertia` the joint carries as MuJoCo's armature (kg or kg m^2, 0 <= armature
  /// < inertia): a motor's reflected rotor inertia. The body keeps inertia - armature, so the
  /// axis' total inertia stays M. Default 0.
  double armature = 0.0;
  /// MuJoCo's time step (s), > 0, written into <option>. Default 0.002 (MuJoCo's own default).
  double timestep = 0.002;
  /// The model's constant force offset (N or N m; MODEL.json parameters.offset, the identified
  /// u = M a + F + offset): MJCF has no term for it, so a nonzero offset is listed as left out.
  /// Default 0.
  double offset = 0.0;
  /// Where the model came from (a MODEL.json file name), quoted in the file's first comment. Optional.
  std::string source;
};

/// One term of the model that the MJCF file does not carry.
struct MjcfLeftOut {
  /// The parameter's name ("Fs", "vs", "Fc_pos", "offset"), or "states" for a dynamic law's
  /// internal states.
  std::string name;
  /// Its value in SI units (the number of states for "states").
  double value = 0.0;
  /// Its unit on the axis ("N", "m/s", "N m", ...); empty for a dimensionless value or a count.
  std::string unit;
  /// Why MuJoCo cannot express it, in one sentence.
  std::string reason;
};

/// The MJCF file and what it maps.
struct MjcfModel {
  /// The whole MJCF text (UTF-8, ASCII in practice), ready to write to a file.
  std::string xml;
  /// "slide" or "hinge".
  std::string joint_type;
  /// frictionloss = the Coulomb level (N or N m).
  double frictionloss = 0.0;
  /// damping = the viscous coefficient (N s/m or N m s/rad).
  double damping = 0.0;
  /// The body's mass (kg; slide) or inertia about the hinge axis (kg m^2; hinge): inertia - armature.
  double body_inertia = 0.0;
  /// The joint's armature (kg or kg m^2).
  double armature = 0.0;
  /// The terms MuJoCo cannot express, in the law's parameter order, the offset last.
  std::vector<MjcfLeftOut> left_out;
};

/// The Coulomb level MJCF's frictionloss takes from `law` (N or N m): its Fc, or the mean of
/// Fc_pos and Fc_neg for a direction-dependent law; nullopt for a law without one (viscous, table).
std::optional<double> mjcf_coulomb_level(const FrictionLaw& law);

/// The MJCF model of an axis with friction `law` (see the top of this file).
/// \throws std::invalid_argument naming the value and its rule: a law without a Coulomb level
///         ("law viscous has no Coulomb level Fc ..."), inertia not > 0, armature not in
///         [0, inertia), timestep not > 0, an offset that is not finite.
MjcfModel mjcf_model(const FrictionLaw& law, const MjcfOptions& options);

/// The left-out terms as text, one line each: "Fs = 1.5 N: REASON".
std::string mjcf_left_out_text(const std::vector<MjcfLeftOut>& left_out);

}  // namespace frictionlab

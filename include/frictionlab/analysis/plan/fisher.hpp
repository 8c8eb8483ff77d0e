#pragma once
// The a-priori (Fisher-information) standard deviation of a plan's parameters: computed from the
// noise-free simulation of the plan on the prior, without any noisy identification. The
// Jacobian J of the method's model at the noise-free fit and the stated sensor noise propagated
// to the signal the method fits give cov = (J'J)^-1 J' S J (J'J)^-1, S the covariance of that
// signal's noise; for white noise of variance sigma^2 this is sigma^2 (J'J)^-1.
//   sweep: J = d F(v_i) / d theta of the static law at the segment means v_i the method finds on
//          the clean record; S = diag((sigma_F^2 + (dF/dv)^2 sigma_v^2) / n_i), n_i the samples
//          each segment averages (white sensor noise: the means are independent).
//   idim:  J = the regressor matrix of the clean record after the method's low-pass,
//          differentiation, skip and decimation (the model is linear in its parameters); the
//          fitted signal's noise is the force noise and the position noise through
//          M qdd + Fv qd, both filtered and decimated by the same pipeline, hence correlated
//          between decimated samples: S is Toeplitz with the autocorrelation of the pipeline's
//          impulse responses at multiples of the decimation, taken by running the pipeline on
//          unit impulses. The Coulomb column sign(qd) is taken as noise-free.
// breakaway and lugre have no a-priori figure (read-offs and an output-error fit).

#include <string>
#include <vector>

#include "frictionlab/analysis/plan/design.hpp"
#include "frictionlab/simulate/trajectory.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A-priori std of a method's parameters, in the method's parameter order.
struct AprioriSpread {
  std::vector<std::string> names;
  /// Std per name, in the parameter's unit (N or N m, m/s or rad/s, ...); NaN when undetermined
  /// (the others' std is then the one with the undetermined parameters held).
  std::vector<double> std;
  /// Parameters whose information is (near) singular: a direction of the column-normalised
  /// J'J with eigenvalue below kSingularInformation times the largest that the parameter takes part in.
  std::vector<std::string> undetermined;
  /// The std the idim fit would have if the fitted signal's noise were white (the correlation
  /// of the filtered noise ignored): sigma_e^2 (J'J)^-1 with sigma_e^2 = S's diagonal; idim
  /// only (empty otherwise), for comparison.
  std::vector<double> std_white;
  /// std of the fitted signal's noise per sample (N or N m): sweep the mean over the points,
  /// idim sqrt of S's diagonal.
  double signal_noise_std = 0.0;
};

/// Relative eigenvalue of the normalised information below which a direction is singular.
inline constexpr double kSingularInformation = 1e-10;

/// The a-priori std of `method`'s parameters for `profile` on the rig, from the noise-free
/// simulation `clean` (simulate_profile on the prior) and the sensor noise. Empty (no names)
/// for breakaway and lugre, and when the clean record gives no identification.
/// \throws std::invalid_argument as the method's pipeline for a record it cannot take.
AprioriSpread a_priori_spread(PlanMethod method, const ExperimentProfile& profile, const PlanRig& rig,
                              const Trajectory& clean, const SensorNoise& noise);

}  // namespace frictionlab

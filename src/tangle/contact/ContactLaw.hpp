#pragma once
/// @file ContactLaw.hpp
/// Normal contact law between two lines: a penalty spring and a linear dashpot whose damping gives a
/// requested coefficient of restitution, with the force clipped so it never pulls the lines together.
///
/// For a contact of effective mass m, stiffness k and damping c (damping ratio zeta = c / (2 sqrt(k m))),
/// the 1-DOF impact  m x'' + c x' + k x = 0,  x(0) = 0, x'(0) = v0  separates when the force
/// k x + c x' reaches zero (not when x returns to zero: the clipped dashpot cannot pull). With
/// omega_d = omega_0 sqrt(1 - zeta^2), a = zeta / sqrt(1 - zeta^2), that happens at the phase
///     tau* = pi - atan2(2 zeta sqrt(1 - zeta^2), 1 - 2 zeta^2)
/// and the coefficient of restitution is
///     e(zeta) = exp(-a tau*) (a sin tau* - cos tau*),
/// (Schwager & Poeschel 2007, "Coefficient of restitution and linear-dashpot model revisited",
/// Granular Matter 9:465-469, eq. 16-20). Without clipping one would get e = exp(-pi a) (e.g. Tsuji et al.
/// 1992); the two agree to first order, e = 1 - pi zeta, and the clipped one is higher by 2 zeta^2 + ...
/// Critical damping (zeta = 1) gives e = exp(-2) = 0.135 and a duration 2 / omega_0. Lower restitutions
/// need zeta > 1: with s = sqrt(zeta^2 - 1) and q = (zeta - s) / (zeta + s), the force vanishes at
/// t* = -ln(q) / (omega_0 s) and e = q^(zeta / s) (same derivation, real roots). e(zeta) decreases
/// monotonically over [0, 100] from 1 to 2.5e-5 (minimumRestitution(); e = 0, plastic, is reached only
/// in the limit); it is inverted here by bisection.

#include <algorithm>

namespace tangle::contact {

/// Coefficient of restitution [-] of a clipped linear spring-dashpot impact with damping ratio zeta >= 0
/// (clamped to at most 100).
double restitutionOfDampingRatio(double zeta);

/// Damping ratio zeta [-] whose clipped spring-dashpot impact has restitution e (clamped to the range
/// the model can reach: e >= minimumRestitution()).
double dampingRatioForRestitution(double e);

/// Smallest restitution used (zeta = 100: 2.5e-5) [-].
double minimumRestitution();

/// Duration [s] of a clipped spring-dashpot impact, from the touch to the separation (tau* / omega_d below
/// critical damping).
double contactDuration(double stiffness, double mass, double zeta);

/// Normal force [N] >= 0 of the spring-dashpot at a converged state: k p + c dp/dt, clipped at 0
/// (p = penetration [m], > 0 in contact; dp/dt [m/s], > 0 while approaching).
inline double normalForce(double penetration, double penetrationRate, double stiffness, double damping) {
  if (penetration <= 0.0) return 0.0;
  const double f = stiffness * penetration + damping * penetrationRate;
  return f > 0.0 ? f : 0.0;
}

/// Regularised penalty law of the line-to-line part (force per unit length [N/m] at penetration p [m]):
/// quadratic below the regularisation depth p0, linear (slope k) beyond, C1 at p0 and zero with zero
/// slope at first touch (Meier, Wall & Popp 2017 use the same idea with the quadratic part at positive
/// gaps; here it is on the penetration side so that no force acts while the surfaces are apart):
///     f = k p^2 / (2 p0)      for 0 <= p <= p0
///     f = k (p - p0 / 2)      for p > p0
/// value() returns f, slope() df/dp.
struct RegularisedPenalty {
  double stiffness = 0.0;  ///< k [N/m per m]
  double depth = 0.0;      ///< p0 [m] (> 0)
  double value(double p) const {
    if (p <= 0.0) return 0.0;
    return p < depth ? 0.5 * stiffness * p * p / depth : stiffness * (p - 0.5 * depth);
  }
  double slope(double p) const {
    if (p <= 0.0) return 0.0;
    return p < depth ? stiffness * p / depth : stiffness;
  }
  /// Fraction of the full dashpot that acts at penetration p: ramps in linearly over p0 so the damping
  /// force starts from zero at first touch (no jump of c v0).
  double dampingFraction(double p) const { return p <= 0.0 ? 0.0 : std::min(1.0, p / depth); }
};

}  // namespace tangle::contact

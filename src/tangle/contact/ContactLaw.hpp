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
/// 1992). e(zeta) decreases monotonically; it is inverted here by bisection. The smallest e a clipped
/// linear dashpot can give with zeta < 1 is about e(0.999) ~ 0.0425 (reported by minimumRestitution()).

namespace tangle::contact {

/// Coefficient of restitution [-] of a clipped linear spring-dashpot impact with damping ratio zeta in [0, 1).
double restitutionOfDampingRatio(double zeta);

/// Damping ratio zeta [-] whose clipped spring-dashpot impact has restitution e (clamped to the range
/// the model can reach: e >= minimumRestitution()).
double dampingRatioForRestitution(double e);

/// Smallest restitution a clipped linear dashpot can produce (zeta -> 1) [-].
double minimumRestitution();

/// Duration [s] of a clipped spring-dashpot impact: tau* / omega_d.
double contactDuration(double stiffness, double mass, double zeta);

/// Normal force [N] >= 0 of the spring-dashpot at a converged state: k p + c dp/dt, clipped at 0
/// (p = penetration [m], > 0 in contact; dp/dt [m/s], > 0 while approaching).
inline double normalForce(double penetration, double penetrationRate, double stiffness, double damping) {
  if (penetration <= 0.0) return 0.0;
  const double f = stiffness * penetration + damping * penetrationRate;
  return f > 0.0 ? f : 0.0;
}

}  // namespace tangle::contact

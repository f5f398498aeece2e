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
#include <cmath>

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

/// Restitution of the distributed formulation by hysteresis: the elastic law's force f(p) is scaled by a
/// factor of the penetration rate v = dp/dt (> 0 approaching),
///     psi(v) = 1 + a tanh(v / v_s),   a = (1 - e^2) / (1 + e^2),
/// so a contact loads along (1 + a) f and unloads along (1 - a) f. An impact of a mass on any elastic law
/// f (linear, regularised, barrier) stores (1 + a) W on the way in and gives back (1 - a) W on the way
/// out, W = integral of f dp up to the deepest point: the rebound speed is e v0 exactly,
/// sqrt((1 - a) / (1 + a)) = e, whatever the law's shape, the mass or the speed (the idea of the
/// different loading and unloading branches of Walton & Braun 1986, J. Rheology 30:949-980, here with
/// the unloading branch proportional to the loading one, so that no history is kept and the surfaces part
/// where they met). Unlike a dashpot (ContactLaw's spring-dashpot, whose force at e -> 0 is c v0 at first
/// touch and grows without bound: 5.7 MN for two risers closing at 1 m/s, 24 times the elastic peak),
/// the force never exceeds (1 + a) f <= 2 f, and a linear law's peak force is sqrt(1 + a) of the elastic
/// one (sqrt 2 at e = 0): bounded and decreasing in e. At rest (v = 0) the factor is 1: a contact settles
/// at the static penetration, and small oscillations about it are damped by d psi / dv = a / v_s (a
/// damping f a / v_s). The smoothing speed v_s makes the law C-infinity in v; the energy exchanged while
/// |v| < v_s near the deepest point, a fraction of order (v_s / v0)^2 of the impact's, is not under the
/// law's control (there the rebound is not exactly e v0; an impact much slower than v_s is nearly
/// elastic, as the first-order expansion psi = 1 + a v / v_s is a Hunt-Crossley damping).
struct HystereticRestitution {
  double amplitude = 0.0;  ///< a [-] in [0, 1]
  double speed = 1.0;      ///< v_s [m/s] (> 0)
  static double amplitudeFor(double restitution) {
    const double e2 = restitution * restitution;
    return (1.0 - e2) / (1.0 + e2);
  }
  /// psi(v) [-], v = dp/dt [m/s].
  double factor(double rate) const { return 1.0 + amplitude * std::tanh(rate / speed); }
  /// d psi / dv [s/m].
  double derivative(double rate) const {
    const double c = std::cosh(rate / speed);
    return amplitude / (speed * c * c);
  }
};

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

/// Penalty law of the distributed formulation with a barrier that bounds the penetration by construction
/// (force per unit length [N/m] at penetration p [m]; DistributedContact.hpp, docs/theory.md 9.11):
///     f = k p^2 / (2 p0)                                          0 <= p <= p0   (regularised first touch)
///     f = k (p - p0 / 2)                                          p0 <= p <= p1  (linear penalty)
///     f = k (p - p0 / 2) + k D (p - p1)^2 / (pmax - p)^2          p1 <= p < pmax (barrier), D = pmax - p1
/// The barrier term and its slope vanish at p1 (the law is C1 everywhere) and it grows without bound as p
/// approaches pmax; so does its work (like k D^3 / (pmax - p)), so any finite kinetic energy is taken up
/// before the surfaces overlap by pmax (the idea of the barrier of Incremental Potential Contact, Li et al.
/// 2020, placed here on the penetration side of an ordinary penalty so that the stiffness a user chose
/// governs every contact that stays above p1). Beyond pcap = pmax - D / 20 the law continues along its
/// tangent at pcap (finite: the barrier adds 361 k D there): a Newton iterate that overshoots gets a
/// finite, large restoring force, and a converged state there is refused (beyondCap()).
struct BarrierPenalty {
  double stiffness = 0.0;     ///< k [N/m per m]
  double depth = 0.0;         ///< p0 [m] (> 0)
  double barrierStart = 0.0;  ///< p1 [m] (> p0)
  double limit = 0.0;         ///< pmax [m] (> p1)

  /// Barrier law of a pair whose penetration scale is D [m] (DistributedContact: the smaller contact
  /// diameter, contactScale): p0 = 1 %, p1 = 25 %, pmax = 50 % of D (an overlap is bounded by the smaller
  /// radius).
  static BarrierPenalty forScale(double stiffness, double scale) {
    return {stiffness, 0.01 * scale, 0.25 * scale, 0.5 * scale};
  }
  double cap() const { return limit - 0.05 * (limit - barrierStart); }
  bool beyondCap(double p) const { return p >= cap(); }
  double value(double p) const {
    if (p <= 0.0) return 0.0;
    if (p < depth) return 0.5 * stiffness * p * p / depth;
    double f = stiffness * (p - 0.5 * depth);
    if (p > barrierStart) {
      const double c = cap();
      f += p < c ? stiffness * barrier(p) : stiffness * (barrier(c) + barrierSlope(c) * (p - c));
    }
    return f;
  }
  double slope(double p) const {
    if (p <= 0.0) return 0.0;
    if (p < depth) return stiffness * p / depth;
    if (p <= barrierStart) return stiffness;
    return stiffness * (1.0 + barrierSlope(std::min(p, cap())));
  }

 private:
  /// D (p - p1)^2 / (pmax - p)^2 [m] and its derivative [-].
  double barrier(double p) const {
    const double a = p - barrierStart, b = limit - p;
    return (limit - barrierStart) * a * a / (b * b);
  }
  double barrierSlope(double p) const {
    const double a = p - barrierStart, b = limit - p;
    return (limit - barrierStart) * (2.0 * a / (b * b) + 2.0 * a * a / (b * b * b));
  }
};

}  // namespace tangle::contact

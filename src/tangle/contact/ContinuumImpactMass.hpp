#pragma once
/// @file ContinuumImpactMass.hpp
/// The mass of two lines that takes part in an impact, from the lines' continuum point impedance rather
/// than from their mesh (docs/theory.md 9.10, issue 43).
///
/// A line struck at a point answers with waves (tension and bending) that run out from it. Over an impact
/// of circular frequency w the point behaves as the driving-point impedance Z(w) = F / v of an infinite,
/// uniform, tensioned Euler-Bernoulli line (EI w'''' - T w'' + mu w_tt = F delta(x) e^{iwt}; symmetric
/// solution A e^{-i k1 |x|} + B e^{-kappa |x|}, w' = 0 and the shear jump F at x = 0):
///
///   Z(w) = 2 EI k1 (k1^2 + kappa^2) / (w (1 - i k1 / kappa)) = 2 k1 S / (w (1 - i k1 / kappa))
///   k1^2    = (-T + S) / (2 EI) = 2 mu w^2 / (T + S)   (travelling waves),   S = sqrt(T^2 + 4 EI mu w^2)
///   kappa^2 = ( T + S) / (2 EI)                         (the near field),   k1 / kappa = 2 sqrt(EI mu) w /
///   (T + S)
///
/// which stays finite for a cable: EI = 0 gives the taut string's Z = 2 sqrt(T mu), T = 0 the beam's
/// 2 EI k^3 (1 + i) / w (e.g. Cremer, Heckl & Petersson, Structure-Borne Sound, 3rd ed., 2005, ch. 5).
/// The mass that takes part at that frequency is m = |Z(w)| / w (exact for a rigid body, Z = i w m): for a
/// string the mass within c / w of the point on either side, for a beam within 1.41 / k. The pair's
/// reduced mass m_pair(w) then meets the contact law as a two-body impact: the approach's kinetic energy
/// 1/2 m_pair v0^2 is taken up at the deepest penetration p*, and the frequency is the law's secant there,
/// w^2 = F(p*) / (m_pair p*) (sqrt(k / m) for a linear law); the three are solved as a fixed point. For a
/// taut string struck through a linear contact by a body much heavier than it this gives m = Z^2 / k: the
/// string's point is a dashpot, the approach stops when F = Z v0, and the spring then holds
/// F^2 / (2 k) = 1/2 (Z^2 / k) v0^2, exactly.
///
/// Where it holds (checked by the caller, LineContact): the contact is a point (its patch much shorter
/// than the participating lengths m / mu), the waves do not reach an end, a support, a lump or a change of
/// section within the impact (pi / w at the group speed), and both lines carry tension or bending (a slack
/// cable has Z = 0: its impact is a stream of small ones, each point's own mass, and none is estimated).

#include <complex>
#include <functional>

namespace tangle::contact {

/// A line's section at the struck point, as its waves see it.
struct LineAtPoint {
  double tension = 0.0;           ///< effective tension [N] (compression < 0)
  double massPerLength = 0.0;     ///< structural + contents + normal added mass [kg/m]
  double bendingStiffness = 0.0;  ///< EI [N m^2]
  bool held = false;              ///< the point cannot move (a support): infinite impedance
};

/// Driving-point impedance of the infinite line at circular frequency omega [rad/s]: F / v [N s/m]
/// (0 for a slack cable; a held point's is infinite: see participatingMass).
std::complex<double> pointImpedance(const LineAtPoint& line, double omega);

/// |Z(omega)| / omega [kg]: +inf for a held point, 0 for a slack cable.
double participatingMass(const LineAtPoint& line, double omega);

/// Group speed d omega / d k of the line's travelling waves at omega [m/s]: sqrt(T / mu) for a string,
/// 2 omega / k for a beam (0 for a slack cable).
double groupSpeed(const LineAtPoint& line, double omega);

/// Normal force of a contact while it loads [N] at penetration p [m] (monotonic, 0 at 0).
using PenetrationForce = std::function<double(double)>;

/// Force [N] of a crossing at penetration p [m] whose law gives `perLength(q)` [N/m] at the local
/// penetration q [m], integrated along the crossing: two straight lines at angle theta (sine > 0) whose
/// surfaces (sum of radii `radii` [m]) overlap by p at the closest points overlap by p - u^2 sine^2 /
/// (2 radii) at u [m] along either line (the parabolic gap of DistributedContact.hpp), so
/// F = (2 / sine) integral_0^sqrt(2 radii p) perLength(p - w^2 / (2 radii)) dw (Simpson, 48 intervals).
double crossingForce(const std::function<double(double)>& perLength, double radii, double sine, double p);

/// Work [J] of a crossing's force from first touch to penetration p [m] (the integral of crossingForce)
/// when the law per length is the regularised penalty f = k q^2 / (2 p0) below p0 and k (q - p0 / 2)
/// beyond (BarrierPenalty's barrier left out: it only adds work past p1 = 25 p0). With q = p - w^2 / (2 R)
/// along the crossing, F(p) = (sqrt(2 R) / sine) integral_0^p f(q) / sqrt(p - q) dq, and exchanging the
/// order of the two integrals W(p) = (2 sqrt(2 R) / sine) integral_0^p f(q) sqrt(p - q) dq, which is closed:
/// (16 / 105) (k / sine) sqrt(2 R) p^(7/2) / p0 below p0. stiffness k [N/m per m], depth p0 [m], radii R
/// [m], sine > 0.
double regularisedCrossingWork(double stiffness, double depth, double radii, double sine, double p);

/// The impact of two lines solved for its frequency (see the file comment).
struct ContinuumImpact {
  bool defined = false;      ///< false: a slack line (Z = 0), both held, or no approach
  double omega = 0.0;        ///< [rad/s]
  double duration = 0.0;     ///< pi / omega, the contact's half period [s]
  double massA = 0.0;        ///< participating mass of line A [kg] (+inf if held)
  double massB = 0.0;        ///< [kg]
  double pairMass = 0.0;     ///< massA massB / (massA + massB) [kg]
  double lengthA = 0.0;      ///< massA / mu_A, the length of line A whose mass takes part [m]
  double lengthB = 0.0;      ///< [m]
  double penetration = 0.0;  ///< deepest penetration p* [m]
  double peakForce = 0.0;    ///< F(p*) [N]
  double energy = 0.0;       ///< 1/2 pairMass v0^2 [J]
};

/// Solves the impact of lines `a` and `b` approaching at `approachSpeed` [m/s] through a contact whose
/// loading force is `force` (see the file comment).
ContinuumImpact continuumImpact(const LineAtPoint& a, const LineAtPoint& b, const PenetrationForce& force,
                                double approachSpeed);

}  // namespace tangle::contact

#pragma once
/// @file WakeModel.hpp
/// Mean velocity deficit (and lift) in the wake of a cylinder, seen by a second cylinder downstream:
/// the two models riser analysts use for wake interference (DNV-RP-F203 2009, sec. 3; docs/theory.md
/// sec. 12). Both work in the plane normal to the upstream cylinder, with x [m] the distance downstream
/// along the flow and y [m] the transverse distance, both measured between the cylinder centres, and
/// U [m/s] the incident flow speed normal to the upstream cylinder.
///
/// Huse (1993, "Interaction in deep-sea riser arrays", OTC 7237), with the coefficients as the Flexcom
/// theory manual restates them (k1 = 0.25, k2 = 1.0, k3 = 0.693 = ln 2):
///   deficit      u(x, y) = k2 U sqrt(Cd D / xs) exp(-k3 (y / b)^2)
///   half-width   b       = k1 sqrt(Cd D xs)                 (u = u_centre / 2 at |y| = b when k3 = ln 2)
///   virtual source xs    = x + D / (4 k1^2 Cd)              (b = D / 2 at the upstream centre, x = 0)
/// with Cd, D the upstream drag coefficient and diameter. No lift.
///
/// Blevins (2005, "Forces on and stability of a cylinder in a wake", J. OMAE 127:39-45), a Gaussian fit
/// of the far wake plus the quasi-steady lift that the transverse velocity gradient produces:
///   deficit      u(x, y) = a1 U sqrt(Cd D / x) exp(-a2 y^2 / (Cd D x))
///   lift coeff.  CL(x, y) = a3 (u / U) y D_d / (Cd D x)     (on the downstream diameter D_d)
///   lift per length  q_L = 1/2 rho CL D_d U^2, along +y (a3 < 0: towards the wake centre line)
/// with defaults a1 = 1.0, a2 = 4.5, a3 = -10.6 (the Flexcom defaults). The lift is the quasi-steady
/// one of a cylinder in a transverse velocity gradient, CL = -c D_d [d/dy (1 - u/U)^2] / (1 - u/U), which
/// for the Gaussian profile is exactly the form above with a3 = -4 c a2 (c = 0.589 for the defaults);
/// see docs/theory.md 12.1 for this form and what is uncertain about it.
///
/// Range of validity: both are far-wake fits; Huse's virtual source keeps the deficit finite up to the
/// upstream centre, Blevins's form is singular there and is evaluated no closer than x = 2 D (the
/// nearest separation of its data). Both cap the deficit at U (no reversed flow). x <= 0 (upstream or
/// level with the upstream centre) gives no wake.

namespace tangle::hydro {

/// Which wake model.
enum class WakeKind { Huse, Blevins };

/// Coefficients of a wake model (defaults as in the file comment).
struct WakeCoefficients {
  WakeKind kind = WakeKind::Huse;
  double k1 = 0.25;   ///< Huse: wake half-width factor [-]
  double k2 = 1.0;    ///< Huse: centre-line deficit factor [-]
  double k3 = 0.693;  ///< Huse: Gaussian profile factor [-] (ln 2: b is the half-value width)
  double a1 = 1.0;    ///< Blevins: centre-line deficit factor [-]
  double a2 = 4.5;    ///< Blevins: Gaussian profile factor [-]
  double a3 = -10.6;  ///< Blevins: lift factor [-] (negative: towards the wake centre)
};

/// The wake at one downstream point.
struct WakeValue {
  double deficit = 0.0;          ///< u / U [-], in [0, 1]
  double liftCoefficient = 0.0;  ///< CL [-] on the downstream diameter, along +y (0 for Huse)
  double halfWidth = 0.0;        ///< b [m]: Huse's half-value width; Blevins: sqrt(ln 2 Cd D x / a2)
};

/// The wake of an upstream cylinder (drag coefficient cd [-], diameter diameter [m]) at (x, y) [m]
/// (formulas in the file comment), seen by a downstream cylinder of diameter downstreamDiameter [m]
/// (Blevins's lift only). Zero wake for x <= 0, cd <= 0 or diameter <= 0.
WakeValue wakeAt(const WakeCoefficients& c, double x, double y, double cd, double diameter,
                 double downstreamDiameter);

}  // namespace tangle::hydro

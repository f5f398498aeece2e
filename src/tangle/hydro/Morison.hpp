#pragma once
/// @file Morison.hpp
/// Hydrodynamic loads on one straight line element from the relative-velocity Morison equation
/// (Morison, O'Brien, Johnson & Schaaf 1950, "The force exerted by surface waves on piles", Petroleum
/// Transactions AIME 189:149-154; DNV-RP-C205 2010, sec. 6.2-6.3), split into normal and axial parts
/// relative to the element tangent (slender-body "independence principle", as in OrcaFlex).
///
/// Per unit length, with t the unit tangent, u and a_f the fluid velocity and acceleration, v the
/// structure velocity, v_r = u - v, and (.)_a = t t^T (.), (.)_n = (I - t t^T)(.):
///   drag, normal:  q_dn = 1/2 rho Cdn D |v_rn| v_rn
///   drag, axial:   q_da = 1/2 rho Cda (pi D) |v_ra| v_ra          (OrcaFlex axial-drag convention:
///                  Cda refers to the wetted perimeter pi D, not to the projected width D)
///   fluid inertia: q_i  = rho A_b a_f + rho A (Can a_fn + Caa a_fa)
///                  (Froude-Krylov on the displaced area in every direction, plus the added-mass part
///                  of the fluid acceleration; i.e. rho A_b (1 + Can) a_fn + rho A_b (1 + Caa) a_fa when
///                  A_b = A)
///   added mass:    m_a  = rho A (Can (I - t t^T) + Caa t t^T)     (multiplies the structure acceleration)
/// with D = LineType::outerDiameter (hydrodynamic diameter), A = pi D^2 / 4, A_b =
/// LineType::displacedAreaPerLength() (buoyancyDiameter; A when buoyancyDiameter <= 0). Buoyancy
/// (hydrostatic) and weight are NOT included here.

#include <algorithm>
#include <cmath>

#include "tangle/core/Types.hpp"
#include "tangle/hydro/WaveField.hpp"
#include "tangle/section/LineType.hpp"

namespace tangle::hydro {

/// Added mass of a node of a straight element [kg]: m_n (I - t t^T) + m_a t t^T, kept as the tangent and
/// the two masses (applying it to an acceleration costs a dot product; the 3x3 matrix is built only for
/// assemblies that need it).
struct AddedMass {
  Vec3 tangent = Vec3::UnitX();  ///< unit tangent t of the element [-]
  double normal = 0.0;           ///< m_n, added mass normal to t [kg]
  double axial = 0.0;            ///< m_a, added mass along t [kg]
  /// The force m a [N] of an acceleration a [m/s^2].
  Vec3 operator*(const Vec3& a) const { return normal * a + ((axial - normal) * tangent.dot(a)) * tangent; }
  /// The matrix m_n I + (m_a - m_n) t t^T [kg].
  Mat3 matrix() const { return normal * Mat3::Identity() + (axial - normal) * (tangent * tangent.transpose()); }
};

/// Morison loads of one element, lumped on its two nodes.
/// The total hydrodynamic force on node i is force_i - addedMassPerNode * (acceleration of node i).
struct MorisonElementLoad {
  Vec3 force1 = Vec3::Zero();  ///< drag + fluid inertia on node 1 [N] (without the added-mass term)
  Vec3 force2 = Vec3::Zero();  ///< drag + fluid inertia on node 2 [N] (without the added-mass term)
  /// Drag linearisation of node 1, C_1 = -d(force1)/d(v1) [N s/m], symmetric positive semi-definite.
  /// force1 does not depend on v2 and force2 not on v1 (nodal lumping, see morisonElementLoad).
  Mat3 damping1 = Mat3::Zero();
  Mat3 damping2 = Mat3::Zero();  ///< C_2 = -d(force2)/d(v2) [N s/m], symmetric positive semi-definite
  /// Drag's dependence on the node positions through the element direction and length [N/m]:
  /// G_1 = d(force1)/d(x2) = -d(force1)/d(x1) (force1 depends on x1, x2 only through d = x2 - x1), with the
  /// fluid velocity and the submerged fraction held. Not symmetric (a follower load: the normal drag turns
  /// with the element). Filled only when asked for (statics, see morisonElementLoad).
  Mat3 positionJacobian1 = Mat3::Zero();
  Mat3 positionJacobian2 = Mat3::Zero();  ///< G_2 = d(force2)/d(x2) = -d(force2)/d(x1) [N/m]
  /// Added mass of each node (the same for both) [kg]: f L/2 rho A (Can (I - t t^T) + Caa t t^T).
  AddedMass addedMassPerNode;
};

/// Morison loads on the element x1-x2 (formulas in the file comment), lumped per node: node i receives
/// the load of half the wetted length, f L / 2, evaluated with the element tangent t, the fluid
/// kinematics given (one point per element) and the node's own velocity v_i. Hence
///   force_i = f L/2 [q_dn(u - v_i) + q_da(u - v_i) + q_i],  C_i = f L/2 d(q_dn + q_da)/d(v_r) at u - v_i,
/// which is the exact derivative of force_i with respect to v_i (d force_i / d v_j = 0 for j != i).
/// With wantPositionJacobian, the drag's derivatives with respect to the node positions through t and L
/// (fluid velocity and submerged fraction held): with d = x2 - x1, w = u - v_i, s = t.w, w_n = w - s t,
/// P = I - t t^T and L q_d = L kn |w_n| w_n + L ka |s| s t,
///   d(L q_dn)/dd = kn (|w_n| w_n t^T - J_n (t w^T + s I) P),  J_n = |w_n| I + w_n w_n^T / |w_n|
///   d(L q_da)/dd = ka (|s| s t t^T + 2 |s| t w^T P + |s| s P)
/// (from dt/dd = P / L, dL/dd = t^T), G_i = f/2 (sum). The fluid inertia's is not included (it vanishes
/// in statics, where this is used).
/// @param x1,x2 node positions [m], distinct
/// @param v1,v2 node velocities [m/s]
/// @param fluid total fluid kinematics (current + waves) for the element, usually at its midpoint, or
///        at the centroid of its wetted part when partly submerged [m/s], [m/s^2]
/// @param type line type (outerDiameter, buoyancyDiameter, dragNormal, dragAxial, addedMassNormal,
///        addedMassAxial are used)
/// @param rho fluid density [kg/m^3], >= 0
/// @param wettedFraction submerged fraction f of the element length in [0, 1] (see submergedFraction);
///        every load, damping and added mass is proportional to it
/// @param wantDamping compute damping1 / damping2 (left zero otherwise: an assembly without a matrix
///        needs the forces alone)
/// @param wantPositionJacobian compute positionJacobian1 / positionJacobian2
/// @throws tangle::Error for coincident nodes, f outside [0, 1], rho < 0 or negative diameters
MorisonElementLoad morisonElementLoad(const Vec3& x1, const Vec3& x2, const Vec3& v1, const Vec3& v2,
                                      const FluidKinematics& fluid, const section::LineType& type, double rho,
                                      double wettedFraction, bool wantDamping = true,
                                      bool wantPositionJacobian = false);

/// The per-unit-length coefficients of one line type in one fluid (formulas in the file comment), validated
/// once so that the per-element evaluation in the assembly loop checks nothing but its own geometry
/// (issue 8: the argument checks of every call were part of the Morison cost).
struct MorisonCoefficients {
  double normalDrag = 0.0;     ///< kn = 1/2 rho Cdn D [kg/m^2]
  double axialDrag = 0.0;      ///< ka = 1/2 rho Cda pi D [kg/m^2]
  double normalMass = 0.0;     ///< rho A Can [kg/m]
  double axialMass = 0.0;      ///< rho A Caa [kg/m]
  double displacedMass = 0.0;  ///< rho A_b [kg/m] (Froude-Krylov)
  bool wet = false;            ///< rho > 0 (a dry fluid gives no load)
};

/// Coefficients of `type` in a fluid of density rho [kg/m^3].
/// @throws tangle::Error for rho < 0 or not finite, or negative or non-finite diameters
MorisonCoefficients morisonCoefficients(const section::LineType& type, double rho);

/// morisonElementLoad with coefficients made by morisonCoefficients and a wetted fraction already in
/// [0, 1] (not checked here).
/// @throws tangle::Error for coincident nodes
MorisonElementLoad morisonElementLoad(const Vec3& x1, const Vec3& x2, const Vec3& v1, const Vec3& v2,
                                      const FluidKinematics& fluid, const MorisonCoefficients& coefficients,
                                      double wettedFraction, bool wantDamping, bool wantPositionJacobian);

/// The forces and added mass of morisonElementLoad without its matrices (most assemblies of a dynamic
/// run ask for the out-of-balance alone; building and zeroing the four 3x3 blocks of MorisonElementLoad
/// was half the cost of the call, issue 8).
struct MorisonNodeForces {
  Vec3 force1;                 ///< drag + fluid inertia on node 1 [N] (without the added-mass term)
  Vec3 force2;                 ///< drag + fluid inertia on node 2 [N] (without the added-mass term)
  AddedMass addedMassPerNode;  ///< added mass of each node [kg] (as MorisonElementLoad's)
};

namespace detail {
/// Throws the coincident-node error of morisonNodeForces (out of line: the message is built off the hot
/// path).
[[noreturn]] void failCoincidentNodes(double length);

/// Fluid inertia per unit length [N/m]: Froude-Krylov + added-mass part of the fluid acceleration.
inline Vec3 fluidInertia(const FluidKinematics& fluid, const MorisonCoefficients& c, const Vec3& t) {
  if (fluid.acceleration.isZero(0.0)) return Vec3::Zero();
  const Vec3& af = fluid.acceleration;
  return (c.displacedMass + c.normalMass) * af + ((c.axialMass - c.normalMass) * t.dot(af)) * t;
}

/// Added mass per unit length rho A (Can (I - t t^T) + Caa t t^T) on the length lumped at a node [kg].
inline AddedMass lumpedAddedMass(const MorisonCoefficients& c, const Vec3& t, double halfLength) {
  AddedMass m;
  m.tangent = t;
  m.normal = halfLength * c.normalMass;
  m.axial = halfLength * c.axialMass;
  return m;
}
}  // namespace detail

/// force1, force2 and addedMassPerNode of morisonElementLoad (same arguments; its formulas arranged for a
/// shorter chain of dependent operations, equal to round-off), with a wetted fraction in (0, 1] and a wet
/// fluid (coefficients.wet); the caller skips dry elements.
/// @throws tangle::Error for coincident nodes
inline MorisonNodeForces morisonNodeForces(const Vec3& x1, const Vec3& x2, const Vec3& v1, const Vec3& v2,
                                           const FluidKinematics& fluid,
                                           const MorisonCoefficients& coefficients, double wettedFraction) {
  // The formulas of morisonElementLoad arranged for a short dependency chain (the call is latency-bound:
  // square root, division and square root in a row; docs/performance.md): with the element vector
  // a = x2 - x1, the normal relative velocity is v_r - (a.v_r / a.a) a and the axial one (a.v_r) / L, so
  // 1 / a.a (a division) and L (a square root) run side by side instead of one after the other.
  const Vec3 axis = x2 - x1;
  const double squaredLength = axis.squaredNorm();
  const double length = std::sqrt(squaredLength);
  if (!(std::isfinite(length) && length > 0.0)) [[unlikely]]
    detail::failCoincidentNodes(length);
  const double inverseSquared = 1.0 / squaredLength;
  const double inverseLength = length * inverseSquared;
  const Vec3 t = inverseLength * axis;
  const double halfLength = 0.5 * wettedFraction * length;  // wetted length lumped on each node [m]
  const Vec3 inertia = detail::fluidInertia(fluid, coefficients, t);
  const double kn = coefficients.normalDrag, ka = coefficients.axialDrag;
  const auto nodeForce = [&](const Vec3& v) {
    const Vec3 vr = fluid.velocity - v;
    const double along = axis.dot(vr);  // L v_ra [m^2/s]
    const Vec3 vn = vr - (along * inverseSquared) * axis;
    const double va = along * inverseLength;
    return Vec3(halfLength * ((kn * vn.norm() * vn + ka * std::abs(va) * va * t) + inertia));
  };
  MorisonNodeForces out;
  out.force1 = nodeForce(v1);
  out.force2 = nodeForce(v2);
  out.addedMassPerNode = detail::lumpedAddedMass(coefficients, t, halfLength);
  return out;
}

/// Fraction [-] of the segment z1-z2 [m] lying below the surface level surfaceElevation [m], assuming a
/// straight segment and a locally flat surface: 1 if both ends are at or below it, 0 if both are at or
/// above it (a horizontal segment exactly on the surface counts as submerged), linear in between.
inline double submergedFraction(double z1, double z2, double surfaceElevation) {
  const double lo = std::min(z1, z2);
  const double hi = std::max(z1, z2);
  if (hi <= surfaceElevation) return 1.0;
  if (lo >= surfaceElevation) return 0.0;
  return (surfaceElevation - lo) / (hi - lo);
}

}  // namespace tangle::hydro

/// @file Morison.cpp
/// Relative-velocity Morison loads on a line element (formulas in Morison.hpp).

#include "tangle/hydro/Morison.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"

namespace tangle::hydro {

namespace {

// The checks run on every call (the function's contract); the message is built out of the hot path.
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] void fail(const char* what, const char* requirement, double value) {
  std::ostringstream os;
  os.precision(17);
  os << "morisonElementLoad: " << what << " must be " << requirement << " (got " << value << ")";
  throw Error(os.str());
}

inline void require(bool ok, const char* what, const char* requirement, double value) {
  if (!ok) [[unlikely]]
    fail(what, requirement, value);
}

/// Drag per unit length q(v_r) = kn |v_rn| v_rn + ka |v_ra| v_ra and its Jacobian J = dq/dv_r:
/// J = kn (|v_rn| (I - t t^T) + v_rn v_rn^T / |v_rn|) + 2 ka |t.v_r| t t^T; the normal part tends to 0 as
/// v_rn -> 0 (|x| x is continuously differentiable), so J = 2 ka |t.v_r| t t^T there.
/// The Jacobian only when asked for (most assemblies need the force alone).
[[gnu::always_inline]] inline void drag(const Vec3& vr, const Vec3& t, double kn, double ka, Vec3& q,
                                        Mat3* jacobian) {
  const double va = t.dot(vr);
  const Vec3 vn = vr - va * t;
  const double vnNorm = vn.norm();
  q = kn * vnNorm * vn + ka * std::abs(va) * va * t;
  if (!jacobian) return;
  const Mat3 ttT = t * t.transpose();
  *jacobian = kn * vnNorm * (Mat3::Identity() - ttT) + 2.0 * ka * std::abs(va) * ttT;
  if (vnNorm > 0.0) *jacobian += (kn / vnNorm) * (vn * vn.transpose());
}

/// d(L q_d)/dd of the drag per unit length times the element length L, with respect to the element vector
/// d = x2 - x1 (formulas in Morison.hpp, morisonElementLoad).
inline Mat3 dragPositionJacobian(const Vec3& vr, const Vec3& t, double kn, double ka) {
  const double s = t.dot(vr);
  const Vec3 wn = vr - s * t;
  const double wnNorm = wn.norm();
  const Mat3 p = Mat3::Identity() - t * t.transpose();
  Mat3 g = ka * (std::abs(s) * s * (t * t.transpose()) + 2.0 * std::abs(s) * t * (vr.transpose() * p) +
                 std::abs(s) * s * p);
  if (wnNorm > 0.0) {
    const Mat3 jn = wnNorm * Mat3::Identity() + (wn * wn.transpose()) / wnNorm;
    g += kn * (wnNorm * wn * t.transpose() - jn * (t * vr.transpose() + s * Mat3::Identity()) * p);
  }
  return g;
}

}  // namespace

MorisonCoefficients morisonCoefficients(const section::LineType& type, double rho) {
  require(std::isfinite(rho) && rho >= 0.0, "fluid density [kg/m^3]", "finite and >= 0", rho);
  require(std::isfinite(type.outerDiameter) && type.outerDiameter >= 0.0, "outerDiameter [m] of line type",
          "finite and >= 0", type.outerDiameter);
  require(std::isfinite(type.buoyancyDiameter) && type.buoyancyDiameter >= 0.0,
          "buoyancyDiameter [m] of line type", "finite and >= 0", type.buoyancyDiameter);
  MorisonCoefficients c;
  const double d = type.outerDiameter;
  const double area = 0.25 * kPi * d * d;                                                           // A [m^2]
  const double displacedArea = type.buoyancyDiameter > 0.0 ? type.displacedAreaPerLength() : area;  // A_b
  c.normalDrag = 0.5 * rho * type.dragNormal * d;
  c.axialDrag = 0.5 * rho * type.dragAxial * kPi * d;
  c.normalMass = rho * area * type.addedMassNormal;
  c.axialMass = rho * area * type.addedMassAxial;
  c.displacedMass = rho * displacedArea;
  c.wet = rho != 0.0;
  return c;
}

MorisonElementLoad morisonElementLoad(const Vec3& x1, const Vec3& x2, const Vec3& v1, const Vec3& v2,
                                      const FluidKinematics& fluid, const section::LineType& type, double rho,
                                      double wettedFraction, bool wantDamping, bool wantPositionJacobian) {
  require(wettedFraction >= 0.0 && wettedFraction <= 1.0, "submerged fraction [-]", "in [0, 1]",
          wettedFraction);
  return morisonElementLoad(x1, x2, v1, v2, fluid, morisonCoefficients(type, rho), wettedFraction,
                            wantDamping, wantPositionJacobian);
}

namespace {

/// Element tangent and length of x1-x2 [-], [m]; throws for coincident nodes.
inline Vec3 unitTangent(const Vec3& x1, const Vec3& x2, double& length) {
  const Vec3 axis = x2 - x1;
  length = axis.norm();
  require(std::isfinite(length) && length > 0.0, "element length [m]", "finite and > 0 (distinct nodes)",
          length);
  return (1.0 / length) * axis;  // one division, not three (the call is latency-bound)
}

}  // namespace

void detail::failCoincidentNodes(double length) {
  fail("element length [m]", "finite and > 0 (distinct nodes)", length);
}

MorisonElementLoad morisonElementLoad(const Vec3& x1, const Vec3& x2, const Vec3& v1, const Vec3& v2,
                                      const FluidKinematics& fluid, const MorisonCoefficients& coefficients,
                                      double wettedFraction, bool wantDamping, bool wantPositionJacobian) {
  double length = 0.0;
  const Vec3 t = unitTangent(x1, x2, length);

  MorisonElementLoad load;
  if (wettedFraction == 0.0 || !coefficients.wet) return load;

  const double halfLength = 0.5 * wettedFraction * length;  // wetted length lumped on each node [m]
  const double kn = coefficients.normalDrag;
  const double ka = coefficients.axialDrag;
  const Vec3 inertia = detail::fluidInertia(fluid, coefficients, t);

  Vec3 q1, q2;
  Mat3 j1, j2;
  drag(fluid.velocity - v1, t, kn, ka, q1, wantDamping ? &j1 : nullptr);
  drag(fluid.velocity - v2, t, kn, ka, q2, wantDamping ? &j2 : nullptr);
  load.force1 = halfLength * (q1 + inertia);
  load.force2 = halfLength * (q2 + inertia);
  if (wantDamping) {
    load.damping1 = halfLength * j1;  // d force1/d v1 = -halfLength * j1
    load.damping2 = halfLength * j2;
  }
  if (wantPositionJacobian) {
    const double half = 0.5 * wettedFraction;
    load.positionJacobian1 = half * dragPositionJacobian(fluid.velocity - v1, t, kn, ka);
    load.positionJacobian2 = half * dragPositionJacobian(fluid.velocity - v2, t, kn, ka);
  }
  load.addedMassPerNode = detail::lumpedAddedMass(coefficients, t, halfLength);
  return load;
}

}  // namespace tangle::hydro

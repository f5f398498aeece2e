#include "tangle/element/Bar.hpp"

#include <string>

#include "tangle/core/Error.hpp"

namespace tangle::element {

Bar::Bar(double axialStiffness, double restLength) : m_ea(axialStiffness), m_l0(restLength) {
  if (!(axialStiffness > 0.0)) {
    throw Error("Bar: axial stiffness EA must be > 0 (got " + std::to_string(axialStiffness) + " N)");
  }
  if (!(restLength > 0.0)) {
    throw Error("Bar: rest length L0 must be > 0 (got " + std::to_string(restLength) + " m)");
  }
}

void Bar::compute(const Vec3& x1, const Vec3& x2, Vec6& internalForce, Mat6& tangent, double compressionFactor) const {
  compute(x1, x2, internalForce, &tangent, compressionFactor);
}

void Bar::compute(const Vec3& x1, const Vec3& x2, Vec6& internalForce, Mat6* tangent, double compressionFactor) const {
  // Crisfield 1991, vol. 1, sec. 3.3: with d = x2 - x1, l = |d|, e = d / l and N = EA (l - L0) / L0,
  // the internal force is [-N e, N e] and its exact derivative is
  // K = [k, -k; -k, k], k = EA / L0 e e^T + N / l (I - e e^T).
  const Axial a = axial(x1, x2, compressionFactor);
  const Vec3& e = a.direction;
  const double l = a.length, ea = a.stiffness, n = a.force;
  internalForce.head<3>() = -n * e;
  internalForce.tail<3>() = n * e;
  if (!tangent) return;

  const Mat3 eeT = e * e.transpose();
  const Mat3 k = (ea / m_l0) * eeT + (n / l) * (Mat3::Identity() - eeT);
  tangent->topLeftCorner<3, 3>() = k;
  tangent->bottomRightCorner<3, 3>() = k;
  tangent->topRightCorner<3, 3>() = -k;
  tangent->bottomLeftCorner<3, 3>() = -k;
}

void Bar::throwCoincidentNodes() { throw Error("Bar: the two nodes coincide (zero current length)"); }

double Bar::axialForce(const Vec3& x1, const Vec3& x2, double compressionFactor) const {
  // axial()'s force without its direction: no throw for coincident nodes (a result, not a solve).
  return law((x2 - x1).norm(), compressionFactor).force;
}

}  // namespace tangle::element

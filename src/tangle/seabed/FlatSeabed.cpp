#include "tangle/seabed/FlatSeabed.hpp"

#include <cmath>

namespace tangle::seabed {

SeabedNodeReaction FlatSeabed::reaction(const Vec3& position, const Vec3& velocity, double tributaryLength,
                                        double radius, bool dynamic) const {
  SeabedNodeReaction r;
  r.penetration = -m_depth - (position.z() - radius);
  if (r.penetration <= 0.0) return r;
  const double k = m_spec.normalStiffness * tributaryLength;
  double normal = k * r.penetration;
  r.stiffness(2, 2) = k;
  if (dynamic && m_spec.damping > 0.0) {
    const double c = m_spec.damping * tributaryLength;
    const double damped = normal - c * velocity.z();
    // The dashpot may lower the reaction but never make the seabed pull the line down.
    if (damped > 0.0) {
      normal = damped;
      r.damping(2, 2) = c;
    } else {
      normal = 0.0;
      r.stiffness(2, 2) = 0.0;
    }
  }
  r.force.z() = normal;
  if (dynamic && m_spec.frictionCoefficient > 0.0 && normal > 0.0) {
    const Vec3 vt(velocity.x(), velocity.y(), 0.0);
    const double speed = vt.norm();
    const double mu = m_spec.frictionCoefficient;
    const double vreg = m_spec.frictionVelocity;
    Mat3 p = Mat3::Zero();  // projector on the seabed plane
    p(0, 0) = p(1, 1) = 1.0;
    if (speed <= vreg) {
      // Linear branch: F = -mu N v / vreg.
      r.force -= mu * normal / vreg * vt;
      r.damping += mu * normal / vreg * p;
      // N falls as z rises (dN/dz = -k), so -dF/dz = -mu k v / vreg.
      r.stiffness.col(2) -= mu * r.stiffness(2, 2) / vreg * vt;
    } else {
      const Vec3 dir = vt / speed;
      r.force -= mu * normal * dir;
      r.damping += mu * normal / speed * (p - dir * dir.transpose());
      r.stiffness.col(2) -= mu * r.stiffness(2, 2) * dir;
    }
  }
  return r;
}

}  // namespace tangle::seabed

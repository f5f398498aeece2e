#include "tangle/seabed/FlatSeabed.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::seabed {

SeabedNodeReaction FlatSeabed::reaction(const Vec3& position, const Vec3& velocity, double tributaryLength,
                                        double radius, bool dynamic) const {
  SeabedNodeReaction r;
  r.penetration = penetration(position, radius);
  if (r.penetration <= 0.0) return r;
  const double k = m_spec.normalStiffness * tributaryLength;
  // C1 onset over the first kSmoothPenetration of penetration (quadratic, then linear and offset by half
  // of it): a node touching down or lifting off changes the tangent continuously, so Newton does not
  // cycle on the touchdown nodes of a finely meshed line.
  double normal = 0.0;
  if (r.penetration < kSmoothPenetration) {
    normal = 0.5 * k * r.penetration * r.penetration / kSmoothPenetration;
    r.stiffness(2, 2) = k * r.penetration / kSmoothPenetration;
  } else {
    normal = k * (r.penetration - 0.5 * kSmoothPenetration);
    r.stiffness(2, 2) = k;
  }
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
  if (dynamic && !m_spec.elasticFriction && m_spec.frictionCoefficient > 0.0 && normal > 0.0) {
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

Vec3 FlatSeabed::reactionForce(const Vec3& position, const Vec3& velocity, double tributaryLength, double radius,
                               bool dynamic) const {
  // reaction()'s force, step by step (its comments give the reasons).
  const double penetration = this->penetration(position, radius);
  if (penetration <= 0.0) return Vec3::Zero();
  const double k = m_spec.normalStiffness * tributaryLength;
  double normal = penetration < kSmoothPenetration ? 0.5 * k * penetration * penetration / kSmoothPenetration
                                                   : k * (penetration - 0.5 * kSmoothPenetration);
  if (dynamic && m_spec.damping > 0.0) {
    const double damped = normal - m_spec.damping * tributaryLength * velocity.z();
    normal = damped > 0.0 ? damped : 0.0;
  }
  Vec3 force(0.0, 0.0, normal);
  if (dynamic && !m_spec.elasticFriction && m_spec.frictionCoefficient > 0.0 && normal > 0.0) {
    const Vec3 vt(velocity.x(), velocity.y(), 0.0);
    const double speed = vt.norm();
    const double mu = m_spec.frictionCoefficient;
    const double vreg = m_spec.frictionVelocity;
    if (speed <= vreg)
      force -= mu * normal / vreg * vt;
    else
      force -= mu * normal * (vt / speed);
  }
  return force;
}

StaticFrictionResult FlatSeabed::staticFriction(const Vec3& position, const Vec2& anchor, double normal,
                                                double normalStiffness, double tributaryLength, const Vec3& velocity,
                                                double dashpot) const {
  StaticFrictionResult r;
  r.anchor = anchor;
  const double mu = m_spec.frictionCoefficient;
  if (mu <= 0.0 || normal <= 0.0) return r;
  const double kt = shearStiffness() * tributaryLength;
  const Vec2 slip(position.x() - anchor.x(), position.y() - anchor.y());
  const double distance = slip.norm();
  const double cap = mu * normal;
  // Stick: linear spring to the anchor and, in dynamics, a dashpot beside it.
  const Vec2 stick = -kt * slip - dashpot * Vec2(velocity.x(), velocity.y());
  // (Without a dashpot the same numbers as kt |s|, bit for bit: statics paths are that sensitive.)
  const double trial = dashpot == 0.0 ? kt * distance : stick.norm();
  if (trial <= cap) {
    r.force.x() = stick.x();
    r.force.y() = stick.y();
    r.stiffness(0, 0) = r.stiffness(1, 1) = kt;
    r.damping(0, 0) = r.damping(1, 1) = dashpot;
    return r;
  }
  // Slip: the force sits on the cap, opposite to the direction n of the trial force's pull (the slip
  // direction without a dashpot), and the anchor follows the node, staying cap / kt behind it
  // (closest-point return map of a 2D isotropic Coulomb law).
  const Vec2 n = dashpot == 0.0 ? Vec2(slip / distance) : Vec2(-stick / trial);
  r.sliding = true;
  r.force.x() = -cap * n.x();
  r.force.y() = -cap * n.y();
  r.anchor = Vec2(position.x(), position.y()) - (cap / kt) * n;
  // -dF/dx = cap / |s| (I - n n^T) in the plane; -dF/dz = -mu dN/dz n... with N = k (penetration) and
  // d(penetration)/dz = -1: dF/dz = mu k n, so -dF/dz = -mu k n.
  const double c = cap / std::max(distance, cap / kt);
  r.stiffness(0, 0) = c * (1.0 - n.x() * n.x());
  r.stiffness(1, 1) = c * (1.0 - n.y() * n.y());
  r.stiffness(0, 1) = r.stiffness(1, 0) = -c * n.x() * n.y();
  r.stiffness(0, 2) = -mu * normalStiffness * n.x();
  r.stiffness(1, 2) = -mu * normalStiffness * n.y();
  return r;
}

double FlatSeabed::restingPenetration(double weightPerLength, double normalStiffness) {
  if (weightPerLength <= 0.0 || normalStiffness <= 0.0) return 0.0;
  const double linear = weightPerLength / normalStiffness;
  return linear >= 0.5 * kSmoothPenetration ? linear + 0.5 * kSmoothPenetration
                                            : std::sqrt(2.0 * linear * kSmoothPenetration);
}

}  // namespace tangle::seabed

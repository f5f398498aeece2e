#include "tangle/seabed/Seabed.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::seabed {

namespace {

/// Penetration [m] along the normal and the normal of the seabed under a node.
struct LocalContact {
  double penetration = 0.0;
  Vec3 normal = Vec3::UnitZ();
};

LocalContact localContact(const SeabedSurface& surface, const Vec3& position, double radius) {
  LocalContact c;
  if (surface.isFlat()) {
    c.penetration = -surface.gap(position, radius);
    return c;
  }
  const SeabedPoint s = surface.at(position.x(), position.y());
  c.penetration = radius - (position.z() - s.height) * s.normal.z();
  c.normal = s.normal;
  return c;
}

}  // namespace

SeabedNodeReaction Seabed::reaction(const Vec3& position, const Vec3& velocity, double tributaryLength,
                                    double radius, bool dynamic) const {
  SeabedNodeReaction r;
  const LocalContact local = localContact(*m_surface, position, radius);
  r.penetration = local.penetration;
  if (r.penetration <= 0.0) return r;
  const Vec3& n = local.normal;
  r.normal = n;
  const double vn = n.dot(velocity);
  // d(penetration)/d(position) = -n (the normal is constant on a plane).
  const NormalLaw law = normalLaw(r.penetration, vn, tributaryLength, dynamic);
  const double normal = law.force;
  const double kn = law.stiffness;
  const double c = law.damping;
  const Mat3 nn = n * n.transpose();
  r.stiffness = kn * nn;
  r.damping = c * nn;
  r.force = normal * n;
  r.normalForce = normal;
  r.normalStiffness = kn;
  if (dynamic && !m_spec.elasticFriction && m_spec.frictionCoefficient > 0.0 && normal > 0.0) {
    const Vec3 vt = velocity - vn * n;  // velocity in the tangent plane
    const double speed = vt.norm();
    const double mu = m_spec.frictionCoefficient;
    const double vreg = m_spec.frictionVelocity;
    const Mat3 p = Mat3::Identity() - nn;  // projector on the tangent plane
    if (speed <= vreg) {
      // Linear branch: F = -mu N v_t / vreg.
      r.force -= mu * normal / vreg * vt;
      r.damping += mu * normal / vreg * p;
      // N falls as the node rises along n (dN/dx = -kn n^T), so -dF/dx = -mu kn / vreg v_t n^T.
      r.stiffness -= (mu * kn / vreg * vt) * n.transpose();
    } else {
      const Vec3 dir = vt / speed;
      r.force -= mu * normal * dir;
      r.damping += mu * normal / speed * (p - dir * dir.transpose());
      r.stiffness -= (mu * kn * dir) * n.transpose();
    }
  }
  return r;
}

Vec3 Seabed::normalAt(const Vec3& position) const {
  return m_surface->isFlat() ? Vec3::UnitZ() : m_surface->at(position.x(), position.y()).normal;
}

Vec3 Seabed::reactionForce(const Vec3& position, const Vec3& velocity, double tributaryLength, double radius,
                           bool dynamic) const {
  // reaction()'s force, step by step (its comments give the reasons).
  const LocalContact local = localContact(*m_surface, position, radius);
  const double penetration = local.penetration;
  if (penetration <= 0.0) return Vec3::Zero();
  const Vec3& n = local.normal;
  const double vn = n.dot(velocity);
  const double normal = normalLaw(penetration, vn, tributaryLength, dynamic).force;
  Vec3 force = normal * n;
  if (dynamic && !m_spec.elasticFriction && m_spec.frictionCoefficient > 0.0 && normal > 0.0) {
    const Vec3 vt = velocity - vn * n;
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

StaticFrictionResult Seabed::staticFriction(const Vec3& position, const Vec2& anchor, double normal,
                                            double normalStiffness, double tributaryLength,
                                            const Vec3& velocity, double dashpot,
                                            const Vec3& surfaceNormal) const {
  StaticFrictionResult r;
  r.anchor = anchor;
  const double mu = m_spec.frictionCoefficient;
  if (mu <= 0.0 || normal <= 0.0) return r;
  const Vec3& n = surfaceNormal;
  const double kt = shearStiffness() * tributaryLength;
  // The slip: from the anchor's point on the seabed to the node, in the tangent plane (on a flat seabed
  // (x - a_x, y - a_y, 0), exactly).
  const Vec3 fromAnchor = position - Vec3(anchor.x(), anchor.y(), m_surface->height(anchor.x(), anchor.y()));
  const Vec3 slip = fromAnchor - n.dot(fromAnchor) * n;
  const double distance = slip.norm();
  const double cap = mu * normal;
  const Vec3 vt = velocity - n.dot(velocity) * n;
  const Mat3 p = Mat3::Identity() - n * n.transpose();  // projector on the tangent plane
  // Stick: linear spring to the anchor and, in dynamics, a dashpot beside it.
  const Vec3 stick = -kt * slip - dashpot * vt;
  // (Without a dashpot the same numbers as kt |s|, bit for bit: statics paths are that sensitive.)
  const double trial = dashpot == 0.0 ? kt * distance : stick.norm();
  if (trial <= cap) {
    r.force = stick;
    r.stiffness = kt * p;
    r.damping = dashpot * p;
    return r;
  }
  // Slip: the force sits on the cap, opposite to the direction m of the trial force's pull (the slip
  // direction without a dashpot), and the anchor follows the node, staying cap / kt behind it on the
  // seabed (closest-point return map of a 2D isotropic Coulomb law in the tangent plane).
  const Vec3 m = dashpot == 0.0 ? Vec3(slip / distance) : Vec3(-stick / trial);
  r.sliding = true;
  r.force = -cap * m;
  const Vec3 onSeabed = position - n.dot(fromAnchor) * n - (cap / kt) * m;
  r.anchor = Vec2(onSeabed.x(), onSeabed.y());
  // F = cap t / |t| with the trial force t = -kt s - c v_t: dF/dt = cap / |t| (I - m m^T), dt/dx = -kt P and
  // dt/dv = -c P, so -dF/dx = cap kt / |t| (P - m m^T) and -dF/dv = cap c / |t| (P - m m^T) in the plane.
  // Without a dashpot |t| = kt |s|: cap / |s| (P - m m^T), written entry by entry so that a flat seabed's
  // numbers are those of before to the last bit. (Until 2026-12-07 the dashpot's share was left out: -dF/dx
  // taken as cap / |s| and -dF/dv as 0, where the dashpot, c gamma / (beta dt) ~ 3 kt for a chain at dt 0.05
  // s, dominates the trial force: a sliding node converged linearly, at about 0.66 per iteration, and a laid
  // mooring leg's steps took three times the iterations of the same leg without friction.) The cap moves with
  // N: dF/dx = -mu m dN/dx = mu kn m n^T, so -dF/dx gains -mu kn m n^T.
  const double c = dashpot == 0.0 ? cap / std::max(distance, cap / kt) : cap * kt / std::max(trial, cap);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.stiffness(i, j) =
          i == j ? c * (p(i, j) - m(i) * m(j))
                 : c * p(i, j) - c * m(std::min(i, j)) * m(std::max(i, j));  // symmetric, bit for bit
  r.stiffness -= (mu * normalStiffness * m) * n.transpose();
  if (dashpot != 0.0) r.damping = (cap * dashpot / std::max(trial, cap)) * (p - m * m.transpose());
  return r;
}

double Seabed::restingPenetration(double weightPerLength, double normalStiffness) {
  if (weightPerLength <= 0.0 || normalStiffness <= 0.0) return 0.0;
  const double linear = weightPerLength / normalStiffness;
  return linear >= 0.5 * kSmoothPenetration ? linear + 0.5 * kSmoothPenetration
                                            : std::sqrt(2.0 * linear * kSmoothPenetration);
}

}  // namespace tangle::seabed

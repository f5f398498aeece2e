#pragma once
/// @file Seabed.hpp
/// Elastic seabed acting on line nodes: penalty normal spring and dashpot per unit length of line along the
/// local normal of its surface (flat, a sloping plane or a bathymetry grid: SeabedSurface), and regularised
/// or elastic Coulomb friction in the local tangent plane.

#include <memory>

#include "tangle/core/Types.hpp"
#include "tangle/seabed/SeabedSpec.hpp"
#include "tangle/seabed/SeabedSurface.hpp"

namespace tangle::seabed {

/// Seabed reaction on one node and its derivatives.
struct SeabedNodeReaction {
  Vec3 force = Vec3::Zero();               ///< force of the seabed on the node [N]
  Mat3 stiffness = Mat3::Zero();           ///< -d(force)/d(position) [N/m]
  Mat3 damping = Mat3::Zero();             ///< -d(force)/d(velocity) [N s/m]
  double penetration = 0.0;                ///< [m], > 0 in contact
  double normalForce = 0.0;                ///< N, the normal reaction's magnitude [N]
  double normalStiffness = 0.0;            ///< dN/d(penetration) [N/m]
  Vec3 normal = Vec3::UnitZ();             ///< the seabed's unit normal under the node [-]
};

/// Statics friction of one node: an elastic spring to the node's anchor point on the seabed (its as-laid
/// position), capped at mu N, with the anchor dragged along when the cap is reached (a return map,
/// as in rate-independent plasticity). See docs/theory.md, "Seabed friction in statics".
struct StaticFrictionResult {
  Vec3 force = Vec3::Zero();      ///< friction force on the node, in the seabed plane [N]
  Mat3 stiffness = Mat3::Zero();  ///< -d(force)/d(position) [N/m]
  Mat3 damping = Mat3::Zero();    ///< -d(force)/d(velocity) [N s/m] (the stick dashpot, dynamics)
  Vec2 anchor = Vec2::Zero();  ///< anchor (x, y) after the return map [m] (the point on the seabed under it)
  bool sliding = false;           ///< the force is at the cap mu N
};

/// Seabed: normal force (k L delta + c L v_n) n (compression only; delta the penetration and n the unit
/// normal of the surface under the node, v_n = v . n) and friction in the tangent plane,
/// mu * N * v_t / max(|v_t|, v_reg) with v_t = v - v_n n (linear "viscous" branch below v_reg so Newton
/// converges; the regularisation of e.g. OrcaFlex's and MoorDyn's seabed friction models), or the elastic
/// law of staticFriction(). On a flat seabed n = e_z and every number is the flat seabed's of before, bit for
/// bit (the general formulas reduce to it exactly: products with 0 and 1).
class Seabed {
 public:
  /// @param spec stiffness [N/m/m], damping [N s/m/m], friction coefficient [-], regularisation velocity
  /// [m/s]
  /// @param surface the seabed's shape (shared, not copied: a grid may be large)
  Seabed(const SeabedSpec& spec, std::shared_ptr<const SeabedSurface> surface)
      : m_spec(spec), m_surface(std::move(surface)) {}
  /// Flat seabed at z = -depth [m].
  Seabed(const SeabedSpec& spec, double depth)
      : m_spec(spec), m_surface(std::make_shared<const SeabedSurface>(SeabedSurface::flat(depth))) {}

  /// Reaction on a node.
  /// @param position node position [m]; @param velocity node velocity [m/s]
  /// @param tributaryLength length of line the node stands for [m]
  /// @param radius contact radius (half the contact diameter) [m]
  /// @param tangent unit line tangent at the node (for the axial/lateral split of friction; friction is
  ///        isotropic in this version, the tangent is reserved)
  /// @param dynamic include damping, and the velocity-regularised friction unless the seabed's friction is
  ///        elastic (then the caller adds staticFriction(), in statics and dynamics alike)
  SeabedNodeReaction reaction(const Vec3& position, const Vec3& velocity, double tributaryLength, double radius,
                              bool dynamic) const;

  /// reaction(...).force alone, by the same arithmetic (no derivatives: the assemblies without a matrix, most
  /// of a dynamic run's; building and zeroing the two 3x3 blocks per grounded node was most of the seabed's
  /// cost there).
  Vec3 reactionForce(const Vec3& position, const Vec3& velocity, double tributaryLength, double radius,
                     bool dynamic) const;
  /// Friction in statics on a node in contact (see StaticFrictionResult).
  /// @param position node position [m]; @param anchor committed anchor (x, y) [m]
  /// @param normal normal reaction N [N] (> 0); @param normalStiffness dN/d(penetration) [N/m]
  /// @param tributaryLength length of line the node stands for [m] (scales the shear stiffness)
  /// @param velocity node velocity [m/s] and @param dashpot [N s/m]: in dynamics a dashpot beside the stick
  ///        spring (Kelvin-Voigt), so that a node held by friction does not ring on the undamped spring
  ///        (theory 7.5); its force counts towards the cap. Zero in statics.
  /// @param surfaceNormal the seabed's unit normal under the node (SeabedNodeReaction::normal): the spring
  ///        acts on the slip projected on the tangent plane, from the anchor's point on the seabed.
  StaticFrictionResult staticFriction(const Vec3& position, const Vec2& anchor, double normal,
                                      double normalStiffness, double tributaryLength,
                                      const Vec3& velocity = Vec3::Zero(), double dashpot = 0.0,
                                      const Vec3& surfaceNormal = Vec3::UnitZ()) const;

  /// Shear (friction spring) stiffness per unit length of line [N/m/m]: the user's value, or the normal stiffness.
  double shearStiffness() const { return m_spec.shearStiffness > 0.0 ? m_spec.shearStiffness : m_spec.normalStiffness; }

  const SeabedSurface& surface() const { return *m_surface; }
  /// Penetration [m] along the normal of a node of contact radius `radius` [m] at `position` (> 0: touching):
  /// the quantity reaction() starts from, for callers that skip the nodes clear of the seabed cheaply.
  double penetration(const Vec3& position, double radius) const { return -m_surface->gap(position, radius); }

  /// Penetration over which the normal reaction sets in smoothly (C1 quadratic onset) [m].
  static constexpr double kSmoothPenetration = 0.002;

  /// The normal reaction's law, the one reaction() and reactionForce() apply along the normal: its magnitude
  /// and derivatives for a node of tributary length `tributaryLength` [m] at penetration `penetration` [m]
  /// (> 0: touching) moving along the normal at `normalVelocity` [m/s] (> 0: away from the seabed), with
  /// the dashpot when `dynamic`.
  struct NormalLaw {
    double force = 0.0;      ///< N [N], >= 0
    double stiffness = 0.0;  ///< dN/d(penetration) [N/m]
    double damping = 0.0;    ///< -dN/d(normal velocity) [N s/m]
  };
  NormalLaw normalLaw(double penetration, double normalVelocity, double tributaryLength, bool dynamic) const {
    NormalLaw law;
    if (penetration <= 0.0) return law;
    const double k = m_spec.normalStiffness * tributaryLength;
    // C1 onset over the first kSmoothPenetration of penetration (quadratic, then linear and offset by half
    // of it): a node touching down or lifting off changes the tangent continuously, so Newton does not
    // cycle on the touchdown nodes of a finely meshed line.
    if (penetration < kSmoothPenetration) {
      law.force = 0.5 * k * penetration * penetration / kSmoothPenetration;
      law.stiffness = k * penetration / kSmoothPenetration;
    } else {
      law.force = k * (penetration - 0.5 * kSmoothPenetration);
      law.stiffness = k;
    }
    if (dynamic && m_spec.damping > 0.0) {
      const double c = m_spec.damping * tributaryLength;
      const double damped = law.force - c * normalVelocity;
      // The dashpot may lower the reaction but never make the seabed pull the line down.
      if (damped > 0.0) {
        law.force = damped;
        law.damping = c;
      } else {
        law = NormalLaw{};
      }
    }
    return law;
  }
  /// Fraction [0, 1] of a node's submerged line weight that the seabed carries under it: the node at
  /// `position` [m] of contact radius `radius` [m], `weightPerLength` [N/m] its lumped submerged line weight
  /// over its tributary length (the mean of its elements' weights per length). The elastic normal reaction
  /// per unit length (no dashpot) over the weight's share across the surface, w n_z (on a slope the rest of
  /// the weight is along it: friction or the line's tension), capped at 1; 0 clear of the seabed or for a
  /// line that floats (w <= 0). Continuous in the position, from 0 where the node just touches to 1 where it
  /// rests under its weight: what a held node's share of an element's weight on the seabed goes by
  /// (theory 7.8).
  double carriedFraction(const Vec3& position, double radius, double weightPerLength) const {
    if (weightPerLength <= 0.0) return 0.0;
    const double reaction = normalLaw(penetration(position, radius), 0.0, 1.0, false).force;
    if (reaction <= 0.0) return 0.0;
    const double across = weightPerLength * std::max(normalAt(position).z(), 1e-6);
    return std::min(1.0, reaction / across);
  }
  /// The seabed's unit normal under `position` [-] (e_z on a flat seabed).
  Vec3 normalAt(const Vec3& position) const;

  /// Penetration [m] at which a laid line of submerged weight `weightPerLength` [N/m] rests on a seabed of
  /// normal stiffness `normalStiffness` [N/m/m]: N = k d^2 / (2 d_s) up to d_s, k (d - d_s / 2) beyond,
  /// solved for N = w. Zero for a line that floats (w <= 0).
  static double restingPenetration(double weightPerLength, double normalStiffness);

 private:
  SeabedSpec m_spec;
  std::shared_ptr<const SeabedSurface> m_surface;
};

}  // namespace tangle::seabed

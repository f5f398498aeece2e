#pragma once
/// @file CorotationalBeam.hpp
/// Two-node 3D co-rotational beam (Crisfield 1990; Battini & Pacoste 2002) for large
/// displacements and rotations with small strains: 6 DOF per node (3 translations, 3 rotations),
/// axial, torsion and bending about two axes, Euler-Bernoulli in the co-rotated frame.
///
/// Node rotations are carried as triads (rotation matrices whose first column is the line tangent
/// in the stress-free straight state); rotation increments are spatial rotation vectors applied
/// multiplicatively: Q <- exp(dtheta) Q. The element is stress-free when both triads are aligned with
/// the chord and the chord length equals the rest length.

#include "tangle/core/Types.hpp"

namespace tangle::element {

/// Stiffness properties of a beam section.
struct BeamProperties {
  double axialStiffness = 0.0;      ///< EA [N]
  double bendingStiffness = 0.0;    ///< EI, same about both transverse axes [N m^2]
  double torsionalStiffness = 0.0;  ///< GJ [N m^2]
};

/// Section forces of a deformed beam element.
struct BeamSectionForces {
  double axialForce = 0.0;  ///< N, positive in tension [N]
  double torque = 0.0;      ///< torsional moment about e1, same section convention as the moments [N m]
  Vec3 moment1;             ///< bending moment vector at node 1 (global axes, torsion excluded) [N m]
  Vec3 moment2;             ///< bending moment vector at node 2 (global axes, torsion excluded) [N m]
  // Convention: *section* moments, i.e. the moment exerted on the node-1 side of a cut by the node-2
  // side, so that uniform bending gives moment1 == moment2 = EI kappa (curvature vector t x dt/ds).
  // Equivalently moment2 is the end moment applied to the element at node 2 and moment1 minus the end
  // moment applied at node 1.
};

/// A two-node co-rotational beam. Stateless apart from its constants; thread-safe.
class CorotationalBeam {
 public:
  /// @param properties EA, EI, GJ, all > 0
  /// @param restLength stress-free length L0 [m], > 0
  /// @throws tangle::Error when a stiffness or L0 is <= 0
  CorotationalBeam(const BeamProperties& properties, double restLength);

  /// Internal nodal forces/moments and the consistent tangent.
  /// @param x1,x2 current node positions [m]
  /// @param q1,q2 current node triads (orthonormal, columns are material axes, first is the tangent)
  /// @param[out] internalForce ordered [F1 (3), M1 (3), F2 (3), M2 (3)], global axes [N, N m];
  ///        the residual is internalForce - externalForce, moments are work-conjugate to spatial
  ///        rotation increments
  /// @param[out] tangent d(internalForce)/d(u1, theta1, u2, theta2) at the current state, i.e. the
  ///        Hessian of the strain energy in spatial increments [N/m, N, N m]; pass nullptr to skip it.
  ///        It is symmetric. The exact derivative of internalForce under Q <- exp(dtheta) Q differs from
  ///        it by -S(M_i)/2 in the rotation-rotation block of each node i (M_i the nodal moment, S the skew
  ///        matrix; Baker-Campbell-Hausdorff); these terms cancel on assembly at an equilibrium without
  ///        applied moments, so Newton keeps its quadratic convergence there.
  /// @throws tangle::Error for an undefined state: coincident nodes, a local rotation of pi, or the mean
  ///         second triad axis parallel to the chord (co-rotated frame undefined)
  void compute(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2, Vec12& internalForce,
               Mat12* tangent) const;

  /// The same force and tangent as compute, as the gradient and Hessian of the strain energy by
  /// second-order automatic differentiation (Jet<9, 2>): the independent reference the closed-form force
  /// and its differentiated tangent are checked against (CorotationalBeamTest); about four times the work
  /// of compute's tangent.
  void referenceTangent(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2, Vec12& internalForce,
                        Mat12& tangent) const;

  /// Section forces at the current state: N = EA u / L0, torque GJ/L0 (phi2x - phi1x), bending moments
  /// from the local end moments EI/L0 (4 phi1 + 2 phi2) and EI/L0 (2 phi1 + 4 phi2) (y, z components)
  /// rotated to global axes by the co-rotated frame (see BeamSectionForces for the sign convention).
  BeamSectionForces sectionForces(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2) const;

  /// Strain energy [J] at the current state.
  double strainEnergy(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2) const;

  const BeamProperties& properties() const { return m_props; }  ///< EA, EI, GJ
  double restLength() const { return m_l0; }                    ///< L0 [m]

 private:
  BeamProperties m_props;
  double m_l0;
};

}  // namespace tangle::element

#pragma once
/// @file Bar.hpp
/// Two-node bar (truss) element for lines without bending stiffness (chain, wire rope).
/// 3 translational DOF per node; exact large-displacement kinematics, linear axial law on
/// engineering strain (Crisfield 1991, vol. 1, sec. 3.3), or a tension-strain curve (a fibre rope).

#include "tangle/core/PiecewiseLinear.hpp"
#include "tangle/core/Types.hpp"

namespace tangle::element {

/// A straight two-node bar. Stateless apart from its constants; thread-safe.
class Bar {
 public:
  /// @param axialStiffness EA [N], > 0
  /// @param restLength unstretched length L0 [m], > 0
  /// @throws tangle::Error when EA <= 0 or L0 <= 0
  Bar(double axialStiffness, double restLength);
  /// A bar whose tension follows `curve` (tension [N] against engineering strain [-], from (0, 0); the
  /// caller keeps it alive) in tension; in compression EA is the curve's first slope (times the compression
  /// factor). `axialStiffness` stays the reference EA of the element (step limits, round-off).
  Bar(double axialStiffness, double restLength, const core::PiecewiseLinear* curve)
      : Bar(axialStiffness, restLength) {
    m_curve = curve;
  }
  /// The tension-strain curve, or null (linear EA).
  const core::PiecewiseLinear* tensionStrainCurve() const { return m_curve; }

  /// Internal (elastic) nodal forces and their tangent. The axial law is linear in tension *and*
  /// compression (no slack cut-off here: a compressed bar pushes with N = EA (l - L0) / L0 < 0).
  /// @throws tangle::Error when the two nodes coincide (direction undefined).
  /// @param x1,x2 current node positions, global axes [m]
  /// @param[out] internalForce forces the element exerts *on its nodes' equations* ordered
  ///        [node1 (3), node2 (3)] [N]; the equilibrium residual is internalForce - externalForce
  /// @param[out] tangent d(internalForce)/d(x1,x2) [N/m], symmetric (material + geometric part)
  /// @param compressionFactor multiplies EA while the bar is shorter than L0 [-] (1: linear elastic in
  ///        compression; statics uses a small value for cables, which cannot carry compression)
  void compute(const Vec3& x1, const Vec3& x2, Vec6& internalForce, Mat6& tangent, double compressionFactor = 1.0) const;
  /// As above; the tangent only if `tangent` is not null (an assembly without a matrix needs the force).
  void compute(const Vec3& x1, const Vec3& x2, Vec6& internalForce, Mat6* tangent, double compressionFactor = 1.0) const;

  /// compute()'s internal force on node 2, N e [N] (node 1 takes -N e), by the same arithmetic: inline, for
  /// the assemblies without a matrix (most of a dynamic run's; the out-of-line call with its force and
  /// tangent arguments showed in profiles: docs/performance.md).
  /// @throws tangle::Error when the two nodes coincide
  Vec3 forceOnNode2(const Vec3& x1, const Vec3& x2, double compressionFactor = 1.0) const {
    const Axial a = axial(x1, x2, compressionFactor);
    return a.force * a.direction;
  }
  /// forceOnNode2's force N e [N] and the chord's direction e = (x2 - x1) / |x2 - x1| [-], bit for bit
  /// (x2 - x1).normalized(): an axial damper on the same chord needs no square root of its own.
  struct ForceAndDirection {
    Vec3 force;
    Vec3 direction;
  };
  ForceAndDirection forceAndDirectionOnNode2(const Vec3& x1, const Vec3& x2,
                                             double compressionFactor = 1.0) const {
    const Axial a = axial(x1, x2, compressionFactor);
    return {a.force * a.direction, a.direction};
  }
  /// Axial force N = EA (l - L0) / L0 [N] (or the curve's), positive in tension, negative in compression.
  /// @param compressionFactor as in compute()
  double axialForce(const Vec3& x1, const Vec3& x2, double compressionFactor = 1.0) const;

  double axialStiffness() const { return m_ea; }  ///< EA [N]
  double restLength() const { return m_l0; }      ///< L0 [m]

 private:
  /// The chord's direction e, current length l [m], the axial stiffness in force ea [N] and the axial force
  /// N = ea (l - L0) / L0 [N] (Crisfield 1991, vol. 1, sec. 3.3; compute() and forceOnNode2 share it).
  struct Axial {
    Vec3 direction;
    double length;
    double stiffness;
    double force;
  };
  Axial axial(const Vec3& x1, const Vec3& x2, double compressionFactor) const {
    const Vec3 d = x2 - x1;
    const double l = d.norm();
    if (!(l > 0.0)) throwCoincidentNodes();
    const Law a = law(l, compressionFactor);
    return {d / l, l, a.stiffness, a.force};
  }
  /// The axial law at the current length l [m]: dN/d(strain) [N] and N [N] (axial() and axialForce share it).
  struct Law {
    double stiffness;
    double force;
  };
  Law law(double l, double compressionFactor) const {
    if (m_curve) {
      // The curve's tension and slope; compressed, its first slope (times the compression factor).
      const double strain = (l - m_l0) / m_l0;
      const core::PiecewiseLinear::Sample s = m_curve->at(std::max(strain, 0.0));
      if (strain >= 0.0) return {s.slope, s.value};
      return {compressionFactor * s.slope, compressionFactor * s.slope * strain};
    }
    // A slack bar (l < L0) may be given a reduced compression stiffness (compressionFactor < 1). (The
    // product before the division, as it always was: results bit for bit.)
    const double ea = l < m_l0 ? compressionFactor * m_ea : m_ea;
    return {ea, ea * (l - m_l0) / m_l0};
  }
  [[noreturn]] static void throwCoincidentNodes();
  double m_ea;
  double m_l0;
  const core::PiecewiseLinear* m_curve = nullptr;  ///< tension-strain curve, or none (linear EA)
};

}  // namespace tangle::element

#pragma once
/// @file FlatSeabed.hpp
/// Flat elastic seabed at z = -depth acting on line nodes: penalty normal spring and dashpot per
/// unit length of line, and regularised Coulomb friction (axial and lateral to the line).

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::seabed {

/// Seabed reaction on one node and its derivatives.
struct SeabedNodeReaction {
  Vec3 force = Vec3::Zero();               ///< force of the seabed on the node [N]
  Mat3 stiffness = Mat3::Zero();           ///< -d(force)/d(position) [N/m]
  Mat3 damping = Mat3::Zero();             ///< -d(force)/d(velocity) [N s/m]
  double penetration = 0.0;                ///< [m], > 0 in contact
};

/// Flat seabed: normal force k L delta + c L v_n (compression only) and friction
/// mu * N * v_t / max(|v_t|, v_reg) (linear "viscous" branch below v_reg so Newton converges;
/// the regularisation of e.g. OrcaFlex's and MoorDyn's seabed friction models).
class FlatSeabed {
 public:
  /// @param spec stiffness [N/m/m], damping [N s/m/m], friction coefficient [-], regularisation velocity [m/s]
  /// @param depth water depth [m] (seabed at z = -depth)
  FlatSeabed(const model::SeabedSpec& spec, double depth) : m_spec(spec), m_depth(depth) {}

  /// Reaction on a node.
  /// @param position node position [m]; @param velocity node velocity [m/s]
  /// @param tributaryLength length of line the node stands for [m]
  /// @param radius contact radius (half the contact diameter) [m]
  /// @param tangent unit line tangent at the node (for the axial/lateral split of friction; friction is
  ///        isotropic in this version, the tangent is reserved)
  /// @param dynamic include damping and friction
  SeabedNodeReaction reaction(const Vec3& position, const Vec3& velocity, double tributaryLength, double radius,
                              bool dynamic) const;

  double depth() const { return m_depth; }  ///< [m]

 private:
  model::SeabedSpec m_spec;
  double m_depth;
};

}  // namespace tangle::seabed

#pragma once
/// @file State.hpp
/// The kinematic state of the whole model at one instant.

#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/DofMap.hpp"

namespace tangle::model {

/// Positions and triads per node; velocities and accelerations per full DOF
/// (translational [m/s], [m/s^2]; spatial angular [rad/s], [rad/s^2]).
struct State {
  double time = 0.0;           ///< [s]
  std::vector<Vec3> position;  ///< node positions, global axes [m]
  std::vector<Mat3> triad;     ///< node triads (beam nodes; identity for bar nodes)
  VecX velocity;               ///< per full DOF
  VecX acceleration;           ///< per full DOF
  /// Internal variables of the viscoelastic rope elements (solver::ViscoelasticElements numbers them): the
  /// slow strain x [-] and the tension [N] of each at `time` [s], the last committed dynamic state. Empty
  /// before the dynamics (the statics uses the ropes' static EA) and in a model without such ropes.
  struct Viscoelastic {
    std::vector<double> slowStrain;
    std::vector<double> tension;
    /// The static branch's load [N]: a SYROPE rope's mean tension T (MoorDyn's segment tension Te), a
    /// viscoelastic rope's EA_1 x (its "mean load").
    std::vector<double> meanTension;
    std::vector<double> maxMeanTension;  ///< a SYROPE rope's largest mean tension so far [N] (0 for others)
    double time = 0.0;
  } viscoelastic;

  /// Applies an increment given per full DOF: x += du, Q <- exp(dtheta) Q (multiplicative, spatial).
  /// With `orthonormalise`, each updated triad is re-orthonormalised (round-off drift over many updates);
  /// a caller that applies several trial increments to the same start may do it once, on the result.
  void applyIncrement(const DofMap& dofs, const VecX& fullIncrement, bool orthonormalise = true);
  /// Positions and triads of `from` with the increment applied (as applyIncrement without the
  /// re-orthonormalisation) and its time; velocity and acceleration are left for the caller to set (a Newton
  /// iterate of a time step computes both from the increment: copying them, and every bar node's identity
  /// triad, per iterate showed in profiles: docs/performance.md).
  /// `from` may be this state.
  void setIncremented(const State& from, const DofMap& dofs, const VecX& fullIncrement);
  /// This state made equal to `from` (same model): time, positions, velocities, accelerations, the internal
  /// variables, and the
  /// triads of the nodes with rotations; the other triads are copied only when this state has none yet (they
  /// are the identity in every state). The copy of a time step's start: 12 bar lines' identity triads were
  /// 174 kB a step.
  void assignFrom(const State& from, const DofMap& dofs);
  /// Re-orthonormalises every triad (nearest rotation through the quaternion).
  void orthonormaliseTriads(const DofMap& dofs);
};

}  // namespace tangle::model

#pragma once
/// @file DynamicRelaxation.hpp
/// Dynamic relaxation, the fallback of the static solve: the model is released from a start shape and
/// integrated in time with heavy damping under the loads of one instant (current, weight, buoyancy, the
/// held ends at their positions, no waves) until it comes to rest; Newton statics then finishes from the
/// rested shape. It reaches equilibria the Newton continuation cannot follow: a slack catenary whose
/// touchdown must slide tens of metres over the seabed against friction (a tangent without stiffness
/// along the slip), the hanging part of a line pushed back over its grounded part by a current. It is
/// the initialisation MoorDyn uses for every model (Hall 2015, MoorDyn user's guide, "Initialization").
///
/// Damping (see run()): mass-proportional Rayleigh damping c = alpha M tuned to the slowest pendulum mode
/// of the longest line, plus the full numerical dissipation of generalized-alpha (rho_inf = 0) at long
/// steps; both vanish at rest, so the rested shape is an equilibrium of the undamped problem.

#include <string>
#include <vector>

#include "tangle/model/ModelSpec.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/time/DynamicAnalysis.hpp"
#include "tangle/time/GeneralizedAlpha.hpp"

namespace tangle::time {

/// Outcome of a relaxation run.
struct RelaxationResult {
  bool settled = false;   ///< the largest node speed fell below the requested one
  double duration = 0.0;  ///< pseudo-time integrated [s]
  int steps = 0;          ///< accepted steps
  double maxSpeed = 0.0;  ///< largest translational node speed at the end [m/s]
  std::string message;    ///< why it stopped
};

/// Damped pseudo-dynamics to a state at rest.
class DynamicRelaxation {
 public:
  /// @param base the model's dynamic settings (Newton tolerance and iterations are taken from it)
  /// @param prescribed held nodes with a motion (kept at their positions of the static time)
  /// @param longestLine length of the longest line [m], sets the damping (see run())
  DynamicRelaxation(solver::Assembler& assembler, const model::DynamicSpec& base,
                    std::vector<model::PrescribedNode> prescribed, double longestLine);

  /// Integrates from `state` (its velocities are reset to zero) for at most `duration` [s] of pseudo-time,
  /// stopping once every translational node speed is below `restSpeed` [m/s]. Loads and held ends are
  /// those of time `staticTime` [s]. On return `state` is the last accepted state, at rest (velocities and
  /// accelerations zero) and with state.time = staticTime.
  /// A step is accepted only if the assembler's rejectStep gives no reason (otherwise it is cut four-fold),
  /// e.g. the line contact's check that no two lines passed through each other. Nothing is committed.
  RelaxationResult run(model::State& state, double staticTime, double duration, double restSpeed);

  /// Mass-proportional damping used [1/s].
  double damping() const { return m_settings.rayleighAlpha; }

 private:
  solver::Assembler* m_assembler;
  model::DynamicSpec m_settings;
  std::vector<model::PrescribedNode> m_prescribed;
};

}  // namespace tangle::time

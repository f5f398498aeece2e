#pragma once
/// @file GeneralizedAlpha.hpp
/// Implicit time stepping of M a + F(q, v, t) = 0 by the generalized-alpha method
/// (Chung & Hulbert 1993, J. Appl. Mech. 60:371), which contains HHT-alpha (Hilber, Hughes & Taylor
/// 1977) and Newmark's average-acceleration rule (Newmark 1959) as special cases. The integrator owns the
/// predictor, the Newmark relations and the residual; the Newton iteration that solves it every step (the
/// convergence test, the kept or fresh iteration matrix, its blocks, stretches and parts) is
/// solver::NewtonIteration. A step the chosen path (`dynamics.solver`) does not converge is retried with a
/// whole refresh, then with full Newton, before it is reported as failed (step()).
///
/// Contract of step(): on input `state` holds q_n, v_n, a_n at t_n (a_n consistent with the
/// previous step); on success it holds q_{n+1}, v_{n+1}, a_{n+1} at t_n + dt. On failure the state is
/// left exactly as it was on input, so the caller may retry with a smaller dt.
/// Rotations: the step increment of a beam node's rotation is a spatial rotation vector dtheta with
/// Q_{n+1} = exp(dtheta) Q_n, integrated by the same Newmark formulas as translations (a first-order
/// consistent treatment of the rotational inertia, which is tiny for slender lines).

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "tangle/model/ModelSpec.hpp"
#include "tangle/model/PrescribedMotion.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/NewtonIteration.hpp"
#include "tangle/time/SeabedPredictor.hpp"

namespace tangle::time {

/// The four parameters of the generalized-alpha family.
struct AlphaParameters {
  double alphaM = 0.0;  ///< weight of a_n in the inertia term [-]
  double alphaF = 0.0;  ///< weight of F_n in the force term [-]
  double beta = 0.25;   ///< Newmark beta [-]
  double gamma = 0.5;   ///< Newmark gamma [-]
  /// Parameters of a scheme for spectral radius at infinite frequency rhoInf in [0, 1]
  /// (Chung & Hulbert 1993 eq. 25; HHT: Hilber et al. 1977 with alpha = -(1 - rho)/(1 + rho), clipped to
  /// [-1/3, 0]; Newmark: average acceleration, no numerical dissipation).
  static AlphaParameters from(model::IntegratorKind kind, double rhoInf);
};

/// Result of one attempted step.
struct StepOutcome {
  bool converged = false;
  int iterations = 0;
  int partIterations = 0;  ///< of those, evaluated on a part of the model (Assembler::assemblePart)
  int blocksLeft = 0;      ///< converged independent blocks not solved at a correction (solveCorrection)
  int refreshes = 0;       ///< iteration matrices assembled and factorised in this step
  int blockRefreshes = 0;  ///< independent blocks of the kept matrix assembled and factorised on their own
  /// Kept matrices made for a new step length with the mass matrix alone and factorised, without an assembly
  /// (solver::NewtonIteration::startAttempt).
  int stepLengthChanges = 0;
  double residual = 0.0;  ///< last max out-of-balance force [N] of a failed step (0 for a converged one)
  int worstNode = -1;     ///< node with the largest out-of-balance force (of a failed step)
  /// Newton path that converged it: 0 the chosen one (dynamics.solver), 1 a whole refresh, 2 full Newton.
  int fallback = 0;
  /// Why a failed step has no out-of-balance force to name (an element that cannot be evaluated, a
  /// singular matrix, a force that is not finite); empty when the residual and worstNode say it.
  std::string failure;
};

/// Generalized-alpha stepper.
class GeneralizedAlpha {
 public:
  GeneralizedAlpha(solver::Assembler& assembler, const model::DynamicSpec& settings,
                   std::vector<model::PrescribedNode> prescribed);

  /// Prepares the first step from a state at rest in equilibrium or with given v, a.
  /// Evaluates F_0 at the state (needed by the alpha_F weighting).
  void initialize(model::State& state);
  /// Advances by dt (see the class contract).
  StepOutcome step(model::State& state, double dt);

  /// Dynamic relaxation (a statics method): every step sees the environment and the prescribed positions
  /// of time `time` [s] with the prescribed nodes at rest and no waves, so the motion decays to the static
  /// equilibrium at that time. The state's own time still advances (pseudo-time).
  void freezeEnvironment(double time) {
    m_frozen = true;
    m_frozenTime = time;
  }

  /// Use the banded linear solver when the pattern suits (the default; LinearSolver.hpp). Dynamic relaxation,
  /// a statics method, keeps the general solver of statics.
  void setBandedSolver(bool allow) { m_newton.setBandedSolver(allow); }
  const AlphaParameters& parameters() const { return m_params; }
  /// Undoes the last accepted step: `previous` is the state before it, as that step was given it. F_n is
  /// evaluated there again (the alpha_F weighting reads it); its velocity and acceleration are kept as they
  /// are: a_n of generalized alpha is the method's own variable, not M^-1 (-F_n) (which would also leave
  /// out the mass-proportional Rayleigh term), so a retry starts from the state the refused step started
  /// from. The acceleration history of the predictor starts again.
  void restore(model::State& previous);
  /// The state at the start of the last step() (bitwise the state it was given), until the next step() or
  /// restore(): what a caller that may refuse the step needs, without a copy of its own.
  model::State& stepStart() { return m_start; }
  /// Out-of-balance force F at the last accepted state (full DOFs) [N]; its values at constrained
  /// DOFs are the support reactions.
  const VecX& lastForce() const { return m_forceOld; }

 private:
  /// One attempt at a step on the Newton path `mode` (step() tries the fallbacks); the contract of step().
  StepOutcome attempt(model::State& state, double dt, const model::DynamicSolverSpec& mode);
  void applyPrescribed(model::State& state, double t) const;
  /// F at `state` into m_forceOld, the prescribed DOFs set at its time; the predictor's history dropped.
  void evaluateStartForce(model::State& state);
  /// Sets the moved nodes (NewtonIteration::movedNodes) of `state` from the step's start and increment dq:
  /// positions, triads, and the Newmark velocities and accelerations of their free DOFs; the other nodes keep
  /// theirs.
  void moveNodes(model::State& state, const model::State& start, const VecX& dq, double dt) const;
  /// Time at which loads and prescribed motions are evaluated for a state at time t [s].
  double environmentTime(double t) const { return m_frozen ? m_frozenTime : t; }

  solver::Assembler* m_assembler;
  model::DynamicSpec m_settings;
  std::vector<model::PrescribedNode> m_prescribed;
  AlphaParameters m_params;
  std::vector<double> m_nodeFloor;     // round-off floor of each node this step [N]
  bool m_floorZero = false;            // m_nodeFloor is all zero (Assembler::roundoffFloorNegligible)
  std::vector<int> m_constrainedDofs;  // full DOFs without an equation
  solver::NewtonIteration m_newton;    // the iteration matrix, its refresh, blocks and parts
  SeabedPredictor m_seabedPredictor;   // the predictor's correction on the seabed (dynamics.solver.predictor)
  VecX m_forceOld;  // F(q_n, v_n, t_n)
  // step()'s work space: the state at the step's start, the prescribed target, the increment over the step
  // (full DOFs), the mass combination, the inertia force and the residual (equations), and a correction in
  // full DOFs (the contact filter's).
  model::State m_start, m_target;
  VecX m_dq, m_combo, m_inertia, m_residual;
  VecX m_force, m_fullCorrection;
  std::vector<bool> m_prescribedDof;
  bool m_debug = false;  // TANGLE_DEBUG_DYNAMICS set: print every Newton iteration on stderr
  model::DynamicSolverSpec m_choice;  // dynamics.solver: the path every step tries first
  double m_lastStep = 0.0;       // the last converged step [s]
  // The predictor's history: the accelerations at the starts of the last two converged steps, a_{n-1} and
  // a_{n-2} [m/s^2], how many steps converged since initialize() (up to 2) and the length of the step before
  // the last [s] (a_{n-2} to a_{n-1}).
  VecX m_previousAcceleration, m_olderAcceleration;
  // Per full DOF, 1 for the translations of nodes without rotations (the DOFs the predictor may extrapolate),
  // and that less this step's loaded nodes.
  VecX m_cableTranslation, m_extrapolated;
  int m_previousSteps = 0;
  double m_stepBefore = 0.0;
  bool m_frozen = false;         // freezeEnvironment was called
  double m_frozenTime = 0.0;     // [s]
};

}  // namespace tangle::time

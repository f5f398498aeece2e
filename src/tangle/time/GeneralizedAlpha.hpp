#pragma once
/// @file GeneralizedAlpha.hpp
/// Implicit time stepping of M a + F(q, v, t) = 0 by the generalized-alpha method
/// (Chung & Hulbert 1993, J. Appl. Mech. 60:371), which contains HHT-alpha (Hilber, Hughes & Taylor
/// 1977) and Newmark's average-acceleration rule (Newmark 1959) as special cases, with Newton
/// iterations every step (modified Newton: the factorised matrix is reused while the residual falls by
/// 4x or more per iteration, refreshed otherwise; `dynamics.solver.newton: full` refreshes it every
/// iteration). With independent blocks in the matrix (lines not coupled to each other) the test and the
/// refresh are per block (`refresh: whole`: the whole matrix). A step the chosen path does not converge is
/// retried with a whole refresh, then with full Newton, before it is reported as failed (step()).
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
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/model/PrescribedMotion.hpp"

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
  void setBandedSolver(bool allow) {
    m_solver.setAllowBanded(allow);
    m_factorValid = false;
  }
  const AlphaParameters& parameters() const { return m_params; }
  /// Undoes the last accepted step: `previous` is the state before it (F_n is re-evaluated there).
  void restore(model::State& previous) { initialize(previous); }
  /// Out-of-balance force F at the last accepted state (full DOFs) [N]; its values at constrained
  /// DOFs are the support reactions.
  const VecX& lastForce() const { return m_forceOld; }

 private:
  /// One attempt at a step with the Newton path m_mode (step() tries the fallbacks); the contract of step().
  StepOutcome attempt(model::State& state, double dt);
  void applyPrescribed(model::State& state, double t) const;
  /// Sets the moved nodes (m_moved) of `state` from the step's start and increment dq: positions, triads,
  /// and the Newmark velocities and accelerations of their free DOFs; the other nodes keep theirs.
  void moveNodes(model::State& state, const model::State& start, const VecX& dq, double dt) const;
  /// Applies the Newton correction m_delta to dq: only at the nodes where it changes a force by more than
  /// kNegligibleCorrection of the allowed out-of-balance, when those are few (true: m_moved and m_part
  /// are set for an iteration on a part), else everywhere (false).
  bool applyCorrection(VecX& dq, bool partsAllowed);
  /// Sets m_delta to the Newton correction for the out-of-balance r (equations) with the kept
  /// factorisation, in the independent blocks of the matrix that have not converged (all of it when it is
  /// one block, or with `assembly: whole`), and m_activeRanges to their equations; m_delta is not set
  /// outside them. Returns the number of blocks left out.
  int solveCorrection(const VecX& r);
  /// After a converged step: whether the next step refreshes the kept matrix (m_refreshDue), from the
  /// residual evaluations of the steps since the last refresh (`refreshed`: this step made a whole one).
  void planRefresh(const StepOutcome& outcome, bool refreshed);
  /// Largest out-of-balance relative to what each equation is allowed (NaN if r holds a NaN); with
  /// independent blocks in the kept matrix also each block's (m_blockRatio), recomputed on a part
  /// (`onPart`) only for the blocks holding one of its nodes.
  double residualRatio(const VecX& r, bool onPart);
  /// True when m_blockStart is the kept matrix's block partition.
  bool sameBlocks() const;
  /// Sets m_slowBlocks to the blocks of the kept matrix, evaluated at this iterate, whose out-of-balance is
  /// above the tolerance and fell by less than 4x since the last iteration (m_blockRatio against
  /// m_previousBlockRatio, of the same partition).
  void findSlowBlocks();
  /// Assembles and factorises the iteration matrix of the blocks m_slowBlocks alone at `state` (the iterate
  /// whose residual `r` is being corrected), the other blocks kept; of a block only the stretch of its nodes
  /// out of balance when that stretch is at most half the block and has no rotations (a cable's). With one
  /// block, only a stretch (else false). False when that cannot stand for a whole
  /// refresh (a block holds a vessel's or a contact's node, the pattern changed, a pivot vanished): the
  /// caller refreshes the whole matrix (m_factorValid is false when the factors were touched).
  bool refreshBlocks(const model::State& state, const solver::AssemblyRequest& request, double mf,
                     const VecX& r);
  /// Time at which loads and prescribed motions are evaluated for a state at time t [s].
  double environmentTime(double t) const { return m_frozen ? m_frozenTime : t; }

  solver::Assembler* m_assembler;
  model::DynamicSpec m_settings;
  std::vector<model::PrescribedNode> m_prescribed;
  AlphaParameters m_params;
  std::vector<double> m_nodeFloor;  // round-off floor of each node this step [N]
  std::vector<int> m_constrainedDofs;  // full DOFs without an equation
  VecX m_delta;                     // Newton correction of the equations [m, rad]
  VecX m_inverseAllowed;                   // 1 / allowed out-of-balance of each equation this step [1/N or 1/(N m)]
  solver::SystemMatrix m_matrix;
  solver::LinearSolver m_solver{true};  // banded when the pattern suits (LinearSolver.hpp)
  SparseMatrix m_k;
  VecX m_forceOld;  // F(q_n, v_n, t_n)
  // step()'s work space: the state at the step's start, the prescribed target, the increment over the step
  // (full DOFs), the mass combination, the inertia force and the residual (equations).
  model::State m_start, m_target;
  VecX m_dq, m_combo, m_inertia, m_residual;
  VecX m_force;
  std::vector<bool> m_prescribedDof;
  // Independent blocks (theory manual 8.2): the block partition and each block's state; iterations on a
  // part: the nodes the last correction moved, the part of the model re-evaluated for them, and the
  // diagonal of the factorised matrix [N/m, N m/rad].
  std::vector<int> m_blockStart;                    // block partition m_blockRatio is for (empty: one block)
  std::vector<double> m_blockRatio;                 // largest out-of-balance / allowed in each block
  std::vector<char> m_blockTouched;                 // work space of residualRatio
  std::vector<int> m_activeBlocks;                  // blocks solved by the last solveCorrection
  std::vector<double> m_previousBlockRatio;         // m_blockRatio at the last iteration (findSlowBlocks)
  std::vector<int> m_slowBlocks;                    // blocks to refresh on their own (findSlowBlocks)
  std::vector<int> m_wholeSlowBlocks;               // those refreshed whole (refreshBlocks)
  std::vector<int> m_slowNodes;                     // one's nodes or stretch (refreshBlocks)
  solver::AssemblyPart m_refreshPart;               // the part of the model they make
  std::vector<std::pair<int, int>> m_activeRanges;  // their equations [begin, end), ascending
  std::vector<unsigned char>
      m_equationMoved;  // applyCorrection: 1 where an equation's correction is not negligible
  std::vector<int> m_moved;
  int m_futileTries = 0;            // corrections in a row that tried a part and found none
  int m_partsPaused = 0;            // corrections left that do not try (applyCorrection)
  solver::AssemblyPart m_part;
  VecX m_kDiagonal;
  bool m_debug = false;  // TANGLE_DEBUG_DYNAMICS set: print every Newton iteration on stderr
  model::DynamicSolverSpec m_choice;  // dynamics.solver: the path every step tries first
  model::DynamicSolverSpec m_mode;    // the path of the attempt under way (step(): the choice or a fallback)
  bool m_factorValid = false;    // m_solver holds a factorisation usable for the next step
  bool m_reuseAcrossSteps = true;  // keep the factorisation from step to step while it converges fast
  int m_stepsSinceRefresh = 0;     // converged steps with the kept matrix (planRefresh)
  double m_evaluationsSinceRefresh = 0.0;  // their residual evaluations (parts count half)
  double m_recentEvaluations = 0.0;        // smoothed evaluations of the latest steps
  bool m_refreshDue = false;               // the next step refreshes the matrix
  double m_factorStep = 0.0;     // the time step that factorisation was made for [s]
  double m_lastStep = 0.0;       // the last converged step [s]
  bool m_frozen = false;         // freezeEnvironment was called
  double m_frozenTime = 0.0;     // [s]
};

}  // namespace tangle::time

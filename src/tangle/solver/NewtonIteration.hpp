#pragma once
/// @file NewtonIteration.hpp
/// The Newton iteration of an implicit time step, apart from the integrator that forms its residual
/// (OpenSees' split of Integrator and Algorithm; time::GeneralizedAlpha is the integrator): the convergence
/// test, the iteration matrix and its factorisation, and how that matrix is kept and refreshed (modified
/// Newton, docs/theory.md 8.2):
///  - the factorised matrix is kept while the out-of-balance falls by 4x or more per iteration, from step
///    to step as well, and the next step refreshes it when keeping it has come to cost more residual
///    evaluations than a refresh (the renewal rule, planRefresh);
///  - with independent blocks in the matrix (lines not coupled to each other) the test, the solve and the
///    refresh are per block, and of a cable's block only the stretch out of balance (its touchdown zone) is
///    refreshed (refreshSlow);
///  - a correction that moves only a few nodes is applied to those alone, and the next residual is
///    evaluated on the part of the model around them (applyCorrection, Assembler::assemblePart).
/// `model::DynamicSolverSpec` chooses which of these are used (`dynamics.solver` in the model file); the
/// integrator's step tries the plainer paths when the chosen one does not converge.
///
/// Protocol for one attempt at a step: setAllowed, startAttempt; then per iteration: wantsMatrix (assemble
/// the matrix into matrix() with the residual when true), residualRatio; when not converged, afterResidual
/// (false: redo the iteration with a whole refresh), factorize when the matrix was assembled,
/// solveCorrection, applyCorrection. After a converged step, planRefresh.

#include <string>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle::solver {

/// What the iteration matrix cost in one attempt at a step.
struct MatrixWork {
  int refreshes = 0;       ///< iteration matrices assembled and factorised whole
  int blockRefreshes = 0;  ///< independent blocks (or stretches of one) assembled and factorised on their own
  int blocksLeft = 0;      ///< converged independent blocks not solved at a correction (solveCorrection)
  int stepLengthChanges = 0;  ///< kept matrices made for another step length with the mass matrix alone
  bool refreshed = false;     ///< a whole matrix was factorised in this attempt
};

/// Newton iteration with a kept (modified Newton) or fresh (full Newton) iteration matrix; see the file
/// comment for the protocol.
class NewtonIteration {
 public:
  /// `debug`: print the refresh decisions on stderr (TANGLE_DEBUG_DYNAMICS).
  NewtonIteration(Assembler& assembler, bool debug);

  /// Sets the out-of-balance each equation is allowed this step: tolerance times its node's force scale
  /// (Assembler::nodeForceScale, [N]), or the node's round-off floor `nodeFloor` [N] when larger; moments
  /// over the node's moment scale [m].
  void setAllowed(double tolerance, const std::vector<double>& nodeFloor);
  /// The out-of-balance force each node is allowed this step (setAllowed's) [N].
  const std::vector<double>& allowedForce() const { return m_allowedForce; }
  /// Starts an attempt at a step of dt [s] from `start` on the Newton path `mode`, whose iteration matrix
  /// holds the mass matrix times `massFactor` [1/s^2]: the kept factorisation is used when it was made for
  /// this step length and no refresh is due. Right after a converged step, a kept matrix of another step
  /// length is made for this one as K_kept + (massFactor - its mass factor) M, M the mass matrix at `start`
  /// alone (Assembler::addMass at a factor of 1), and factorised again without the rest of an assembly (a
  /// step length that changes at every step, as the contact's impact steps do, refreshed the whole matrix at
  /// each: 374 of drilling-riser-drift's 733 refreshes).
  void startAttempt(const model::State& start, double dt, const model::DynamicSolverSpec& mode,
                    double massFactor);
  const model::DynamicSolverSpec& mode() const { return m_mode; }
  /// True when this iteration assembles and factorises a new matrix (none kept, or full Newton).
  bool wantsMatrix() const { return !m_haveFactor || !m_mode.modifiedNewton; }
  /// The matrix the assembly adds its entries to when wantsMatrix() (also work space for the caller between
  /// attempts: invalidate() after such use).
  SystemMatrix& matrix() { return m_matrix; }
  /// Forgets the kept factorisation: the next attempt starts with a fresh matrix.
  void invalidate() { m_factorValid = false; }
  /// Use the banded linear solver when the pattern suits (the default; LinearSolver.hpp).
  void setBandedSolver(bool allow) {
    m_solver.setAllowBanded(allow);
    m_factorValid = false;
  }

  /// Largest out-of-balance of the equations' residual r [N, N m] relative to what each is allowed (NaN if r
  /// holds a NaN); with independent blocks in the kept matrix also each block's, recomputed on a part
  /// (`onPart`: r changed only at part().nodes) only for the blocks holding one of its nodes.
  double residualRatio(const VecX& r, bool onPart);
  /// After an iteration that did not converge (largest ratio `ratio`, residual r at `state`): with a kept
  /// matrix whose convergence slowed (a ratio that fell by less than 4x), the slow blocks' or stretch's
  /// matrix is made again at this iterate (request and mf [1/s^2]: the assembly's, for a matrix), or, when
  /// that cannot be done, false: the caller redoes this iteration with a whole new matrix (wantsMatrix() is
  /// then true). `matrixAssembled`: this iteration assembled a whole matrix.
  bool afterResidual(const model::State& state, const AssemblyRequest& request, double mf, const VecX& r,
                     double ratio, bool matrixAssembled);
  /// Factorises the matrix assembled at this iteration for a step of dt [s], its mass matrix times
  /// `massFactor` [1/s^2]; false if it is singular.
  bool factorize(double dt, double massFactor);
  /// Sets correction() to the Newton correction for the out-of-balance r with the kept factorisation, in the
  /// blocks that have not converged (all of it when it is one block, or without part iterations).
  void solveCorrection(const VecX& r);
  /// The Newton correction of the equations [m, rad], zero in the blocks left out (the caller may scale it
  /// before applyCorrection).
  VecX& correction() { return m_delta; }
  /// Adds the correction to dq (full DOFs): only at the nodes where it changes a force by more than a fifth
  /// of the allowed out-of-balance, when those are few and `partsAllowed` (true: movedNodes() and part() are
  /// the nodes moved and the part of the model to evaluate next), else everywhere (false).
  bool applyCorrection(VecX& dq, bool partsAllowed);
  const std::vector<int>& movedNodes() const { return m_moved; }
  const AssemblyPart& part() const { return m_part; }
  /// The work of the attempt under way.
  const MatrixWork& work() const { return m_work; }
  /// After a converged step of `iterations` residual evaluations, `partIterations` of them on parts:
  /// whether the next step refreshes the kept matrix. `relaxation`: dynamic relaxation (the renewal rule
  /// is not applied).
  void planRefresh(int iterations, int partIterations, bool relaxation);

 private:
  /// True when m_blockStart is the kept matrix's block partition.
  bool sameBlocks() const;
  /// Sets m_slowBlocks to the blocks of the kept matrix, evaluated at this iterate, whose out-of-balance is
  /// above the tolerance and fell by less than 4x since the last iteration.
  void findSlowBlocks();
  /// Assembles and factorises the iteration matrix of the blocks m_slowBlocks alone at `state` (the iterate
  /// whose residual `r` is being corrected), the other blocks kept; of a block only the stretch of its nodes
  /// out of balance when that stretch is at most half the block and has no rotations (a cable's). With one
  /// block, only a stretch (else false). False when that cannot stand for a whole refresh (a block holds a
  /// vessel's or a contact's node, the pattern changed, a pivot vanished): the caller refreshes the whole
  /// matrix (m_factorValid is false when the factors were touched).
  bool refreshBlocks(const model::State& state, const AssemblyRequest& request, double mf, const VecX& r);

  Assembler* m_assembler;
  bool m_debug;
  model::DynamicSolverSpec m_mode;  // the path of the attempt under way
  MatrixWork m_work;
  VecX m_delta;           // Newton correction of the equations [m, rad]
  VecX m_inverseAllowed;  // 1 / allowed out-of-balance of each equation this step [1/N or 1/(N m)]
  std::vector<double> m_allowedForce;  // allowed out-of-balance force of each node this step [N]
  SystemMatrix m_matrix;
  LinearSolver m_solver{true};  // banded when the pattern suits (LinearSolver.hpp)
  SparseMatrix m_k;
  VecX m_kDiagonal;              // diagonal of the factorised matrix [N/m, N m/rad]
  bool m_haveFactor = false;     // this attempt's current iterate may use the kept factorisation
  double m_previousRatio = 0.0;  // largest ratio at the last iteration of this attempt
  // Independent blocks (theory manual 8.2): the block partition and each block's state.
  std::vector<int> m_blockStart;                    // block partition m_blockRatio is for (empty: one block)
  std::vector<double> m_blockRatio;                 // largest out-of-balance / allowed in each block
  std::vector<char> m_blockTouched;                 // work space of residualRatio
  std::vector<int> m_activeBlocks;                  // blocks solved by the last solveCorrection
  std::vector<double> m_previousBlockRatio;         // m_blockRatio at the last iteration (findSlowBlocks)
  std::vector<int> m_slowBlocks;                    // blocks to refresh on their own (findSlowBlocks)
  std::vector<int> m_wholeSlowBlocks;               // those refreshed whole (refreshBlocks)
  std::vector<int> m_slowNodes;                     // one's nodes or stretch (refreshBlocks)
  AssemblyPart m_refreshPart;                       // the part of the model they make
  std::vector<std::pair<int, int>> m_activeRanges;  // their equations [begin, end), ascending
  // Iterations on a part: the nodes the last correction moved and the part of the model re-evaluated for
  // them.
  std::vector<unsigned char> m_equationMoved;  // applyCorrection: 1 where a correction is not negligible
  std::vector<int> m_moved;
  AssemblyPart m_part;
  int m_futileTries = 0;  // corrections in a row that tried a part and found none
  int m_partsPaused = 0;  // corrections left that do not try (applyCorrection)
  // The kept factorisation from step to step (planRefresh).
  bool m_factorValid = false;              // m_solver holds a factorisation usable for the next step
  int m_stepsSinceRefresh = 0;             // converged steps with the kept matrix
  double m_evaluationsSinceRefresh = 0.0;  // their residual evaluations (parts count half)
  double m_recentEvaluations = 0.0;        // smoothed evaluations of the latest steps
  bool m_refreshDue = false;               // the next step refreshes the matrix
  double m_factorStep = 0.0;               // the time step that factorisation was made for [s]
  // A change of step length (startAttempt).
  bool m_afterConvergedStep = false;  // the last attempt converged (planRefresh) and none started since
  double m_factorMassFactor = 0.0;    // the mass factor the kept matrix holds [1/s^2]
  SystemMatrix m_massAssembly;        // M's assembly (replayed from one change to the next)
  SparseMatrix m_mass;                // M over the equations [kg, kg m^2]
  /// Factorises m_k as the kept matrix of a step of dt [s] with mass factor `massFactor` [1/s^2]; false
  /// (none kept) if it is singular.
  bool factorizeKept(double dt, double massFactor);
  /// Makes the kept matrix that of a step of dt [s] with mass factor `massFactor`, M taken at `state`
  /// (startAttempt); false (the factorisation dropped) when M has an entry outside the kept matrix's pattern
  /// or the matrix cannot be factorised.
  bool changeStepLength(const model::State& state, double dt, double massFactor);
};

/// True when two step lengths [s] are the same step: equal but for round-off (a step cut to land on an
/// output time is the difference of two times: 0.1 - 0.09 = 0.010000000000000009, not 0.01).
bool sameStep(double a, double b);

}  // namespace tangle::solver

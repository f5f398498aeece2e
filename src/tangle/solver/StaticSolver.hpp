#pragma once
/// @file StaticSolver.hpp
/// Static equilibrium of the whole model (docs/theory.md, "Static solution"):
///  1. Newton-Raphson from the starting shape with a Levenberg-Marquardt trust region: each
///     increment solves (K + mu D) dq = -r (D the diagonal of K) and is accepted only if it lowers
///     the scaled residual; mu grows on rejection and shrinks on success, so the iteration is plain
///     Newton (quadratic) near the solution and a damped, descent-like iteration far from it. The
///     largest nodal translation and rotation per iteration are capped, and contributors (contact) may
///     cap the increment further (LoadContributor::limitIncrement).
///  2. If that fails, continuation in a load fraction lambda from the starting shape: the equations
///     solved are r(q) - (1 - lambda) r(q0) = 0 (a Newton homotopy), so at lambda = 0 the starting
///     shape is the solution and every load - weight, buoyancy, current drag, vessel loads, end
///     offsets - is ramped together from the state the start shape balances to the full load.
///     Increments of lambda grow after successes and are cut after failures.
/// Convergence is measured against a force scale of the model that does not shrink with the mesh (the
/// largest line weight, see Assembler::forceScale) and accepts a residual stalled at the
/// round-off floor of the elements (Assembler::roundoffFloor). Seabed friction acts in statics as an
/// elastic-plastic spring to the as-laid position, committed after every converged increment.
/// A converged state is checked before it is reported: slack suspended cable elements (an unstable
/// branch for a line without bending stiffness) trigger a restart from a perturbed shape, and a state
/// a contributor rejects (lines passed through each other) is never reported as converged.

#include <functional>
#include <string>
#include <vector>

#include "tangle/core/ConsoleProgress.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::solver {

/// Outcome of a static solve.
struct StaticResult {
  bool converged = false;
  int iterations = 0;            ///< Newton iterations in all (accepted and rejected trial increments)
  double loadFraction = 0.0;     ///< largest load fraction at which equilibrium was reached [-]
  double residual = 0.0;         ///< final max out-of-balance force [N] (moments divided by 1 m)
  double tolerance = 0.0;        ///< force tolerance that was applied [N]
  bool roundoffLimited = false;  ///< accepted at the round-off floor, above the requested tolerance
  int worstNode = -1;            ///< global node with the largest out-of-balance force
  int continuationSteps = 0;     ///< load steps of the continuation from the start shape (0: Newton at full load)
  int currentSteps = 0;  ///< steps of the current continuation from still water (0: not used; StaticSolver)
  int arcLengthSteps = 0;  ///< of those, steps in arc length past a fold of the path (ArcLengthContinuation)
  std::string message;           ///< human-readable summary (on failure: where, how large, what to change)
  /// Set when the loading path itself has no equilibrium beyond the point it stopped at (a free line on the
  /// seabed slides as a whole at the fraction of the current's drag that `message` gives): the fallbacks,
  /// which leave the path (a coarse mesh, dynamic relaxation), are not tried.
  bool noEquilibrium = false;
  std::vector<std::string> warnings;  ///< e.g. bar elements left in compression
};

/// Static analysis driver.
class StaticSolver {
 public:
  StaticSolver(Assembler& assembler, const model::StaticSpec& settings) : m_assembler(&assembler), m_settings(settings) {}

  /// Solves for equilibrium starting from `state` (modified in place: on success it is the
  /// equilibrium; on failure the starting state or the last equilibrium reached at a lower load fraction).
  StaticResult solve(model::State& state, double time = 0.0);

  /// Puts the drag's dependence on the element directions (Morison.hpp, theory 6.4) into the tangent and
  /// solves with sparse LU. Off by default: measured on 60 trial models it turns 10-40x more iterations
  /// where a laid line slides under friction, but it rescues models with a limp line across a current
  /// (the caller's second attempt, Simulation::solveStatics). Does nothing without a current.
  void setDragStiffness(bool on) { m_dragStiffness = on; }
  /// True when the model has a current of non-zero speed at some level (so setDragStiffness matters).
  static bool hasCurrent(const model::Model& model);
  /// True when TANGLE_DEBUG_STATICS is set: statics and its fallbacks (Simulation::solveStatics) print their
  /// progress on stderr.
  static bool debugOutput();
  /// `engaged` tells whether line contact has carried force at a converged increment of this solve (null:
  /// no line contact). While it has, a load continuation whose increments fall below
  /// kContactCrawlIncrement stops there as stalled: it crawls through the contact's closing and sliding
  /// (a flexible pushed across an SCR by a current: 4 400 iterations, 11 s, from 0.4 to 0.93 of the drag in
  /// increments of 1e-3) where the caller's dynamic relaxation goes through them (Simulation::solveStatics).
  void setContactEngaged(std::function<bool()> engaged) { m_contactEngaged = std::move(engaged); }
  /// Smallest load increment a continuation takes while line contact is engaged [-] (setContactEngaged).
  static constexpr double kContactCrawlIncrement = 1.0 / 256.0;

  /// Prints progress lines (iterations, load fraction, out-of-balance) on `progress` while solving; `stage`
  /// names the attempt in them (e.g. "with a quarter of the elements"). Null: none (the default).
  void setProgress(core::ConsoleProgress* progress, std::string stage = {}) {
    m_progress = progress;
    m_progressStage = std::move(stage);
  }

 private:
  struct NewtonOutcome {
    bool converged = false;
    bool roundoff = false;
    int iterations = 0;
    double residual = 0.0;
    int worstNode = -1;
    std::string failure;  // why it stopped, when not converged
  };
  /// One attempt from `start` towards the full load, with continuation when needed.
  /// `tautStart`: see continuation().
  /// The first contributor's reason to reject `state` (LoadContributor::rejectState), empty if none.
  std::string inadmissible(const model::State& state) const;
  /// A continuation's increment below kContactCrawlIncrement with line contact engaged (setContactEngaged).
  bool crawlingInContact(double increment) const {
    return increment < kContactCrawlIncrement && m_contactEngaged && m_contactEngaged();
  }
  bool solveFrom(model::State& state, double time, StaticResult& result, int& budget, bool tautStart = false);
  /// Stage 2: the homotopy from `start` (see the file comment); `tautStart` also starts slack suspended cable
  /// elements at a small strain. On failure `failure` says why.
  bool continuation(model::State& state, const model::State& start, double time, StaticResult& result, int& budget,
                    bool tautStart, std::string& failure);
  /// Stage 2a, in a current: the equilibrium in still water from `state` (solveFrom without the current), then
  /// the current's drag ramped from there to its full value (its speed times sqrt(f) for f from 0 to 1), every
  /// increment an equilibrium of the model in a weaker current. On success `state` is the equilibrium.
  bool currentContinuation(model::State& state, double time, StaticResult& result, int& budget, bool tautStart);
  /// Newton (trust region) at a fixed load fraction; `offset` is (1 - lambda) r(q0) over the equations.
  enum class NewtonMode { Plain, Merit, Natural };
  /// Plain: every step that can be evaluated is taken (full Newton within the displacement caps; fails
  /// when the residual grows 8 times in a row); otherwise damped: the natural monotonicity test with a
  /// pseudo-transient shift.
  NewtonOutcome newton(model::State& state, const VecX& offset, double time, int maxIterations, double tolerance,
                       NewtonMode mode);
  /// Plain Newton, then the damped variants from the same start while they fail.
  NewtonOutcome newtonWithFallback(model::State& state, const VecX& offset, double time, int maxIterations,
                                   double tolerance);
  /// r over the equations from the full-DOF force vector minus the homotopy offset.
  void gatherResidual(const VecX& force, const VecX& offset, VecX& r) const;
  /// Where one path of the solve stopped short of its full load. The failure's message reports the path that
  /// got furthest, not the last one tried: a lazy-wave pair whose current ramp stalled at 0.293 of the drag
  /// near the downstream anchor was reported at the homotopy's 0.009, at the upstream line.
  struct Stall {
    std::string path;              ///< the path, as the message names it
    std::string context;           ///< the stage of solve() it ran in (m_pathContext), empty for the first
    std::string loading;           ///< what `fraction` is of ("the load", "the current's drag")
    double fraction = -1.0;        ///< the fraction of `loading` in equilibrium [-]
    double residual = 0.0;         ///< largest out-of-balance force where it stopped [N]
    int worstNode = -1;            ///< where that force is (global node; -1: unknown)
    Vec3 position = Vec3::Zero();  ///< that node's position then [m]
    std::string why;               ///< the last failure's reason
  };
  /// Records a stall of `path` (m_pathContext appended) for the final diagnosis.
  void noteStall(const std::string& path, const std::string& loading, double fraction, double residual,
                 int worstNode, const model::State& state, const std::string& why);
  /// Failure message: the furthest path's stall (where, how large), the others' reach, and what to change.
  std::string diagnose(const StaticResult& result) const;
  /// Failure message for one stall.
  std::string diagnose(const Stall& stall, const StaticResult& result, const std::string& others) const;

  /// Debug (TANGLE_DEBUG_TANGENT): prints how far `tangent` times the Newton `step` is from central
  /// differences of the residual along it.
  void checkTangent(const model::State& state, const AssemblyRequest& request, const VecX& offset,
                    const SparseMatrix& tangent, const VecX& step);

  Assembler* m_assembler;
  model::StaticSpec m_settings;
  double m_forceScale = 1.0;
  bool m_dragStiffness = false;
  std::function<bool()> m_contactEngaged;  // setContactEngaged
  bool m_wakeDragStiffness = false;  // AssemblyRequest::wakeDragStiffness of newton() (the arc length's end)
  core::ConsoleProgress* m_progress = nullptr;  // setProgress
  std::string m_progressStage;
  int m_progressIterations = 0;     // Newton iterations of this solve so far (for the progress lines)
  double m_progressFraction = 1.0;  // load fraction being solved for [-]
  double m_currentFactor = 1.0;     // AssemblyRequest::currentFactor of every assembly (currentContinuation)
  std::vector<Stall> m_stalls;      // of this solve, in the order tried (noteStall)
  std::string m_pathContext;        // the stage of solve() a path runs in, for its Stall::context
  bool m_stillWaterPath = false;    // solving in still water first (currentContinuation), for Stall::path
};

}  // namespace tangle::solver

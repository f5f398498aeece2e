#include "tangle/solver/StaticSolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <numbers>

#include "tangle/core/Error.hpp"
#include "tangle/core/Interrupt.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/solver/ArcLengthContinuation.hpp"
#include "tangle/solver/IncrementLimits.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/ResidualNorm.hpp"
#include "tangle/solver/StartShapeRepair.hpp"

namespace tangle::solver {

namespace {

/// A load fraction for a message: three decimals, more when that would round a fraction short of 1 up to
/// 1 (a continuation stalled at 0.99998 is not at the full load).
std::string fractionText(double fraction) {
  fraction = std::max(fraction, 0.0);
  if (fraction >= 1.0 || fraction < 0.9995) return fmt::format("{:.3f}", fraction);
  return fmt::format("{:.6f}", std::min(fraction, 0.999999));
}
/// Largest Levenberg-Marquardt factor before a Newton solve gives up [-].
constexpr double kMaxShift = 1e4;
/// Restarts from a perturbed shape when bar elements end in compression.
constexpr int kMaxPerturbedRestarts = 2;
bool debugTangent() {
  static const bool on = std::getenv("TANGLE_DEBUG_TANGENT") != nullptr;
  return on;
}
/// What a failed stage of solve() leaves in the result: its iterations, and where its path found that the
/// loading has no equilibrium (a laid line sliding as a whole), that diagnosis, which stops the later stages
/// and the caller's fallbacks (theory 7.1). (The hanging start and the cable-law stages dropped it, and the
/// fallbacks went on to blame another line.)
void keepFailedStage(StaticResult& result, const StaticResult& stage) {
  result.iterations = stage.iterations;
  if (stage.noEquilibrium) {
    result.noEquilibrium = true;
    result.message = stage.message;
  }
}
}  // namespace

bool StaticSolver::debugOutput() {
  static const bool on = std::getenv("TANGLE_DEBUG_STATICS") != nullptr;
  return on;
}

bool StaticSolver::hasCurrent(const model::Model& model) {
  if (model.environment().currentGrid) return true;  // (a grid of zeros too: harmless)
  for (const model::CurrentLevel& c : model.environment().current)
    if (c.speed != 0.0) return true;
  return false;
}

StaticResult StaticSolver::solve(model::State& state, double time) {
  StaticResult result;
  const model::Model& model = m_assembler->model();
  if (model.dofs().equationCount() == 0) {
    result.converged = true;
    result.loadFraction = 1.0;
    result.message = "no free degrees of freedom";
    return result;
  }
  m_forceScale = m_assembler->forceScale();
  result.tolerance = m_settings.tolerance * m_forceScale;
  const model::State start = state;
  m_stalls.clear();
  m_pathContext.clear();
  struct ClearContext {
    std::string* context;
    ~ClearContext() { context->clear(); }
  } clearContext{&m_pathContext};
  // Iterations in all: max_iterations bounds each Newton solve; the whole continuation gets 20 times that.
  int budget = std::max(20 * m_settings.maxIterations, 200);

  model::State trial = start;
  bool ok = solveFrom(trial, time, result, budget);
  if (!ok && !result.noEquilibrium) {
    // A line held at one end and free at the other that is far more flexible than its weight (a heavy
    // rope or slender pipe clamped horizontally, w L^3 / EI in the thousands) cannot be reached from the
    // given straight shape: its first Newton step is the linear deflection (kilometres) and every
    // continuation increment stretches the stiff elements. Start again with it hanging.
    model::State hanging = start;
    StaticResult stage = result;
    if (hangFreeLines(m_assembler->model(), hanging)) {
      if (debugOutput()) std::cerr << "  restart with the free lines hanging from their held ends\n";
      // Its own allowance: the attempt from the given shape may have used the whole budget.
      budget = std::max(budget, 5 * m_settings.maxIterations);
      m_pathContext = "with the free lines hanging from their held ends";
      if (solveFrom(hanging, time, stage, budget)) {
        ok = true;
        trial = hanging;
        result = stage;
      } else {
        keepFailedStage(result, stage);
      }
    }
  }
  // The next two variants change only the cable (bar) elements' law and start shape: a model of beams alone
  // would repeat the path it has just failed on (a flexible and an SCR in current: 6 s of the same crawl).
  const bool anyCable = std::any_of(model.elements().begin(), model.elements().end(),
                                    [](const model::LineElement& el) { return el.bar; });
  if (!ok && budget > 0 && !result.noEquilibrium && anyCable) {
    // Continuation in the cable law: solve with cables that resist compression like tension (a regular
    // tangent even where the start shape leaves them slack), then take that stiffness away in decades
    // down to the real, compression-free cable, each stage starting from the last equilibrium.
    const double slack = m_assembler->slackFactor();
    model::State linear = start;
    StaticResult stage = result;
    m_assembler->setSlackFactor(1.0);
    m_pathContext = "with the cables resisting compression as tension";
    bool staged = solveFrom(linear, time, stage, budget);
    for (double f = 0.1; staged; f *= 0.1) {
      // Down to the cables' own law (the lower bound 0 leaves LineType::compressionFactor, 1e-6 by default).
      const bool last = f < 1e-6;
      m_assembler->setSlackFactor(last ? 0.0 : f);
      m_pathContext = last ? "with the cables' own compression law, after the staged one"
                           : fmt::format("with the cables resisting compression at {:.0e} of tension", f);
      staged = solveFrom(linear, time, stage, budget);
      if (debugOutput())
        std::cerr << fmt::format("  cable compression factor {:.0e}: {}\n", last ? 0.0 : f,
                                 staged ? "ok" : "failed");
      if (last) break;
    }
    m_assembler->setSlackFactor(slack);
    if (staged) {
      ok = true;
      trial = linear;
      result = stage;
    } else {
      keepFailedStage(result, stage);
    }
  }
  if (!ok && budget > 0 && !result.noEquilibrium && anyCable) {
    // Last resort: the continuation again, with slack suspended cable elements starting taut.
    model::State taut = start;
    StaticResult stage = result;
    m_pathContext = "with the slack suspended cable elements starting taut";
    if (solveFrom(taut, time, stage, budget, true)) {
      ok = true;
      trial = taut;
      result = stage;
    } else {
      keepFailedStage(result, stage);
    }
  }
  m_pathContext.clear();
  for (int restart = 0; ok && restart < kMaxPerturbedRestarts; ++restart) {
    const std::vector<int> slackElements = slackSuspendedBars(m_assembler->model(), trial);
    if (slackElements.empty()) break;
    // A slack line without bending stiffness is on an unstable or indifferent branch (e.g. a buoyant cable
    // pushed straight): start again from a shape bulged the way its load pushes it.
    if (debugOutput())
      std::cerr << fmt::format("  {} slack cable elements: restart from a bulged shape\n",
                               slackElements.size());
    model::State again = trial;
    bulgeSlackRuns(m_assembler->model(), again, slackElements);
    StaticResult second = result;
    if (solveFrom(again, time, second, budget)) {
      trial = again;
      result = second;
      continue;
    }
    // The failed attempt laid the seabed anchors and the contact's references afresh at its own states
    // (solveFrom, beginStatics): the equilibrium found before is solved again from itself, so that what is
    // committed (the friction that holds it) is its own. (Kept as it was, the laid line of a current held by
    // friction was returned with anchors of the failed attempt: 0.23 of its weight out of balance in the
    // equilibrium audit, and the dynamics started by jumping.)
    result.iterations = second.iterations;
    model::State resolved = trial;
    StaticResult third = result;
    m_pathContext = "again from the equilibrium found, after a restart from a bulged shape failed";
    budget = std::max(budget, m_settings.maxIterations);  // its own allowance: the restart may have used all
    if (solveFrom(resolved, time, third, budget)) {
      trial = resolved;
      result = third;
    } else {
      ok = false;
      keepFailedStage(result, third);
    }
    m_pathContext.clear();
    break;
  }
  if (ok) {
    const std::vector<int> slackElements = slackSuspendedBars(m_assembler->model(), trial);
    if (!slackElements.empty()) {
      const int e = slackElements.front();
      const auto& el = model.elements()[e];
      result.warnings.push_back(fmt::format(
          "{} suspended cable element(s) are slack (shorter than unstretched) at the static equilibrium "
          "(first at "
          "{}): a line without bending stiffness cannot carry compression; check the line length against the "
          "distance between its ends, or give the section a bending_stiffness",
          slackElements.size(), model.describeNode(el.node1)));
    }
    const std::string why = m_assembler->rejectState(trial);
    if (!why.empty()) {
      ok = false;
      result.message = fmt::format("static analysis reached a state that is not admissible: {}", why);
    }
  }
  result.converged = ok;
  if (ok) {
    state = trial;
    result.loadFraction = 1.0;
    result.message = result.roundoffLimited ? fmt::format(
                                                  "static equilibrium found in {} iterations (max "
                                                  "out-of-balance {:.3g} N: the round-off floor, "
                                                  "above the requested {:.3g} N)",
                                                  result.iterations, result.residual, result.tolerance)
                                            : fmt::format(
                                                  "static equilibrium found in {} iterations (max "
                                                  "out-of-balance {:.3g} N, tolerance {:.3g} N)",
                                                  result.iterations, result.residual, result.tolerance);
    // The path taken, for the log: Newton at the full load failed and the load was continued from the start
    // shape (a hint that the start shape is far from the equilibrium: docs/model-format.md, start_shape).
    if (result.continuationSteps > 0)
      result.message += fmt::format(", by continuation from the start shape in {} load steps",
                                    result.continuationSteps);
    if (result.currentSteps > 0)
      result.message += fmt::format(", from the equilibrium in still water with the current ramped in {} steps",
                                    result.currentSteps);
    if (result.arcLengthSteps > 0)
      result.message +=
          fmt::format(" ({} of them in arc length past a fold of the path)", result.arcLengthSteps);
  } else {
    if (result.message.empty()) result.message = diagnose(result);
    state = start;
  }
  return result;
}

std::string StaticSolver::inadmissible(const model::State& state) const {
  return m_assembler->rejectState(state);
}

bool StaticSolver::solveFrom(model::State& state, double time, StaticResult& result, int& budget,
                             bool tautStart) {
  const model::Model& model = m_assembler->model();
  const int neq = model.dofs().equationCount();
  const model::State start = state;
  const double tolerance = result.tolerance;
  const int perSolve = std::max(m_settings.maxIterations, 10);

  // 1. Newton from the starting shape at the full load.
  m_assembler->beginStatics(start);
  const VecX noOffset = VecX::Zero(neq);
  NewtonOutcome full = newtonWithFallback(state, noOffset, time, std::min(perSolve, budget), tolerance);
  budget -= full.iterations;
  if (full.converged) {
    // A converged state that a contributor rejects (lines passed through each other) is not an
    // equilibrium of the problem: continue in load from the start shape instead.
    const std::string why = inadmissible(state);
    if (!why.empty()) {
      full.converged = false;
      full.failure = why;
      state = start;
    }
  }
  result.iterations += full.iterations;
  result.residual = full.residual;
  result.worstNode = full.worstNode;
  if (full.converged) {
    result.roundoffLimited = full.roundoff;
    m_assembler->commitIncrement(state);
    return true;
  }
  if (debugOutput())
    std::cerr << "  full load failed (" << full.failure << "): continuation from the start shape\n";
  noteStall("Newton at the full load", "", 0.0, full.residual, full.worstNode, start, full.failure);

  // 2. Continuation from lambda = 0 (the start shape) to 1 in the residual and in length:
  //    r(q; L(lambda)) - (1 - lambda) r(q0; L(0)) = 0, with L(lambda) = L0 + lambda (L - L0).
  //    Elements the start shape compresses (a kink of the analytic shape inside an element, which with
  //    EA ~ 1e9 N is a force of 1e8 N) start at their current chord, stress-free, and are paid out to
  //    their own length as lambda grows; all others keep their length. Every load is then ramped from
  //    the state the start shape balances, like a line paid out onto its final position.
  std::string failure = full.failure;
  // 2a. In a current, the current continued from still water (currentContinuation).
  if (budget > 0 && m_currentFactor == 1.0 && hasCurrent(model)) {
    if (currentContinuation(state, time, result, budget, tautStart)) return true;
    state = start;
    if (result.noEquilibrium) return false;
    m_assembler->beginStatics(start);
  }
  if (budget > 0 && continuation(state, start, time, result, budget, tautStart, failure)) return true;
  if (debugOutput()) std::cerr << "  continuation failed (" << failure << ")\n";
  state = start;
  return false;
}

bool StaticSolver::continuation(model::State& state, const model::State& start, double time,
                                StaticResult& result, int& budget, bool tautStart, std::string& failure) {
  const model::Model& model = m_assembler->model();
  const int neq = model.dofs().equationCount();
  const double tolerance = result.tolerance;
  const int perSolve = std::max(m_settings.maxIterations, 10);
  const VecX noOffset = VecX::Zero(neq);
  state = start;
  m_assembler->beginStatics(start);
  const std::size_t elementCount = model.elements().size();
  std::vector<double> startLength(elementCount, std::numeric_limits<double>::quiet_NaN());
  {
    const std::vector<double> tension = m_assembler->elementTension(start);
    for (std::size_t e = 0; e < elementCount; ++e) {
      const model::LineElement& el = model.elements()[e];
      const double chord = (start.position[el.node2] - start.position[el.node1]).norm();
      if (tension[e] < -1e-2 * m_forceScale) {
        startLength[e] = chord;
      } else if (tautStart && el.bar && chord <= el.restLength * (1.0 + 1e-5)) {
        // A slack suspended cable element (the analytic shape of a multi-section line is built on one
        // equivalent section, so some sections come out slightly short) has no stiffness across itself;
        // a current across the line then meets a singular tangent. In this second attempt it starts at a
        // strain of 1e-4, taut, and the length continuation takes that away again.
        const seabed::SeabedSurface& bed = model.seabedSurface();
        const double lowest =
            std::min(bed.gap(start.position[el.node1], 0.5 * model.nodeContactDiameter()[el.node1]),
                     bed.gap(start.position[el.node2], 0.5 * model.nodeContactDiameter()[el.node2]));
        if (lowest > 1e-3) startLength[e] = chord / (1.0 + 1e-4);
      }
    }
  }
  auto lengthsAt = [&](double lambda) {
    std::vector<double> l(elementCount, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t e = 0; e < elementCount; ++e)
      if (!std::isnan(startLength[e]))
        l[e] = startLength[e] + lambda * (model.elements()[e].restLength - startLength[e]);
    return l;
  };
  struct RestoreLengths {
    Assembler* a;
    ~RestoreLengths() { a->setRestLengths({}); }
  } restore{m_assembler};
  m_assembler->setRestLengths(lengthsAt(0.0));
  VecX force;
  VecX r0(neq);
  AssemblyRequest request;
  request.time = time;
  request.dynamic = false;
  request.wantMatrix = false;
  request.currentFactor = m_currentFactor;
  try {
    m_assembler->assemble(start, request, force, nullptr);
  } catch (const Error& e) {
    failure = fmt::format("the starting shape cannot be evaluated ({})", e.what());
    noteStall("the continuation from the start shape", "the load", 0.0, result.residual, result.worstNode,
              start, failure);
    return false;
  }
  gatherResidual(force, noOffset, r0);
  double reached = 0.0;
  double increment = 0.125;
  std::string lastFailure = failure;
  while (reached < 1.0 && budget > 0) {
    const double target = std::min(1.0, reached + increment);
    m_progressFraction = target;
    model::State trial = state;
    const VecX offset = (1.0 - target) * r0;
    m_assembler->setRestLengths(lengthsAt(target));
    // Intermediate states need not be as accurate as the final one: they are only starting points.
    const double tol = target < 1.0 ? std::max(tolerance, 1e-4 * m_forceScale) : tolerance;
    NewtonOutcome step = newtonWithFallback(trial, offset, time, std::min(perSolve, budget), tol);
    budget -= step.iterations;
    result.iterations += step.iterations;
    result.residual = step.residual;
    result.worstNode = step.worstNode;
    if (step.converged) {
      const std::string why = inadmissible(trial);
      if (!why.empty()) {
        step.converged = false;
        step.failure = why;
      }
    }
    if (debugOutput())
      std::cerr << fmt::format("  continuation lambda {:.5f} -> {}, {} iterations\n", target,
                               step.converged ? "ok" : step.failure, step.iterations);
    if (step.converged) {
      state = trial;
      m_assembler->commitIncrement(state);
      reached = target;
      result.loadFraction = reached;
      result.roundoffLimited = step.roundoff;
      ++result.continuationSteps;
      increment = std::min(1.0, increment * (step.iterations <= 6 ? 2.0 : 1.0));
    } else {
      lastFailure = step.failure;
      increment *= 0.25;
      if (increment < 1e-5 || crawlingInContact(increment)) break;
      m_assembler->beginStatics(state);  // from the last converged state, re-laid (theory 7.1)
    }
  }
  m_progressFraction = 1.0;
  if (reached >= 1.0) return true;
  failure = lastFailure;
  noteStall("the continuation from the start shape", "the load", reached, result.residual, result.worstNode,
            state, failure);
  return false;
}

bool StaticSolver::currentContinuation(model::State& state, double time, StaticResult& result, int& budget,
                                       bool tautStart) {
  // Why: a long line across a strong current swings hundreds of metres sideways (a lazy wave in 1500 m with
  // 1 m/s at the surface: about 300 m), the drag turns with it, and Newton at the full current, or the
  // homotopy from the start shape, crawls or stalls at a fold of the homotopy path (a fixed force field
  // (1 - lambda) r(q0) that does not turn with the line): 3 000 - 6 000 iterations, or a coarse mesh first.
  // In still water the analytic start shape is close (a few iterations), and every increment of a weaker
  // current is a physical equilibrium on the same stable branch, so the path has no fold.
  const model::Model& model = m_assembler->model();
  const int neq = model.dofs().equationCount();
  const double tolerance = result.tolerance;
  const int perSolve = std::max(m_settings.maxIterations, 10);
  struct RestoreFactor {
    double* factor;
    ~RestoreFactor() { *factor = 1.0; }
  } restore{&m_currentFactor};
  m_currentFactor = 0.0;
  if (m_progress) m_progress->stage("statics: the model in still water first, then the current ramped");
  model::State still = state;
  StaticResult stage = result;
  m_stillWaterPath = true;
  const bool calm = solveFrom(still, time, stage, budget, tautStart);
  m_stillWaterPath = false;
  result.iterations = stage.iterations;
  if (debugOutput()) std::cerr << "  current continuation: still water " << (calm ? "ok" : "failed") << "\n";
  if (!calm) return false;
  const int stillSteps = stage.continuationSteps;
  const VecX noOffset = VecX::Zero(neq);
  double reached = 0.0;  // fraction of the drag (of the current's speed squared) in equilibrium
  double increment = 0.25;
  int steps = 0;
  int slidingLine = -1;  // Assembler::lineSlidingAsAWhole at `still`, as committed
  std::string lastFailure;
  while (reached < 1.0 && budget > 0) {
    const double target = std::min(1.0, reached + increment);
    m_currentFactor = std::sqrt(target);
    m_progressFraction = target;
    model::State trial = still;
    // Every increment to the full tolerance: a looser one (the homotopy's 1e-4 of the force scale) is more
    // than the drag on a node of a long line, and the steps "converged" without moving.
    // Plain Newton only: an increment it does not converge is halved, which costs less than the damped
    // variants (about 80 iterations for each failed increment of the lazy wave in 1.5 m/s).
    NewtonOutcome step = newton(trial, noOffset, time, std::min(perSolve, budget), tolerance, NewtonMode::Plain);
    budget -= step.iterations;
    result.iterations += step.iterations;
    result.residual = step.residual;
    result.worstNode = step.worstNode;
    if (step.converged) {
      const std::string why = inadmissible(trial);
      if (!why.empty()) {
        step.converged = false;
        step.failure = why;
      }
    }
    if (debugOutput())
      std::cerr << fmt::format("  current continuation: drag fraction {:.5f} -> {}, {} iterations\n", target,
                               step.converged ? "ok" : step.failure, step.iterations);
    if (step.converged) {
      still = trial;
      m_assembler->commitIncrement(still);
      slidingLine = m_assembler->lineSlidingAsAWhole(still);  // against the anchors just committed
      reached = target;
      result.roundoffLimited = step.roundoff;
      ++steps;
      // Doubled after a quick increment; grown by a quarter after one of 7-10 iterations. Plain Newton
      // without the drag's stiffness converges linearly, in about as many iterations whatever the increment,
      // and an increment held until one took 6 or fewer crawled (a hose anchored under a chain tether: 290
      // increments of 2.4e-4 of the drag, 8-10 iterations each).
      increment = std::min(1.0, increment * (step.iterations <= 6    ? 2.0
                                             : step.iterations <= 10 ? 1.25
                                                                     : 1.0));
    } else {
      lastFailure = step.failure;
      increment *= 0.5;
      // A free laid line at its friction capacity slides as a whole: no smaller increment helps (below).
      if (increment < 1e-4 || slidingLine >= 0 || crawlingInContact(increment)) break;
      m_assembler->beginStatics(still);  // from the last converged state, re-laid (theory 7.1)
    }
  }
  if (reached < 1.0 && slidingLine >= 0) {
    // Stalled with a free line on the seabed held by friction at its capacity
    // (Assembler::lineSlidingAsAWhole): more current moves it as a whole, and no path (arc length round a
    // fold, or the fallbacks, which leave the path and lay the anchors afresh) reaches an equilibrium of this
    // loading (theory 7.1).
    result.noEquilibrium = true;
    result.message = fmt::format(
        "static analysis found no equilibrium: line '{}' lies on the seabed with both ends free and "
        "slides as a whole at {:.4f} of the current's drag, where the seabed friction reaches its capacity "
        "mu N at every node (environment.seabed.friction_coefficient {}); under the full current the drag "
        "on the laid line exceeds its friction capacity and it has no static equilibrium. What to change: "
        "hold or anchor an end of the line, or check the current and the friction coefficient",
        model.lines()[static_cast<std::size_t>(slidingLine)].name, reached,
        model.environment().seabed.frictionCoefficient);
    if (debugOutput()) std::cerr << "  " << result.message << "\n";
    m_progressFraction = 1.0;
    return false;
  }
  std::string path = "the current ramped from still water";
  double furthest = reached;
  if (reached < 1.0 && budget > 0 && reached > 0.0) {
    // Stalled: a fold of the equilibrium path (a line in another's wake whose drag falls as it closes in
    // collapses onto it, theory 12.2), or Newton failing on a tangent without that negative stiffness. Follow
    // the path in arc length, round a fold if there is one; at full current, Newton.
    if (m_progress) m_progress->stage("statics: the current continued in arc length past a fold of the path");
    ArcLengthContinuation::Settings settings;
    settings.tolerance = tolerance;
    settings.target = 1.0;
    settings.firstIncrement = std::max(increment * 64.0, 1e-3);
    settings.debug = debugOutput();
    // With the wake's drag in the tangent: on the path, where the lines close in, the corrections converge
    // only with the negative stiffness it holds.
    const bool wakes = !model.spec().wakes.empty();
    settings.nonSymmetricTangent = wakes;
    auto finish = [&](model::State& trial) {
      m_currentFactor = 1.0;
      m_wakeDragStiffness = wakes;
      NewtonOutcome last = newton(trial, noOffset, time, std::min(perSolve, std::max(budget, 0)), tolerance,
                                  NewtonMode::Plain);
      m_wakeDragStiffness = false;
      budget -= last.iterations;
      result.iterations += last.iterations;
      result.residual = last.residual;
      result.worstNode = last.worstNode;
      if (last.converged && !inadmissible(trial).empty()) last.converged = false;
      if (last.converged) result.roundoffLimited = last.roundoff;
      if (debugOutput())
        std::cerr << fmt::format("  arc length: Newton at the full current {} in {} iterations\n",
                                 last.converged ? "converged" : last.failure, last.iterations);
      return last.converged;
    };
    ArcLengthContinuation arc(
        *m_assembler, settings,
        [wakes](double lambda, AssemblyRequest& request) {
          request.currentFactor = std::copysign(std::sqrt(std::abs(lambda)), lambda);
          request.wakeDragStiffness = wakes;
        },
        finish);
    m_assembler->beginStatics(still);
    // Its own share of what is left, so that the later stages (the homotopy, the caller's coarser mesh)
    // keep theirs when the path cannot be followed.
    int arcBudget = std::min(budget, 10 * perSolve);
    const int arcStart = arcBudget;
    const ArcLengthContinuation::Outcome arcOutcome = arc.run(still, reached, arcBudget);
    budget -= arcStart - arcBudget;
    result.iterations += arcOutcome.iterations;
    steps += arcOutcome.steps;
    if (arcOutcome.reached) {
      reached = 1.0;
      result.arcLengthSteps = arcOutcome.steps;
      // The closing Newton's equilibrium committed (seabed friction anchors, contact), as every other path's.
      m_assembler->commitIncrement(still);
    } else {
      result.residual = arcOutcome.residual;
      result.worstNode = arcOutcome.worstNode;
      path += ", then followed in arc length";
      furthest = std::max(reached, arcOutcome.lambda);
      lastFailure = arcOutcome.failure;
      if (debugOutput()) std::cerr << "  arc length failed: " << arcOutcome.failure << "\n";
    }
  }
  m_progressFraction = 1.0;
  if (reached < 1.0) {
    noteStall(path, "the current's drag", furthest, result.residual, result.worstNode, still, lastFailure);
    return false;
  }
  state = still;
  result.loadFraction = 1.0;
  result.continuationSteps = stillSteps;
  result.currentSteps = steps;
  return true;
}

StaticSolver::NewtonOutcome StaticSolver::newtonWithFallback(model::State& state, const VecX& offset,
                                                             double time, int maxIterations,
                                                             double tolerance) {
  // A portfolio, cheapest first: plain Newton (quadratic, and the only one that takes the large
  // non-monotone first steps of axially stiff beams), then pseudo-transient continuation judged on the
  // residual (slack cables), then damped Newton judged by the natural monotonicity test.
  NewtonOutcome out;
  int used = 0;
  for (NewtonMode mode : {NewtonMode::Plain, NewtonMode::Merit, NewtonMode::Natural}) {
    model::State trial = state;
    out = newton(trial, offset, time, maxIterations, tolerance, mode);
    used += out.iterations;
    if (out.converged) {
      state = trial;
      break;
    }
    if (debugOutput())
      std::cerr << "   Newton mode " << static_cast<int>(mode) << " failed: " << out.failure << "\n";
  }
  out.iterations = used;
  return out;
}

StaticSolver::NewtonOutcome StaticSolver::newton(model::State& state, const VecX& offset, double time,
                                                 int maxIterations, double tolerance, NewtonMode mode) {
  const bool plain = mode == NewtonMode::Plain;
  const bool merit = mode == NewtonMode::Merit;
  NewtonOutcome out;
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const int neq = dofs.equationCount();
  const auto& eqDofs = dofs.equationDofs();
  double lref = 1.0;
  for (const auto& line : model.lines()) lref = std::max(lref, line.length);
  // Largest nodal translation [m] and rotation [rad] per iteration (a trust region in displacement).
  const double maxTranslation = translationCap(model);
  const double maxRotation = kRotationCap;
  const double floor = m_assembler->roundoffFloor(state);
  if (debugOutput())
    std::cerr << fmt::format("   round-off floor {:.3g} N, tolerance {:.3g} N\n", floor, tolerance);

  AssemblyRequest request;
  request.time = time;
  request.dynamic = false;
  // In a current, when asked for: the drag's follower stiffness (theory 6.4) in the tangent, solved by LU.
  request.dragStiffness = m_dragStiffness && hasCurrent(model);
  request.wakeDragStiffness = m_wakeDragStiffness;
  request.currentFactor = m_currentFactor;
  SystemMatrix matrix(dofs);
  SparseMatrix kAccepted;
  SparseMatrix k;
  LinearSolver solver;
  solver.setNonSymmetric(request.dragStiffness || request.wakeDragStiffness);
  VecX force;
  VecX r(neq), rTrial(neq);
  m_assembler->beginStep();
  try {
    m_assembler->assemble(state, request, force, &matrix);
  } catch (const Error& e) {
    out.failure = fmt::format("an element cannot be evaluated ({})", e.what());
    return out;
  }
  gatherResidual(force, offset, r);
  matrix.build(kAccepted);

  out.residual = residualNorm(model, r, ResidualIndexing::Equations, &out.worstNode, kStaticMomentLever);
  if (debugOutput() && out.worstNode >= 0)
    std::cerr << fmt::format("   start |r| {:.4e} N at {}\n", out.residual,
                             model.describeNode(out.worstNode));
  double mu = 0.0;
  int stalled = 0;
  double best = out.residual;
  int sinceBest = 0;
  double lastStep = std::numeric_limits<double>::infinity();
  double lastShift = 0.0;
  bool lastCapped = false;
  bool assembledAtState = true;  // false while the last assembly was of a refused trial
  for (int it = 0; it < maxIterations; ++it) {
    if (core::interruptRequested()) {  // Ctrl-C / SIGTERM: stop now, not after every remaining stage
      out.failure = "interrupted by the user";
      return out;
    }
    if (!std::isfinite(out.residual)) {
      out.failure = "the out-of-balance force is not finite";
      return out;
    }
    // Converged: forces balanced to the tolerance, or stalled at the round-off floor of the elements
    // (a residual cannot be driven below the noise of EA times the strain round-off).
    const bool balanced = out.residual <= tolerance;
    // The step criterion: a correction of 1e-12 of the model's size changes only the last few digits of
    // the coordinates, so the residual is whatever round-off leaves (seen with fine beam meshes).
    // Only a full (unshifted) Newton step counts: a step made tiny by the pseudo-transient shift says
    // nothing about convergence.
    const bool roundoff = stalled >= 2 && (out.residual <= floor ||
                                           (lastStep <= 1e-12 * lref && lastShift == 0.0 && !lastCapped));
    if (balanced || roundoff) {
      // The contributors' trial data (seabed friction anchors, contact samples) are the last assembly's:
      // after a refused trial, that was the trial's. Assembled again at the state returned, so that what the
      // caller commits and the active set are the returned state's.
      if (!assembledAtState) {
        try {
          m_assembler->assemble(state, request, force, &matrix);
        } catch (const Error& e) {
          out.failure = fmt::format("an element cannot be evaluated ({})", e.what());
          return out;
        }
        assembledAtState = true;
      }
      if (!m_assembler->updateActiveSet()) {
        out.converged = true;
        out.roundoff = !balanced;
        return out;
      }
      // A contributor changed its active set (a contact released): iterate on.
      m_assembler->assemble(state, request, force, &matrix);
      gatherResidual(force, offset, r);
      matrix.build(kAccepted);
      out.residual = residualNorm(model, r, ResidualIndexing::Equations, &out.worstNode, kStaticMomentLever);
      stalled = 0;
      continue;
    }
    out.iterations = it + 1;
    ++m_progressIterations;
    if (m_progress && m_progress->due())
      m_progress->print(fmt::format("statics{}: {} Newton iterations, load fraction {:.3f}, out-of-balance {:.3g} N",
                                    m_progressStage.empty() ? "" : " " + m_progressStage, m_progressIterations,
                                    m_progressFraction, out.residual));
    const SparseMatrix* system = &kAccepted;
    if (mu > 0.0) {
      k = kAccepted;
      // Fictitious mass D of the pseudo-transient term: per node, the largest diagonal stiffness of its
      // translations (and of its rotations), the same in every direction, so a direction in which the
      // tangent has no stiffness (a slack line laterally on a frictionless seabed) is damped like the
      // stiff ones. Scaled per node: one scale for all (a vessel's link) would soften every line DOF.
      VecX diag = k.diagonal().cwiseAbs();
      {
        VecX nodeMax = VecX::Zero(2 * dofs.nodeCount());
        for (int i = 0; i < neq; ++i) {
          const int dof = eqDofs[i];
          const int n = dofs.nodeOf(dof);
          const int slot = 2 * n + (dof - dofs.firstDof(n) < 3 ? 0 : 1);
          nodeMax[slot] = std::max(nodeMax[slot], diag[i]);
        }
        for (int i = 0; i < neq; ++i) {
          const int dof = eqDofs[i];
          const int n = dofs.nodeOf(dof);
          diag[i] = nodeMax[2 * n + (dof - dofs.firstDof(n) < 3 ? 0 : 1)];
        }
      }
      const double dmax = std::max(diag.maxCoeff(), 1e-12);
      for (int i = 0; i < neq; ++i) k.coeffRef(i, i) += mu * std::max(diag[i], 1e-9 * dmax);
      system = &k;
    }
    if (!solver.factorize(*system)) {
      mu = std::max(1e-4, mu * 10.0);
      if (mu > kMaxShift) {
        out.failure = "the stiffness matrix is singular";
        return out;
      }
      continue;
    }
    const VecX dq = -solver.solve(r);
    if (debugTangent()) checkTangent(state, request, offset, kAccepted, dq);
    double largestT = 0.0, largestR = 0.0;
    int largestNode = -1;
    for (int i = 0; i < neq; ++i) {
      const int dof = eqDofs[i];
      const bool translation = dof - dofs.firstDof(dofs.nodeOf(dof)) < 3;
      if (translation && std::abs(dq[i]) > largestT) largestNode = dofs.nodeOf(dof);
      (translation ? largestT : largestR) = std::max(translation ? largestT : largestR, std::abs(dq[i]));
    }
    if (debugOutput() && largestNode >= 0)
      std::cerr << fmt::format("    largest step {:.3e} m at {}\n", largestT,
                               model.describeNode(largestNode));
    double scale = 1.0;
    if (largestT > maxTranslation) scale = std::min(scale, maxTranslation / largestT);
    if (largestR > maxRotation) scale = std::min(scale, maxRotation / largestR);
    VecX full = VecX::Zero(dofs.fullDofCount());
    for (int i = 0; i < neq; ++i) full[eqDofs[i]] = scale * dq[i];
    // A step shortened by a contributor (no line through another) or by the strain trust region below is
    // no full Newton step: its length says nothing about convergence at the round-off floor.
    bool capped = false;
    for (LoadContributor* c : m_assembler->contributors()) {
      const double limit = c->limitIncrement(state, full);
      if (limit < 1.0) {
        full *= std::max(limit, 0.0);
        scale *= std::max(limit, 0.0);
        capped = true;
      }
    }
    // Trust region in cable strain (see kMaxStrainStep): the largest stretch of a bar beyond max(its strain
    // now, 0) that the linearised step proposes, in units of the allowed one.
    {
      const double worst = strainStepRatio(model, *m_assembler, state, full);
      if (worst > 1.0) {
        full /= worst;
        scale /= worst;
        capped = true;
      }
    }
    model::State trial = state;
    trial.applyIncrement(dofs, full);
    lastStep = scale * largestT;
    lastShift = mu;
    lastCapped = capped;
    bool evaluated = true;
    try {
      m_assembler->assemble(trial, request, force, &matrix);
    } catch (const Error&) {
      evaluated = false;  // an element folded on itself: the increment is too large
    }
    // Natural monotonicity test (Deuflhard 2004, "Newton methods for nonlinear problems", sec. 3.3): the
    // simplified Newton correction at the trial state with the same factorisation must be shorter than
    // the step just taken (Theta < 1). Unlike a residual norm it is affine invariant: a large residual in
    // a stiff direction (an axially stiff beam stretched by a rotation step, EA theta^2 / 2) needs only a
    // tiny correction and is accepted, while a residual in a soft or singular direction (a slack line)
    // is not. Lengths are compared in metres, rotations over a 1 m lever.
    double theta = std::numeric_limits<double>::infinity();
    if (evaluated) {
      gatherResidual(force, offset, rTrial);
      if (rTrial.allFinite() && (!plain || debugOutput())) {  // plain Newton does not need it
        const VecX correction = solver.solve(rTrial);
        theta = correction.norm() / std::max(scale * dq.norm(), 1e-300);
      }
    }
    if (debugOutput())
      std::cerr << fmt::format("    it {:3d} |r| {:.4e} step {:.3e} scale {:.3g} mu {:.2e} theta {:.3g}\n",
                               it, out.residual, scale * largestT, scale, mu, theta);
    if (plain && (!evaluated || !rTrial.allFinite())) {
      out.failure = "an element folds or the out-of-balance force is not finite";
      return out;
    }
    // Plain Newton takes every step; pseudo-transient continuation refuses a ten-fold rise of |r|_2;
    // damped Newton needs Theta < 1.
    const bool accept =
        plain || (merit ? evaluated && rTrial.allFinite() && rTrial.squaredNorm() < 100.0 * r.squaredNorm()
                        : theta < 1.0);
    if (!accept) {
      assembledAtState = false;
      ++stalled;
      mu = std::max(1e-4, mu * 10.0);
      if (mu > kMaxShift) {
        out.failure = evaluated ? "no increment reduces the Newton correction"
                                : "elements fold for every increment tried";
        return out;
      }
      continue;
    }
    const double ratio = rTrial.norm() / std::max(r.norm(), 1e-300);
    const double previous = out.residual;
    assembledAtState = evaluated;
    state = std::move(trial);
    r = rTrial;
    matrix.build(kAccepted);
    out.residual = residualNorm(model, r, ResidualIndexing::Equations, &out.worstNode, kStaticMomentLever);
    stalled = out.residual > 0.5 * previous ? stalled + 1 : 0;
    if (plain) {
      // A shift raised because the matrix could not be factorised is relaxed again (pure Newton).
      mu = mu > 1e-6 ? 0.1 * mu : 0.0;
    } else if (merit) {
      // Pseudo-transient continuation (Kelley & Keyes 1998; implicit dynamic relaxation with fictitious
      // masses proportional to the diagonal stiffness) with switched evolution relaxation:
      // mu <- mu |r_new| / |r_old|, switched on when a step raises the residual.
      if (mu == 0.0) {
        if (ratio > 1.0) mu = 1e-4;
      } else {
        mu *= std::clamp(ratio, 0.1, 10.0);
        if (mu < 1e-9) mu = 0.0;
      }
    } else if (theta < 0.5) {
      mu = mu > 1e-9 ? 0.25 * mu : 0.0;  // relaxed as Newton contracts well, kept when it does not
    }
    // Divergence watch: plain Newton may be non-monotone at first but must improve within 8 steps; the
    // damped variants must halve the largest out-of-balance force within 25 (40) accepted steps.
    const double improvement = plain ? 1.0 : 0.5;
    const int patience = plain ? 8 : (merit ? 25 : 40);
    if (out.residual < best) {
      best = improvement * out.residual;
      sinceBest = 0;
    } else if (++sinceBest > patience) {
      out.failure =
          plain ? "the out-of-balance force keeps growing" : "the out-of-balance force stopped decreasing";
      return out;
    }
  }
  out.failure = fmt::format("not converged in {} iterations", maxIterations);
  return out;
}

void StaticSolver::checkTangent(const model::State& state, const AssemblyRequest& request, const VecX& offset,
                                const SparseMatrix& tangent, const VecX& step) {
  // K d against the central difference of the residual along d (the step scaled to a largest component
  // of 1), printed for the eight DOFs that differ most. Leaves the assembler's path-dependent trial data
  // as it was at `state`.
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const auto& eqDofs = dofs.equationDofs();
  const int neq = dofs.equationCount();
  const VecX d = step / std::max(step.cwiseAbs().maxCoeff(), 1e-300);
  VecX fullD = VecX::Zero(dofs.fullDofCount());
  for (int i = 0; i < neq; ++i) fullD[eqDofs[i]] = d[i];
  constexpr double eps = 1e-5;
  model::State plus = state, minus = state;
  plus.applyIncrement(dofs, eps * fullD);
  minus.applyIncrement(dofs, -eps * fullD);
  VecX force, rPlus(neq), rMinus(neq);
  m_assembler->assemble(plus, request, force, nullptr);
  gatherResidual(force, offset, rPlus);
  m_assembler->assemble(minus, request, force, nullptr);
  gatherResidual(force, offset, rMinus);
  m_assembler->assemble(state, request, force, nullptr);
  const VecX fd = (rPlus - rMinus) / (2 * eps);
  const VecX kd = tangent * d;
  std::vector<std::pair<double, int>> errors;
  for (int i = 0; i < neq; ++i) errors.emplace_back(std::abs(fd[i] - kd[i]), i);
  const int shown = std::min(8, neq);
  std::partial_sort(errors.begin(), errors.begin() + shown, errors.end(), std::greater<>());
  std::cerr << fmt::format(
      "    tangent check: |Kd| {:.4e} |fd| {:.4e} |Kd-fd| {:.4e}; largest differences:\n", kd.norm(),
      fd.norm(), (kd - fd).norm());
  for (int j = 0; j < shown; ++j) {
    const int i = errors[static_cast<std::size_t>(j)].second;
    const int node = dofs.nodeOf(eqDofs[i]);
    const Vec3& x = state.position[node];
    std::cerr << fmt::format("      {} dof {} at ({:.3f}, {:.3f}, {:.4f}): K {:.4e} fd {:.4e}\n",
                             model.describeNode(node), eqDofs[i] - dofs.firstDof(node), x.x(), x.y(), x.z(),
                             kd[i], fd[i]);
  }
}

void StaticSolver::gatherResidual(const VecX& force, const VecX& offset, VecX& r) const {
  const auto& eqDofs = m_assembler->model().dofs().equationDofs();
  r.resize(static_cast<Eigen::Index>(eqDofs.size()));
  for (std::size_t i = 0; i < eqDofs.size(); ++i)
    r[static_cast<Eigen::Index>(i)] = force[eqDofs[i]] - offset[static_cast<Eigen::Index>(i)];
}

void StaticSolver::noteStall(const std::string& path, const std::string& loading, double fraction,
                             double residual, int worstNode, const model::State& state,
                             const std::string& why) {
  Stall stall;
  stall.path = m_stillWaterPath ? path + " in still water" : path;
  stall.context = m_pathContext;
  stall.loading = loading;
  stall.fraction = fraction;
  stall.residual = residual;
  stall.worstNode = worstNode;
  if (worstNode >= 0 && worstNode < static_cast<int>(state.position.size()))
    stall.position = state.position[worstNode];
  stall.why = why;
  if (debugOutput())
    std::cerr << fmt::format("  stall: {}{} at {} of {} ({})\n", stall.path,
                             stall.context.empty() ? "" : " (" + stall.context + ")", fractionText(fraction),
                             loading.empty() ? "the load" : loading, why);
  m_stalls.push_back(std::move(stall));
}

std::string StaticSolver::diagnose(const StaticResult& result) const {
  if (m_stalls.empty()) {  // not reached (every failing path notes its stall); the position unknown
    Stall unknown;
    unknown.fraction = result.loadFraction;
    unknown.residual = result.residual;
    unknown.worstNode = result.worstNode;
    unknown.position = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    return diagnose(unknown, result, "");
  }
  // The furthest path; of equal ones the first tried (the later stages of solve() repeat the paths with a
  // changed model, and often stall at the same point).
  std::size_t best = 0;
  for (std::size_t i = 1; i < m_stalls.size(); ++i)
    if (m_stalls[i].fraction > m_stalls[best].fraction) best = i;
  // The other paths by their furthest reach in any stage, each named once, in the order tried.
  std::vector<const Stall*> reach;
  for (std::size_t i = 0; i < m_stalls.size(); ++i) {
    if (i == best || m_stalls[i].path == m_stalls[best].path) continue;
    auto it =
        std::find_if(reach.begin(), reach.end(), [&](const Stall* r) { return r->path == m_stalls[i].path; });
    if (it == reach.end())
      reach.push_back(&m_stalls[i]);
    else if (m_stalls[i].fraction > (*it)->fraction)
      *it = &m_stalls[i];
  }
  std::string others;
  for (const Stall* r : reach)
    others += r->loading.empty() ? fmt::format("{}{} did not converge", others.empty() ? "" : "; ", r->path)
                                 : fmt::format("{}{} reached {} of {}", others.empty() ? "" : "; ", r->path,
                                               fractionText(r->fraction), r->loading);
  return diagnose(m_stalls[best], result, others);
}

std::string StaticSolver::diagnose(const Stall& stall, const StaticResult& result,
                                   const std::string& others) const {
  const model::Model& model = m_assembler->model();
  const auto& env = model.environment();
  const int node = stall.worstNode;
  std::string where = node >= 0 ? model.describeNode(node) : std::string("an unknown node");
  std::string hint;
  if (node >= 0 && model.lineOfNode(node) >= 0 && stall.position.allFinite()) {
    const Vec3& x = stall.position;
    const bool onSeabed = model.seabedSurface().gap(x, 0.5 * model.nodeContactDiameter()[node]) <= 1e-3;
    // On a slope steeper than the friction angle a laid line free to slide has no equilibrium.
    const double slope = std::acos(std::clamp(model.seabedSurface().at(x.x(), x.y()).normal.z(), -1.0, 1.0));
    if (onSeabed && slope > std::atan(env.seabed.frictionCoefficient) + 1e-9)
      hint = fmt::format(
          "the node lies on the seabed where it slopes {:.1f} deg, steeper than the friction angle atan(mu) "
          "= {:.1f} deg (environment.seabed.friction_coefficient {}): a laid line that nothing holds up the "
          "slope slides down it and has no static equilibrium; anchor or hold the line, or check the slope "
          "and "
          "the friction",
          slope * 180.0 / std::numbers::pi,
          std::atan(env.seabed.frictionCoefficient) * 180.0 / std::numbers::pi,
          env.seabed.frictionCoefficient);
    else if (onSeabed && !env.current.empty())
      hint =
          env.seabed.frictionCoefficient <= 0.0
              ? "the node lies on a frictionless seabed in a current, which may have no static equilibrium: "
                "set environment.seabed.friction_coefficient (0.3 to 1.0 is typical)"
              : "the node lies on the seabed in a current: if the drag on the laid line exceeds its friction "
                "capacity mu w (environment.seabed.friction_coefficient) the line slides and has no static "
                "equilibrium";
  }
  if (hint.empty())
    hint =
        "check the line lengths against the distances between their ends and the section properties; a "
        "larger statics.max_iterations or a mesh with fewer, longer elements near that node may help";
  const std::string path = stall.context.empty() ? stall.path : stall.path + " (" + stall.context + ")";
  std::string reached;
  if (stall.path.empty())
    reached = fmt::format("load fraction reached {}", fractionText(stall.fraction));
  else if (stall.loading.empty())
    reached = fmt::format("{} did not converge", path);
  else
    reached = fmt::format("the path that got furthest, {}, reached {} of {}", path,
                          fractionText(stall.fraction), stall.loading);
  return fmt::format(
      "static analysis did not converge: {}{}, {} iterations in all, largest out-of-balance force {:.4g} N "
      "at {} "
      "(tolerance {:.3g} N){}. What to change: {}",
      reached, stall.why.empty() ? std::string() : fmt::format(" ({})", stall.why), result.iterations,
      stall.residual, where, result.tolerance,
      others.empty() ? std::string() : fmt::format("; the other paths: {}", others), hint);
}

}  // namespace tangle::solver

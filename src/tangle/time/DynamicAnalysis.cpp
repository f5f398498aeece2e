#include "tangle/time/DynamicAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/core/Interrupt.hpp"
#include "tangle/time/CableSnapLimit.hpp"

namespace tangle::time {

namespace {
/// The solver's choices as the model file names them: "newton modified, assembly parts, ...".
std::string solverChoices(const model::DynamicSolverSpec& solver) {
  std::string text;
  for (const model::DynamicSolverSpec::Choice& choice : model::DynamicSolverSpec::kChoices)
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", choice.key, solver.valueOf(choice));
  return text;
}
}  // namespace

std::vector<model::PrescribedNode> prescribedNodes(const model::Model& model) {
  std::vector<model::PrescribedNode> out;
  const double rampTime = model.spec().dynamics.rampTime;
  for (const model::Line& line : model.lines()) {
    for (int end = 0; end < 2; ++end) {
      const model::EndSpec& e = end == 0 ? line.spec->endA : line.spec->endB;
      if (!e.motion.enabled) continue;
      if (e.kind == model::EndKind::Free || e.kind == model::EndKind::Vessel) continue;
      const model::PrescribedMotion motion(e.motion, rampTime);
      out.push_back({end == 0 ? line.firstNode : line.lastNode(), e.position,
                     [motion](double t) { return motion.at(t); }});
    }
  }
  return out;
}

double localErrorEstimate(const model::Model& model, const model::State& before, const model::State& after,
                          double h, double betaError) {
  // Zienkiewicz & Xie (1991), Earthquake Eng. Struct. Dyn. 20:871: the Newmark-family displacement update
  // matches a cubic Taylor expansion except for e = (beta - 1/6) h^2 (a_{n+1} - a_n); the relative error is
  // |e| / |u_{n+1} - u_n| over the translational DOFs of every node (2-norms).
  const model::DofMap& dofs = model.dofs();
  double error2 = 0.0, increment2 = 0.0;
  for (int n = 0; n < model.nodeCount(); ++n) {
    const int d = dofs.firstDof(n);
    const Vec3 da = after.acceleration.segment<3>(d) - before.acceleration.segment<3>(d);
    error2 += da.squaredNorm();
    increment2 += (after.position[static_cast<std::size_t>(n)] - before.position[static_cast<std::size_t>(n)])
                      .squaredNorm();
  }
  const double error = betaError * h * h * std::sqrt(error2);
  // A model at rest moves by round-off: 1 nm per node is "no motion", not a step to refine.
  const double floor = 1e-9 * std::sqrt(static_cast<double>(model.nodeCount()));
  return error / std::max(std::sqrt(increment2), floor);
}

DynamicAnalysis::DynamicAnalysis(solver::Assembler& assembler, const model::DynamicSpec& settings)
    : m_assembler(&assembler), m_settings(settings) {}

DynamicResult DynamicAnalysis::run(model::State& state) {
  start(state);
  advance(state, m_settings.duration);
  return finish(state);
}

void DynamicAnalysis::start(model::State& state) {
  m_wallStart = std::chrono::steady_clock::now();
  m_lastPrint = m_wallStart;
  const model::Model& model = m_assembler->model();
  std::vector<model::PrescribedNode> prescribed = prescribedNodes(model);
  prescribed.insert(prescribed.end(), m_extraPrescribed.begin(), m_extraPrescribed.end());
  m_stepper = std::make_unique<GeneralizedAlpha>(*m_assembler, m_settings, std::move(prescribed));
  m_result = DynamicResult();
  m_stopped = false;
  state.time = 0.0;
  m_stepper->initialize(state);
  if (m_observer) m_observer(state, m_stepper->lastForce());
  if (m_stepObserver) m_stepObserver(state, 0.0);
  // Output times are k * interval (not a running sum, whose round-off would leave slivers of steps).
  m_outputIndex = 1;
  m_nextOutput = std::min(m_settings.outputInterval, m_settings.duration);
  m_dt = m_settings.timeStep;
  m_lastStep = m_settings.timeStep;  // the step grows at most twofold (maxStepGrowth) per step
  m_successes = 0;
}

bool DynamicAnalysis::advance(model::State& state, double until) {
  using Clock = std::chrono::steady_clock;
  if (!m_stepper) throw Error("DynamicAnalysis::advance called before start");
  if (m_stopped) return false;
  GeneralizedAlpha& stepper = *m_stepper;
  DynamicResult& result = m_result;
  const model::Model& model = m_assembler->model();
  const double duration = m_settings.duration;
  const double end = std::min(until, duration);
  const double nominal = m_settings.timeStep;
  const double out = m_settings.outputInterval;
  // Error control (dynamics.error_tolerance > 0): the step follows the local error estimate, up to
  // maxStep; otherwise fixed steps of `nominal`, cut on failure and regrown twofold after 4 successes.
  const double tolerance = m_settings.errorTolerance;
  const bool errorControl = tolerance > 0.0;
  const double maxStep =
      errorControl ? (m_settings.maxTimeStep > 0.0 ? m_settings.maxTimeStep : out) : nominal;
  const double betaError = std::abs(stepper.parameters().beta - 1.0 / 6.0);
  double& dt = m_dt;
  int& successes = m_successes;
  // Remainders shorter than this are round-off, not time to simulate.
  const double eps = 1e-6 * nominal;
  // Contributors that may refuse a converged step (lines passed through each other) need the state before it:
  // the stepper's own copy of it (a copy per step here was 0.27 G instructions of drilling-riser-drift's
  // run).
  model::State& before = stepper.stepStart();
  const bool checkSteps = m_stepControl && m_assembler->rejectsSteps();
  double& lastStep = m_lastStep;
  while (state.time < end - eps) {
    if (core::interruptRequested() || (m_stop && m_stop())) {
      result.message = fmt::format("dynamic analysis interrupted by the user at t = {:.4f} s", state.time);
      result.interrupted = true;
      m_stopped = true;
      return false;
    }
    double h = std::min(dt, end - state.time);
    // The limits are asked about the longest step that can follow (the growth below is at most twofold):
    // whatever they answer at or above it changes nothing (Assembler::maxStepGrowth <= 2).
    if (m_stepControl)
      h = std::min(
          h, std::max(m_settings.minTimeStep, m_assembler->limitStep(state, std::min(h, 2.0 * lastStep))));
    // The largest ratio of a step to the one before it: 2, or less where a contributor asks (the distributed
    // contact in contact, LineContact::maxStepGrowth; asked after limitStep, which sees the state).
    h = std::min(h, (m_stepControl ? m_assembler->maxStepGrowth() : 2.0) * lastStep);
    // Land exactly on output times and on the end of this advance, in equal steps: the time left to the
    // next of them is cut into the fewest steps no longer than h, so that no sliver of a step is left
    // before it. (A sliver was the step the next one grew from: with the distributed contact's 1.25-fold
    // growth a free fall with 1 ms outputs never got back to its 1 ms step after the impact, 6340 steps
    // for 2290 nominal ones; and a long step right after a sliver amplifies the sliver's acceleration
    // error, (dq - h v) / (beta h^2).) The 1e-6 keeps a whole number of steps from rounding up to one more.
    const double left = std::min(m_nextOutput, end) - state.time;
    const auto land = [&](double step) {
      return left > eps && step > eps ? left / std::max(1.0, std::ceil(left / step - 1e-6)) : step;
    };
    h = land(h);
    // The cable snap limit looks ahead over the step it is given, so it is asked about the landed step (a
    // host coupled at its own step and a run with outputs at that step then take the same steps).
    const double snap =
        std::max(m_settings.minTimeStep, cableSnapStepLimit(model, state, m_settings.maxCableStrainStep, h));
    if (snap < h) h = land(snap);
    if (h <= eps) h = std::min(dt, end - state.time);
    const bool clippedForOutput = h < dt * (1.0 - 1e-9);
    StepOutcome o = stepper.step(state, h);
    result.newtonIterations += o.iterations;
    result.partIterations += o.partIterations;
    result.blocksLeft += o.blocksLeft;
    result.matrixRefreshes += o.refreshes;
    result.blockRefreshes += o.blockRefreshes;
    result.matrixStepLengthChanges += o.stepLengthChanges;
    if (o.fallback > 0) ++result.fallbackSteps;
    bool rejected = false;
    std::string rejection;
    if (o.converged && checkSteps) rejection = m_assembler->rejectStep(before, state);
    if (!rejection.empty()) {
      // Converged but not acceptable (e.g. lines passed through each other): undo and cut.
      stepper.restore(before);
      state = before;
      o.converged = false;
      rejected = true;
    }
    if (!o.converged) {
      ++result.cutbacks;
      dt = 0.5 * h;
      successes = 0;
      if (dt < m_settings.minTimeStep) {
        const std::string where = model.describeNode(o.worstNode);
        result.message =
            rejected ? fmt::format(
                           "dynamic analysis stopped at t = {:.6g} s: the step is refused even with the "
                           "minimum time step {:.3g} s: {}",
                           state.time, m_settings.minTimeStep, rejection)
            : !o.failure.empty()
                ? fmt::format(
                      "dynamic analysis stopped at t = {:.6g} s: a step fails even with the minimum "
                      "time step {:.3g} s, with full Newton: {}",
                      state.time, m_settings.minTimeStep, o.failure)
                : fmt::format(
                      "dynamic analysis stopped at t = {:.6g} s: Newton did not converge even with "
                      "the minimum time step {:.3g} s and full Newton; largest out-of-balance force "
                      "{:.4g} N at {}",
                      state.time, m_settings.minTimeStep, o.residual, where);
        m_stopped = true;
        return false;
      }
      continue;
    }
    // A converged step taken again from its start, `factor` of its length [-] (not below the minimum step),
    // counted in `count`. (The growth count restarts; it acts only with fixed steps.)
    const auto redoShorter = [&](int& count, double factor) {
      stepper.restore(before);
      state = before;
      ++count;
      dt = std::max(m_settings.minTimeStep, h * factor);
      successes = 0;
    };
    // A cable element carried from tension across its kink into slack within the step releases the work of
    // its start force over the whole shortening, more than it stored (CableSnapLimit.hpp): the step again,
    // ending before the kink. (A 4 m wire released from a strain of 2e-3 in air, unloaded bar by bar from
    // rest, reached 3.8e4 times its stored energy in 0.5 s: CableSnapTest.)
    if (m_settings.maxCableStrainStep > 0.0 && h > m_settings.minTimeStep * (1.0 + 1e-9)) {
      const double fraction = cableUnloadStepFraction(model, before, state, m_settings.maxCableStrainStep);
      if (fraction < 1.0) {
        // The linear interpolation in strain is short of an unload that accelerates; not below a tenth.
        redoShorter(result.unloadRejections, std::max(fraction, 0.1));
        continue;
      }
    }
    if (errorControl) {
      const double eta = localErrorEstimate(model, before, state, h, betaError);
      const double factor = std::clamp(0.9 * std::cbrt(tolerance / std::max(eta, 1e-300)), 0.2, 2.0);
      if (eta > 2.0 * tolerance && h > m_settings.minTimeStep * (1.0 + 1e-9)) {
        // Too inaccurate: redo the step shorter (h factor, factor <= 0.9 (1/2)^(1/3) here).
        redoShorter(result.errorRejections, factor);
        continue;
      }
      // A step shortened to land on an output time says little about the step the error allows: accurate,
      // it may let the step grow but not shrink (output times are landed on in equal steps, so most steps
      // are a little shorter than dt; taken as the step to grow from, dt only ever shrank: 320 748 steps
      // where 4 000 did, ErrorControlTest).
      const double next = std::clamp(h * factor, m_settings.minTimeStep, maxStep);
      dt = clippedForOutput && eta <= tolerance ? std::max(dt, next) : next;
    }
    ++result.steps;
    // With fixed steps the next step grows from this one (output times are landed on in equal steps, above).
    lastStep = errorControl && clippedForOutput ? std::max(h, lastStep) : h;
    m_assembler->commitStep(state, h);  // path-dependent state: trial -> committed
    if (!errorControl && ++successes >= 4 && dt < nominal) {
      dt = std::min(nominal, 2.0 * dt);
      successes = 0;
    }
    const bool output = state.time >= m_nextOutput - eps;
    if (output)
      state.time = m_nextOutput;  // land exactly (the step was cut to reach it)
    else if (state.time >= end - eps)
      state.time = end;
    if (m_stepObserver) m_stepObserver(state, h);
    if (output) {
      if (m_observer) m_observer(state, stepper.lastForce());
      ++m_outputIndex;
      m_nextOutput = std::min(static_cast<double>(m_outputIndex) * out, duration);
    }
    if (m_progress) {
      const auto now = Clock::now();
      if (std::chrono::duration<double>(now - m_lastPrint).count() > 2.0) {
        const double wall = std::chrono::duration<double>(now - m_wallStart).count();
        std::cerr << fmt::format("  t = {:8.2f} / {:.2f} s ({:3.0f} %), real-time factor {:.1f}\n",
                                 state.time, duration, 100.0 * state.time / duration, state.time / wall);
        m_lastPrint = now;
      }
    }
  }
  return true;
}

DynamicResult DynamicAnalysis::finish(model::State& state) {
  using Clock = std::chrono::steady_clock;
  DynamicResult& result = m_result;
  m_assembler->finish(state.time);
  const double duration = m_settings.duration;
  const double eps = 1e-6 * m_settings.timeStep;
  const bool errorControl = m_settings.errorTolerance > 0.0;
  result.endTime = state.time;
  result.completed = state.time >= duration - eps;
  result.wallSeconds = std::chrono::duration<double>(Clock::now() - m_wallStart).count();
  if (result.completed) {
    const model::DynamicSolverSpec& c = m_settings.solver;
    result.message = fmt::format(
        "dynamic analysis completed: {:.2f} s simulated in {} steps ({} cut back{}{}), {:.2f} s wall time, "
        "real-time factor {:.1f}; solver: {}",
        result.endTime, result.steps, result.cutbacks,
        errorControl ? fmt::format(", {} redone for accuracy, mean step {:.4g} s", result.errorRejections,
                                   result.endTime / std::max(result.steps, 1))
                     : "",
        result.fallbackSteps > 0
            ? fmt::format(", {} retried with a whole refresh or full Newton", result.fallbackSteps)
            : "",
        result.wallSeconds, result.endTime / std::max(result.wallSeconds, 1e-9), solverChoices(c));
  }
  return result;
}

}  // namespace tangle::time

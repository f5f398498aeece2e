#include "tangle/time/DynamicRelaxation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/core/Interrupt.hpp"

namespace tangle::time {

namespace {
/// Longest pseudo-time step [s]. The slowest modes of a moored line have periods of tens of seconds;
/// with rho_inf = 0 a step of 1 s removes everything faster than a few seconds in a few steps.
constexpr double kRelaxationStep = 1.0;
/// First step [s]: the start shape is not in equilibrium under the full loads, and Newton from rest over a
/// long first step diverges (the grounded part of a line has only its seabed contact and mass to resist).
constexpr double kFirstRelaxationStep = 0.05;
/// Shortest step before the relaxation gives up [s]. The first second of pseudo-time, when the start shape
/// springs towards the loads, can need steps of a few ms or less: the slack chain of the slack mooring line
/// in a 1.5 m/s current towards the anchor (StaticsRobustnessTest) snaps taut element after element, and
/// with a floor of 1e-3 s a round ended there on some paths and not others (round-off decided).
constexpr double kMinRelaxationStep = 1e-5;
}  // namespace

DynamicRelaxation::DynamicRelaxation(solver::Assembler& assembler, const model::DynamicSpec& base,
                                     std::vector<model::PrescribedNode> prescribed, double longestLine)
    : m_assembler(&assembler), m_settings(base), m_prescribed(std::move(prescribed)) {
  m_settings.integrator = model::IntegratorKind::GeneralizedAlpha;
  m_settings.spectralRadius = 0.0;  // asymptotic annihilation of the high frequencies (Chung & Hulbert 1993)
  m_settings.rayleighBeta = 0.0;
  m_settings.maxIterations = std::max(m_settings.maxIterations, 30);
  // Critical damping of the slowest mode: the pendulum of the longest line, omega = sqrt(g / L)
  // (a hanging chain's first mode is 1.2 sqrt(g / L); a catenary's slower in-plane drift is bounded by
  // it within a factor of order one). alpha = 2 zeta omega with zeta = 1.
  const double omega = std::sqrt(9.80665 / std::max(longestLine, 1.0));
  m_settings.rayleighAlpha = 2.0 * omega;
}

RelaxationResult DynamicRelaxation::run(model::State& state, double staticTime, double duration,
                                        double restSpeed) {
  RelaxationResult result;
  const model::DofMap& dofs = m_assembler->model().dofs();
  const int nodes = m_assembler->model().nodeCount();
  GeneralizedAlpha stepper(*m_assembler, m_settings, m_prescribed);
  // The general sparse solver, as the rest of statics: with the banded one (same solutions to 1e-12) the
  // statics of the slack line in a 1.5 m/s current towards the anchor (StaticsRobustnessTest) ends on a
  // different rested shape from which Newton does not converge - a path that sensitive to round-off is a
  // doubt noted in issue 8.
  stepper.setBandedSolver(false);
  stepper.freezeEnvironment(staticTime);
  state.velocity.setZero();
  state.acceleration.setZero();
  state.time = 0.0;
  stepper.initialize(state);
  double dt = kFirstRelaxationStep;
  int successes = 0;
  model::State before;
  const bool checkSteps = m_assembler->rejectsSteps();  // a contributor may refuse a step: keep its start
  auto maxSpeed = [&](const model::State& s) {
    double v = 0.0;
    for (int n = 0; n < nodes; ++n) v = std::max(v, s.velocity.segment<3>(dofs.firstDof(n)).norm());
    return v;
  };
  while (state.time < duration) {
    if (core::interruptRequested()) {
      result.message = "interrupted by the user";
      break;
    }
    const double h = std::min(dt, duration - state.time);
    if (checkSteps) before = state;
    const StepOutcome o = stepper.step(state, h);
    const bool invalid = o.converged && checkSteps && !m_assembler->rejectStep(before, state).empty();
    if (invalid) state = before;  // a converged step that the validator refuses: back to its start
    if (!o.converged || invalid) {
      dt *= 0.25;
      successes = 0;
      if (dt < kMinRelaxationStep) {
        result.message =
            fmt::format("a step of {:.1e} s does not converge at pseudo-time {:.2f} s", dt * 4.0, state.time);
        break;
      }
      stepper.restore(state);
      continue;
    }
    ++result.steps;
    if (++successes >= 4 && dt < kRelaxationStep) {
      dt = std::min(2.0 * dt, kRelaxationStep);
      successes = 0;
    }
    result.maxSpeed = maxSpeed(state);
    // At rest only after the first few steps: the start shape is at rest too.
    if (result.steps >= 3 && result.maxSpeed < restSpeed) {
      result.settled = true;
      break;
    }
  }
  result.duration = state.time;
  if (result.message.empty())
    result.message = result.settled ? fmt::format("at rest after {:.0f} s of pseudo-time ({} steps)",
                                                  result.duration, result.steps)
                                    : fmt::format("still moving at {:.3g} m/s after {:.0f} s of pseudo-time",
                                                  result.maxSpeed, result.duration);
  state.velocity.setZero();
  state.acceleration.setZero();
  state.time = staticTime;
  return result;
}

}  // namespace tangle::time

#include "tangle/analysis/Simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "tangle/core/Interrupt.hpp"
#include "tangle/time/DynamicRelaxation.hpp"

namespace tangle::analysis {

Simulation::Simulation(model::ModelSpec spec)
    : m_model(std::make_unique<model::Model>(std::move(spec))),
      m_assembler(std::make_unique<solver::Assembler>(*m_model)),
      m_hydro(std::make_unique<hydro::HydroLoads>(*m_model)),
      m_state(m_model->initialState()) {
  m_assembler->addContributor(m_hydro.get());
  if (!m_model->vessels().empty()) {
    m_vessels = std::make_unique<vessel::VesselSystem>(*m_model, *m_hydro);
    m_assembler->addContributor(m_vessels.get());
  }
  if (m_model->spec().contact.enabled) {
    m_contact = std::make_unique<contact::LineContact>(*m_model, m_model->spec().contact,
                                                       m_model->spec().dynamics.timeStep);
    m_assembler->addContributor(m_contact.get());
  }
}

Simulation::~Simulation() = default;

solver::StaticResult Simulation::solveStatics() {
  solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
  solver::StaticResult result = solver.solve(m_state);
  if (!result.converged && !core::interruptRequested()) relaxThenSolve(result);
  if (!result.converged && core::interruptRequested())
    result.message =
        "static analysis interrupted by the user (Ctrl-C or SIGTERM) before it converged; where it "
        "stood: " +
        result.message;
  // Contacts at rest in the static equilibrium become the starting contacts of the dynamics.
  if (m_contact && result.converged) m_contact->commitStep(m_state, 0.0);
  return result;
}

bool Simulation::relaxThenSolve(solver::StaticResult& result) {
  // Not (yet) with line contact (the relaxation's impacts would enter the clash report) nor with free
  // vessels (a DP unit held in statics would drift off during the relaxation).
  if (m_contact) return false;
  for (const model::VesselSpec& v : m_model->spec().vessels)
    if (v.mode == model::VesselMode::Free) return false;
  double longest = 0.0;
  for (const model::LineSpec& line : m_model->spec().lines) {
    double length = 0.0;
    for (const model::SectionSpec& s : line.sections) length += s.length;
    longest = std::max(longest, length);
  }
  std::vector<time::PrescribedNode> prescribed = time::prescribedNodes(*m_model);
  if (m_vessels)
    for (time::PrescribedNode& n : m_vessels->prescribedNodes()) prescribed.push_back(std::move(n));
  time::DynamicRelaxation relaxation(*m_assembler, m_model->spec().dynamics, std::move(prescribed), longest);
  // Rounds of two periods of the slowest (pendulum) mode, each followed by a Newton solve from the shape
  // reached; at rest means slower than 1 mm/s.
  const double period = 2.0 * std::numbers::pi / (0.5 * relaxation.damping());
  constexpr int kRounds = 4;
  constexpr double kRestSpeed = 1e-3;
  const bool debug = std::getenv("TANGLE_DEBUG_STATICS") != nullptr;
  model::State relaxed = m_state;
  const int newtonIterations = result.iterations;
  int lastRound = 0;
  for (int round = 0; round < kRounds; ++round) {
    const time::RelaxationResult r = relaxation.run(relaxed, m_state.time, 2.0 * period, kRestSpeed);
    if (debug) std::cerr << fmt::format("  dynamic relaxation round {}: {}\n", round + 1, r.message);
    if (core::interruptRequested()) return false;
    if (r.steps == 0) break;  // the relaxation cannot move: Newton would start where it failed
    model::State trial = relaxed;
    solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
    solver::StaticResult again = solver.solve(trial);
    if (again.converged) {
      again.iterations += newtonIterations;
      again.message += fmt::format(
          ", from the shape at rest after dynamic relaxation ({} round(s), damping {:.3g} 1/s; {} Newton "
          "iterations "
          "in all)",
          round + 1, relaxation.damping(), again.iterations);
      result = again;
      m_state = trial;
      return true;
    }
    lastRound = round + 1;
  }
  if (lastRound > 0)
    result.message += fmt::format(
        "; dynamic relaxation was tried as well ({} round(s)) and Newton did not converge "
        "from the shape it reached either",
        lastRound);
  return false;
}

std::vector<solver::LineSnapshot> Simulation::snapshot(bool dynamic) {
  VecX force;
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  request.dynamic = dynamic;
  request.time = m_state.time;
  m_assembler->assemble(m_state, request, force, nullptr);
  if (dynamic) {
    // Inertia belongs in the support reactions of a moving line.
    VecX inertia = VecX::Zero(force.size());
    m_assembler->addMass(m_state, 0.0, nullptr, &m_state.acceleration, &inertia);
    force += inertia;
  }
  // Ends tied to vessels: take the link forces out, so what remains at the end node is the line's pull.
  if (m_vessels) force -= m_vessels->endConnectionForces(m_state, m_state.time);
  return solver::computeLineResults(*m_model, *m_assembler, m_state, force);
}

std::vector<solver::LineSnapshot> Simulation::sectionSnapshot() const {
  const VecX noReactions = VecX::Zero(m_model->dofs().fullDofCount());
  return solver::computeLineResults(*m_model, *m_assembler, m_state, noReactions);
}

time::DynamicResult Simulation::runDynamics(const time::DynamicAnalysis::Observer& observer, bool progress,
                                            const time::DynamicAnalysis::StepObserver& stepObserver,
                                            const time::DynamicAnalysis::StopRequest& stop) {
  time::DynamicAnalysis dynamics(*m_assembler, m_model->spec().dynamics);
  dynamics.setProgress(progress);
  dynamics.setObserver(observer);
  if (stepObserver) dynamics.setStepObserver(stepObserver);
  if (stop) dynamics.setStopRequest(stop);
  if (m_vessels) dynamics.addPrescribed(m_vessels->prescribedNodes());
  if (m_contact) {
    dynamics.setStepLimiter([this](const model::State& s) { return m_contact->stepLimit(s); });
    dynamics.setStepValidator([this](const model::State& before, const model::State& after) {
      return m_contact->acceptStep(before, after);
    });
    dynamics.setStepHook([this](model::State& s, double dt) { m_contact->commitStep(s, dt); });
  }
  // The run advances m_state itself, so snapshot() inside the observer sees the output state.
  const time::DynamicResult result = dynamics.run(m_state);
  if (m_contact) m_contact->finish(m_state.time);
  return result;
}

}  // namespace tangle::analysis

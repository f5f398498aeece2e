#include "tangle/analysis/Simulation.hpp"

namespace tangle::analysis {

Simulation::Simulation(model::ModelSpec spec)
    : m_model(std::make_unique<model::Model>(std::move(spec))),
      m_assembler(std::make_unique<solver::Assembler>(*m_model)),
      m_hydro(std::make_unique<hydro::HydroLoads>(*m_model)),
      m_state(m_model->initialState()) {
  m_assembler->addContributor(m_hydro.get());
}

Simulation::~Simulation() = default;

solver::StaticResult Simulation::solveStatics() {
  solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
  return solver.solve(m_state);
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
  return solver::computeLineResults(*m_model, *m_assembler, m_state, force);
}

time::DynamicResult Simulation::runDynamics(const time::DynamicAnalysis::Observer& observer, bool progress) {
  time::DynamicAnalysis dynamics(*m_assembler, m_model->spec().dynamics);
  dynamics.setProgress(progress);
  dynamics.setObserver(observer);
  // The run advances m_state itself, so snapshot() inside the observer sees the output state.
  return dynamics.run(m_state);
}

}  // namespace tangle::analysis

#include "tangle/analysis/EnergyAccount.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/analysis/Simulation.hpp"

namespace tangle::analysis {

namespace {
// Sources in the order of EnergyTotals::work.
enum Source { kElastic, kDamping, kWeight, kSeabed, kHydro, kContact, kVessels, kOther, kRayleighMass, kSupports, kCount };
}  // namespace

EnergyAccount::EnergyAccount(Simulation& simulation) : m_simulation(&simulation) {
  m_names = {"elastic forces (minus the strain energy)",
             "structural damping",
             "weight and buoyancy",
             "seabed",
             "hydrodynamic loads",
             "contact",
             "vessels (body loads, links, tensioners)",
             "other",
             "Rayleigh mass damping",
             "supports (held and prescribed ends)"};
  m_work.assign(kCount, 0.0);
}

void EnergyAccount::powers(const model::State& state, std::vector<double>& power, double& kinetic) {
  solver::Assembler& assembler = m_simulation->assembler();
  const model::Model& model = m_simulation->model();
  const model::DofMap& dofs = model.dofs();
  const int size = dofs.fullDofCount();
  solver::AssemblyRequest request;
  request.time = state.time;
  request.dynamic = true;
  request.wantMatrix = false;
  power.assign(kCount, 0.0);
  VecX total = VecX::Zero(size);
  // Work done on the model by a source of out-of-balance force F (external loads negative): -F . v.
  const auto add = [&](int source, const VecX& f) {
    power[static_cast<std::size_t>(source)] += -f.dot(state.velocity);
    total += f;
  };
  VecX f = VecX::Zero(size);
  solver::AssemblyRequest elastic = request;
  elastic.dynamic = false;
  assembler.addTerm(solver::Assembler::Term::Elements, state, elastic, f);
  add(kElastic, f);
  VecX withDamping = VecX::Zero(size);
  assembler.addTerm(solver::Assembler::Term::Elements, state, request, withDamping);
  add(kDamping, withDamping - f);
  f.setZero();
  assembler.addTerm(solver::Assembler::Term::Weight, state, request, f);
  assembler.addTerm(solver::Assembler::Term::Attachments, state, request, f);
  add(kWeight, f);
  f.setZero();
  assembler.addTerm(solver::Assembler::Term::Seabed, state, request, f);
  add(kSeabed, f);
  for (solver::LoadContributor* c : assembler.contributors()) {
    f.setZero();
    c->addForces(state, request, f, nullptr);
    const int source = c->source() == solver::LoadSource::Hydrodynamic ? kHydro
                       : c->source() == solver::LoadSource::Contact    ? kContact
                       : c->source() == solver::LoadSource::Vessels    ? kVessels
                                                                       : kOther;
    add(source, f);
  }
  // Mass: kinetic energy 1/2 v.M v (structural, rotational, added mass, vessels) and the inertia at the
  // held DOFs, where the supports supply F + M a.
  VecX massVelocity = VecX::Zero(size), massAcceleration = VecX::Zero(size);
  assembler.addMass(state, 0.0, nullptr, &state.velocity, &massVelocity);
  assembler.addMass(state, 0.0, nullptr, &state.acceleration, &massAcceleration);
  kinetic = 0.5 * state.velocity.dot(massVelocity);
  const double alpha = model.spec().dynamics.rayleighAlpha;
  power[kRayleighMass] = -alpha * state.velocity.dot(massVelocity);
  for (int dof = 0; dof < size; ++dof)
    if (dofs.equation(dof) < 0)
      power[kSupports] += (total[dof] + massAcceleration[dof]) * state.velocity[dof];
}

void EnergyAccount::start(const model::State& state) {
  double kinetic = 0.0;
  powers(state, m_lastPower, kinetic);
  m_startKinetic = kinetic;
  m_totals = {};
  m_totals.time = state.time;
  m_totals.kinetic = kinetic;
  std::fill(m_work.begin(), m_work.end(), 0.0);
  m_totals.work.clear();
  for (std::size_t k = 0; k < m_names.size(); ++k) m_totals.work.emplace_back(m_names[k], 0.0);
}

void EnergyAccount::step(const model::State& state, double dt) {
  std::vector<double> power;
  double kinetic = 0.0;
  powers(state, power, kinetic);
  double sum = 0.0;
  for (std::size_t k = 0; k < power.size(); ++k) {
    const double increment = 0.5 * (power[k] + m_lastPower[k]) * dt;  // trapezoidal rule
    m_work[k] += increment;
    m_totals.throughput += std::abs(increment);
    m_totals.work[k].second = m_work[k];
    sum += m_work[k];
  }
  m_lastPower = std::move(power);
  m_totals.time = state.time;
  m_totals.kinetic = kinetic;
  m_totals.kineticChange = kinetic - m_startKinetic;
  m_totals.residual = m_totals.kineticChange - sum;
}

std::string EnergyAccount::warning() const {
  const EnergyTotals& t = m_totals;
  if (!(t.throughput > 0.0) || std::abs(t.residual) <= kTolerance * t.throughput) return {};
  return fmt::format("energy account: at t = {:.4g} s the kinetic energy changed by {:.4g} J and the loads did {:.4g} "
                     "J of work: {:.4g} J ({:.1f} % of the {:.4g} J that flowed) {} (tolerance {:.0f} %; see "
                     "dynamics/energy.csv)",
                     t.time, t.kineticChange, t.kineticChange - t.residual, std::abs(t.residual),
                     100.0 * std::abs(t.residual) / t.throughput, t.throughput,
                     t.residual > 0.0 ? "appeared from nowhere" : "were dissipated by the integrator",
                     100.0 * kTolerance);
}

}  // namespace tangle::analysis

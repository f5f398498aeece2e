// Issue 30: the energy account of the dynamics (analysis/EnergyAccount, theory 8.6).
//
// Model: a chain-like cable (100 m, 20 bars, EA 5e7 N, 100 kg/m, 0.1 m) between two pinned ends 98 m apart
// at 50 m depth, without drag or added mass, one end moved along the line by 0.5 m at a 4 s period (ramped
// over 4 s) for 20 s. Nothing dissipates but the integrator.
//
// Independent truth: the strain energy of the bars, sum of EA / (2 L0) (L - L0)^2 over the taut elements,
// computed here from the positions, and the kinetic energy 1/2 m v^2 of the lumped node masses: the
// account's work of the elastic forces must be minus the strain energy's change (1 % of the largest strain
// energy change: the trapezoidal rule over 0.01 s steps of a 4 s motion errs by (dt / T)^2 ~ 1e-5, and the
// slack-bar factor 1e-6 EA adds less), and its kinetic energy the lumped one (1e-9, round-off).
// Closure: with the energy-conserving parameters (rho_inf = 1: alpha_m = alpha_f = 1/2, the trapezoidal
// rule, Chung & Hulbert 1993) the residual stays below 1e-3 of the energy that flowed; with rho_inf = 0.3
// the integrator dissipates the high frequencies of the snatching cable: the residual is negative
// (energy lost, never created).

#include <gtest/gtest.h>

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/EnergyAccount.hpp"
#include "tangle/analysis/Simulation.hpp"

namespace tangle {
namespace {

model::ModelSpec cable(double spectralRadius) {
  model::ModelSpec spec;
  spec.sourceFile = "energy account (test)";
  spec.environment.waterDepth = 100.0;
  section::LineType type = test::cableType("chain", 0.1, 100.0, 5.0e7);
  type.dragNormal = type.dragAxial = 0.0;
  type.addedMassNormal = type.addedMassAxial = 0.0;
  spec.lineTypes["chain"] = type;
  model::LineSpec line = test::simpleLine("cable", "chain", 100.0, 20, model::EndKind::Pinned, Vec3(0, 0, -50),
                                          model::EndKind::Pinned, Vec3(98, 0, -50));
  line.endB.motion.enabled = true;
  line.endB.motion.amplitude = Vec3(0.5, 0.0, 0.0);
  line.endB.motion.period = 4.0;
  spec.lines = {line};
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 20.0;
  spec.dynamics.timeStep = 0.01;
  spec.dynamics.rampTime = 4.0;
  spec.dynamics.outputInterval = 1.0;
  spec.dynamics.spectralRadius = spectralRadius;
  return spec;
}

/// Strain energy of the bars [J] (tension only; the slack factor's share is negligible).
double strainEnergy(const model::Model& m, const model::State& s) {
  double u = 0.0;
  for (const model::LineElement& el : m.elements()) {
    const double stretch = (s.position[el.node2] - s.position[el.node1]).norm() - el.restLength;
    if (stretch > 0.0) u += 0.5 * el.type->axialStiffness / el.restLength * stretch * stretch;
  }
  return u;
}

double lumpedKineticEnergy(const model::Model& m, const model::State& s) {
  double k = 0.0;
  for (int n = 0; n < m.nodeCount(); ++n)
    k += 0.5 * m.nodeMass()[n] * s.velocity.segment<3>(m.dofs().firstDof(n)).squaredNorm();
  return k;
}

struct Outcome {
  double elasticError = 0.0;  // |W_elastic + dU| / max |dU|
  double kineticError = 0.0;  // |K - K_lumped| / max K
  double residual = 0.0;      // residual / energy that flowed
};

Outcome run(double spectralRadius) {
  analysis::Simulation sim(cable(spectralRadius));
  EXPECT_TRUE(sim.solveStatics().converged);
  analysis::EnergyAccount energy(sim);
  energy.start(sim.state());
  const double u0 = strainEnergy(sim.model(), sim.state());
  double largestDu = 0.0, largestK = 0.0, elasticMiss = 0.0, kineticMiss = 0.0;
  const time::DynamicResult result = sim.runDynamics(nullptr, false, [&](const model::State& s, double dt) {
    energy.step(s, dt);
    const double du = strainEnergy(sim.model(), s) - u0;
    const double k = lumpedKineticEnergy(sim.model(), s);
    largestDu = std::max(largestDu, std::abs(du));
    largestK = std::max(largestK, k);
    elasticMiss = std::max(elasticMiss, std::abs(energy.totals().work[0].second + du));
    kineticMiss = std::max(kineticMiss, std::abs(energy.totals().kinetic - k));
  });
  EXPECT_TRUE(result.completed) << result.message;
  Outcome o;
  o.elasticError = elasticMiss / largestDu;
  o.kineticError = kineticMiss / largestK;
  o.residual = energy.totals().residual / energy.totals().throughput;
  return o;
}

TEST(EnergyAccount, WorkOfTheElasticForcesIsTheStrainEnergyAndTheAccountCloses) {
  const Outcome o = run(1.0);
  EXPECT_LT(o.elasticError, 0.01);
  EXPECT_LT(o.kineticError, 1e-9);
  EXPECT_LT(std::abs(o.residual), 1e-3);
  RecordProperty("elastic_work_error", std::to_string(o.elasticError));
  RecordProperty("relative_residual", std::to_string(o.residual));
}

TEST(EnergyAccount, NumericalDampingShowsAsEnergyLost) {
  const Outcome o = run(0.3);
  EXPECT_LT(o.residual, 0.0);
  RecordProperty("relative_residual", std::to_string(o.residual));
}

}  // namespace
}  // namespace tangle

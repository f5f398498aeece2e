// Validation against the seed paper, section 6.2 (Silva, Pereira & Jacob 2007): free fall with
// restitution. (draft)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/ContactLaw.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kE = 70.0e9, kRho = 2680.0;
constexpr double kLargeLength = 10.0, kLargeDiameter = 10.0;
constexpr double kSmallLength = 0.01, kSmallDiameter = 0.01;
constexpr double kDrop = 4.85;
constexpr double kAxisZ = 10.0;

struct Case {
  double restitution;
  model::ImpactModel model;
  double timeStep;
  double stiffness;
};

class FreeFall : public ::testing::TestWithParam<Case> {};

TEST_P(FreeFall, ReboundHeight) {
  const Case c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "free fall (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["large"] = test::solidRodType("large", kLargeDiameter, kE, kRho);
  spec.lineTypes["small"] = test::solidRodType("small", kSmallDiameter, kE, kRho);
  const double top = kAxisZ + 0.5 * kLargeDiameter;
  const double touchZ = top + 0.5 * kSmallDiameter;  // centre height at first touch
  const double z0 = touchZ + kDrop;
  model::LineSpec large = test::simpleLine("large", "large", kLargeLength, 10, model::EndKind::Fixed,
                                           Vec3(-0.5 * kLargeLength, 0, kAxisZ), model::EndKind::Fixed,
                                           Vec3(0.5 * kLargeLength, 0, kAxisZ));
  model::LineSpec small = test::simpleLine("small", "small", kSmallLength, 2, model::EndKind::Free,
                                           Vec3(0, -0.5 * kSmallLength, z0), model::EndKind::Free,
                                           Vec3(0, 0.5 * kSmallLength, z0));
  spec.lines = {large, small};
  spec.contact.enabled = true;
  spec.contact.restitution = c.restitution;
  spec.contact.model = c.model;
  spec.contact.stiffness = c.stiffness;
  spec.dynamics.enabled = true;
  const double fallTime = std::sqrt(2.0 * kDrop / kStandardGravity);
  spec.dynamics.duration = fallTime * (1.0 + c.restitution) + 0.05;
  spec.dynamics.timeStep = c.timeStep;
  spec.dynamics.outputInterval = 1e-3;
  spec.dynamics.rampTime = 0.0;
  spec.dynamics.minTimeStep = 1e-9;
  if (std::getenv("RHO")) spec.dynamics.spectralRadius = std::atof(std::getenv("RHO"));

  analysis::Simulation sim(std::move(spec));
  const int smallLine = 1;
  const model::Line& line = sim.model().lines()[smallLine];
  const int mid = line.firstNode + 1;
  const model::DofMap& dofs = sim.model().dofs();
  for (int n = line.firstNode; n <= line.lastNode(); ++n) sim.state().acceleration[dofs.firstDof(n) + 2] = -kStandardGravity;
  double zmax = -1e9, tmax = 0;
  bool hit = false;
  double vImpact = 0;
  double prevZ = z0;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    const double z = s.position[mid].z();
    if (!hit && s.velocity[dofs.firstDof(mid) + 2] > 0.0) hit = true;
    if (!hit) vImpact = s.velocity[dofs.firstDof(mid) + 2];
    if (hit && z > zmax) {
      zmax = z;
      tmax = s.time;
    }
    prevZ = z;
    if (std::getenv("FF_TRACE") && s.time > 0.99 && s.time < 1.05) {
      std::printf("t %.4f", s.time);
      for (int n = line.firstNode; n <= line.lastNode(); ++n)
        std::printf(" | z %.6f v %.4f %.4f %.4f w %.1f %.1f %.1f", s.position[n].z(), s.velocity[dofs.firstDof(n)],
                    s.velocity[dofs.firstDof(n) + 1], s.velocity[dofs.firstDof(n) + 2], s.velocity[dofs.firstDof(n) + 3],
                    s.velocity[dofs.firstDof(n) + 4], s.velocity[dofs.firstDof(n) + 5]);
      std::printf("\n");
    }
  });
  ASSERT_TRUE(run.completed) << run.message;
  const double rebound = zmax - touchZ;
  const double expected = c.restitution * c.restitution * kDrop;
  std::printf("e %.2f model %d: rebound %.5f expected %.5f err %.3e  steps %d cut %d newton %ld wall %.3f tmax %.4f vimp %.5f\n",
              c.restitution, static_cast<int>(c.model), rebound, expected, rebound / expected - 1.0, run.steps,
              run.cutbacks, run.newtonIterations, run.wallSeconds, tmax, vImpact);
  for (const auto& ev : sim.contact()->events())
    std::printf("  mpair %.4e event %.6f-%.6f imp %.4e peak %.4e v %.4f mA %.4e mB %.4e lumpA %.3e lumpB %.3e pen %.3e\n", 2.0 * ev.impactEnergy / (ev.impactVelocity * ev.impactVelocity), ev.startTime, ev.endTime,
                ev.impulse, ev.peakForce, ev.impactVelocity, ev.effectiveMassA, ev.effectiveMassB, ev.lumpedMassA, ev.lumpedMassB,
                ev.maxPenetration);
  EXPECT_NEAR(rebound, expected, 0.01 * expected);
}

INSTANTIATE_TEST_SUITE_P(Paper62, FreeFall,
                         ::testing::Values(Case{1.0, model::ImpactModel::Impulse, 1e-3, 3e5},
Case{0.9, model::ImpactModel::Impulse, 1e-3, 3e5},
Case{0.75, model::ImpactModel::Impulse, 1e-3, 3e5},
Case{0.5, model::ImpactModel::Impulse, 1e-3, 3e5}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return std::string(p.param.model == model::ImpactModel::Penalty ? "Penalty" : "Impulse") +
                                  "_e" + std::to_string(static_cast<int>(std::round(100.0 * p.param.restitution))) + "_k" + std::to_string(static_cast<int>(p.param.stiffness > 0 ? std::log10(p.param.stiffness)*10 : 0));
                         });

}  // namespace
}  // namespace tangle

// Issue 45: buoyancy modules by pitch (lines[].attachments with pitch and count). A riser hangs
// vertically from a fixed top in still water with a free bottom end and a row of buoyancy modules. In
// equilibrium the top tension is the submerged weight of everything below it (Archimedes; no other vertical
// load): T_top = w L + n (m_b - rho V) g. The row is meshed three ways: the pitch a multiple of the
// element length, the pitch not one (modules between nodes, shared by the lever rule), and elements longer
// than the pitch (several modules per element). Tolerance 1e-6 of the top tension: the static solver's
// tolerance (1e-9 of the force scale per node, 60 nodes) with margin; the resultant is exact for any mesh
// because the lever rule keeps each module's whole load on the line.
//
// The lever rule also keeps each module's moment: the first moment of the node loads about end A equals
// the modules' own, checked on the model's attachments to round-off.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"

namespace tangle {
namespace {

constexpr double kLength = 120.0;  // [m]
constexpr double kModuleMass = 300.0, kModuleVolume = 1.2;  // [kg], [m^3]: 930 kg of net lift each
constexpr double kFirst = 20.0, kPitch = 3.5;
constexpr int kModules = 20;  // 20 to 86.5 m

class ModuleRow : public ::testing::TestWithParam<int> {};

TEST_P(ModuleRow, TopTensionIsTheWeightBelowAndTheModulesKeepTheirMoment) {
  model::ModelSpec spec;
  spec.sourceFile = "buoyancy module row (test)";
  spec.environment.waterDepth = 300.0;
  spec.lineTypes["riser"] = test::beamType("riser", 0.3, 200.0, 5.0e9, 2.0e7, 1.0, 1.0);
  model::LineSpec line = test::simpleLine("riser", "riser", kLength, GetParam(), model::EndKind::Free,
                                          Vec3(0, 0, -130.0), model::EndKind::Fixed, Vec3(0, 0, -10.0));
  model::AttachmentSpec module;
  module.mass = kModuleMass;
  module.volume = kModuleVolume;
  module.dragArea = 0.5;
  module.shared = true;
  for (int k = 0; k < kModules; ++k) {
    module.arcLength = kFirst + k * kPitch;
    line.attachments.push_back(module);
  }
  spec.lines.push_back(line);
  spec.statics.tolerance = 1e-9;
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const solver::LineSnapshot s = sim.snapshot().front();
  const model::EnvironmentSpec& env = sim.model().environment();
  const double w = sim.model().elements()[0].type->submergedWeight(env.waterDensity, env.gravity);
  const double top = w * kLength + kModules * (kModuleMass - env.waterDensity * kModuleVolume) * env.gravity;
  EXPECT_NEAR(s.endTensionB, top, 1e-6 * std::abs(top));
  RecordProperty("top_tension_error_N", fmt::format("{:.3e}", s.endTensionB - top));

  double mass = 0.0, moment = 0.0, drag = 0.0;
  const model::Line& l = sim.model().lines()[0];
  for (const model::NodeAttachment& a : sim.model().attachments()) {
    mass += a.spec.mass;
    drag += a.spec.dragArea;
    moment += a.spec.mass * l.arcLength[static_cast<std::size_t>(a.node - l.firstNode)];
  }
  double ownMoment = 0.0;
  for (int k = 0; k < kModules; ++k) ownMoment += kModuleMass * (kFirst + k * kPitch);
  EXPECT_NEAR(mass, kModules * kModuleMass, 1e-9);
  EXPECT_NEAR(drag, kModules * 0.5, 1e-12);
  EXPECT_NEAR(moment, ownMoment, 1e-9 * ownMoment);
}

// 60 elements of 2 m (modules between nodes every other one), 240 of 0.5 m (a module on every seventh
// node), 12 of 10 m (two or three modules per element).
INSTANTIATE_TEST_SUITE_P(Meshes, ModuleRow, ::testing::Values(60, 240, 12));

}  // namespace
}  // namespace tangle

// Issue 30: the static state is the initial state of the dynamics. A model with no time-varying load must
// stay at its static equilibrium: the seabed friction that holds a line in statics must hold it in the
// dynamics too. Before the fix a lazy-wave riser in a steady current lost 80 % of its anchor tension in
// 10 s of dynamics with nothing changing (35.5 -> 6.5 kN): the velocity-regularised dynamic friction holds
// nothing at rest, and the static friction's anchors were not carried over.
//
// The elastic law (`friction_model: elastic`, the default; docs/theory.md 5.4) carries the static friction
// into the dynamics, with a critical dashpot beside each stick spring.
//
// Model: a lazy-wave flexible in 300 m of water (250 m bare, 100 m of buoyancy modules, 350 m bare; top
// pinned 20 m below the surface, anchor on the seabed 450 m away), in a uniform current of 0.5 m/s across
// its plane, seabed friction 0.5; 140 elements. Statics, then 60 s of dynamics with no waves and nothing
// prescribed.
//
// Check: the end tensions and every node's position at the end of the 60 s equal the static ones within
// 0.5 % of the static tension (the bound) and 0.1 m. Why not closer: the dynamics starts at rest
// from the static state, which satisfies the dynamic equations to the static tolerance, and the implicit
// integrator keeps it there; what can move is the friction springs' stick (mu N / k_t, about 4 mm) if the
// static state's friction differs from the dynamic law's. Control: the same model with
// `friction_model: viscous` (MoorDyn's regularised law) drifts by more than that bound, so the check
// can fail.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "TestPaths.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/vessel/VesselSystem.hpp"

namespace tangle {
namespace {

model::ModelSpec lazyWave(bool elasticFriction) {
  model::ModelSpec spec;
  spec.sourceFile = "lazy wave in a steady current (test)";
  spec.environment.waterDepth = 300.0;
  spec.environment.seabed.frictionCoefficient = 0.5;
  spec.environment.seabed.elasticFriction = elasticFriction;
  spec.environment.current = {{0.0, 0.5, 0.5 * 3.141592653589793}};
  section::LineType flex = test::cableType("flex", 0.3, 150.0, 5.0e8);
  flex.bendingStiffness = 5.0e4;
  flex.torsionalStiffness = 5.0e4;
  flex.dragNormal = 1.0;
  section::LineType buoyancy = flex;
  buoyancy.name = "buoyancy";
  buoyancy.outerDiameter = buoyancy.buoyancyDiameter = buoyancy.contactDiameter = 0.8;
  buoyancy.massPerLength = 200.0;
  spec.lineTypes["flex"] = flex;
  spec.lineTypes["buoyancy"] = buoyancy;
  model::LineSpec riser = test::simpleLine("riser", "flex", 250.0, 50, model::EndKind::Pinned, Vec3(0, 0, -20),
                                           model::EndKind::Anchored, Vec3(450, 0, -300));
  riser.sections = {{"flex", 250.0, 50}, {"buoyancy", 100.0, 20}, {"flex", 350.0, 70}};
  spec.lines = {riser};
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 60.0;
  spec.dynamics.timeStep = 0.1;
  spec.dynamics.outputInterval = 60.0;
  return spec;
}

struct Drift {
  double tension = 0.0;   // largest relative change of an end tension [-]
  double position = 0.0;  // largest node displacement [m]
};

Drift runFromStatics(bool elasticFriction) {
  analysis::Simulation sim(lazyWave(elasticFriction));
  const solver::StaticResult statics = sim.solveStatics();
  EXPECT_TRUE(statics.converged) << statics.message;
  const solver::LineSnapshot before = sim.snapshot().front();
  const time::DynamicResult run = sim.runDynamics(nullptr);
  EXPECT_TRUE(run.completed) << run.message;
  const solver::LineSnapshot after = sim.snapshot(true).front();
  Drift d;
  d.tension = std::max(std::abs(after.endTensionA / before.endTensionA - 1.0),
                       std::abs(after.endTensionB / before.endTensionB - 1.0));
  for (std::size_t i = 0; i < before.position.size(); ++i)
    d.position = std::max(d.position, (after.position[i] - before.position[i]).norm());
  return d;
}

TEST(StaticsIntoDynamics, LazyWaveInSteadyCurrentStaysAtItsStaticState) {
  const Drift d = runFromStatics(true);
  EXPECT_LT(d.tension, 0.005);
  EXPECT_LT(d.position, 0.1);
  RecordProperty("end_tension_change", fmt::format("{:.3e}", d.tension));
  RecordProperty("largest_displacement_m", fmt::format("{:.3e}", d.position));
}

TEST(StaticsIntoDynamics, ControlViscousFrictionLetsTheLineSlide) {
  const Drift d = runFromStatics(false);
  EXPECT_GT(std::max(d.tension / 0.005, d.position / 0.1), 1.0);
  RecordProperty("end_tension_change", fmt::format("{:.3e}", d.tension));
  RecordProperty("largest_displacement_m", fmt::format("{:.3e}", d.position));
}

// Every other path-dependent state of the statics carried into the dynamics, on two examples with nothing
// time-varying left (waves and vessel motions removed, 20 s): risers-in-contact (two risers pushed together
// by the current, resting on each other along a length, with friction 0.3 between them: the contacts at
// rest and their friction anchors are the dynamics' start contacts) and riser-interference (two top-tensioned risers on tensioners of a fixed TLP, in a current with
// wake shielding: the tensioner strokes). Same bounds as the lazy wave: end tensions within 0.5 %, nodes
// within 0.1 m, tensioner strokes within 1 cm, all compared with the dynamics' own results at t = 0 (the
// same definitions: the end forces of the dynamics are extrapolated, theory 7.8).
class ExampleAtRest : public ::testing::TestWithParam<const char*> {};

TEST_P(ExampleAtRest, StaysAtItsStaticState) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/" + GetParam() + "/model.yaml");
  spec.environment.waves = {};
  // Friction between the lines (0.3, steel on coating), path-dependent like the seabed's.
  if (spec.contact.enabled) spec.contact.frictionCoefficient = 0.3;
  for (model::VesselSpec& v : spec.vessels)
    if (v.mode == model::VesselMode::Prescribed) v.mode = model::VesselMode::Fixed;
  spec.dynamics.duration = 20.0;
  spec.dynamics.outputInterval = 20.0;
  analysis::Simulation sim(std::move(spec));
  ASSERT_TRUE(sim.solveStatics().converged);
  const std::vector<solver::LineSnapshot> before = sim.snapshot(true);
  std::vector<double> strokes;
  if (sim.vessels())
    for (const auto& r : sim.vessels()->tensionerReadings(sim.state(), 0.0)) strokes.push_back(r.stroke);
  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;
  const std::vector<solver::LineSnapshot> after = sim.snapshot(true);
  double tension = 0.0, position = 0.0, stroke = 0.0;
  for (std::size_t l = 0; l < before.size(); ++l) {
    tension = std::max({tension, std::abs(after[l].endTensionA / before[l].endTensionA - 1.0),
                        std::abs(after[l].endTensionB / before[l].endTensionB - 1.0)});
    for (std::size_t i = 0; i < before[l].position.size(); ++i)
      position = std::max(position, (after[l].position[i] - before[l].position[i]).norm());
  }
  if (sim.vessels()) {
    const auto readings = sim.vessels()->tensionerReadings(sim.state(), sim.state().time);
    for (std::size_t k = 0; k < readings.size(); ++k) stroke = std::max(stroke, std::abs(readings[k].stroke - strokes[k]));
  }
  EXPECT_LT(tension, 0.005);
  EXPECT_LT(position, 0.1);
  EXPECT_LT(stroke, 0.01);
  RecordProperty("end_tension_change", fmt::format("{:.3e}", tension));
  RecordProperty("largest_displacement_m", fmt::format("{:.3e}", position));
  RecordProperty("largest_stroke_change_m", fmt::format("{:.3e}", stroke));
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleAtRest, ::testing::Values("risers-in-contact", "riser-interference"),
                         [](const auto& example) {
                           std::string name = example.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace tangle

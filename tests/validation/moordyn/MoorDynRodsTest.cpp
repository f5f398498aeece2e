// Issue 47: MoorDyn's rods, read from MoorDyn v2.7.1's own decks (tests/data/moordyn, unchanged) and checked
// against the closed forms MoorDyn's tests use (tests/beam.cpp, tests/rods.cpp), with tangle's tolerances:
// - BeamCantilevered.txt: a 10 m beam line (EI 1e7 N m^2, 100 kg/m, in air) clamped to a fixed rod's end. The
//   Euler-Bernoulli cantilever under a uniform load p = w g: z(x) = -p x^2 (6 L^2 - 4 x L + x^2) / (24 EI)
//   (MoorDyn's cantilevered_solution; e.g. Roark's Formulas, table 8.1 case 2a). MoorDyn allows 50 % of z at
//   each node; tangle 0.5 % of the tip deflection (0.1226 m): the co-rotational beam adds a geometric effect
//   of order (z/L)^2 = 1.5e-4 and the 19-element mesh's lumped load less than 0.1 % (measured +0.08 % at the
//   tip).
// - RodHanging.txt: a free 20 m rod hung level from two equal ropes stays level and centred (MoorDyn checks
//   the same to TOL = 1e-2 of its length); tangle's statics is symmetric to round-off (1e-9 L), centred to
//   the stiff beam's stretch (1e-5 L), and the ropes' vertical pulls at the rod carry exactly its wet weight
//   (rho pi/4 d^2 - m) g L (1e-6 relative: the ties' stretch and the solver tolerance).
// - RodPinnedFloating.txt: buoyant 1 m rods pinned at one end float up to the vertical (MoorDyn: the last
// node
//   above the first); the pin holds their net buoyancy (rho pi/4 d^2 - m) g L to 1e-6.
// - rod_tests/AddedMass.txt: a free buoyant rod with added mass (Ca = 1) and no drag rises from rest at the
//   constant acceleration a = (rho V - M) g / (M + Ca rho V), z(t) = z0 + a t^2 / 2 (MoorDyn's added_mass
//   test, 1e-8 relative). Generalized-alpha integrates a constant acceleration exactly; the Newton tolerance
//   (1e-6 of the rod's weight) bounds the error: 1e-6 m allowed over the 9 m rise.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kG = 9.80665;  // MoorDyn's default g (the decks give none)

std::string deck(const std::string& name) { return std::string(test::kTestDataDir) + "/moordyn/" + name; }

const model::Line& lineNamed(const model::Model& m, const std::string& name) {
  const int index = m.lineIndex(name);
  EXPECT_GE(index, 0) << name;
  return m.lines()[static_cast<std::size_t>(index)];
}

TEST(MoorDynRods, BeamClampedToAFixedRodIsTheEulerBernoulliCantilever) {
  analysis::Simulation sim(io::readModelFile(deck("BeamCantilevered.txt")));
  ASSERT_TRUE(sim.solveStatics().converged);
  const double p = 100.0 * kG, length = 10.0, ei = 1.0e7, z0 = 10.0;
  const auto cantilever = [&](double x) {
    return -p * x * x * (6.0 * length * length - 4.0 * x * length + x * x) / (24.0 * ei);
  };
  const double tip = std::abs(cantilever(length));
  ASSERT_NEAR(tip, 0.1226, 1e-4);
  const model::Line& beam = lineNamed(sim.model(), "line1");
  for (int i = 0; i < beam.nodeCount; ++i) {
    const Vec3& x = sim.state().position[static_cast<std::size_t>(beam.firstNode + i)];
    EXPECT_NEAR(x.z() - z0, cantilever(x.x()), 5e-3 * tip) << "node " << i << " at x = " << x.x();
  }
}

TEST(MoorDynRods, FreeRodHungFromTwoEqualRopesStaysLevelAndCarriesItsWeight) {
  analysis::Simulation sim(io::readModelFile(deck("RodHanging.txt")));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::Line& rod = lineNamed(sim.model(), "rod1");
  const Vec3 a = sim.state().position[static_cast<std::size_t>(rod.firstNode)];
  const Vec3 b = sim.state().position[static_cast<std::size_t>(rod.lastNode())];
  const double length = 20.0;
  // Symmetric to round-off; centred to the rod's stretch under the ropes' 806 kN pull (strain 2.1e-6 of the
  // stiff beam that stands for MoorDyn's rigid rod: 1e-5 L allowed).
  EXPECT_NEAR(a.x(), -b.x(), 1e-9 * length);
  EXPECT_NEAR(a.x(), -10.0, 1e-5 * length);
  EXPECT_NEAR(a.z(), b.z(), 1e-9 * length);
  EXPECT_NEAR(a.y(), 0.0, 1e-9 * length);
  // The ropes' pull at the rod (their end B) holds the rod's wet weight.
  const double wet = (77.7066 - 1025.0 * std::numbers::pi / 4.0 * 0.25 * 0.25) * kG * length;
  double lift = 0.0;
  for (const solver::LineSnapshot& s : sim.snapshot())
    if (s.name == "line1" || s.name == "line2") lift += s.endForceB.z();
  // endForceB is the force the rope exerts on the rod end, pointing into the rope (up and outwards).
  EXPECT_NEAR(lift, wet, 1e-6 * 2.0 * 314e3) << "the ropes' own weights are 314 kN each";
}

TEST(MoorDynRods, BuoyantPinnedRodsFloatUpright) {
  analysis::Simulation sim(io::readModelFile(deck("RodPinnedFloating.txt")));
  ASSERT_TRUE(sim.solveStatics().converged);
  const double net = (1000.0 * std::numbers::pi / 4.0 * 0.25 * 0.25 - 10.0) * kG * 1.0;
  for (const std::string name : {"rod1", "rod2"}) {
    const model::Line& rod = lineNamed(sim.model(), name);
    const Vec3 a = sim.state().position[static_cast<std::size_t>(rod.firstNode)];
    const Vec3 b = sim.state().position[static_cast<std::size_t>(rod.lastNode())];
    EXPECT_NEAR(b.z() - a.z(), 1.0, 1e-6) << name;
    for (const solver::LineSnapshot& s : sim.snapshot())
      if (s.name == name) {
        EXPECT_NEAR(s.endForceA.z(), net, 1e-6 * net) << name;
      }
  }
}

TEST(MoorDynRods, BuoyantFreeRodRisesAtItsAddedMassAcceleration) {
  model::ModelSpec spec = io::readModelFile(deck("rod_AddedMass.txt"));
  spec.dynamics.duration = 2.3;
  spec.dynamics.timeStep = 0.01;
  spec.dynamics.outputInterval = 0.1;
  analysis::Simulation sim(spec);
  sim.solveStatics();
  const double rho = 1025.0, area = std::numbers::pi / 4.0 * 0.5 * 0.5, mass = 100.0;
  const double acceleration = (rho * area - mass) * kG / (mass + 1.0 * rho * area);
  const model::Line& rod = lineNamed(sim.model(), "rod1");
  int checked = 0;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    const double expected = -10.0 + 0.5 * acceleration * s.time * s.time;
    for (int i = 0; i < rod.nodeCount; ++i)
      EXPECT_NEAR(s.position[static_cast<std::size_t>(rod.firstNode + i)].z(), expected, 1e-6)
          << "node " << i << " at t = " << s.time;
    ++checked;
  });
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_GE(checked, 20);
}

}  // namespace
}  // namespace tangle

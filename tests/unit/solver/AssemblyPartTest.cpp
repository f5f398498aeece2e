// Unit tests of the assembly of a part of the model (Assembler::selectPart / assemblePart / addPartMass):
// after some nodes move, re-evaluating the part gives every entry of F and of M a that a whole assembly
// gives, bit for bit (the same terms summed in the same order), so that the integrator's convergence test
// on a part is the whole model's test. One case per kind of term: bars and beams (Rayleigh and axial
// damping), weight and buoyancy across the water surface, the seabed, Morison loads in current and waves,
// point attachments (weight, drag, added mass), lumped and consistent mass.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "support/ContactChecks.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

/// A chain lying partly on the seabed (100 m water) and rising to the surface, with a clump and a buoy,
/// and a steel beam across the water surface; current and a regular wave.
model::ModelSpec partModel(bool lumped) {
  model::ModelSpec spec;
  spec.sourceFile = "assembly part (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.current = {{0.0, 1.0, degToRad(30.0)}, {-100.0, 0.3, degToRad(60.0)}};
  spec.environment.waves.kind = model::WaveKind::Airy;
  spec.environment.waves.height = 4.0;
  spec.environment.waves.period = 9.0;
  section::LineType chain = test::cableType("chain", 0.15, 120.0, 5.0e8);
  chain.dragNormal = 2.4;
  chain.dragAxial = 1.1;
  chain.addedMassNormal = 1.0;
  chain.addedMassAxial = 0.5;
  chain.axialDamping = 2.0e5;
  spec.lineTypes[chain.name] = chain;
  section::LineType rod = test::solidRodType("rod", 0.3, 2.1e11, 7850.0);
  rod.dragNormal = 1.0;
  rod.addedMassNormal = 1.0;
  spec.lineTypes[rod.name] = rod;
  model::LineSpec mooring = test::simpleLine("mooring", "chain", 160.0, 16, model::EndKind::Anchored,
                                             Vec3(0, 0, -100.0), model::EndKind::Pinned, Vec3(120, 10, -2.0));
  mooring.attachments.push_back({40.0, 2000.0, 0.1, 1.5, 300.0});   // clump
  mooring.attachments.push_back({120.0, 500.0, 3.0, 2.0, 2500.0});  // buoy
  spec.lines.push_back(mooring);
  spec.lines.push_back(test::simpleLine("beam", "rod", 30.0, 6, model::EndKind::Fixed, Vec3(0, 40, -10.0),
                                        model::EndKind::Fixed, Vec3(0, 70, 3.0)));
  spec.dynamics.lumpedMass = lumped;
  spec.dynamics.rayleighAlpha = 0.05;
  spec.dynamics.rayleighBeta = 1e-3;
  return spec;
}

/// A state with every node displaced, moving and accelerating (deterministic pseudo-random values), the
/// chain's first nodes pressed into the seabed.
void stir(model::State& s, const model::DofMap& dofs, unsigned seed) {
  unsigned x = seed;
  const auto next = [&x]() {
    x = x * 1664525u + 1013904223u;
    return static_cast<double>(x >> 8) / static_cast<double>(1u << 24) - 0.5;  // [-0.5, 0.5)
  };
  for (int n = 0; n < dofs.nodeCount(); ++n) {
    for (int k = 0; k < 3; ++k) s.position[n][k] += 0.05 * next();
    if (dofs.hasRotations(n))
      s.triad[n] = geometry::expMap(Vec3(0.01 * next(), 0.01 * next(), 0.01 * next())) * s.triad[n];
  }
  for (int n = 0; n < 4; ++n) s.position[n].z() = -100.0 + 0.075 - 0.02 * (n + 1);  // radius 0.075 m
  for (Eigen::Index i = 0; i < s.velocity.size(); ++i) {
    s.velocity[i] = 0.4 * next();
    s.acceleration[i] = 2.0 * next();
  }
}

/// A residual of the dynamics at time t [s] (no matrix), as the integrator's iterations request it.
solver::AssemblyRequest dynamicResidual(double t) {
  solver::AssemblyRequest request;
  request.time = t;
  request.dynamic = true;
  request.wantMatrix = false;
  return request;
}

void expectPartEqualsWhole(bool lumped, const std::vector<int>& moved) {
  analysis::Simulation sim(partModel(lumped));
  solver::Assembler& assembler = sim.assembler();
  const model::DofMap& dofs = sim.model().dofs();
  ASSERT_TRUE(assembler.supportsParts());
  const solver::AssemblyRequest request = dynamicResidual(3.7);

  model::State before = sim.state();
  stir(before, dofs, 7);
  VecX force, inertia = VecX::Zero(dofs.fullDofCount());
  assembler.assemble(before, request, force, nullptr);
  assembler.addMass(before, 0.0, nullptr, &before.acceleration, &inertia);

  // Only `moved` change: position, triad, velocity, acceleration.
  model::State after = before;
  model::State stirred = before;
  stir(stirred, dofs, 99);
  for (const int n : moved) {
    after.position[n] = stirred.position[n];
    after.triad[n] = stirred.triad[n];
    const int d = dofs.firstDof(n);
    const int count = dofs.hasRotations(n) ? 6 : 3;
    after.velocity.segment(d, count) = stirred.velocity.segment(d, count);
    after.acceleration.segment(d, count) = stirred.acceleration.segment(d, count);
  }
  solver::AssemblyPart part;
  assembler.selectPart(moved, part);
  VecX partForce = force, partInertia = inertia;
  assembler.assemblePart(after, request, part, partForce);
  assembler.addPartMass(after, part, after.acceleration, partInertia);

  VecX wholeForce, wholeInertia = VecX::Zero(dofs.fullDofCount());
  assembler.assemble(after, request, wholeForce, nullptr);
  assembler.addMass(after, 0.0, nullptr, &after.acceleration, &wholeInertia);
  ASSERT_NE(wholeForce, force) << "the moved nodes must change the forces, or the test proves nothing";
  for (Eigen::Index i = 0; i < wholeForce.size(); ++i) {
    // Bit for bit: the convergence test on a part must be the whole model's test.
    EXPECT_EQ(partForce[i], wholeForce[i])
        << "force at full DOF " << i << " (node " << dofs.nodeOf(static_cast<int>(i)) << ")";
    EXPECT_EQ(partInertia[i], wholeInertia[i]) << "inertia at full DOF " << i;
  }
}

TEST(AssemblyPart, SeabedNodesAndClumpOfTheChainLumpedMass) { expectPartEqualsWhole(true, {1, 2, 3, 5}); }

TEST(AssemblyPart, NodesAtTheSurfaceWithTheBuoyConsistentMass) { expectPartEqualsWhole(false, {11, 12, 13}); }

TEST(AssemblyPart, BeamNodesAndTheChainsLastFreeNode) {
  // The chain has 17 nodes (0-16), the beam 7 (17-23).
  expectPartEqualsWhole(true, {15, 18, 19, 22});
  expectPartEqualsWhole(false, {15, 18, 19, 22});
}

TEST(AssemblyPart, SelectPartTakesTheNeighboursAndTheirElements) {
  analysis::Simulation sim(partModel(true));
  solver::AssemblyPart part;
  sim.assembler().selectPart({5}, part);
  // Node 5 of the chain: nodes 4-6 are recomputed through elements 3-6; nodes 3-7 are written.
  EXPECT_EQ(part.nodes, (std::vector<int>{4, 5, 6}));
  EXPECT_EQ(part.elements, (std::vector<int>{3, 4, 5, 6}));
  EXPECT_EQ(part.writtenNodes, (std::vector<int>{3, 4, 5, 6, 7}));
  // The clump at 40 m of 160 m (16 elements of 10 m) sits on node 4.
  EXPECT_EQ(part.attachments, (std::vector<int>{0}));
}

/// The support reactions of Simulation::snapshot, which assembles the line ends as a part, against a whole
/// assembly (plus M a in dynamics) read at the end nodes: bit for bit (the same terms in the same order).
void expectSnapshotEndForcesEqualWhole(bool dynamic) {
  analysis::Simulation sim(partModel(true));
  const model::DofMap& dofs = sim.model().dofs();
  stir(sim.state(), dofs, 11);
  sim.state().time = 2.3;
  // The part path is the one under test: the four line ends (anchored, pinned, two fixed) are accepted.
  solver::AssemblyPart part;
  ASSERT_TRUE(sim.assembler().supportsParts());
  ASSERT_TRUE(sim.assembler().selectPart({0, 16, 17, 23}, part));
  solver::AssemblyRequest request;
  request.time = sim.state().time;
  request.dynamic = dynamic;
  request.wantMatrix = false;
  VecX whole, inertia = VecX::Zero(dofs.fullDofCount());
  sim.assembler().assemble(sim.state(), request, whole, nullptr);
  if (dynamic) sim.assembler().addMass(sim.state(), 0.0, nullptr, &sim.state().acceleration, &inertia);
  whole += inertia;
  const std::vector<solver::LineSnapshot> lines = sim.snapshot(dynamic);
  ASSERT_EQ(lines.size(), 2u);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const model::Line& line = sim.model().lines()[l];
    const Vec3 a = -whole.segment<3>(dofs.firstDof(line.firstNode));
    const Vec3 b = -whole.segment<3>(dofs.firstDof(line.lastNode()));
    ASSERT_GT(a.norm(), 0.0) << "a zero reaction would prove nothing";
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(lines[l].endForceA[k], a[k]) << line.name << " end A, component " << k;
      EXPECT_EQ(lines[l].endForceB[k], b[k]) << line.name << " end B, component " << k;
    }
  }
}

TEST(AssemblyPart, OutputSnapshotSupportReactionsEqualAWholeAssemblyInDynamics) {
  expectSnapshotEndForcesEqualWhole(true);
}

TEST(AssemblyPart, OutputSnapshotSupportReactionsEqualAWholeAssemblyInStatics) {
  expectSnapshotEndForcesEqualWhole(false);
}

TEST(AssemblyPart, NotOfferedWhenAContributorCouplesDistantNodes) {
  // A wake makes each element of the downstream line depend on the upstream line.
  model::ModelSpec spec = partModel(true);
  spec.lines.push_back(test::simpleLine("downstream", "chain", 160.0, 16, model::EndKind::Anchored,
                                        Vec3(0, 5, -100.0), model::EndKind::Pinned, Vec3(120, 15, -2.0)));
  model::WakeSpec wake;
  wake.upstream = "mooring";
  wake.downstream = "downstream";
  spec.wakes.push_back(wake);
  analysis::Simulation sim(std::move(spec));
  EXPECT_FALSE(sim.assembler().supportsParts());
}

}  // namespace
}  // namespace tangle

namespace tangle {
namespace {

TEST(AssemblyPart, LeavesOutVesselsAndContactOnlyAwayFromTheirNodes) {
  // The drilling-riser example: a free drilling unit holds the riser (tensioner) and a mooring line runs
  // under it; contact between riser and mooring. Parts are allowed (both contributors mark their nodes) but
  // refused when they hold a vessel node or a line end tied to a vessel.
  analysis::Simulation sim(
      io::readModelFile(std::string(test::kExamplesDir) + "/drilling-riser-drift/model.yaml"));
  solver::Assembler& assembler = sim.assembler();
  const model::Model& m = sim.model();
  ASSERT_TRUE(assembler.supportsParts());
  // Assemble once (contact finds its candidate pairs: none, the lines are 32 m apart in this state).
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  VecX force;
  assembler.assemble(sim.state(), request, force, nullptr);
  solver::AssemblyPart part;
  const model::Line& mooring = m.lines().at(0);
  EXPECT_TRUE(assembler.selectPart({mooring.firstNode + mooring.nodeCount / 2}, part));
  for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v)
    EXPECT_FALSE(assembler.selectPart({m.vesselNode(v)}, part)) << "vessel " << v;
  // The node next to a line end tied to a vessel: its part holds the end.
  for (const model::Line& line : m.lines()) {
    if (line.spec->endA.kind == model::EndKind::Vessel) {
      EXPECT_FALSE(assembler.selectPart({line.firstNode + 1}, part)) << line.name;
    }
    if (line.spec->endB.kind == model::EndKind::Vessel) {
      EXPECT_FALSE(assembler.selectPart({line.lastNode() - 1}, part)) << line.name;
    }
  }
}

}  // namespace
}  // namespace tangle

namespace tangle {
namespace {

TEST(AssemblyPart, EveryPartAllowedNextToAContactIsExact) {
  // The risers-in-contact example at its static equilibrium (two risers pressed together by the current):
  // contact marks the candidate elements and their neighbours. For every single node whose part is
  // allowed, moving that node and assembling the part must give the whole model's forces bit for bit at
  // every DOF: a node the contact loads or reads left unmarked would show here as a difference.
  model::ModelSpec spec =
      io::readModelFile(std::string(test::kExamplesDir) + "/risers-in-contact/model.yaml");
  analysis::Simulation sim(std::move(spec));
  ASSERT_TRUE(sim.solveStatics().converged);
  ASSERT_NE(sim.contact(), nullptr);
  solver::Assembler& assembler = sim.assembler();
  const model::DofMap& dofs = sim.model().dofs();
  ASSERT_TRUE(assembler.supportsParts());
  const solver::AssemblyRequest request = dynamicResidual(1.0);
  const model::State base = sim.state();
  VecX force;
  assembler.assemble(base, request, force, nullptr);  // finds this time's contact candidates
  int allowed = 0, refused = 0;
  for (int n = 0; n < sim.model().nodeCount(); ++n) {
    solver::AssemblyPart part;
    if (!assembler.selectPart({n}, part)) {
      ++refused;
      continue;
    }
    ++allowed;
    model::State moved = base;
    moved.position[n] += Vec3(1e-3, -2e-3, 1.5e-3);
    moved.velocity.segment<3>(dofs.firstDof(n)) += Vec3(0.01, 0.02, -0.01);
    VecX partForce = force;
    assembler.assemblePart(moved, request, part, partForce);
    VecX whole;
    assembler.assemble(moved, request, whole, nullptr);
    for (Eigen::Index i = 0; i < whole.size(); ++i)
      ASSERT_EQ(partForce[i], whole[i]) << "node " << n << " moved, full DOF " << i;
    assembler.assemble(base, request, force, nullptr);  // back to the base state (and its contacts)
  }
  // Both kinds exist: the contact zone is refused, the rest allowed.
  EXPECT_GT(refused, 2);
  EXPECT_GT(allowed, 10);
  RecordProperty("refused", refused);
  RecordProperty("allowed", allowed);
}

TEST(AssemblyPart, OutputSnapshotWithContactTakesTheEndsAloneAndEqualsAWholeAssembly) {
  // Two taut wires crossing at mid-span, the upper one laid on the lower (its start shape lifted off it,
  // then its weight pressing at the crossing: about 100 N in statics), their ends 50 m from the crossing,
  // moving and accelerating: the output snapshot assembles the four line ends as a part (the contact loads
  // nodes far from them), and its support reactions are a whole assembly's (plus M a in dynamics) at the
  // ends, bit for bit.
  analysis::Simulation sim(io::readModelString(R"(
environment: {water_depth: 100}
line_types:
  - {name: wire, outer_diameter: 0.2, mass_per_length: 40, axial_stiffness: 5.0e8}
lines:
  - name: a
    end_a: {type: pinned, position: [-50, 0, -50]}
    end_b: {type: pinned, position: [50, 0, -50]}
    sections: [{type: wire, length: 99.9, elements: 20}]
  - name: b
    end_a: {type: pinned, position: [0, -50, -49.81]}
    end_b: {type: pinned, position: [0, 50, -49.81]}
    sections: [{type: wire, length: 99.9, elements: 20}]
contact: {restitution: 0.5}
)",
                                               "crossing wires (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::DofMap& dofs = sim.model().dofs();
  for (Eigen::Index i = 0; i < sim.state().velocity.size(); ++i) {
    sim.state().velocity[i] = 0.01 * std::sin(0.7 * static_cast<double>(i));
    sim.state().acceleration[i] = 0.1 * std::cos(1.3 * static_cast<double>(i));
  }
  for (const bool dynamic : {false, true}) {
    solver::AssemblyRequest request;
    request.time = sim.state().time;
    request.dynamic = dynamic;
    request.wantMatrix = false;
    VecX whole, inertia = VecX::Zero(dofs.fullDofCount());
    sim.assembler().assemble(sim.state(), request, whole, nullptr);  // the contact's candidates now
    if (dynamic) sim.assembler().addMass(sim.state(), 0.0, nullptr, &sim.state().acceleration, &inertia);
    whole += inertia;
    std::vector<int> ends;
    for (const model::Line& line : sim.model().lines())
      ends.insert(ends.end(), {line.firstNode, line.lastNode()});
    solver::AssemblyPart part;
    ASSERT_TRUE(sim.assembler().selectPart(ends, part)) << "the part path is the one under test";
    // The contact acts at the whole assembly (its force, whichever formulation).
    EXPECT_GT(test::pressedContact(*sim.contact(), 0, 1).normalForce, 10.0);
    const std::vector<solver::LineSnapshot> lines = sim.snapshot(dynamic);
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const model::Line& line = sim.model().lines()[l];
      const Vec3 a = -whole.segment<3>(dofs.firstDof(line.firstNode));
      const Vec3 b = -whole.segment<3>(dofs.firstDof(line.lastNode()));
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(lines[l].endForceA[k], a[k])
            << line.name << " end A, component " << k << ", dynamic " << dynamic;
        EXPECT_EQ(lines[l].endForceB[k], b[k])
            << line.name << " end B, component " << k << ", dynamic " << dynamic;
      }
    }
  }
}

}  // namespace
}  // namespace tangle

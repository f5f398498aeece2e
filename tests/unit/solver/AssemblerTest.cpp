// Unit tests of the assembler's inertia and damping terms: consistent and lumped mass carry the same
// total mass (rigid translation), axial damping opposes the stretching rate with its exact derivative,
// attachment drag opposes the relative velocity, the waterplane stiffness of an element through the
// surface is the derivative of its buoyancy, a damped bar's force is the same with and without the matrix,
// and the round-off floors' shortcut holds only where the floors are below the allowances.

#include <gtest/gtest.h>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

model::ModelSpec twoBarLine(bool lumped, double axialDamping) {
  model::ModelSpec spec;
  spec.sourceFile = "assembler (test)";
  spec.environment.waterDepth = 100.0;
  section::LineType t = test::cableType("cable", 0.1, 50.0, 1.0e7);
  t.axialDamping = axialDamping;
  spec.lineTypes[t.name] = t;
  // In air (z = 20), free at both ends: nothing but the elements.
  spec.lines.push_back(test::simpleLine("l", "cable", 20.0, 2, model::EndKind::Free, Vec3(0, 0, 20),
                                        model::EndKind::Free, Vec3(20, 0, 20)));
  spec.dynamics.lumpedMass = lumped;
  return spec;
}

// The statics length continuation (setRestLengths) gives elements other unstretched lengths: a fibre rope's
// element keeps its tension-strain curve. (The copy was made with EA alone, the curve's largest slope, so
// a rope whose start shape compressed an element reached its static equilibrium, at lambda = 1 of the
// continuation, with a linear law there: 600 kN where the curve gives 300 kN at the strain 0.015 below.)
TEST(Assembler, ContinuationLengthsKeepARopesTensionStrainCurve) {
  analysis::Simulation sim(io::readModelString(R"(
environment: {water_depth: 100}
line_types:
  - {name: rope, outer_diameter: 0.15, mass_per_length: 20, tension_strain: [[0.01, 1.0e5], [0.02, 5.0e5]]}
lines:
  - name: l
    end_a: {type: pinned, position: [0, 0, 20]}
    end_b: {type: pinned, position: [20.3, 0, 20]}
    sections: [{type: rope, length: 20, elements: 2}]
)",
                                               "rope (test)"));
  model::State& state = sim.state();
  const model::Line& line = sim.model().lines()[0];
  for (int i = 0; i < line.nodeCount; ++i)
    state.position[line.firstNode + i] = Vec3(1.015 * line.arcLength[static_cast<std::size_t>(i)], 0, 20);
  // Strain 0.015, halfway between the curve's points: 3e5 N.
  for (double t : sim.assembler().elementTension(state)) EXPECT_NEAR(t, 3.0e5, 1e-6 * 3.0e5);
  std::vector<double> lengths;
  for (const model::LineElement& el : sim.model().elements()) lengths.push_back(el.restLength);
  sim.assembler().setRestLengths(lengths);
  for (double t : sim.assembler().elementTension(state)) EXPECT_NEAR(t, 3.0e5, 1e-6 * 3.0e5);
  // And at a length of the continuation: rest lengths that make the strain 0.0125, 2e5 N on the curve (the
  // linear copy gave 5e5 N).
  for (double& l : lengths) l *= 1.015 / 1.0125;
  sim.assembler().setRestLengths(lengths);
  for (double t : sim.assembler().elementTension(state)) EXPECT_NEAR(t, 2.0e5, 1e-6 * 2.0e5);
  sim.assembler().setRestLengths({});
}

TEST(Assembler, ConsistentAndLumpedMassCarryTheSameTotalMass) {
  // A uniform acceleration a of the whole line needs a force (total mass) * a, whatever the mass matrix
  // (consistent mass rows sum to the lumped mass): exact, tolerance round-off.
  for (bool lumped : {true, false}) {
    analysis::Simulation sim(twoBarLine(lumped, 0.0));
    const int n = sim.model().dofs().fullDofCount();
    VecX a = VecX::Zero(n), out = VecX::Zero(n);
    for (int node = 0; node < sim.model().nodeCount(); ++node) a[sim.model().dofs().firstDof(node)] = 2.0;
    sim.assembler().addMass(sim.state(), 0.0, nullptr, &a, &out);
    double total = 0.0;
    for (int node = 0; node < sim.model().nodeCount(); ++node)
      total += out[sim.model().dofs().firstDof(node)];
    EXPECT_NEAR(total, 50.0 * 20.0 * 2.0, 1e-9) << (lumped ? "lumped" : "consistent");
  }
}

TEST(Assembler, ConsistentMassCouplesNeighbouringNodes) {
  // Element mass m L = 500 kg: M = m L / 6 [2 1; 1 2]; accelerating node 0 alone loads node 1 with 500/6 a.
  analysis::Simulation sim(twoBarLine(false, 0.0));
  const int n = sim.model().dofs().fullDofCount();
  VecX a = VecX::Zero(n), out = VecX::Zero(n);
  a[0] = 1.0;
  sim.assembler().addMass(sim.state(), 0.0, nullptr, &a, &out);
  EXPECT_NEAR(out[0], 500.0 / 3.0, 1e-9);
  EXPECT_NEAR(out[3], 500.0 / 6.0, 1e-9);
}

TEST(Assembler, AxialDampingOpposesStretchingRate) {
  // c = 1e4 N s; the end node moves away along the line at 0.1 m/s: strain rate 0.1 / 10 per s on the
  // last element, damping force c * 0.01 = 100 N pulling the end node back (out-of-balance +100 N in x).
  analysis::Simulation sim(twoBarLine(true, 1.0e4));
  model::State& s = sim.state();
  const model::DofMap& dofs = sim.model().dofs();
  s.velocity[dofs.firstDof(2)] = 0.1;
  VecX force;
  solver::AssemblyRequest request;
  request.dynamic = true;
  request.wantMatrix = false;
  sim.assembler().assemble(s, request, force, nullptr);
  EXPECT_NEAR(force[dofs.firstDof(2)], 100.0, 1e-6);
  EXPECT_NEAR(force[dofs.firstDof(1)], -100.0, 1e-6);
  // Its velocity derivative is c / L0 = 1e3 N s/m on the diagonal: check by finite difference.
  const double h = 1e-6;
  s.velocity[dofs.firstDof(2)] += h;
  VecX force2;
  sim.assembler().assemble(s, request, force2, nullptr);
  EXPECT_NEAR((force2[dofs.firstDof(2)] - force[dofs.firstDof(2)]) / h, 1.0e3, 1e-3);
}

TEST(Assembler, DampedBarsGiveTheSameForceWithAndWithoutTheMatrix) {
  // A bar's force and its axial damper's are computed on one chord direction in an assembly without a matrix
  // (Assembler::addElements) and apart, with their tangents, in one with a matrix: the out-of-balance must be
  // the same bit for bit (the convergence test and the parts' assembly rely on it). Nodes moved and given
  // velocities in every direction, so that each chord turns and stretches.
  analysis::Simulation sim(twoBarLine(true, 1.0e4));
  model::State& s = sim.state();
  const model::DofMap& dofs = sim.model().dofs();
  for (int node = 0; node < sim.model().nodeCount(); ++node) {
    s.position[static_cast<std::size_t>(node)] += Vec3(0.013 * node, -0.021 * node * node, 0.007);
    for (int k = 0; k < 3; ++k) s.velocity[dofs.firstDof(node) + k] = 0.1 * (k + 1) - 0.07 * node;
  }
  solver::AssemblyRequest request;
  request.dynamic = true;
  request.kf = 1.0;
  request.cf = 200.0;
  request.wantMatrix = false;
  VecX alone, withMatrix;
  sim.assembler().assemble(s, request, alone, nullptr);
  solver::SystemMatrix matrix(dofs);
  request.wantMatrix = true;
  sim.assembler().assemble(s, request, withMatrix, &matrix);
  ASSERT_EQ(alone.size(), withMatrix.size());
  for (Eigen::Index i = 0; i < alone.size(); ++i) EXPECT_EQ(alone[i], withMatrix[i]) << "DOF " << i;
  EXPECT_GT(alone.cwiseAbs().maxCoeff(), 1.0);  // the damper and the stretched bars do load the nodes
}

TEST(Assembler, RoundoffFloorNegligibleOnlyWhereEveryFloorIsBelowItsAllowance) {
  // roundoffFloorNegligible stands for nodeRoundoffFloor in the dynamic convergence test: where it says
  // so, every node's floor must lie below tolerance * its force scale (then max(allowance, floor) is the
  // allowance); where the floors reach the allowance (a tolerance at round-off, or coordinates of 1e12 m),
  // it must not.
  analysis::Simulation sim(twoBarLine(true, 0.0));
  const solver::Assembler& assembler = sim.assembler();
  std::vector<double> floor;
  assembler.nodeRoundoffFloor(sim.state(), floor);
  const std::vector<double>& scale = assembler.nodeForceScale();
  ASSERT_TRUE(assembler.roundoffFloorNegligible(sim.state(), 1e-6));
  for (std::size_t n = 0; n < floor.size(); ++n) EXPECT_LT(floor[n], 1e-6 * scale[n]) << "node " << n;
  // At a tolerance of 1e-16 the floors (16 EA eps |x| / L: about 1e-6 N here) exceed the allowance.
  bool above = false;
  for (std::size_t n = 0; n < floor.size(); ++n) above = above || floor[n] >= 1e-16 * scale[n];
  ASSERT_TRUE(above);
  EXPECT_FALSE(assembler.roundoffFloorNegligible(sim.state(), 1e-16));
  // The same tolerance with the line moved 1e12 m away: the floors grow with |x|.
  model::State far = sim.state();
  for (Vec3& x : far.position) x.x() += 1e12;
  assembler.nodeRoundoffFloor(far, floor);
  above = false;
  for (std::size_t n = 0; n < floor.size(); ++n) above = above || floor[n] >= 1e-6 * scale[n];
  ASSERT_TRUE(above);
  EXPECT_FALSE(assembler.roundoffFloorNegligible(far, 1e-6));
}

TEST(Assembler, AttachmentDragOpposesRelativeVelocity) {
  // A node at rest in a 1 m/s current with Cd A = 2 m^2: drag 1/2 * 1025 * 2 * 1^2 = 1025 N downstream.
  model::ModelSpec spec = twoBarLine(true, 0.0);
  spec.lines[0].endA.position.z() = -20.0;
  spec.lines[0].endB.position.z() = -20.0;
  spec.lines[0].attachments.push_back({10.0, 0.0, 0.0, 2.0, 0.0});
  spec.environment.current.push_back({0.0, 1.0, kPi / 2});  // towards +y
  analysis::Simulation sim(std::move(spec));
  VecX with, without;
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  sim.assembler().assemble(sim.state(), request, with, nullptr);
  const int d = sim.model().dofs().firstDof(1);
  // The line's own drag acts too; remove it by comparing with the same model without the attachment.
  model::ModelSpec plain = twoBarLine(true, 0.0);
  plain.lines[0].endA.position.z() = -20.0;
  plain.lines[0].endB.position.z() = -20.0;
  plain.environment.current.push_back({0.0, 1.0, kPi / 2});
  analysis::Simulation reference(std::move(plain));
  reference.assembler().assemble(reference.state(), request, without, nullptr);
  EXPECT_NEAR(-(with[d + 1] - without[d + 1]), 0.5 * 1025.0 * 2.0, 1e-6);
  EXPECT_NEAR(with[d] - without[d], 0.0, 1e-9);
}

TEST(Assembler, WaterplaneStiffnessIsTheDerivativeOfTheBuoyancy) {
  // A free float line through the surface (its middle element from z = -1.3 to +0.7, tilted), nothing but its
  // bars, weight and buoyancy: the vertical entries of H at the middle element's nodes equal the central
  // difference of the out-of-balance force. Without the waterplane term (docs/theory.md 5.1) they would miss
  // rho g A_b L / 2 x |z_j| / (z2 - z1)^2, 0.6-1.0 kN/m here. Tolerance: the central difference's truncation
  // and round-off on bars of EA / L = 5e6 N/m, 1e-3 N/m.
  model::ModelSpec spec;
  spec.sourceFile = "assembler (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["float"] = test::cableType("float", 0.5, 50.0, 1.0e7);
  spec.lines.push_back(test::simpleLine("l", "float", 6.0, 3, model::EndKind::Free, Vec3(0, 0, -3.3),
                                        model::EndKind::Free, Vec3(0.5, 0, 2.7)));
  analysis::Simulation sim(std::move(spec));
  model::State state = sim.state();
  state.position[1] = Vec3(0.2, 0.1, -1.3);
  state.position[2] = Vec3(0.3, -0.1, 0.7);
  const model::DofMap& dofs = sim.model().dofs();
  solver::AssemblyRequest request;
  solver::SystemMatrix matrix(dofs);
  VecX f0;
  sim.assembler().assemble(state, request, f0, &matrix);
  SparseMatrix k;
  matrix.build(k);
  const Eigen::MatrixXd dense(k);
  const double h = 1e-6;
  const double waterplane = 1025.0 * 9.80665 * 0.25 * kPi * 0.25 * 2.0 / 2.0;  // rho g A_b L / 2 [N/m]
  for (const int node : {1, 2}) {
    model::State sp = state, sm = state;
    sp.position[static_cast<std::size_t>(node)].z() += h;
    sm.position[static_cast<std::size_t>(node)].z() -= h;
    solver::AssemblyRequest forcesOnly = request;
    forcesOnly.wantMatrix = false;
    VecX fp, fm;
    sim.assembler().assemble(sp, forcesOnly, fp, nullptr);
    sim.assembler().assemble(sm, forcesOnly, fm, nullptr);
    const VecX column = (fp - fm) / (2 * h);
    const int col = dofs.equation(dofs.firstDof(node) + 2);
    for (const int other : {1, 2}) {
      const int row = dofs.firstDof(other) + 2;
      EXPECT_NEAR(dense(dofs.equation(row), col), column[row], 1e-3)
          << "node " << node << ", row node " << other;
    }
  }
  // The term itself at the upper node's column: rho g A_b L / 2 |z1| / (z2 - z1)^2 in both rows.
  const double zLow = -1.3, zHigh = 0.7;
  const double expected = waterplane * std::abs(zLow) / ((zHigh - zLow) * (zHigh - zLow));
  model::State sp = state;
  sp.position[2].z() += h;
  solver::AssemblyRequest weightOnly = request;
  VecX wp = VecX::Zero(dofs.fullDofCount()), w0 = VecX::Zero(dofs.fullDofCount());
  sim.assembler().addTerm(solver::Assembler::Term::Weight, sp, weightOnly, wp);
  sim.assembler().addTerm(solver::Assembler::Term::Weight, state, weightOnly, w0);
  EXPECT_NEAR((wp[dofs.firstDof(2) + 2] - w0[dofs.firstDof(2) + 2]) / h, expected, 1e-3 * expected);
}

}  // namespace
}  // namespace tangle

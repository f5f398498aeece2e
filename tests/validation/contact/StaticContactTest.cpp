// Static contact: a heavy line resting on a taut line, from the static solve alone (issue 4; the seed
// paper, Silva, Pereira & Jacob 2007: contact in the static as well as the dynamic analysis, 6.1).
//
// Set-up (in air, gravity 9.80665 m/s2): line A is a taut wire along x, 10 m between pinned ends at
// z = 20 m, 10 elements, d = 0.1 m, 50 kg/m, EA = 1e9 N, pretension 500 kN. Line B is a heavy chain-like
// cable, d = 0.1 m, 100 kg/m, EA = 5e8 N, 40 elements, along y with both ends pinned 2 m below A at
// y = -3 m and y = 3 m, passing over A: it starts as a stretched inverted V (see the code) and at
// equilibrium hangs over A in two catenaries, its middle node on A's middle node (a node on a node).
//
// Checks:
// - One contact patch: B is kinked over A by about 70 deg at its middle node. Under the point formulation
//   point-to-point contact is measured on the smooth (C1) centrelines, which round that kink, so the patch
//   is one point at the node or two symmetric points, one each side of it (a line wrapped over another),
//   never more; under the distributed one (the default) B's pressing Gauss points lie within its two
//   elements at the middle node (the C1 curve rounds the kink over those elements).
// Both formulations run (issue 43: the distributed one became the default).
// - The contact force equals the weight the contact carries, from the vertical equilibrium of each line
//   as a free body with its support reactions from the static solution (Simulation::snapshot):
//     B: F_z = W_B - (support reactions on B)_z,   A: F_z = (support reactions on A)_z - W_A.
//   Tolerance 1e-5 of B's weight: every nodal equilibrium holds to 1e-6 of the reference force
//   (StaticSpec::tolerance); measured 1e-9.
// - Independently, the elastic-catenary solution of each half of B between the apex and its support
//   gives the contact force (twice the vertical tension at the apex) and the horizontal tension at the
//   supports: tolerance 0.5 % (see the code); measured 0.08 % and 0.12 %.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "support/ContactChecks.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

class StaticContact : public ::testing::TestWithParam<model::ContactFormulation> {};

TEST_P(StaticContact, ContactForceCarriesTheWeightTheSupportsDoNot) {
  constexpr double kZ = 20.0, kD = 0.1, kMassA = 50.0, kMassB = 100.0, kDrop = 2.0, kEAB = 5e8, kStretchB = 1e-4;
  // B starts as an inverted V from its ends over A, its apex (middle node) 0.5 mm into A, stretched by
  // 1e-4 (tension 50 kN), so that the starting shape is close to an equilibrium without gravity (the
  // static solve ramps the loads from zero): the V's tension pulls the apex onto A.
  const Vec3 apex(0, 0, kZ + kD - 0.0005);
  const double lengthV = 2.0 * std::sqrt(9.0 + (apex.z() - (kZ - kDrop)) * (apex.z() - (kZ - kDrop)));
  const double kLengthB = lengthV / (1.0 + kStretchB);
  model::ModelSpec spec;
  spec.sourceFile = "static contact (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["wire"] = test::cableType("wire", kD, kMassA, 1e9);
  spec.lineTypes["chain"] = test::cableType("chain", kD, kMassB, kEAB);
  spec.lines = {test::simpleLine("wire", "wire", 10.0 / (1.0 + 5e5 / 1e9), 10, model::EndKind::Pinned,
                                 Vec3(-5.0, 0, kZ), model::EndKind::Pinned, Vec3(5.0, 0, kZ)),
                test::simpleLine("chain", "chain", kLengthB, 40, model::EndKind::Pinned, Vec3(0, -3.0, kZ - kDrop),
                                 model::EndKind::Pinned, Vec3(0, 3.0, kZ - kDrop))};
  spec.contact.enabled = true;
  spec.contact.formulation = GetParam();
  analysis::Simulation sim(std::move(spec));

  const model::Line& b = sim.model().lines()[1];
  for (int i = 0; i < b.nodeCount; ++i) {
    const double f = static_cast<double>(i) / (b.nodeCount - 1);
    const Vec3 end = f < 0.5 ? Vec3(0, -3.0, kZ - kDrop) : Vec3(0, 3.0, kZ - kDrop);
    const double w = f < 0.5 ? 1.0 - 2.0 * f : 2.0 * f - 1.0;
    sim.state().position[b.firstNode + i] = apex + w * (end - apex);
  }

  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto lines = sim.snapshot(false);

  const double contactZ = sim.contact()->pairForce(1, 0).z();  // vertical force on B from A [N]
  const test::PressedContact pressed = test::pressedContact(*sim.contact(), 1, 0);
  ASSERT_GE(pressed.points, 1);
  if (GetParam() == model::ContactFormulation::Point) {
    ASSERT_LE(pressed.points, 2);
  } else {  // one patch at the kink: B's Gauss points within its two elements at the middle node
    const double element = kLengthB / 40.0;
    EXPECT_GT(pressed.arcMin, 0.5 * kLengthB - element);
    EXPECT_LT(pressed.arcMax, 0.5 * kLengthB + element);
  }

  const double g = kStandardGravity;
  const double weightA = kMassA * sim.model().lines()[0].length * g;
  const double weightB = kMassB * kLengthB * g;
  const double fromB = weightB + lines[1].endForceA.z() + lines[1].endForceB.z();
  const double fromA = -(lines[0].endForceA.z() + lines[0].endForceB.z()) - weightA;
  EXPECT_NEAR(contactZ, fromB, 1e-5 * weightB);
  EXPECT_NEAR(contactZ, fromA, 1e-5 * weightB);

  // Independent check: B is an elastic catenary on each side from the outermost node the contact loads
  // (node k: its stencil nodes, one beyond the elements it presses on) to its support: with a the
  // catenary parameter, l the unstretched length from k stretched by T / EA, b the horizontal distance
  // and dz the drop from k to the support, sqrt(l^2 - dz^2) = 2 a sinh(b / (2 a)), H = w a, and the
  // vertical tension at k, V = H sinh(y_v / a) with y_v the vertex's distance from k (Irvine 1981, Cable
  // Structures, ch. 1). The contact carries both sides' V and the weight of B between the two nodes k;
  // the supports pull with H horizontally. (Under the point formulation the load is at the middle node's
  // neighbours; under the distributed one it spreads over the C1 curve's rounding of the kink.)
  const double w = kMassB * g, element = kLengthB / 40.0;
  const model::Line& chain = sim.model().lines()[1];
  const auto side = [&](int node, double supportY) {  // {H, V} of the catenary from `node` to its support
    const double span = std::abs(supportY - lines[1].position[node].y());
    const double dz = lines[1].position[node].z() - (kZ - kDrop);
    const double unstretched = (supportY > 0.0 ? chain.nodeCount - 1 - node : node) * element;
    double ell = unstretched, a = 0.0, v = 0.0;
    for (int pass = 0; pass < 4; ++pass) {  // the stretch depends on the tension, found in the same pass
      const double chord = std::sqrt(ell * ell - dz * dz);
      double lo = 0.01, hi = 1e4;  // 2 a sinh(span / 2a) decreases with a towards span
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (2.0 * mid * std::sinh(span / (2.0 * mid)) > chord ? lo : hi) = mid;
      }
      a = 0.5 * (lo + hi);
      // Vertex abscissa y_v: a (cosh(y_v / a) - cosh((span - y_v) / a)) = dz (k at 0, support at span).
      double ylo = -100.0, yhi = 100.0;
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (ylo + yhi);
        (a * (std::cosh(mid / a) - std::cosh((span - mid) / a)) < dz ? ylo : yhi) = mid;
      }
      v = w * a * std::sinh(0.5 * (ylo + yhi) / a);
      ell = unstretched * (1.0 + std::hypot(w * a, v) / kEAB);
    }
    return std::array<double, 2>{w * a, v};
  };
  const int nodeA = std::max(0, static_cast<int>(std::floor(pressed.arcMin / element)) - 1);
  const int nodeB = std::min(chain.nodeCount - 1, static_cast<int>(std::floor(pressed.arcMax / element)) + 2);
  const std::array<double, 2> towardsA = side(nodeA, -3.0), towardsB = side(nodeB, 3.0);
  const double carried = towardsA[1] + towardsB[1] + w * (nodeB - nodeA) * element;
  // Tolerance 0.5 %: B's 20 elements per half carry the weight at their nodes (a polygon, not the
  // catenary: error of order (element / half-length)^2 = 0.25 %; measured 0.1 %).
  EXPECT_NEAR(contactZ, carried, 0.005 * contactZ);
  EXPECT_NEAR(std::abs(lines[1].endForceA.y()), towardsA[0], 0.005 * towardsA[0]);
  EXPECT_NEAR(std::abs(lines[1].endForceB.y()), towardsB[0], 0.005 * towardsB[0]);
  RecordProperty("loaded_nodes", fmt::format("{}-{}", nodeA, nodeB));
  RecordProperty("catenary_relative_error", fmt::format("{:.3e}", contactZ / carried - 1.0));
  RecordProperty("contact_force", fmt::format("{:.3f}", contactZ));
  RecordProperty("relative_error_B", fmt::format("{:.3e}", fromB / contactZ - 1.0));
  RecordProperty("relative_error_A", fmt::format("{:.3e}", fromA / contactZ - 1.0));
}

INSTANTIATE_TEST_SUITE_P(Formulations, StaticContact, test::bothFormulations(), test::formulationTestName);

}  // namespace
}  // namespace tangle

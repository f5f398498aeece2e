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
// - One contact patch: B is kinked over A by about 70 deg at its middle node; point-to-point contact is
//   measured on the smooth (C1) centrelines, which round that kink, so the patch is one point at the
//   node or two symmetric points, one each side of it (a line wrapped over another), never more.
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

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

TEST(StaticContact, ContactForceCarriesTheWeightTheSupportsDoNot) {
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

  double contactZ = 0.0;  // vertical force on B from A [N]
  int points = 0;
  for (const contact::ContactPoint& p : sim.contact()->contacts()) {
    if (p.normalForce <= 0.0) continue;
    ++points;
    contactZ += -(p.normalForce * p.normal + p.frictionForce).z();  // force on B (lineB) = - force on A
  }
  ASSERT_GE(points, 1);
  ASSERT_LE(points, 2);

  const double g = kStandardGravity;
  const double weightA = kMassA * sim.model().lines()[0].length * g;
  const double weightB = kMassB * kLengthB * g;
  const double fromB = weightB + lines[1].endForceA.z() + lines[1].endForceB.z();
  const double fromA = -(lines[0].endForceA.z() + lines[0].endForceB.z()) - weightA;
  EXPECT_NEAR(contactZ, fromB, 1e-5 * weightB);
  EXPECT_NEAR(contactZ, fromA, 1e-5 * weightB);

  // Independent check: each half of B is an elastic catenary between the apex (B's middle node, the
  // height the contact found) and its support, 3 m away horizontally: with a the catenary parameter
  // and s the unstretched half-length stretched by T / EA, sqrt(l^2 - dz^2) = 2 a sinh(3 / (2 a)),
  // H = w a, and the vertical tension at the apex V = H sinh((0 - y_vertex) / a) (Irvine 1981, Cable
  // Structures, ch. 1). The contact carries 2 V, the supports pull with H horizontally.
  const double w = kMassB * g, span = 3.0;
  const double dz = lines[1].position[20].z() - (kZ - kDrop);
  double ell = 0.5 * kLengthB, a = 0.0, vApex = 0.0;
  for (int pass = 0; pass < 4; ++pass) {  // the stretch depends on the tension, found in the same pass
    const double chord = std::sqrt(ell * ell - dz * dz);
    double lo = 0.01, hi = 1e4;  // 2 a sinh(span / 2a) decreases with a towards span
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (2.0 * mid * std::sinh(span / (2.0 * mid)) > chord ? lo : hi) = mid;
    }
    a = 0.5 * (lo + hi);
    // Vertex abscissa y_v: a (cosh(y_v / a) - cosh((span - y_v) / a)) = dz (apex at y = 0, support at span).
    double ylo = -100.0, yhi = 100.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (ylo + yhi);
      (a * (std::cosh(mid / a) - std::cosh((span - mid) / a)) < dz ? ylo : yhi) = mid;
    }
    const double yVertex = 0.5 * (ylo + yhi);
    vApex = w * a * std::sinh(yVertex / a);
    ell = 0.5 * kLengthB * (1.0 + std::hypot(w * a, vApex) / kEAB);
  }
  // Tolerance 0.5 %: B's 20 elements per half carry the weight at their nodes (a polygon, not the
  // catenary: error of order (element / half-length)^2 = 0.25 %; measured 0.1 %).
  EXPECT_NEAR(contactZ, 2.0 * vApex, 0.005 * contactZ);
  EXPECT_NEAR(std::abs(lines[1].endForceA.y()), w * a, 0.005 * w * a);
  RecordProperty("catenary_relative_error", fmt::format("{:.3e}", contactZ / (2.0 * vApex) - 1.0));
  RecordProperty("contact_force", fmt::format("{:.3f}", contactZ));
  RecordProperty("relative_error_B", fmt::format("{:.3e}", fromB / contactZ - 1.0));
  RecordProperty("relative_error_A", fmt::format("{:.3e}", fromA / contactZ - 1.0));
}

}  // namespace
}  // namespace tangle

// Issue 47: free points where any number of line ends meet (`points`, end type `point`): a 3D buoy held
// down by three taut legs and a clump hung from a bridle of three unequal legs, each against a hand
// equilibrium of the junction.
//
// Reference: the lines are neutrally buoyant (mass per length = rho pi D^2 / 4) and carry no drag, so each
// is a straight two-force member: its tension is EA (l - L0) / L0 along its chord, l the distance from its
// far end to the point. The point's equilibrium sum_i T_i (a_i - x) / l_i + W = 0 (W its weight less its
// buoyancy, along -z) is solved here by bisection (the symmetric buoy: one unknown, the height) and by a
// 3D Newton iteration with a finite-difference Jacobian (the bridle), independently of the FE model.
//
// Tolerances: the ties of the second and third legs to the point (a penalty of 100 EA / L of their end
// element, docs/theory.md 2.5) stretch by 1 % of one element's extension (0.27 mm for the buoy's 36 kN): the
// point's position within 1 mm (measured 0.36 and 0.21 mm). A tied leg is the leg in series with its tie,
// 0.1 % more compliant than the hand model's: its tension moves by a small part of that (measured 2e-5):
// tensions within 1e-4.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "tangle/analysis/EquilibriumAudit.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kRho = 1025.0, kG = 9.81;
constexpr double kDiameter = 0.1;
/// Neutral line: it displaces its own mass [kg/m].
const double kNeutralMass = kRho * 0.25 * 3.141592653589793 * kDiameter * kDiameter;

struct Leg {
  std::string name;
  Vec3 anchor;    ///< far end [m]
  double length;  ///< unstretched [m]
  double ea;      ///< [N]
  bool beam;      ///< a beam line type (EI > 0): its end node has rotations
  bool pointAtA;  ///< the point is at end A (else at end B)
};

/// The model text: `legs` from their far ends (type `far`) to a point `p` at `start` with mass and volume.
std::string junctionModel(const std::vector<Leg>& legs, const std::string& far, const Vec3& start,
                          double mass, double volume) {
  const auto vec = [](const Vec3& v) { return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z()); };
  std::string y = fmt::format(R"(
environment: {{water_depth: 100, water_density: {}, gravity: {}}}
line_types:
)",
                              kRho, kG);
  for (std::size_t i = 0; i < legs.size(); ++i)
    y += fmt::format(
        "  - {{name: t{}, outer_diameter: {}, mass_per_length: {:.12g}, axial_stiffness: {}, "
        "bending_stiffness: {}, "
        "drag_normal: 0, drag_axial: 0}}\n",
        i, kDiameter, kNeutralMass, legs[i].ea, legs[i].beam ? 1.0e4 : 0.0);
  y += fmt::format("points:\n  - {{name: p, position: {}, mass: {}, volume: {}}}\nlines:\n", vec(start), mass,
                   volume);
  for (std::size_t i = 0; i < legs.size(); ++i) {
    const std::string farEnd = fmt::format("{{type: {}, position: {}}}", far, vec(legs[i].anchor));
    const std::string pointEnd = "{type: point, point: p}";
    y += fmt::format(
        "  - name: {}\n    end_a: {}\n    end_b: {}\n    sections: [{{type: t{}, length: {}, elements: "
        "10}}]\n",
        legs[i].name, legs[i].pointAtA ? pointEnd : farEnd, legs[i].pointAtA ? farEnd : pointEnd, i,
        legs[i].length);
  }
  return y;
}

/// The legs' pull on the point at x plus its net weight [N] (zero at the hand equilibrium).
Vec3 outOfBalance(const std::vector<Leg>& legs, const Vec3& x, double netWeight) {
  Vec3 f(0.0, 0.0, -netWeight);
  for (const Leg& leg : legs) {
    const Vec3 chord = leg.anchor - x;
    const double l = chord.norm();
    f += leg.ea * (l - leg.length) / leg.length * chord / l;
  }
  return f;
}

/// The hand equilibrium: Newton from `start` with a central-difference Jacobian.
Vec3 handEquilibrium(const std::vector<Leg>& legs, Vec3 x, double netWeight) {
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Vec3 f = outOfBalance(legs, x, netWeight);
    if (f.norm() < 1e-9 * std::abs(netWeight)) break;
    Mat3 jacobian;
    for (int k = 0; k < 3; ++k) {
      Vec3 h = Vec3::Zero();
      h[k] = 1e-6;
      jacobian.col(k) = (outOfBalance(legs, x + h, netWeight) - outOfBalance(legs, x - h, netWeight)) / 2e-6;
    }
    x -= jacobian.lu().solve(f);
  }
  return x;
}

struct JunctionSolution {
  Vec3 point;                   ///< the point's position [m]
  std::vector<double> tension;  ///< each leg's tension at the point [N]
  solver::EquilibriumAudit audit;
};

JunctionSolution solve(const std::string& yaml) {
  analysis::Simulation sim(io::readModelString(yaml, "junction (test)"));
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << r.message;
  const std::vector<solver::LineSnapshot> lines = sim.snapshot();
  JunctionSolution s;
  const model::Model& model = sim.model();
  EXPECT_EQ(model.points().size(), 1u);
  s.point = sim.state().position[static_cast<std::size_t>(model.points().front().node)];
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const bool atA = model.lines()[l].spec->endA.kind == model::EndKind::Point;
    s.tension.push_back(atA ? lines[l].endTensionA : lines[l].endTensionB);
  }
  s.audit = analysis::auditStatics(sim, lines);
  return s;
}

void expectLegTensions(const std::vector<Leg>& legs, const Vec3& x, const std::vector<double>& tension) {
  for (std::size_t i = 0; i < legs.size(); ++i) {
    const double l = (legs[i].anchor - x).norm();
    const double expected = legs[i].ea * (l - legs[i].length) / legs[i].length;
    EXPECT_NEAR(tension[i], expected, 1e-4 * expected) << legs[i].name;
  }
}

TEST(Junction, BuoyOnThreeTautLegsMatchesTheHandEquilibrium) {
  // A 10 m^3 buoy of 2 t held by three legs of 75 m from anchors 50 m around it, 1 m above the seabed (an
  // anchor on the seabed is seated on its contact surface, a radius higher); legs 1 and 2 reach it with their
  // end B, leg 3 with its end A.
  const double c = std::cos(2.0 * 3.141592653589793 / 3.0), s = std::sin(2.0 * 3.141592653589793 / 3.0);
  const std::vector<Leg> legs{{"leg1", {50.0, 0.0, -99.0}, 75.0, 1.0e7, false, false},
                              {"leg2", {50.0 * c, 50.0 * s, -99.0}, 75.0, 1.0e7, false, false},
                              {"leg3", {50.0 * c, -50.0 * s, -99.0}, 75.0, 1.0e7, false, true}};
  const double mass = 2000.0, volume = 10.0;
  const double net = (mass - kRho * volume) * kG;  // < 0: it floats
  // By symmetry the buoy is above the centre at height h over the anchors: 3 T(h) h / l = -net, bisection.
  double lo = 0.0, hi = 100.0;
  for (int k = 0; k < 200; ++k) {
    const double h = 0.5 * (lo + hi), l = std::hypot(50.0, h);
    const double up = 3.0 * 1.0e7 * (l - 75.0) / 75.0 * h / l;
    (up > -net ? hi : lo) = h;
  }
  const Vec3 expected(0.0, 0.0, -99.0 + 0.5 * (lo + hi));
  const JunctionSolution r = solve(junctionModel(legs, "anchored", {0.0, 0.0, -40.0}, mass, volume));
  EXPECT_NEAR((r.point - expected).norm(), 0.0, 1e-3) << r.point.transpose();
  expectLegTensions(legs, expected, r.tension);
  ASSERT_EQ(r.audit.points.size(), 1u);
  EXPECT_TRUE(r.audit.points[0].balanced()) << r.audit.points[0].relativeResidual();
  EXPECT_TRUE(r.audit.warnings().empty());
}

TEST(Junction, ClumpOnAnUnequalBridleMatchesTheHandEquilibrium) {
  // A 3 t clump (0.4 m^3) hung from three pinned points at different heights by legs of different length and
  // stiffness, the second a beam (its end node has rotations); the point starts 3 m off its equilibrium.
  const std::vector<Leg> legs{{"a", {30.0, 5.0, -10.0}, 32.0, 2.0e7, false, true},
                              {"b", {-20.0, 25.0, -20.0}, 30.0, 8.0e6, true, false},
                              {"c", {-15.0, -30.0, -5.0}, 40.0, 1.5e7, false, false}};
  const double mass = 3000.0, volume = 0.4;
  const double net = (mass - kRho * volume) * kG;
  const Vec3 expected = handEquilibrium(legs, {0.0, 0.0, -35.0}, net);
  ASSERT_LT(outOfBalance(legs, expected, net).norm(), 1e-6 * net);
  for (const Leg& leg : legs) ASSERT_GT((leg.anchor - expected).norm(), leg.length) << "legs taut";
  const JunctionSolution r =
      solve(junctionModel(legs, "pinned", expected + Vec3(2.0, -2.0, 1.0), mass, volume));
  EXPECT_NEAR((r.point - expected).norm(), 0.0, 1e-3)
      << r.point.transpose() << " vs " << expected.transpose();
  expectLegTensions(legs, expected, r.tension);
  ASSERT_EQ(r.audit.points.size(), 1u);
  const solver::ForceBalance& b = r.audit.points[0];
  EXPECT_TRUE(b.balanced()) << b.relativeResidual();
  // The body's term is its net weight; the lines' term holds it up.
  EXPECT_NEAR(b.terms[0].second.z(), -net, 1e-9 * net);
  EXPECT_NEAR(b.terms[2].second.z(), net, 1e-6 * net);
}

TEST(Junction, LinesMeetingAtAPointAreNeitherAClashNorAClearanceFailure) {
  // The three legs touch at the buoy by construction: contact, the clash report's clearance and the
  // DNV-RP-F203 envelope skip them there (a shared connection, as lines at one fairlead), and measure the
  // legs where they part: one element (7.5 m) from the buoy, at 120 degrees, 14 m apart. Before, the envelope
  // read -0.10 m (the sum of the radii) at the point and failed every pair.
  const double c = std::cos(2.0 * 3.141592653589793 / 3.0), s = std::sin(2.0 * 3.141592653589793 / 3.0);
  const std::vector<Leg> legs{{"leg1", {50.0, 0.0, -99.0}, 75.0, 1.0e7, false, false},
                              {"leg2", {50.0 * c, 50.0 * s, -99.0}, 75.0, 1.0e7, false, false},
                              {"leg3", {50.0 * c, -50.0 * s, -99.0}, 75.0, 1.0e7, false, true}};
  analysis::Simulation sim(io::readModelString(
      junctionModel(legs, "anchored", {0.0, 0.0, -40.0}, 2000.0, 10.0) + "contact: {}\n", "junction (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  ASSERT_NE(sim.contact(), nullptr);
  contact::ClearanceEnvelope envelope(sim.model(), sim.contact()->assessedPairs(sim.state()));
  envelope.recordStatic(sim.state());
  ASSERT_EQ(envelope.sides().size(), 6u);
  for (const contact::ClearanceEnvelope::Side& side : envelope.sides()) {
    const double smallest = *std::min_element(side.staticClearance.begin(), side.staticClearance.end());
    EXPECT_GT(smallest, 10.0) << side.line << " to " << side.other;
    EXPECT_GT(sim.contact()->clearance(sim.state(), side.line, side.other)[0], 10.0);
  }
}

}  // namespace
}  // namespace tangle

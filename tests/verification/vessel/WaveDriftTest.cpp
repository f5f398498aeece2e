/// @file WaveDriftTest.cpp
/// The mean wave drift on a free vessel is one sea's, however the sea is written down.
///
/// Source: the mean second-order force of a sea of regular components is the sum of the components' own,
/// each D(beta_i) a_i^2 with D the drift per unit amplitude squared (Faltinsen 1990, "Sea loads on ships and
/// offshore structures", ch. 5; for a spectrum F = 2 int S(omega) D d omega = 2 m0 D, with m0 = Hs^2 / 16).
/// So an Airy wave of height 2 m (a^2 = 1 m^2), one component of amplitude 1 m, two components with
/// a_1^2 + a_2^2 = 1 m^2 and a JONSWAP sea of Hs = 2 sqrt(2) m (2 m0 = 1 m^2), all travelling towards +y,
/// push the vessel alike (tolerance 1e-9 of the offset: the same force, so the same equilibrium up to the
/// static solver's tolerance). A component that travels another way pushes that way: rows towards +x and
/// +y of equal amplitude move the vessel diagonally (the four lines are symmetric about the diagonal).
/// Until 2026-12-06 an irregular sea used a = Hs / 2 = 2 sqrt(m0) (twice the drift), and every component
/// the block's azimuth (0 when not given).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

/// A free vessel held by four taut ropes (in x and y) under a drift table of 1e4 N per m^2 along the waves'
/// direction, its statics solved in the sea `waves`; the vessel's horizontal offset [m].
Vec3 offsetIn(const std::string& waves) {
  const std::string yaml = fmt::format(R"(
environment:
  water_depth: 100
  waves:
{}
line_types:
  - {{name: rope, outer_diameter: 0.1, mass_per_length: 8.05, axial_stiffness: 1.0e6}}
vessels:
  - name: v
    mode: free
    position: [0, 0, 0]
    mass: 1.0e6
    inertia: [1e8, 1e8, 1e8]
    hydrostatic_stiffness: [0, 0, 1.0e6, 1.0e9, 1.0e9, 0]
    wave_drift: [[0, 1.0e4, 0, 0], [90, 0, 1.0e4, 0], [180, -1.0e4, 0, 0], [270, 0, -1.0e4, 0]]
lines:
  - {{name: l1, end_a: {{type: pinned, position: [-100, 0, -10]}}, end_b: {{type: vessel, vessel: v, position: [0, 0, -10]}}, sections: [{{type: rope, length: 99, elements: 10}}]}}
  - {{name: l2, end_a: {{type: pinned, position: [0, -100, -10]}}, end_b: {{type: vessel, vessel: v, position: [0, 0, -10]}}, sections: [{{type: rope, length: 99, elements: 10}}]}}
  - {{name: l3, end_a: {{type: pinned, position: [100, 0, -10]}}, end_b: {{type: vessel, vessel: v, position: [0, 0, -10]}}, sections: [{{type: rope, length: 99, elements: 10}}]}}
  - {{name: l4, end_a: {{type: pinned, position: [0, 100, -10]}}, end_b: {{type: vessel, vessel: v, position: [0, 0, -10]}}, sections: [{{type: rope, length: 99, elements: 10}}]}}
)",
                                       waves);
  analysis::Simulation sim(io::readModelString(yaml, "wave drift (test)"));
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << r.message;
  const Vec3 p = sim.state().position[sim.model().vesselNode(0)];
  return Vec3(p.x(), p.y(), 0.0);
}

TEST(WaveDrift, OneSeaWrittenFourWaysPushesTheVesselAlike) {
  const Vec3 airy = offsetIn("    {type: airy, height: 2.0, period: 10.0, azimuth: 90}");
  ASSERT_GT(airy.y(), 0.1) << "the drift of 1e4 N moves the vessel along +y";
  EXPECT_NEAR(airy.x(), 0.0, 1e-9);
  const double tol = 1e-9 * airy.y();
  const Vec3 one = offsetIn("    {type: components, table: [[10.0, 1.0, 0, 90]]}");
  EXPECT_NEAR(one.x(), 0.0, tol);
  EXPECT_NEAR(one.y(), airy.y(), tol) << "one component of amplitude 1 m against the Airy wave of height 2 m";
  const Vec3 two = offsetIn("    {type: components, azimuth: 90, table: [[10.0, 0.6, 0], [8.0, 0.8, 1.0]]}");
  EXPECT_NEAR(two.y(), airy.y(), tol) << "a_1^2 + a_2^2 = 1 m^2";
  const Vec3 spectrum =
      offsetIn("    {type: jonswap, significant_height: 2.8284271247461903, peak_period: 10.0, azimuth: 90}");
  EXPECT_NEAR(spectrum.y(), airy.y(), tol) << "2 m0 = Hs^2 / 8 = 1 m^2";
}

TEST(WaveDrift, EachComponentPushesAlongItsOwnDirection) {
  const Vec3 crossing = offsetIn("    {type: components, table: [[10.0, 1.0, 0, 0], [10.0, 1.0, 0, 90]]}");
  EXPECT_GT(crossing.x(), 0.1);
  EXPECT_NEAR(crossing.x(), crossing.y(), 1e-9 * crossing.x()) << "rows towards +x and +y";
}

}  // namespace
}  // namespace tangle

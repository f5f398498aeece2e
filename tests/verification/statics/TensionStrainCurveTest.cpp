// Issue 47, "nonlinear ropes": line_types[].tension_strain, a cable's tension against strain (a polyester or
// nylon rope's stiffening), read by element::Bar.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

std::string hangingRope(const std::string& stiffness, const std::string& endB, double clumpMass) {
  return fmt::format(R"(title: a rope hanging from a pin with a clump
environment: {{water_depth: 300}}
line_types:
  - {{name: rope, outer_diameter: 0.15, mass_per_length: 200, {}}}
lines:
  - name: rope
    end_a: {{type: pinned, position: [0, 0, -10]}}
    end_b: {}
    sections: [{{type: rope, length: 100, elements: 50}}]
    attachments: [{{arc_length: 100, mass: {}, volume: 0}}]
dynamics: {{duration: 0}}
)",
                     stiffness, endB, clumpMass);
}

// A linear curve is the constant EA: a hanging catenary (end B pinned 60 m across, 50 m down) with
// tension_strain [[0.01, 0.01 EA]] against axial_stiffness EA. Reference: the same model with EA; tolerance
// 1e-6 of the tension, the statics' convergence tolerance (the two are solved separately).
TEST(TensionStrainCurve, ALinearCurveIsTheConstantAxialStiffness) {
  const std::string endB = "{type: pinned, position: [60, 0, -60]}";
  const auto endTensions = [](const std::string& yaml) {
    analysis::Simulation sim(io::readModelString(yaml, "rope.yaml"));
    EXPECT_TRUE(sim.solveStatics().converged);
    const std::vector<solver::LineSnapshot> s = sim.snapshot();
    return std::pair{s.front().endTensionA, s.front().endTensionB};
  };
  const auto linear = endTensions(hangingRope("axial_stiffness: 2.0e7", endB, 0.0));
  const auto curve = endTensions(hangingRope("tension_strain: [[0.01, 2.0e5]]", endB, 0.0));
  EXPECT_NEAR(curve.first, linear.first, 1e-6 * linear.first);
  EXPECT_NEAR(curve.second, linear.second, 1e-6 * linear.second);
}

// A stiffening curve on a vertical rope: 100 m of rope (200 kg/m, 0.15 m: w = 1.78 kN/m submerged) with a
// 150 kN clump hangs from a pin; the effective tension runs from 150 kN at the clump to 328 kN at the top,
// through the curve's knee at 300 kN. Reference: the stretch integral(eps(T(s)) ds) over the unstretched
// length, T(s) = W_c + w (L - s), eps the curve's inverse, by the midpoint rule on 1e6 intervals (converged
// to 1e-10). Tolerance 0.1 %: the mesh carries one tension per element (50 elements: the midpoint rule on the
// element's own strain, exact where eps is linear in s, off in the knee's element only, by at most about
// h^2 (jump of d eps/ds) / 8 = (2 m)^2 x 3.8e-5 /m / 8 = 1.9e-5 m of 1.69 m); measured 2e-6 m.
TEST(TensionStrainCurve, AStiffeningRopeStretchesAsItsCurveIntegratedAlongItsTension) {
  constexpr double kClump = 150.0e3 / 9.80665;  // [kg] with no volume: 150 kN
  const std::string curve = "tension_strain: [[0.01, 1.0e5], [0.02, 3.0e5], [0.04, 1.0e6]]";
  analysis::Simulation sim(
      io::readModelString(hangingRope(curve, "{type: free, position: [0, 0, -110]}", kClump), "rope.yaml"));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::Model& m = sim.model();
  const model::Line& line = m.lines().front();
  const double length = sim.state().position[line.firstNode].z() - sim.state().position[line.lastNode()].z();
  // The reference.
  const double g = 9.80665, rho = 1025.0;
  const double w = (200.0 - rho * std::numbers::pi * 0.15 * 0.15 / 4.0) * g;
  const auto strainOf = [](double t) {  // the curve's inverse
    const double s[] = {0.0, 0.01, 0.02, 0.04}, f[] = {0.0, 1.0e5, 3.0e5, 1.0e6};
    int i = 0;
    while (i < 2 && t > f[i + 1]) ++i;
    return s[i] + (t - f[i]) * (s[i + 1] - s[i]) / (f[i + 1] - f[i]);
  };
  constexpr int kIntervals = 1000000;
  double stretch = 0.0;
  for (int k = 0; k < kIntervals; ++k) {
    const double s = (k + 0.5) * 100.0 / kIntervals;
    stretch += strainOf(150.0e3 + w * (100.0 - s)) * 100.0 / kIntervals;
  }
  EXPECT_NEAR(length - 100.0, stretch, 1e-3 * stretch);
  // The top tension: the whole weight, whatever the law; within 1e-5: the statics leaves each of the 51 nodes
  // up to 1e-6 of the force scale out of balance (measured 1.5e-6).
  EXPECT_NEAR(sim.snapshot().front().endTensionA, 150.0e3 + 100.0 * w, 1e-5 * (150.0e3 + 100.0 * w));
  RecordProperty("stretch_m", fmt::format("{:.6f}", length - 100.0));
  RecordProperty("reference_m", fmt::format("{:.6f}", stretch));
}

}  // namespace
}  // namespace tangle

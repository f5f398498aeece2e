// Verification of the steady current load (issue 3, item 4): a vertical tensioned riser between two pins
// in a uniform current. The static analysis applies the Morison drag of the current (HydroLoads), so
// the steady deflection is compared with closed forms for a uniform lateral load
// q = 1/2 rho Cd D U^2 [N/m]:
//
// - string (bars) with constant tension T, pinned ends (e.g. Irvine 1981, "Cable structures", ch. 1;
//   any statics text):               y(s) = q s (L - s) / (2 T);
// - tensioned beam (tie-rod) with bending stiffness EI, pinned (moment-free) ends: solution of
//   EI y'''' - T y'' = q, y = y'' = 0 at s = 0, L (Timoshenko & Gere 1961, "Theory of elastic stability",
//   sec. 1.11, beam-column in tension), with k = sqrt(T / EI):
//     y(s) = q / T [ s (L - s) / 2 + (cosh(k (s - L/2)) / cosh(k L / 2) - 1) / k^2 ].
//
// Constant tension: the riser's submerged weight is zero (mass per length = rho A_b, so weight and
// buoyancy cancel), and the tension T comes from the pins being further apart than the rest length
// (L0 = L / (1 + T / EA)).
//
// Second-order effects neglected by the closed forms (all far below the 1 % issue bound):
// - drag on the normal velocity component only, q cos^2(theta), theta <= qL/(2T) = 2.6e-3 rad: 7e-6;
// - the normal drag has a vertical component q sin(theta), antisymmetric about mid-span: it changes the
//   tension by at most q theta L / 4 = 1.6 N = 3e-6 T;
// - axial drag: Cda = 0.008 on the axial current component U sin(theta): 1e-7 N/m, nil;
// - the lateral deflection stretches the line: tension rise EA/T x mean(y'^2)/2 = 100 x 1.1e-6 = 1.1e-4
//   T, which reduces the deflection by the same fraction (the dominant error for the string);
// - beam only: the co-rotational element's bending energy EI/L0 (...) refers EI to the unstretched
//   length (curvature per reference arc length, as in Reissner's rod theory), so in the stretched riser
//   (strain eps = T/EA = 1 %) it bends like a beam of stiffness EI (1 + eps) per current length. The
//   bending part of the deflection is 3.5 % of it here, hence a 3.6e-4 smaller deflection (the
//   dominant error for the beam). Both closed forms evaluated with the measured FE tension and, for the
//   beam, EI (1 + eps) leave only the tiny terms above and the discretisation: checked at 1e-4.
// Discretisation: with lumped nodal loads q h the string's nodal deflections are exact (the discrete
// equation T (2 y_i - y_i-1 - y_i+1) / h = q h is solved by the parabola); the beam converges as h^2
// (measured 3e-7 with 100 elements, k h = 0.15, against the EI (1 + eps) solution).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/hydro/CurrentGrid.hpp"

namespace tangle {
namespace {

constexpr double kRho = 1025.0;      // [kg/m^3]
constexpr double kSpeed = 0.5;       // uniform current [m/s]
constexpr double kTension = 5.0e5;   // [N]
constexpr double kEA = 5.0e7;        // [N]: EA / T = 100
constexpr double kSpan = 100.0;      // distance between the pins [m]
constexpr double kBottom = -150.0;   // lower pin [m]
constexpr double kDepth = 200.0;     // [m]: the riser is fully submerged and clear of the seabed

struct RiserResult {
  std::vector<double> height;      // s = height of each node above the lower pin [m]
  std::vector<double> deflection;  // x of each node [m]
  double tension = 0.0;            // mean element tension [N]
  /// max |y_FE - exact(s)| over the nodes divided by max exact(s) [-].
  template <class Exact>
  double relativeError(Exact exact) const {
    double err = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < height.size(); ++i) {
      err = std::max(err, std::abs(deflection[i] - exact(height[i])));
      peak = std::max(peak, exact(height[i]));
    }
    return err / peak;
  }
};

/// Static deflection of the riser (a vertical line between pins in a uniform current).
RiserResult solveRiser(const section::LineType& type, int elements,
                       std::shared_ptr<const hydro::CurrentGrid> grid = nullptr) {
  model::ModelSpec spec;
  spec.sourceFile = "riser in current (test)";
  spec.environment.waterDepth = kDepth;
  spec.environment.waterDensity = kRho;
  spec.environment.current = {{0.0, kSpeed, 0.0}, {-kDepth, kSpeed, 0.0}};  // uniform, towards +x
  if (grid) {
    spec.environment.current.clear();
    spec.environment.currentGrid = std::move(grid);
  }
  spec.lineTypes[type.name] = type;
  const double restLength = kSpan / (1.0 + kTension / kEA);
  spec.lines.push_back(test::simpleLine("riser", type.name, restLength, elements, model::EndKind::Pinned,
                                        Vec3(0, 0, kBottom), model::EndKind::Pinned, Vec3(0, 0, kBottom + kSpan)));
  spec.statics.tolerance = 1e-9;
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << r.message;
  RiserResult out;
  const model::Line& line = sim.model().lines()[0];
  for (int i = 0; i < line.nodeCount; ++i) {
    const Vec3& x = sim.state().position[line.firstNode + i];
    out.height.push_back(x.z() - kBottom);
    out.deflection.push_back(x.x());
    EXPECT_NEAR(x.y(), 0.0, 1e-9) << "no load across the current";
  }
  const std::vector<double> t = sim.assembler().elementTension(sim.state());
  for (double v : t) out.tension += v / static_cast<double>(t.size());
  return out;
}

section::LineType riserType(const std::string& name, double diameter, double bendingStiffness) {
  section::LineType type = test::cableType(name, diameter, 0.0, kEA);
  type.massPerLength = kRho * type.displacedAreaPerLength();  // zero submerged weight
  type.bendingStiffness = bendingStiffness;
  type.dragNormal = 1.0;
  type.dragAxial = 0.008;
  return type;
}

TEST(RiserInCurrentTest, StringDeflectionMatchesParabola) {
  const section::LineType type = riserType("riser", 0.2, 0.0);
  const double q = 0.5 * kRho * type.dragNormal * type.outerDiameter * kSpeed * kSpeed;  // 25.6 N/m
  const RiserResult r = solveRiser(type, 50);
  const auto parabola = [&](double tension) {
    return [=](double s) { return q * s * (kSpan - s) / (2.0 * tension); };
  };
  const double error = r.relativeError(parabola(kTension));
  const double errorMeasuredT = r.relativeError(parabola(r.tension));
  std::printf("string riser: max deflection %.5f m, relative error %.3e (%.3e with the FE tension %.1f N)\n",
              q * kSpan * kSpan / (8.0 * kTension), error, errorMeasuredT, r.tension);
  // Issue bound 1 % of the deflection; expected ~1.1e-4 (stretch-induced tension rise, file comment).
  EXPECT_LE(error, 0.01);
  // The tension stays the prescribed one up to that rise (5e-4: 4.5x the estimate).
  EXPECT_NEAR(r.tension, kTension, 5e-4 * kTension);
  // With the FE tension only the O(theta^2) drag terms remain (~1e-5): bound 1e-4.
  EXPECT_LE(errorMeasuredT, 1e-4);
}

TEST(RiserInCurrentTest, TensionedBeamDeflectionMatchesTieRodSolution) {
  // 10-3/4" riser pipe stiffness, EI = 2.2e7 N m^2: k L = 15, bending reduces the mid-span deflection
  // by 3.5 % against the string, so the test discriminates the beam from the string at the 1 % bound.
  const double ei = 2.2e7;
  const section::LineType type = riserType("riser_beam", 0.2731, ei);
  const double q = 0.5 * kRho * type.dragNormal * type.outerDiameter * kSpeed * kSpeed;
  const auto tieRod = [&](double tension, double bending) {
    const double k = std::sqrt(tension / bending);
    return [=](double s) {
      return q / tension *
             (0.5 * s * (kSpan - s) + (std::cosh(k * (s - 0.5 * kSpan)) / std::cosh(0.5 * k * kSpan) - 1.0) / (k * k));
    };
  };
  const RiserResult r = solveRiser(type, 100);
  const double error = r.relativeError(tieRod(kTension, ei));
  const double strain = r.tension / kEA;
  const double errorCorrected = r.relativeError(tieRod(r.tension, ei * (1.0 + strain)));
  const double beamMid = tieRod(kTension, ei)(0.5 * kSpan);
  const double stringMid = q * kSpan * kSpan / (8.0 * kTension);
  std::printf("beam riser: max deflection %.5f m (string %.5f m), relative error %.3e (%.3e with the FE tension "
              "and EI (1 + eps))\n",
              beamMid, stringMid, error, errorCorrected);
  // Issue bound 1 %; expected 3.6e-4 (EI per unstretched length) + 2e-4 (tension rise): file comment.
  EXPECT_LE(error, 0.01);
  EXPECT_GT(stringMid - beamMid, 0.03 * stringMid) << "the case must discriminate beam from string";
  // Both understood effects removed: only O(theta^2) drag terms and discretisation remain (1e-5).
  EXPECT_LE(errorCorrected, 1e-4);
}

// A current on a grid in space and time (environment.current.grid) loads the riser as the same field given as
// a profile: a uniform grid gives the string's parabola (source: as StringDeflectionMatchesParabola, same
// bound), and a grid that is uniform in x, y and t but sheared in z gives the profile's shape to the solver's
// tolerance (two code paths for one field: HydroLoads evaluates both at the element midpoints; 1e-6 m on ~0.3
// m).
TEST(RiserInCurrentTest, CurrentGridLoadsAsTheSameProfile) {
  const section::LineType type = riserType("riser", 0.2, 0.0);
  const double q = 0.5 * kRho * type.dragNormal * type.outerDiameter * kSpeed * kSpeed;
  const auto uniform = std::make_shared<const hydro::CurrentGrid>(
      std::array<std::vector<double>, 4>{std::vector<double>{-50.0, 50.0}, {0.0}, {-kDepth}, {0.0, 100.0}},
      std::vector<Vec3>(4, Vec3(kSpeed, 0.0, 0.0)));
  const RiserResult r = solveRiser(type, 50, uniform);
  EXPECT_LE(r.relativeError([&](double s) { return q * s * (kSpan - s) / (2.0 * kTension); }), 0.01);

  // Sheared: 0.2 m/s at the seabed to 0.5 m/s at the surface, towards +x.
  const auto sheared = std::make_shared<const hydro::CurrentGrid>(
      std::array<std::vector<double>, 4>{std::vector<double>{0.0}, {0.0}, {-kDepth, 0.0}, {0.0}},
      std::vector<Vec3>{Vec3(0.2, 0.0, 0.0), Vec3(kSpeed, 0.0, 0.0)});
  const RiserResult fromGrid = solveRiser(type, 50, sheared);
  model::ModelSpec spec;
  spec.sourceFile = "riser in a sheared current (test)";
  spec.environment.waterDepth = kDepth;
  spec.environment.waterDensity = kRho;
  spec.environment.current = {{0.0, kSpeed, 0.0}, {-kDepth, 0.2, 0.0}};
  spec.lineTypes[type.name] = type;
  spec.lines.push_back(test::simpleLine("riser", type.name, kSpan / (1.0 + kTension / kEA), 50,
                                        model::EndKind::Pinned, Vec3(0, 0, kBottom), model::EndKind::Pinned,
                                        Vec3(0, 0, kBottom + kSpan)));
  spec.statics.tolerance = 1e-9;
  analysis::Simulation sim(std::move(spec));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::Line& line = sim.model().lines()[0];
  for (int i = 0; i < line.nodeCount; ++i)
    EXPECT_NEAR(fromGrid.deflection[static_cast<std::size_t>(i)],
                sim.state().position[line.firstNode + i].x(), 1e-6)
        << "node " << i;
  EXPECT_GT(fromGrid.deflection[25], 0.02);  // the current does load it (0.032 m; uniform 0.5 m/s: 0.064 m)
}

}  // namespace
}  // namespace tangle

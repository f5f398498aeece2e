// Issue 45: risers with contents and internal pressure.
//
// 1. A vertical top-tensioned riser (TTR) on a tensioner, wholly submerged, with contents (oil, 850 kg/m^3)
//    and an internal pressure of 20 MPa at a reference level, in static equilibrium. Closed forms (Sparks
//    1984, "The influence of tension, pressure and weight on pipe and riser deformations and stresses", J.
//    Energy Resources Technology 106; DNV-OS-F201 (2010) Sec. 4 B 200; API RP 2RD (2013) 5.2):
//      T_e(s) = T_top - w_e (L - s),  w_e = (m_s + rho_c A_i - rho_w A_e) g   (effective weight),
//      p_i(z) = p_ref + rho_c g (z_ref - z),  p_e(z) = rho_w g (-z),
//      T_w(z) = T_e(z) + p_i(z) A_i - p_e(z) A_e                                    (wall tension).
//    with s the unstretched arc length from the bottom and L the riser's unstretched length (mass and
//    displaced volume per unstretched length: 0.04 % less per metre of the riser stretched by T/EA).
//    The riser is straight and vertical, so the effective tension is linear in s and the nodes' values (the
//    mean of the adjacent elements' tensions, each exact at its mid-point) are exact: the tolerance, 1e-6 of
//    the top tension (2 N of 2 MN), is the static solver's tolerance (1e-9 of the force scale per node,
//    summed over 56 nodes: 0.02 N) with a margin for the end tension's extrapolation; the pressures are
//    formulas of the solved node heights (1e-9 relative: round-off). Three cases: the reference level above
//    the riser (the head extended from its top), within it (interpolated on the element that reaches it),
//    and an empty riser without pressure (T_w = T_e - p_e A_e).
// 2. The natural frequencies of a taut pipe, empty and full: the contents are inertia. Taut string
//    f_n = n / (2 L) sqrt(T / m) with m = (m_s + rho_c A_i) per stretched length (Rao 2011, "Mechanical
//    Vibrations", sec. 8.2); in air at a tiny gravity as tests/verification/dynamics/NaturalFrequencyTest.cpp
//    (its file comment gives the reasons), 1 % for the bound (the beaded string's discretisation
//    error is 1.5e-3 for n = 3 on 50 elements) and the full/empty ratio sqrt(m_s / (m_s + rho_c A_i)) to
//    1e-6 (the same mesh: the discretisation error cancels).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "support/ModalAnalysis.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kOuter = 0.30;        // outer (and buoyancy) diameter [m]
constexpr double kBore = 0.25;         // internal diameter [m]
constexpr double kSteelMass = 150.0;   // m_s [kg/m]
constexpr double kOil = 850.0;         // rho_c [kg/m^3]
constexpr double kPressure = 20.0e6;   // p_ref [Pa]
constexpr double kTopTension = 2.0e6;  // tensioner [N]

section::LineType riserType() {
  section::LineType t = test::beamType("riser", kOuter, kSteelMass, 5.0e9, 2.0e7, 1.0, 1.0);
  t.internalDiameter = kBore;
  return t;
}

struct Case {
  std::string name;
  double density;     // contents [kg/m^3]
  double pressure;    // [Pa]
  double referenceZ;  // [m]
};

class TopTensionedRiser : public ::testing::TestWithParam<Case> {};

TEST_P(TopTensionedRiser, EffectiveAndWallTensionAlongItsLengthAgainstSparks) {
  const Case& c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "top-tensioned riser with contents (test)";
  spec.environment.waterDepth = 300.0;
  spec.lineTypes["riser"] = riserType();
  model::VesselSpec platform;
  platform.name = "platform";
  spec.vessels.push_back(platform);
  // Bottom pinned 10 m above the seabed, top 10 m below the surface on the platform's tensioner: 280 m.
  model::LineSpec riser = test::simpleLine("riser", "riser", 279.9, 56, model::EndKind::Pinned, Vec3(0, 0, -290.0),
                                           model::EndKind::Vessel, Vec3(0, 0, -10.0));
  riser.endB.vessel = "platform";
  riser.endB.tensioner.enabled = true;
  riser.endB.tensioner.tension = kTopTension;
  riser.contents.density = c.density;
  riser.contents.pressure = c.pressure;
  riser.contents.referenceZ = c.referenceZ;
  spec.lines.push_back(riser);
  spec.statics.tolerance = 1e-9;
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const solver::LineSnapshot s = sim.snapshot().front();
  ASSERT_EQ(s.wallTension.size(), s.tension.size());
  ASSERT_EQ(s.internalPressure.size(), s.tension.size());

  const double rho = sim.model().environment().waterDensity, g = sim.model().environment().gravity;
  const double ai = kPi / 4.0 * kBore * kBore, ae = kPi / 4.0 * kOuter * kOuter;
  const double we = (kSteelMass + c.density * ai - rho * ae) * g;
  const double length = s.arcLength.back();
  double largestTension = 0.0, largestWall = 0.0, largestPressure = 0.0;
  for (std::size_t i = 0; i < s.tension.size(); ++i) {
    const double z = s.position[i].z();
    EXPECT_NEAR(s.position[i].x(), 0.0, 1e-9);
    const double te = kTopTension - we * (length - s.arcLength[i]);
    const double pi = c.pressure + c.density * g * (c.referenceZ - z);
    const double tw = te + pi * ai - rho * g * (-z) * ae;
    EXPECT_NEAR(s.tension[i], te, 1e-6 * kTopTension) << "node " << i << " at z = " << z;
    EXPECT_NEAR(s.internalPressure[i], pi, 1e-9 * kPressure) << "node " << i;
    EXPECT_NEAR(s.wallTension[i], tw, 1e-6 * kTopTension) << "node " << i;
    largestTension = std::max(largestTension, std::abs(s.tension[i] - te));
    largestWall = std::max(largestWall, std::abs(s.wallTension[i] - tw));
    largestPressure = std::max(largestPressure, std::abs(s.internalPressure[i] - pi));
  }
  // The bottom's effective tension: the top tension less the effective weight of 280 m of riser.
  EXPECT_NEAR(s.tension.front(), kTopTension - we * length, 1e-6 * kTopTension);
  RecordProperty("largest_effective_tension_error_N", fmt::format("{:.3e}", largestTension));
  RecordProperty("largest_wall_tension_error_N", fmt::format("{:.3e}", largestWall));
  RecordProperty("largest_pressure_error_Pa", fmt::format("{:.3e}", largestPressure));
}

INSTANTIATE_TEST_SUITE_P(Sparks, TopTensionedRiser,
                         ::testing::Values(Case{"ReferenceAboveTheRiser", kOil, kPressure, 0.0},
                                           Case{"ReferenceWithinTheRiser", kOil, kPressure, -150.0},
                                           Case{"Empty", 0.0, 0.0, 0.0}),
                         [](const ::testing::TestParamInfo<Case>& param) { return param.param.name; });

// ---------------------------------------------------------------------------------------------------------
// Natural frequencies of a taut pipe, empty and full.

constexpr double kSpan = 20.0;       // distance between the pins [m]
constexpr double kTension = 5.0e5;   // [N]
constexpr double kEA = 5.0e9;        // [N]
constexpr int kElements = 50;

/// The first three transverse frequencies [Hz] of the taut pipe with contents of `density` [kg/m^3], and
/// the mass per stretched length [kg/m].
std::pair<std::vector<double>, double> tautPipeFrequencies(double density) {
  model::ModelSpec spec;
  spec.sourceFile = "taut pipe (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 1e-6;  // no sag (NaturalFrequencyTest's file comment)
  section::LineType pipe = test::cableType("pipe", kOuter, kSteelMass, kEA);
  pipe.internalDiameter = kBore;
  spec.lineTypes["pipe"] = pipe;
  const double rest = kSpan / (1.0 + kTension / kEA);
  model::LineSpec line = test::simpleLine("pipe", "pipe", rest, kElements, model::EndKind::Pinned, Vec3(0, 0, 10.0),
                                          model::EndKind::Pinned, Vec3(kSpan, 0, 10.0));
  line.contents.density = density;
  spec.lines.push_back(line);
  spec.statics.tolerance = 1e-9;
  model::Model m(std::move(spec));
  solver::Assembler assembler(m);
  model::State state = m.initialState();
  solver::StaticSolver statics(assembler, m.spec().statics);
  const solver::StaticResult r = statics.solve(state);
  EXPECT_TRUE(r.converged) << r.message;
  const test::ModalResult modal = test::modalAnalysis(assembler, state);
  std::vector<double> f;
  for (int n = 1; n <= 3; ++n) f.push_back(0.5 * (modal.frequency[2 * n - 2] + modal.frequency[2 * n - 1]));
  const double mass = (kSteelMass + density * kPi / 4.0 * kBore * kBore) * rest / kSpan;
  return {f, mass};
}

TEST(TautPipe, ContentsAreInertiaEmptyAndFullAgainstTheTautString) {
  const auto [empty, emptyMass] = tautPipeFrequencies(0.0);
  const auto [full, fullMass] = tautPipeFrequencies(kOil);
  for (int n = 1; n <= 3; ++n) {
    const double exactEmpty = n / (2.0 * kSpan) * std::sqrt(kTension / emptyMass);
    const double exactFull = n / (2.0 * kSpan) * std::sqrt(kTension / fullMass);
    EXPECT_NEAR(empty[n - 1], exactEmpty, 0.01 * exactEmpty) << "mode " << n;
    EXPECT_NEAR(full[n - 1], exactFull, 0.01 * exactFull) << "mode " << n;
    EXPECT_NEAR(full[n - 1] / empty[n - 1], std::sqrt(emptyMass / fullMass), 1e-6) << "mode " << n;
    RecordProperty(fmt::format("mode{}_periods_empty_full_s", n),
                   fmt::format("{:.5f} / {:.5f}", 1.0 / empty[n - 1], 1.0 / full[n - 1]));
  }
}

}  // namespace
}  // namespace tangle

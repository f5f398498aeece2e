/// @file ViscoelasticRopeTest.cpp
/// A viscoelastic rope (line_types[].viscoelastic) stretched harmonically through the whole dynamic analysis
/// (model file, statics, DynamicAnalysis, the assembler's commit of the slow strain, the reported tension):
/// its tension amplitude over its strain amplitude is the complex modulus of the standard linear solid, and a
/// rope snapped slack and taut by a large motion runs through without pushing.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kEA = 1.0e8;         // static stiffness [N]
constexpr double kEADynamic = 2.0e8;  // dynamic stiffness [N]: the static branch's EA_1 = 2e8 N too
constexpr double kSlowDamping = 2e8;  // BA [N s]: relaxation time BA / (EA_1 + EA_2) = 0.5 s
constexpr double kFastDamping = 1e6;  // BA_d [N s]

/// The tension amplitude [N] of a 10 m rope (one element, no weight, in air) held at its end A and moved at
/// its end B along its axis, x = 10.1 + a sin(2 pi t / T), a = 0.01 m, after the start has died away.
double tensionAmplitude(double period) {
  const double tau = kSlowDamping / (2.0 * kEADynamic);
  const std::string yaml = fmt::format(R"(title: viscoelastic rope stretched harmonically
environment: {{water_depth: 100, water_density: 0, gravity: 0}}
line_types:
  - name: polyester
    outer_diameter: 0.1
    mass_per_length: 10
    axial_stiffness: {}
    viscoelastic: {{dynamic_stiffness: {}, slow_damping: {}, dynamic_damping: {}}}
lines:
  - name: rope
    end_a: {{type: fixed, position: [0, 0, -50]}}
    end_b: {{type: fixed, position: [10.1, 0, -50], motion: {{amplitude: [0.01, 0, 0], period: {}, phase: 0}}}}
    sections: [{{type: polyester, length: 10, elements: 1}}]
dynamics: {{duration: {}, time_step: {}, ramp_time: 0}}
)",
                                       kEA, kEADynamic, kSlowDamping, kFastDamping, period,
                                       std::max(3.0 * period, 10.0 * tau) + 2.0 * period, period / 400.0);
  analysis::Simulation sim(io::readModelString(yaml, "viscoelastic-rope.yaml"));
  EXPECT_TRUE(sim.solveStatics().converged);
  const double measureFrom = std::max(3.0 * period, 10.0 * tau);
  double lo = 1e300, hi = -1e300;
  const time::DynamicResult r = sim.runDynamics([](const model::State&, const VecX&) {}, false,
                                                [&](const model::State& state, double) {
                                                  if (state.time < measureFrom) return;
                                                  const double t = sim.assembler().elementTension(state)[0];
                                                  lo = std::min(lo, t);
                                                  hi = std::max(hi, t);
                                                });
  EXPECT_TRUE(r.completed) << r.message;
  return 0.5 * (hi - lo);
}

// Source: the complex modulus of the two branches in series (each a spring with its dashpot in parallel):
// E*(w) = 1 / (1 / (EA_1 + i w BA) + 1 / (EA_2 + i w BA_d)); the tension amplitude is |E*| a / L0. Slow (w
// tau = 0.05: the static EA), around the relaxation (w tau = 1) and fast (w tau = 20: the dynamic spring with
// its dashpot). Tolerance 1 %: backward Euler's amplitude error on a first-order relaxation is at most w dt /
// 2 = pi / 400 = 0.8 % of the relaxing part at 400 steps a period; the sampled extremes of 400 points a
// period miss the peak by 3e-5.
TEST(ViscoelasticRope, TensionAmplitudeIsTheComplexModulusOfTheStandardLinearSolid) {
  const double tau = kSlowDamping / (2.0 * kEADynamic);
  for (const double omegaTau : {0.05, 1.0, 20.0}) {
    const double omega = omegaTau / tau;
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> modulus =
        1.0 / (1.0 / (kEADynamic + i * omega * kSlowDamping) + 1.0 / (kEADynamic + i * omega * kFastDamping));
    const double expected = std::abs(modulus) * 0.01 / 10.0;
    const double amplitude = tensionAmplitude(2.0 * std::numbers::pi / omega);
    EXPECT_NEAR(amplitude, expected, 0.01 * expected) << "w tau = " << omegaTau;
    ::testing::Test::RecordProperty(fmt::format("amplitude_over_expected_wtau_{}", omegaTau),
                                    std::to_string(amplitude / expected));
  }
  // The test discriminates: slow and fast differ by more than the tolerance.
  EXPECT_GT(std::abs(1.0 / (1.0 / (kEADynamic + 20.0 * kSlowDamping / 0.5) + 1.0 / kEADynamic)), 1.5 * kEA);
}

// A viscoelastic and a SYROPE section in series, 200 m between points 180 m apart, the top moved 5 m at a 10
// s period: the rope goes slack and snaps taut every cycle (peaks near 2 MN on a 325 kN mean). The run
// completes (it stopped at 3.0 s while a rope being stretched fast through zero strain jumped from its slack
// law to its dashpots' pull), and no element ever pushes harder than its slack law (compression factor x EA x
// strain: a folded slack rope's elements are shortened by up to a quarter, -30 N).
TEST(ViscoelasticRope, PolyesterRopeSnappedSlackAndTautRunsThroughWithoutPushing) {
  const std::string yaml = R"(title: polyester ropes snapped slack and taut
environment: {water_depth: 100}
line_types:
  - name: visco
    outer_diameter: 0.14
    mass_per_length: 22
    axial_stiffness: 1.4e8
    viscoelastic: {dynamic_stiffness: 1.6e8, dynamic_stiffness_slope: 0.4, slow_damping: 4e9, dynamic_damping: 1.1e7}
  - name: syrope
    outer_diameter: 0.2
    mass_per_length: 40
    syrope: {original_curve: [[0, 0], [0.01, 8.0e5], [0.02, 1.4e6], [0.04, 2.4e6]], working_curve: quadratic,
             k1: 0.25, k2: 1.0, dynamic_stiffness: 1.53e8, dynamic_stiffness_slope: 23.12, slow_damping: 5e10,
             dynamic_damping: 1e5, initial_max_mean_tension: 1.1e6}
lines:
  - name: rope
    end_a: {type: fixed, position: [0, 0, -10], motion: {amplitude: [5, 0, 0], period: 10, phase: 0}}
    end_b: {type: anchored, position: [180, 0, -100]}
    sections:
      - {type: visco, length: 100, elements: 5}
      - {type: syrope, length: 100, elements: 5}
dynamics: {duration: 60, time_step: 0.1}
)";
  analysis::Simulation sim(io::readModelString(yaml, "polyester-snap.yaml"));
  ASSERT_TRUE(sim.solveStatics().converged);
  double lowest = 1e300, highest = 0.0, pushing = 0.0;
  const time::DynamicResult r = sim.runDynamics(
      [](const model::State&, const VecX&) {}, false,
      [&](const model::State& state, double) {
        const std::vector<double> tension = sim.assembler().elementTension(state);
        for (std::size_t e = 0; e < tension.size(); ++e) {
          const model::LineElement& el = sim.model().elements()[e];
          const double strain =
              ((state.position[el.node2] - state.position[el.node1]).norm() - el.restLength) / el.restLength;
          const double slack = el.type->compressionFactor * el.type->axialStiffness * std::min(strain, 0.0);
          pushing = std::max(pushing, slack - tension[e]);  // > 0: pushing harder than the slack law
          lowest = std::min(lowest, tension[e]);
          highest = std::max(highest, tension[e]);
        }
      });
  EXPECT_TRUE(r.completed) << r.message;
  EXPECT_LE(pushing, 1e-9 * highest);
  EXPECT_LT(lowest, 1e3);     // it did go slack
  EXPECT_GT(highest, 1.0e6);  // and snapped taut
}

}  // namespace
}  // namespace tangle

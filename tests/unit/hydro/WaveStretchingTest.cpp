/// @file WaveStretchingTest.cpp
/// Wave stretching options of the model (issue 13: `waves.stretching` none / wheeler /
/// vertical_extrapolation) through the wave field the analysis builds (makeWaveField), against the
/// linear-wave formulas. Source: Airy theory, u = (H/2) omega cosh(k (z + h)) / sinh(k h) cos(theta)
/// (Dean & Dalrymple 1991, eq. 4.8), Wheeler (1970) z' = h (z - eta) / (h + eta), vertical
/// extrapolation u(z > 0) = u(0) (API RP 2A-WSD 2014, sec. C2.3.1b). Tolerance 1e-10 relative: the same
/// formulas in closed form, only round-off differs.

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Units.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle::hydro {
namespace {

constexpr double kDepth = 50.0, kHeight = 5.0, kPeriod = 8.0;

std::unique_ptr<WaveField> field(model::WaveStretching stretching) {
  model::EnvironmentSpec env;
  env.waterDepth = kDepth;
  env.waves.kind = model::WaveKind::Airy;
  env.waves.height = kHeight;
  env.waves.period = kPeriod;
  env.waves.stretching = stretching;
  return makeWaveField(env);
}

/// Horizontal particle velocity of linear theory at level z under the crest (theta = 0) [m/s].
double linearU(double z) {
  const double omega = 2.0 * kPi / kPeriod;
  const double k = solveDispersion(omega, kDepth, kStandardGravity);
  return 0.5 * kHeight * omega * std::cosh(k * (z + kDepth)) / std::sinh(k * kDepth);
}

TEST(WaveStretching, OptionsMatchTheirFormulasUnderTheCrest) {
  const double eta = 0.5 * kHeight;  // crest at x = 0, t = 0
  const auto none = field(model::WaveStretching::None);
  const auto wheeler = field(model::WaveStretching::Wheeler);
  const auto vertical = field(model::WaveStretching::Extrapolation);
  ASSERT_NEAR(none->elevation(0.0, 0.0, 0.0), eta, 1e-12);
  for (double z : {-30.0, -5.0, -0.5}) {
    SCOPED_TRACE(z);
    EXPECT_NEAR(none->kinematics(Vec3(0, 0, z), 0.0).velocity.x(), linearU(z), 1e-10 * linearU(z));
    EXPECT_NEAR(vertical->kinematics(Vec3(0, 0, z), 0.0).velocity.x(), linearU(z), 1e-10 * linearU(z));
    const double zw = kDepth * (z - eta) / (kDepth + eta);
    EXPECT_NEAR(wheeler->kinematics(Vec3(0, 0, z), 0.0).velocity.x(), linearU(zw), 1e-10 * linearU(zw));
  }
  // Above still water under the crest: none has no fluid, vertical keeps u(0), Wheeler maps to z' < 0.
  const double z = 1.5;
  EXPECT_EQ(none->kinematics(Vec3(0, 0, z), 0.0).velocity.norm(), 0.0);
  EXPECT_NEAR(vertical->kinematics(Vec3(0, 0, z), 0.0).velocity.x(), linearU(0.0), 1e-10 * linearU(0.0));
  const double zw = kDepth * (z - eta) / (kDepth + eta);
  EXPECT_NEAR(wheeler->kinematics(Vec3(0, 0, z), 0.0).velocity.x(), linearU(zw), 1e-10 * linearU(zw));
}

TEST(WaveStretching, ReaderAcceptsTheThreeNames) {
  const std::string base = "environment:\n  water_depth: 50\n  waves: {type: airy, height: 5, period: 8, stretching: ";
  const std::string rest = "}\nline_types:\n  - {name: c, outer_diameter: 0.1, mass_per_length: 20, axial_stiffness: 1e8}\n"
                           "lines:\n  - name: l\n    end_a: {type: anchored, position: [0, 0, -50]}\n"
                           "    end_b: {type: fixed, position: [60, 0, -5]}\n    sections: [{type: c, length: 80, elements: 8}]\n";
  EXPECT_EQ(io::readModelString(base + "none" + rest, "s.yaml").environment.waves.stretching,
            model::WaveStretching::None);
  EXPECT_EQ(io::readModelString(base + "wheeler" + rest, "s.yaml").environment.waves.stretching,
            model::WaveStretching::Wheeler);
  EXPECT_EQ(io::readModelString(base + "vertical_extrapolation" + rest, "s.yaml").environment.waves.stretching,
            model::WaveStretching::Extrapolation);
}

}  // namespace
}  // namespace tangle::hydro

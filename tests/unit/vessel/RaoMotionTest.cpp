/// @file RaoMotionTest.cpp
/// First-order vessel motion from RAOs (tangle::vessel::RaoMotion).

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/vessel/RaoMotion.hpp"

namespace tangle::vessel {
namespace {

using Row = std::array<double, 6>;

/// Periods 8, 12 s; headings 0, 90, 180, 270 deg. Heave amplitude depends on period and heading; heave
/// lag 0.5 rad except at (12 s, 180 deg) where it is -3.0 (tests shortest-angle interpolation against 3.0).
model::RaoTable raoTable() {
  model::RaoTable t;
  t.period = {8.0, 12.0};
  t.heading = {0.0, 0.5 * kPi, kPi, 1.5 * kPi};
  t.amplitude.resize(2);
  t.phase.resize(2);
  for (int p = 0; p < 2; ++p) {
    for (int h = 0; h < 4; ++h) {
      // surge, sway, heave, roll, pitch, yaw
      t.amplitude[p].push_back(Row{0.1 * (h + 1), 0.2, 0.5 + 0.3 * p + 0.1 * h, 0.01 * (p + 1), 0.02, 0.003});
      t.phase[p].push_back(Row{0.2, 0.3, 0.5, 1.0, 1.5, 2.0});
    }
  }
  t.phase[0][2][2] = 3.0;
  t.phase[1][2][2] = -3.0;
  return t;
}

/// Deep-water wave number for omega.
double deepK(double omega) { return omega * omega / kStandardGravity; }

// Source: the definition motion = a |RAO| cos(omega t - k X + psi - lag) at a table point
// (T = 8 s, relative heading 90 deg: vessel heading 30 deg, waves towards 120 deg). Tolerance 1e-12 relative.
TEST(RaoMotion, AmplitudeAndPhaseAtTablePoint) {
  const double omega = 2.0 * kPi / 8.0;
  const double k = deepK(omega);
  const double heading = degToRad(30.0);
  const double azimuth = degToRad(120.0);
  const RaoMotion rao(raoTable(), heading, {{1.5, omega, k, azimuth, 0.4}});
  const Vec3 ref(20.0, -7.0, 0.0);
  const double kx = k * (ref.x() * std::cos(azimuth) + ref.y() * std::sin(azimuth));
  for (double t : {0.0, 1.3, 5.0, 11.7}) {
    const RaoMotion::Motion m = rao.at(t, ref, 1.0);
    const double theta = omega * t - kx + 0.4;
    // Heave (vertical: unchanged by the heading rotation): |RAO| = 0.5 + 0.1, lag 0.5.
    EXPECT_NEAR(m.displacement(2), 1.5 * 0.6 * std::cos(theta - 0.5), 1e-12);
    // Surge |RAO| 0.2 (h index 1), sway 0.2, in vessel axes rotated by 30 deg.
    const double surge = 1.5 * 0.2 * std::cos(theta - 0.2);
    const double sway = 1.5 * 0.2 * std::cos(theta - 0.3);
    EXPECT_NEAR(m.displacement(0), std::cos(heading) * surge - std::sin(heading) * sway, 1e-12);
    EXPECT_NEAR(m.displacement(1), std::sin(heading) * surge + std::cos(heading) * sway, 1e-12);
    // Yaw: about z, unchanged.
    EXPECT_NEAR(m.displacement(5), 1.5 * 0.003 * std::cos(theta - 2.0), 1e-14);
  }
}

// Source: phase-lag convention (OrcaFlex): the motion peaks lag/omega after the crest passes the
// reference point (crest at t = 0 for X = 0, phase 0).
TEST(RaoMotion, PhaseLagDelaysThePeak) {
  const double omega = 2.0 * kPi / 8.0;
  const RaoMotion rao(raoTable(), 0.0, {{1.0, omega, deepK(omega), 0.5 * kPi, 0.0}});
  const double tPeak = 0.5 / omega;  // heave lag 0.5 rad at (8 s, 90 deg)
  const double peak = rao.at(tPeak, Vec3::Zero(), 1.0).displacement(2);
  EXPECT_NEAR(peak, 0.6, 1e-12);
  EXPECT_LT(rao.at(tPeak - 0.1, Vec3::Zero(), 1.0).displacement(2), peak);
  EXPECT_LT(rao.at(tPeak + 0.1, Vec3::Zero(), 1.0).displacement(2), peak);
}

// Source: consistency with the wave field. A component built from hydro::AiryWave with the NEGATED phase,
// and a heave RAO of 1 m/m with zero lag, heaves exactly with the surface elevation at the reference point.
// Tolerance 1e-12 m: same cosine evaluated two ways.
TEST(RaoMotion, UnitHeaveRaoFollowsAiryWaveElevation) {
  const hydro::AiryWave wave(3.0, 9.0, 0.8, 200.0, kStandardGravity, 1.1);
  model::RaoTable t;
  t.period = {9.0};
  t.heading = {0.0};
  t.amplitude = {{Row{0.0, 0.0, 1.0, 0.0, 0.0, 0.0}}};
  t.phase = {{Row{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}}};
  const RaoMotion rao(t, 0.3, {{0.5 * wave.height(), wave.angularFrequency(), wave.waveNumber(), wave.azimuth(),
                                -wave.phase()}});
  const Vec3 ref(35.0, -12.0, 0.0);
  for (double time : {0.0, 2.1, 7.7}) {
    EXPECT_NEAR(rao.at(time, ref, 1.0).displacement(2), wave.elevation(ref.x(), ref.y(), time), 1e-12);
  }
}

// Source: bilinear interpolation (period, heading), shortest-angle phase interpolation, clamping and
// heading wrap-around, computed by hand from the table. Tolerance 1e-12.
TEST(RaoMotion, InterpolatesBetweenTablePoints) {
  const RaoMotion rao(raoTable(), 0.0, {});
  Row a{};
  Row lag{};
  // T = 10 s (halfway), heading 45 deg (halfway between 0 and 90): heave 0.5 + 0.15 + 0.05.
  rao.interpolateRao(10.0, 0.25 * kPi, a, lag);
  EXPECT_NEAR(a[2], 0.7, 1e-12);
  EXPECT_NEAR(a[0], 0.15, 1e-12);
  EXPECT_NEAR(lag[2], 0.5, 1e-12);
  // T = 10 s, heading 180 deg: lags 3.0 and -3.0 meet across +-pi -> pi (not 0).
  rao.interpolateRao(10.0, kPi, a, lag);
  EXPECT_NEAR(std::cos(lag[2]), -1.0, 1e-12);
  // Clamped outside the period range.
  rao.interpolateRao(3.0, kPi, a, lag);
  EXPECT_NEAR(a[2], 0.7, 1e-12);
  EXPECT_NEAR(lag[2], 3.0, 1e-12);
  rao.interpolateRao(30.0, kPi, a, lag);
  EXPECT_NEAR(a[2], 1.0, 1e-12);
  EXPECT_NEAR(lag[2], -3.0, 1e-12);
  // Heading wrap-around: 315 deg is halfway between 270 deg (surge 0.4) and 360 deg = 0 (surge 0.1).
  rao.interpolateRao(8.0, 1.75 * kPi, a, lag);
  EXPECT_NEAR(a[0], 0.25, 1e-12);
  rao.interpolateRao(8.0, -0.25 * kPi, a, lag);
  EXPECT_NEAR(a[0], 0.25, 1e-12);
}

// Source: the relative heading is azimuth - vessel heading: a vessel at 90 deg in waves towards 0 deg sees
// them at 270 deg; its roll (vessel x = global y) appears about global y.
TEST(RaoMotion, RelativeHeadingAndRotationToGlobal) {
  const double omega = 2.0 * kPi / 12.0;
  const RaoMotion rao(raoTable(), 0.5 * kPi, {{2.0, omega, deepK(omega), 0.0, 0.0}});
  const RaoMotion::Motion m = rao.at(0.0, Vec3::Zero(), 1.0);
  // T = 12 s, heading 270 deg (index 3): surge 0.4, lag 0.2 -> along global +y.
  EXPECT_NEAR(m.displacement(1), 2.0 * 0.4 * std::cos(0.2), 1e-12);
  // Roll 0.02 rad/m about vessel x = global +y.
  EXPECT_NEAR(m.displacement(4), 2.0 * 0.02 * std::cos(1.0), 1e-12);
  EXPECT_NEAR(m.displacement(3), -2.0 * 0.02 * std::cos(1.5), 1e-12);  // pitch about vessel y = global -x
}

// Source: velocity and acceleration are the time derivatives of the displacement (two components).
// Central differences, h = 1e-4 s: truncation (omega h)^2/6 ~ 1e-9 relative, rounding ~1e-12 / 1e-4.
TEST(RaoMotion, VelocityAndAccelerationAreTimeDerivatives) {
  const double w1 = 2.0 * kPi / 9.0;
  const double w2 = 2.0 * kPi / 11.5;
  const RaoMotion rao(raoTable(), 0.3, {{1.0, w1, deepK(w1), 2.0, 0.3}, {0.6, w2, deepK(w2), 2.4, 1.7}});
  const Vec3 ref(5.0, 3.0, 0.0);
  const double h = 1e-4;
  for (double t : {0.7, 4.2}) {
    const RaoMotion::Motion m = rao.at(t, ref, 0.8);
    const RaoMotion::Motion mp = rao.at(t + h, ref, 0.8);
    const RaoMotion::Motion mm = rao.at(t - h, ref, 0.8);
    const Vec6 v = (mp.displacement - mm.displacement) / (2.0 * h);
    const Vec6 a = (mp.velocity - mm.velocity) / (2.0 * h);
    EXPECT_LT((v - m.velocity).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_LT((a - m.acceleration).cwiseAbs().maxCoeff(), 1e-7);
  }
  // Ramp multiplies everything.
  const RaoMotion::Motion full = rao.at(2.0, ref, 1.0);
  const RaoMotion::Motion half = rao.at(2.0, ref, 0.5);
  EXPECT_LT((half.displacement - 0.5 * full.displacement).norm(), 1e-14);
}

// Source: first-order kinematics u_p = u + theta x (R r). Pure roll phi about vessel x (= global x for
// heading 0): a point 10 m to port moves up by 10 phi; a point 5 m above the origin moves to starboard.
TEST(RaoMotion, PointDisplacementForPureRoll) {
  RaoMotion::Motion m;
  const double phi = 0.01;
  m.displacement(3) = phi;
  m.velocity(3) = 2.0 * phi;
  m.acceleration(3) = 3.0 * phi;
  const Mat3 r = Mat3::Identity();
  EXPECT_LT((RaoMotion::pointDisplacement(m, r, Vec3(0.0, 10.0, 0.0)) - Vec3(0.0, 0.0, 10.0 * phi)).norm(), 1e-15);
  EXPECT_LT((RaoMotion::pointDisplacement(m, r, Vec3(0.0, 0.0, 5.0)) - Vec3(0.0, -5.0 * phi, 0.0)).norm(), 1e-15);
  EXPECT_LT((RaoMotion::pointVelocity(m, r, Vec3(0.0, 10.0, 0.0)) - Vec3(0.0, 0.0, 20.0 * phi)).norm(), 1e-15);
  EXPECT_LT((RaoMotion::pointAcceleration(m, r, Vec3(0.0, 10.0, 0.0)) - Vec3(0.0, 0.0, 30.0 * phi)).norm(), 1e-15);
  // Vessel heading 90 deg: roll is about global y; the offset (0, 10, 0) in vessel axes is global (-10, 0, 0);
  // (phi e_y) x (-10 e_x) = +10 phi e_z: the port side still goes up.
  const Mat3 r90 = Eigen::AngleAxisd(0.5 * kPi, Vec3::UnitZ()).toRotationMatrix();
  RaoMotion::Motion m90;
  m90.displacement(4) = phi;
  EXPECT_LT((RaoMotion::pointDisplacement(m90, r90, Vec3(0.0, 10.0, 0.0)) - Vec3(0.0, 0.0, 10.0 * phi)).norm(),
            1e-14);
}

TEST(RaoMotion, EmptyTableGivesNoMotionAndBadInputThrows) {
  const RaoMotion none(model::RaoTable{}, 0.0, {{1.0, 1.0, 0.1, 0.0, 0.0}});
  EXPECT_EQ(none.at(3.0, Vec3::Zero(), 1.0).displacement, Vec6::Zero());
  model::RaoTable bad = raoTable();
  bad.amplitude[1].pop_back();
  EXPECT_THROW(RaoMotion(bad, 0.0, {}), Error);
  bad = raoTable();
  bad.period = {12.0, 8.0};
  EXPECT_THROW(RaoMotion(bad, 0.0, {}), Error);
  EXPECT_THROW(RaoMotion(raoTable(), 0.0, {{1.0, 0.0, 0.1, 0.0, 0.0}}), Error);
}

}  // namespace
}  // namespace tangle::vessel

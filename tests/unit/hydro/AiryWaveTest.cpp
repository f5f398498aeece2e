/// @file AiryWaveTest.cpp
/// Dispersion relation, depth attenuation and regular-wave kinematics (tangle::hydro::AiryWave).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/AiryWave.hpp"

namespace tangle::hydro {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kG = kStandardGravity;

// ---------------------------------------------------------------------------------------------
// Dispersion relation omega^2 = g k tanh(k h)
// ---------------------------------------------------------------------------------------------

// Source: kh solving kh tanh(kh) = omega^2 h / g computed independently with 40-digit arithmetic
// (mpmath.findroot, Python), rounded to 20 digits. Tolerance 4 eps relative: the Newton iteration is
// run to machine precision and y -> y tanh y is well conditioned (condition number <= 1).
TEST(Dispersion, MatchesHighPrecisionReferenceValues) {
  struct Case {
    double x0;  // omega^2 h / g
    double kh;
  };
  const Case cases[] = {
      {1e-6, 0.0010000001666666972222}, {1e-3, 0.031628048030808897316},
      {0.01, 0.1001669725590555071},    {0.1, 0.32159590469121039971},
      {0.5, 0.77170231920910422398},    {1.0, 1.1996786402577338339},
      {2.0, 2.0653381389747047281},     {5.0, 5.0004536081839098664},
      {10.0, 10.000000041223069135},    {40.0, 40.0},
  };
  const double depth = 50.0;
  for (const Case& c : cases) {
    const double omega = std::sqrt(c.x0 * kG / depth);
    const double kh = solveDispersion(omega, depth, kG) * depth;
    // omega^2 h / g is rounded when rebuilt from omega: allow that plus 4 eps.
    EXPECT_NEAR(kh, c.kh, 8.0 * kEps * c.kh) << "omega^2 h / g = " << c.x0;
  }
}

// Source: direct substitution into the dispersion relation. Tolerance 4 eps relative (the residual
// of a machine-precision root is a few rounding errors of y tanh y).
TEST(Dispersion, SatisfiesTheRelationByDirectSubstitution) {
  for (double x0 = 1e-8; x0 < 1e4; x0 *= 1.7) {
    const double depth = 1.0;
    const double omega = std::sqrt(x0 * kG / depth);
    const double k = solveDispersion(omega, depth, kG);
    const double x0Rebuilt = omega * omega * depth / kG;
    EXPECT_NEAR(k * depth * std::tanh(k * depth), x0Rebuilt, 4.0 * kEps * x0Rebuilt) << "x0 = " << x0;
  }
}

// Source: deep-water limit tanh(kh) = 1 in double precision for kh > 19: k = omega^2 / g exactly.
// Tolerance 2 eps (one division and one multiplication).
TEST(Dispersion, DeepWaterLimit) {
  const double omega = 2.0 * kPi / 6.0;  // T = 6 s in 3000 m: kh ~ 335
  const double k = solveDispersion(omega, 3000.0, kG);
  EXPECT_NEAR(k, omega * omega / kG, 2.0 * kEps * k);
}

// Source: shallow-water expansion of y tanh y = x (y = kh): y = sqrt(x) (1 + x/6 + O(x^2)), i.e. the
// long-wave celerity c = sqrt(g h). With x = 1e-6 the neglected O(x^2) term is ~1e-12 (relative):
// tolerance 1e-11.
TEST(Dispersion, ShallowWaterLimit) {
  const double depth = 1.0;
  const double x0 = 1e-6;
  const double omega = std::sqrt(x0 * kG / depth);
  const double kh = solveDispersion(omega, depth, kG) * depth;
  EXPECT_NEAR(kh, std::sqrt(x0) * (1.0 + x0 / 6.0), 1e-11 * kh);
  EXPECT_NEAR(omega / (kh / depth), std::sqrt(kG * depth), 1e-6 * std::sqrt(kG * depth));
}

TEST(Dispersion, RejectsInvalidArguments) {
  EXPECT_THROW(solveDispersion(0.0, 10.0, kG), Error);
  EXPECT_THROW(solveDispersion(-1.0, 10.0, kG), Error);
  EXPECT_THROW(solveDispersion(1.0, 0.0, kG), Error);
  EXPECT_THROW(solveDispersion(1.0, std::numeric_limits<double>::infinity(), kG), Error);
  EXPECT_THROW(solveDispersion(1.0, 10.0, 0.0), Error);
  EXPECT_THROW(solveDispersion(std::nan(""), 10.0, kG), Error);
}

// ---------------------------------------------------------------------------------------------
// Depth attenuation
// ---------------------------------------------------------------------------------------------

// Source: definition cosh(k(z+h))/sinh(kh), sinh(k(z+h))/sinh(kh) evaluated with std::cosh/std::sinh
// (fine for moderate kh). Tolerance 1e-13 relative: both forms are accurate to a few ulps.
TEST(DepthAttenuation, MatchesHyperbolicFormsForModerateDepth) {
  const double depth = 30.0;
  for (double k : {0.001, 0.02, 0.1, 0.5}) {
    for (double z : {0.0, -1.0, -7.5, -15.0, -29.0, -30.0}) {
      const DepthAttenuation att = depthAttenuation(k, z, depth);
      const double ch = std::cosh(k * (z + depth)) / std::sinh(k * depth);
      const double sh = std::sinh(k * (z + depth)) / std::sinh(k * depth);
      EXPECT_NEAR(att.horizontal, ch, 1e-13 * ch) << "k = " << k << ", z = " << z;
      EXPECT_NEAR(att.vertical, sh, 1e-13 * std::max(ch, 1.0)) << "k = " << k << ", z = " << z;
    }
  }
}

// Source: exact limits of the definition: at z = 0 the ratios are coth(kh) and 1; at the seabed 1/sinh(kh)
// and 0; for kh -> infinity both tend to e^{kz} (deep water). Tolerances: a few ulps.
TEST(DepthAttenuation, LimitsAndDeepWaterWithoutOverflow) {
  const DepthAttenuation top = depthAttenuation(0.2, 0.0, 10.0);
  EXPECT_NEAR(top.horizontal, 1.0 / std::tanh(2.0), 4.0 * kEps);
  EXPECT_NEAR(top.vertical, 1.0, 4.0 * kEps);
  const DepthAttenuation bottom = depthAttenuation(0.2, -10.0, 10.0);
  EXPECT_NEAR(bottom.horizontal, 1.0 / std::sinh(2.0), 4.0 * kEps);
  EXPECT_EQ(bottom.vertical, 0.0);
  // kh = 2000: cosh(kh) would overflow.
  const double k = 2.0;
  const double depth = 1000.0;
  for (double z : {0.0, -0.5, -3.0, -20.0, -999.0, -1000.0}) {
    const DepthAttenuation att = depthAttenuation(k, z, depth);
    ASSERT_TRUE(std::isfinite(att.horizontal) && std::isfinite(att.vertical));
    EXPECT_NEAR(att.horizontal, std::exp(k * z), 4.0 * kEps * std::exp(k * z) + 1e-300);
    EXPECT_NEAR(att.vertical, std::exp(k * z), 4.0 * kEps * std::exp(k * z) + 1e-300);
  }
}

// Source: Wheeler (1970) z' = h (z - eta)/(h + eta); vertical stretching z' = min(z, 0).
TEST(StretchedLevel, WheelerAndVertical) {
  const double h = 20.0;
  EXPECT_DOUBLE_EQ(stretchedLevel(2.0, 2.0, h, Stretching::Wheeler), 0.0);  // surface -> 0
  EXPECT_DOUBLE_EQ(stretchedLevel(-h, 2.0, h, Stretching::Wheeler), -h);    // seabed -> seabed
  EXPECT_DOUBLE_EQ(stretchedLevel(-9.0, 2.0, h, Stretching::Wheeler), h * (-11.0) / 22.0);
  EXPECT_DOUBLE_EQ(stretchedLevel(-25.0, 2.0, h, Stretching::Wheeler), -h);   // below seabed: clamped
  EXPECT_DOUBLE_EQ(stretchedLevel(-1.0, -1.0, h, Stretching::Wheeler), 0.0);  // trough surface -> 0
  EXPECT_DOUBLE_EQ(stretchedLevel(1.5, 2.0, h, Stretching::Vertical), 0.0);
  EXPECT_DOUBLE_EQ(stretchedLevel(-3.0, 2.0, h, Stretching::Vertical), -3.0);
  EXPECT_DOUBLE_EQ(stretchedLevel(-30.0, 2.0, h, Stretching::Vertical), -h);
}

// ---------------------------------------------------------------------------------------------
// AiryWave
// ---------------------------------------------------------------------------------------------

// Closed-form linear kinematics (Dean & Dalrymple 1991, ch. 3-4; DNV-RP-C205 2010, sec. 3.2) written
// directly with cosh/sinh, independently of the implementation.
struct Closed {
  double uh, w, duh, dw;
};
Closed closedForm(double height, double omega, double k, double h, double z, double theta) {
  const double a = 0.5 * height;
  const double ch = std::cosh(k * (z + h)) / std::sinh(k * h);
  const double sh = std::sinh(k * (z + h)) / std::sinh(k * h);
  return {a * omega * ch * std::cos(theta), a * omega * sh * std::sin(theta),
          a * omega * omega * ch * std::sin(theta), -a * omega * omega * sh * std::cos(theta)};
}

TEST(AiryWave, WaveNumberWavelengthAndCelerity) {
  const AiryWave wave(2.0, 8.0, 0.0, 25.0);
  const double omega = 2.0 * kPi / 8.0;
  EXPECT_DOUBLE_EQ(wave.angularFrequency(), omega);
  EXPECT_DOUBLE_EQ(wave.waveNumber(), solveDispersion(omega, 25.0, kStandardGravity));
  // L = g T^2 / (2 pi) tanh(2 pi h / L) (Dean & Dalrymple 1991, ch. 3); tolerance 1e-12 relative.
  const double L = wave.wavelength();
  EXPECT_NEAR(L, kG * 64.0 / (2.0 * kPi) * std::tanh(2.0 * kPi * 25.0 / L), 1e-12 * L);
  EXPECT_DOUBLE_EQ(wave.phaseSpeed(), L / 8.0);
}

// Source: eta = H/2 cos(k (x cos b + y sin b) - omega t + phase). Tolerance 1e-12 m (cos of the same
// argument computed in a different order).
TEST(AiryWave, ElevationFormula) {
  const double H = 3.0, T = 9.0, beta = degToRad(30.0), h = 40.0, phase = 0.7;
  const AiryWave wave(H, T, beta, h, kG, phase);
  const double k = wave.waveNumber(), omega = wave.angularFrequency();
  for (double t : {0.0, 1.3, 7.9}) {
    for (double x : {-50.0, 0.0, 12.0}) {
      for (double y : {-3.0, 0.0, 40.0}) {
        const double expected =
            0.5 * H * std::cos(k * (x * std::cos(beta) + y * std::sin(beta)) - omega * t + phase);
        EXPECT_NEAR(wave.elevation(x, y, t), expected, 1e-12);
      }
    }
  }
  EXPECT_NEAR(wave.elevation(0.0, 0.0, 0.0), 0.5 * H * std::cos(phase), 1e-15);
}

// Source: a wave with azimuth 90 deg travels towards +y: the crest at the origin at t = 0 is found at
// y = c t at time t, the horizontal velocity under the crest points to +y. Tolerances: 1e-9 m on a 1 m
// amplitude (argument rounding), exact zero x-velocity (cos(pi/2) is 6e-17: 1e-15 m/s).
TEST(AiryWave, AzimuthGivesDirectionOfTravel) {
  const AiryWave wave(2.0, 10.0, degToRad(90.0), 100.0, kG, 0.0, Stretching::Vertical);
  const double c = wave.phaseSpeed();
  const double t = 2.5;
  EXPECT_NEAR(wave.elevation(0.0, c * t, t), 1.0, 1e-9);
  EXPECT_LT(wave.elevation(0.0, -c * t, t), 0.9);          // the crest did not go towards -y
  EXPECT_NEAR(wave.elevation(37.0, c * t, t), 1.0, 1e-9);  // crests are parallel to x
  const FluidKinematics under = wave.kinematics(Vec3(0.0, c * t, -5.0), t);
  EXPECT_GT(under.velocity.y(), 0.0);
  EXPECT_NEAR(under.velocity.x(), 0.0, 1e-15);
  // Azimuth 180 deg: travels towards -x.
  const AiryWave west(2.0, 10.0, degToRad(180.0), 100.0);
  EXPECT_NEAR(west.elevation(-west.phaseSpeed() * t, 0.0, t), 1.0, 1e-9);
  EXPECT_LT(west.kinematics(Vec3(0.0, 0.0, -1.0), 0.0).velocity.x(), 0.0);
}

// Source: closed formulas (see closedForm) at several points and times, below the trough with vertical
// stretching (no stretching there). Tolerance 1e-12 relative to the amplitude a omega (a omega^2): the
// implementation uses the exponential form of the attenuation (few ulps).
TEST(AiryWave, KinematicsMatchClosedFormulas) {
  const double H = 4.0, T = 11.0, beta = degToRad(-40.0), h = 60.0, phase = -1.1;
  const AiryWave wave(H, T, beta, h, kG, phase, Stretching::Vertical);
  const double k = wave.waveNumber(), omega = wave.angularFrequency();
  const double scaleV = 0.5 * H * omega / std::tanh(k * h);
  const double scaleA = scaleV * omega;
  const Vec3 dir(std::cos(beta), std::sin(beta), 0.0);
  for (double t : {0.0, 2.0, 5.5, 13.0}) {
    for (const Vec3& p :
         {Vec3(0, 0, -2.5), Vec3(10, -20, -10), Vec3(-33, 7, -30), Vec3(5, 5, -59.9), Vec3(100, 50, -60)}) {
      const double theta = k * dir.dot(p) - omega * t + phase;
      const Closed e = closedForm(H, omega, k, h, p.z(), theta);
      const FluidKinematics kin = wave.kinematics(p, t);
      EXPECT_NEAR(kin.velocity.x(), e.uh * dir.x(), 1e-12 * scaleV);
      EXPECT_NEAR(kin.velocity.y(), e.uh * dir.y(), 1e-12 * scaleV);
      EXPECT_NEAR(kin.velocity.z(), e.w, 1e-12 * scaleV);
      EXPECT_NEAR(kin.acceleration.x(), e.duh * dir.x(), 1e-12 * scaleA);
      EXPECT_NEAR(kin.acceleration.y(), e.duh * dir.y(), 1e-12 * scaleA);
      EXPECT_NEAR(kin.acceleration.z(), e.dw, 1e-12 * scaleA);
    }
  }
}

// Source: closedForm, from shallow water (kh ~ 0.3) to the drilling-riser example's deep water (kh ~ 14),
// 41 levels from the trough down to the seabed (where the vertical ratio vanishes and the exponential form
// must stay exact absolutely). Tolerance as above, 1e-12 of the amplitude a omega (a omega^2).
TEST(AiryWave, KinematicsMatchClosedFormulasFromShallowToDeepWater) {
  struct Case {
    double period, depth;
  };
  for (const Case c : {Case{30.0, 10.0}, Case{10.0, 50.0}, Case{10.0, 345.0}, Case{7.0, 1000.0}}) {
    const AiryWave wave(2.0, c.period, 0.0, c.depth, kG, 0.0, Stretching::Vertical);
    const double k = wave.waveNumber(), omega = wave.angularFrequency(), h = c.depth;
    ASSERT_LT(k * h, 300.0);  // std::sinh in closedForm stays finite
    const double scaleV = omega / std::tanh(k * h), scaleA = scaleV * omega;  // H/2 = 1 m
    for (int i = 0; i <= 40; ++i) {
      const double z = -1.0 - (h - 1.0) * (i / 40.0) * (i / 40.0);  // below the trough, denser up there
      for (const double t : {0.0, 0.27 * c.period, 0.61 * c.period}) {
        const Closed e = closedForm(2.0, omega, k, h, z, -omega * t);
        const FluidKinematics kin = wave.kinematics(Vec3(0, 0, z), t);
        EXPECT_NEAR(kin.velocity.x(), e.uh, 1e-12 * scaleV) << "T " << c.period << " h " << h << " z " << z;
        EXPECT_NEAR(kin.velocity.z(), e.w, 1e-12 * scaleV) << "T " << c.period << " h " << h << " z " << z;
        EXPECT_NEAR(kin.acceleration.x(), e.duh, 1e-12 * scaleA) << "T " << c.period << " h " << h << " z " << z;
        EXPECT_NEAR(kin.acceleration.z(), e.dw, 1e-12 * scaleA) << "T " << c.period << " h " << h << " z " << z;
      }
    }
  }
}

// Source: horizontal velocity amplitude pi H / T cosh(k(z+h))/sinh(kh) (Dean & Dalrymple 1991, ch. 4),
// reached under the crest; vertical amplitude pi H / T sinh(k(z+h))/sinh(kh) a quarter period later.
// Tolerance 1e-12 relative.
TEST(AiryWave, VelocityAmplitudes) {
  const double H = 2.0, T = 7.0, h = 15.0;
  const AiryWave wave(H, T, 0.0, h, kG, 0.0, Stretching::Vertical);
  const double k = wave.waveNumber();
  const double z = -4.0;
  const double uMax = kPi * H / T * std::cosh(k * (z + h)) / std::sinh(k * h);
  const double wMax = kPi * H / T * std::sinh(k * (z + h)) / std::sinh(k * h);
  EXPECT_NEAR(wave.kinematics(Vec3(0, 0, z), 0.0).velocity.x(), uMax, 1e-12 * uMax);
  // theta = -omega t = -pi/2 at t = T/4: w = -wMax; at x = L/4 and t = 0, theta = pi/2: w = +wMax.
  EXPECT_NEAR(wave.kinematics(Vec3(0.25 * wave.wavelength(), 0, z), 0.0).velocity.z(), wMax, 1e-12 * wMax);
  EXPECT_NEAR(wave.kinematics(Vec3(0, 0, z), 0.25 * T).velocity.z(), -wMax, 1e-12 * wMax);
}

// Source: linear-theory identities (Dean & Dalrymple 1991, ch. 3): continuity du/dx + dw/dz = 0, the
// kinematic surface condition w(z=0) = d eta / dt and a = du/dt, checked by central finite differences
// (step 1e-4: truncation ~1e-8 relative, rounding ~1e-12; tolerance 1e-6 relative).
TEST(AiryWave, KinematicsAreConsistentWithLinearTheory) {
  const AiryWave wave(1.0, 6.0, degToRad(20.0), 12.0, kG, 0.3, Stretching::Vertical);
  const Vec3 dir(std::cos(degToRad(20.0)), std::sin(degToRad(20.0)), 0.0);
  const double omega = wave.angularFrequency();
  const double scale = 0.5 * omega / std::tanh(wave.waveNumber() * 12.0);
  const double d = 1e-4;
  int surfaceChecks = 0;
  for (double t = 0.0; t < 6.0; t += 0.5) {
    const Vec3 p(3.0, -2.0, -3.0);
    const double dudx = (wave.kinematics(p + d * dir, t).velocity.dot(dir) -
                         wave.kinematics(p - d * dir, t).velocity.dot(dir)) /
                        (2 * d);
    const double dwdz =
        (wave.kinematics(p + d * kUp, t).velocity.z() - wave.kinematics(p - d * kUp, t).velocity.z()) /
        (2 * d);
    EXPECT_NEAR(dudx + dwdz, 0.0, 1e-6 * scale * wave.waveNumber());
    const Vec3 accFd = (wave.kinematics(p, t + d).velocity - wave.kinematics(p, t - d).velocity) / (2 * d);
    EXPECT_LT((accFd - wave.kinematics(p, t).acceleration).norm(), 1e-6 * scale * omega);
    const double detadt = (wave.elevation(3.0, -2.0, t + d) - wave.elevation(3.0, -2.0, t - d)) / (2 * d);
    const double x = 3.0, y = -2.0;
    if (wave.elevation(x, y, t) >= 0.0) {
      EXPECT_NEAR(wave.kinematics(Vec3(x, y, 0.0), t).velocity.z(), detadt, 1e-6 * scale);
      ++surfaceChecks;
    }
  }
  EXPECT_GE(surfaceChecks, 4);  // the point z = 0 is wet about half of the time
}

// Source: Wheeler (1970): the kinematics at z equal the linear profile at z' = h (z - eta)/(h + eta); at
// the instantaneous surface they equal the z = 0 values, at the seabed the seabed values. Tolerance
// 1e-12 relative to a omega.
TEST(AiryWave, WheelerStretching) {
  const double H = 6.0, T = 10.0, h = 30.0;
  const AiryWave wheeler(H, T, 0.0, h);
  const AiryWave vertical(H, T, 0.0, h, kG, 0.0, Stretching::Vertical);
  const double k = wheeler.waveNumber(), omega = wheeler.angularFrequency();
  const double scale = 0.5 * H * omega / std::tanh(k * h);
  for (double t : {0.0, 1.5, 4.0, 6.0, 8.5}) {
    const double x = 7.0;
    const double eta = wheeler.elevation(x, 0.0, t);
    const double theta = k * x - omega * t;
    // At the surface: the z = 0 linear values.
    const Closed top = closedForm(H, omega, k, h, 0.0, theta);
    const FluidKinematics atSurface = wheeler.kinematics(Vec3(x, 0.0, eta), t);
    EXPECT_NEAR(atSurface.velocity.x(), top.uh, 1e-12 * scale) << "t = " << t;
    EXPECT_NEAR(atSurface.velocity.z(), top.w, 1e-12 * scale);
    EXPECT_NEAR(atSurface.acceleration.x(), top.duh, 1e-12 * scale * omega);
    // Mid-depth: evaluated at z'.
    const double z = -12.0;
    const double zPrime = h * (z - eta) / (h + eta);
    const Closed mid = closedForm(H, omega, k, h, zPrime, theta);
    const FluidKinematics atMid = wheeler.kinematics(Vec3(x, 0.0, z), t);
    EXPECT_NEAR(atMid.velocity.x(), mid.uh, 1e-12 * scale);
    EXPECT_NEAR(atMid.velocity.z(), mid.w, 1e-12 * scale);
    EXPECT_NEAR(atMid.acceleration.z(), mid.dw, 1e-12 * scale * omega);
    // Seabed: unaffected by stretching.
    EXPECT_LT(
        (wheeler.kinematics(Vec3(x, 0, -h), t).velocity - vertical.kinematics(Vec3(x, 0, -h), t).velocity)
            .norm(),
        1e-12 * scale);
  }
}

// Source: definition of WaveField::kinematics: zero above the instantaneous surface.
TEST(AiryWave, NoKinematicsAboveTheSurface) {
  for (Stretching s : {Stretching::Wheeler, Stretching::Vertical}) {
    const AiryWave wave(2.0, 8.0, 0.0, 50.0, kG, 0.0, s);
    for (double t : {0.0, 2.0, 4.0}) {
      const double eta = wave.elevation(1.0, 0.0, t);
      const FluidKinematics dry = wave.kinematics(Vec3(1.0, 0.0, eta + 1e-9), t);
      EXPECT_EQ(dry.velocity, Vec3::Zero());
      EXPECT_EQ(dry.acceleration, Vec3::Zero());
      EXPECT_GT(wave.kinematics(Vec3(1.0, 0.0, eta - 1e-3), t).velocity.norm(), 0.1);
    }
  }
}

// Source: deep-water limit (kh = 1e3, cosh would overflow): u = a omega e^{kz} cos(theta); tolerance
// 1e-13 relative. Also finite values near the seabed.
TEST(AiryWave, DeepWaterWithoutOverflow) {
  const double H = 1.0, T = 4.0, h = 4000.0;
  const AiryWave wave(H, T, 0.0, h, kG, 0.0, Stretching::Vertical);
  const double k = wave.waveNumber(), omega = wave.angularFrequency();
  ASSERT_GT(k * h, 700.0);
  for (double z : {-0.5, -2.0, -10.0}) {
    const FluidKinematics kin = wave.kinematics(Vec3(0, 0, z), 0.0);
    const double expected = 0.5 * H * omega * std::exp(k * z);
    EXPECT_NEAR(kin.velocity.x(), expected, 1e-13 * expected);
  }
  const FluidKinematics bottom = wave.kinematics(Vec3(0, 0, -h), 0.3);
  EXPECT_TRUE(bottom.velocity.allFinite() && bottom.acceleration.allFinite());
  EXPECT_EQ(bottom.velocity.norm(), 0.0);  // e^{-kh} underflows
}

// Source: class contract: below the seabed the seabed values are returned.
TEST(AiryWave, BelowSeabedClampsToSeabed) {
  const AiryWave wave(2.0, 12.0, 0.5, 20.0);
  const FluidKinematics at = wave.kinematics(Vec3(1, 2, -20.0), 3.0);
  const FluidKinematics below = wave.kinematics(Vec3(1, 2, -21.0), 3.0);
  EXPECT_EQ(at.velocity, below.velocity);
  EXPECT_EQ(at.acceleration, below.acceleration);
}

TEST(AiryWave, RejectsInvalidParameters) {
  EXPECT_THROW(AiryWave(-1.0, 8.0, 0.0, 50.0), Error);
  EXPECT_THROW(AiryWave(1.0, 0.0, 0.0, 50.0), Error);
  EXPECT_THROW(AiryWave(1.0, 8.0, 0.0, 0.0), Error);
  EXPECT_THROW(AiryWave(1.0, 8.0, 0.0, 50.0, 0.0), Error);
  EXPECT_THROW(AiryWave(1.0, 8.0, std::nan(""), 50.0), Error);
  EXPECT_THROW(AiryWave(12.0, 8.0, 0.0, 5.0), Error);  // trough below the seabed
  EXPECT_NO_THROW(AiryWave(0.0, 8.0, 0.0, 5.0));       // calm sea
}

}  // namespace
}  // namespace tangle::hydro

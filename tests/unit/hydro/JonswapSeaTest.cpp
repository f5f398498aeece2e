/// @file JonswapSeaTest.cpp
/// JONSWAP spectrum formula and component synthesis (tangle::hydro::JonswapSea). The statistical checks
/// of generated records are in tests/verification/hydro/JonswapSpectrumTest.cpp.

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/JonswapSea.hpp"

namespace tangle::hydro {
namespace {

JonswapSea::Parameters baseParameters() {
  JonswapSea::Parameters p;
  p.significantHeight = 5.0;
  p.peakPeriod = 11.0;
  p.gamma = 3.3;
  p.azimuth = degToRad(60.0);
  p.waterDepth = 80.0;
  p.componentCount = 120;
  p.seed = 2024;
  return p;
}

/// Composite Simpson integral of the target spectrum over [a, b] with n (even) intervals.
double integrate(const JonswapSea& sea, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = sea.spectralDensity(a) + sea.spectralDensity(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * sea.spectralDensity(a + i * h);
  return sum * h / 3.0;
}

// Source: DNV-RP-C205 (2010) sec. 3.5.5, written out independently: at the peak the enhancement is gamma,
// so S(wp) = A_gamma gamma 5/16 Hs^2 / wp exp(-5/4); elsewhere sigma = 0.07 below, 0.09 above the peak.
// Tolerance 1e-13 relative (same formula, different evaluation order).
TEST(JonswapSea, SpectralDensityFormula) {
  const JonswapSea sea(baseParameters());
  const double hs = 5.0, wp = 2.0 * kPi / 11.0, g = 3.3;
  const double aGamma = 1.0 - 0.287 * std::log(g);
  EXPECT_DOUBLE_EQ(sea.normalisingFactor(), aGamma);
  EXPECT_DOUBLE_EQ(sea.peakFrequency(), wp);
  const double atPeak = aGamma * g * 5.0 / 16.0 * hs * hs / wp * std::exp(-1.25);
  EXPECT_NEAR(sea.spectralDensity(wp), atPeak, 1e-13 * atPeak);
  for (double w : {0.3 * wp, 0.8 * wp, 0.95 * wp, 1.05 * wp, 1.3 * wp, 2.5 * wp, 6.0 * wp}) {
    const double sigma = w <= wp ? 0.07 : 0.09;
    const double pm =
        5.0 / 16.0 * hs * hs * std::pow(wp, 4) * std::pow(w, -5) * std::exp(-1.25 * std::pow(w / wp, -4));
    const double expected = aGamma * pm * std::pow(g, std::exp(-0.5 * std::pow((w - wp) / (sigma * wp), 2)));
    EXPECT_NEAR(sea.spectralDensity(w), expected, 1e-13 * expected) << "omega / omega_p = " << w / wp;
  }
  EXPECT_EQ(sea.spectralDensity(0.0), 0.0);
  EXPECT_EQ(sea.spectralDensity(-1.0), 0.0);
  EXPECT_EQ(sea.spectralDensity(1e-300), 0.0);
}

// Source: for gamma = 1 the spectrum is Pierson-Moskowitz, whose zeroth moment is exactly Hs^2/16.
// Integral over [0.15, 60] omega_p (outside: < 1e-7 of m0) by Simpson with 2e5 intervals: tolerance 1e-6.
// For gamma = 3.3, A_gamma is an approximation: m0 = 1.0024 Hs^2/16 (40-digit quadrature, mpmath); tolerance
// 0.5 %.
TEST(JonswapSea, ZerothMomentGivesSignificantHeight) {
  JonswapSea::Parameters p = baseParameters();
  p.gamma = 1.0;
  const JonswapSea pm(p);
  const double wp = pm.peakFrequency();
  const double target = 5.0 * 5.0 / 16.0;
  EXPECT_NEAR(integrate(pm, 0.15 * wp, 60.0 * wp, 200000), target, 1e-6 * target);
  const JonswapSea jonswap(baseParameters());
  EXPECT_NEAR(integrate(jonswap, 0.15 * wp, 60.0 * wp, 200000), target, 5e-3 * target);
}

// Source: class contract: bins of width (3.0 - 0.5) omega_p / N, one frequency per bin (random inside or at
// its centre), k from the dispersion relation, a = sqrt(2 S(omega) d_omega), phase in [0, 2 pi).
TEST(JonswapSea, ComponentsFollowTheDiscretisation) {
  for (bool randomFrequencies : {true, false}) {
    JonswapSea::Parameters p = baseParameters();
    p.randomFrequencies = randomFrequencies;
    const JonswapSea sea(p);
    const double wp = sea.peakFrequency();
    const double dw = 2.5 * wp / 120.0;
    EXPECT_NEAR(sea.frequencyStep(), dw, 1e-15);
    const std::vector<WaveComponent> components = sea.components();
    ASSERT_EQ(components.size(), 120u);
    for (std::size_t i = 0; i < components.size(); ++i) {
      const WaveComponent& c = components[i];
      const double binStart = 0.5 * wp + static_cast<double>(i) * dw;
      EXPECT_GE(c.omega, binStart - 1e-12);
      EXPECT_LE(c.omega, binStart + dw + 1e-12);
      if (!randomFrequencies) {
        EXPECT_NEAR(c.omega, binStart + 0.5 * dw, 1e-12);
      }
      EXPECT_NEAR(c.waveNumber, solveDispersion(c.omega, 80.0, kStandardGravity), 1e-15);
      EXPECT_NEAR(c.amplitude, std::sqrt(2.0 * sea.spectralDensity(c.omega) * dw), 1e-14);
      EXPECT_GE(c.phase, 0.0);
      EXPECT_LT(c.phase, 2.0 * kPi);
    }
    // Discretised variance: the band [0.5, 3] omega_p holds 99.2 % of m0 (mpmath quadrature): Hs from the
    // components 0.4 % below target; bin sampling adds < 0.5 % (N = 120): tolerance 1.5 %.
    EXPECT_NEAR(4.0 * std::sqrt(sea.componentVariance()), 5.0, 0.015 * 5.0);
  }
}

// Source: repeatability requirement: same parameters and seed -> identical components; another seed ->
// different phases; the phases do not depend on randomFrequencies (drawn first).
TEST(JonswapSea, SeedDeterminesTheSea) {
  const JonswapSea a(baseParameters());
  const JonswapSea b(baseParameters());
  JonswapSea::Parameters other = baseParameters();
  other.seed = 2025;
  const JonswapSea c(other);
  JonswapSea::Parameters regular = baseParameters();
  regular.randomFrequencies = false;
  const JonswapSea d(regular);
  const auto ca = a.components(), cb = b.components(), cc = c.components(), cd = d.components();
  int samePhase = 0;
  for (std::size_t i = 0; i < ca.size(); ++i) {
    EXPECT_EQ(ca[i].omega, cb[i].omega);
    EXPECT_EQ(ca[i].phase, cb[i].phase);
    EXPECT_EQ(ca[i].phase, cd[i].phase);
    samePhase += ca[i].phase == cc[i].phase;
  }
  EXPECT_EQ(samePhase, 0);
  EXPECT_EQ(a.elevation(3.0, -4.0, 100.0), b.elevation(3.0, -4.0, 100.0));
  EXPECT_NE(a.elevation(3.0, -4.0, 100.0), c.elevation(3.0, -4.0, 100.0));
}

// Source: linear superposition: elevation and (vertically stretched) kinematics are the sums of the Airy
// waves of the components (AiryWave, verified against closed formulas). Points below the deepest trough.
// Tolerance 1e-12 relative to the sum of the component amplitudes (rounding of 120 terms).
TEST(JonswapSea, IsTheSumOfItsAiryComponents) {
  JonswapSea::Parameters p = baseParameters();
  p.stretching = Stretching::Vertical;
  const JonswapSea sea(p);
  std::vector<AiryWave> waves;
  double sumA = 0.0, sumV = 0.0, sumAcc = 0.0;
  for (const WaveComponent& c : sea.components()) {
    waves.emplace_back(2.0 * c.amplitude, 2.0 * kPi / c.omega, p.azimuth, p.waterDepth, p.gravity, c.phase,
                       Stretching::Vertical);
    sumA += c.amplitude;
    sumV += c.amplitude * c.omega / std::tanh(c.waveNumber * p.waterDepth);
    sumAcc += c.amplitude * c.omega * c.omega / std::tanh(c.waveNumber * p.waterDepth);
  }
  for (double t : {0.0, 17.0, 333.3}) {
    for (const Vec3& x : {Vec3(0, 0, -sumA - 0.1), Vec3(40, -25, -20), Vec3(-300, 10, -79)}) {
      double eta = 0.0;
      FluidKinematics sum;
      for (const AiryWave& w : waves) {
        eta += w.elevation(x.x(), x.y(), t);
        const FluidKinematics k = w.kinematics(x, t);
        sum.velocity += k.velocity;
        sum.acceleration += k.acceleration;
      }
      EXPECT_NEAR(sea.elevation(x.x(), x.y(), t), eta, 1e-12 * sumA);
      const FluidKinematics kin = sea.kinematics(x, t);
      EXPECT_LT((kin.velocity - sum.velocity).norm(), 1e-12 * sumV);
      EXPECT_LT((kin.acceleration - sum.acceleration).norm(), 1e-12 * sumAcc);
    }
  }
}

// Source: Wheeler (1970): at the instantaneous surface the kinematics are the linear values at z = 0 (i.e.
// the vertical-stretching values at z = 0 when the surface is above it); zero above the surface; the
// velocity is horizontal along the azimuth plus vertical. Tolerance 1e-12 relative.
TEST(JonswapSea, WheelerStretchingAndDrySurface) {
  const JonswapSea wheeler(baseParameters());
  JonswapSea::Parameters pv = baseParameters();
  pv.stretching = Stretching::Vertical;
  const JonswapSea vertical(pv);
  int crests = 0;
  for (double t = 0.0; t < 200.0; t += 3.7) {
    const double eta = wheeler.elevation(10.0, 5.0, t);
    const FluidKinematics dry = wheeler.kinematics(Vec3(10.0, 5.0, eta + 1e-6), t);
    EXPECT_EQ(dry.velocity, Vec3::Zero());
    EXPECT_EQ(dry.acceleration, Vec3::Zero());
    if (eta <= 0.0) continue;
    ++crests;
    const FluidKinematics top = wheeler.kinematics(Vec3(10.0, 5.0, eta), t);
    const FluidKinematics zero = vertical.kinematics(Vec3(10.0, 5.0, 0.0), t);
    EXPECT_LT((top.velocity - zero.velocity).norm(), 1e-12 * (1.0 + zero.velocity.norm()));
    EXPECT_LT((top.acceleration - zero.acceleration).norm(), 1e-12 * (1.0 + zero.acceleration.norm()));
    // Horizontal part along azimuth 60 deg.
    EXPECT_NEAR(top.velocity.y() * std::cos(degToRad(60.0)) - top.velocity.x() * std::sin(degToRad(60.0)),
                0.0, 1e-12);
  }
  EXPECT_GT(crests, 5);
}

TEST(JonswapSea, RejectsInvalidParameters) {
  auto make = [](auto modify) {
    JonswapSea::Parameters p = baseParameters();
    modify(p);
    return JonswapSea(p);
  };
  EXPECT_THROW(make([](auto& p) { p.significantHeight = 0.0; }), Error);
  EXPECT_THROW(make([](auto& p) { p.peakPeriod = -1.0; }), Error);
  EXPECT_THROW(make([](auto& p) { p.gamma = 0.5; }), Error);
  EXPECT_THROW(make([](auto& p) { p.waterDepth = 0.0; }), Error);
  EXPECT_THROW(make([](auto& p) { p.componentCount = 0; }), Error);
  EXPECT_THROW(make([](auto& p) { p.maxFrequencyFactor = 0.4; }), Error);
  EXPECT_THROW(make([](auto& p) { p.minFrequencyFactor = 0.0; }), Error);
  try {
    make([](auto& p) { p.peakPeriod = 0.0; });
    FAIL() << "expected tangle::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("peakPeriod"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tangle::hydro

namespace tangle::hydro {
namespace {

// kinematics(p, t, elevation) is what the Morison loads call at every element midpoint and step: it must
// give exactly the separate elevation() and kinematics() (the same operations; bit for bit), under a
// crest, in a trough, at depth and at dry points above the surface, for both wave fields.
void expectCombinedEqualsSeparate(const WaveField& field) {
  for (const Vec3& p : {Vec3(0, 0, -1.0), Vec3(13.0, -4.0, -30.0), Vec3(-50.0, 20.0, -99.0), Vec3(7.0, 3.0, 0.8),
                        Vec3(-21.0, 8.0, 2.5)})
    for (const double t : {0.0, 3.3, 17.9}) {
      double eta = -1.0;
      const FluidKinematics combined = field.kinematics(p, t, eta);
      const FluidKinematics separate = field.kinematics(p, t);
      EXPECT_EQ(eta, field.elevation(p.x(), p.y(), t)) << p.transpose() << " at " << t << " s";
      EXPECT_EQ(combined.velocity, separate.velocity) << p.transpose() << " at " << t << " s";
      EXPECT_EQ(combined.acceleration, separate.acceleration) << p.transpose() << " at " << t << " s";
    }
}

TEST(WaveField, KinematicsWithElevationEqualsTheSeparateCallsAiry) {
  expectCombinedEqualsSeparate(AiryWave(3.0, 9.0, degToRad(30.0), 100.0));
}

TEST(WaveField, KinematicsWithElevationEqualsTheSeparateCallsJonswap) {
  JonswapSea::Parameters p = baseParameters();
  p.waterDepth = 100.0;
  expectCombinedEqualsSeparate(JonswapSea(p));
}

}  // namespace
}  // namespace tangle::hydro

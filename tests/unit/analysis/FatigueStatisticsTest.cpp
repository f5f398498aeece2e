// Rainflow counting, Miner's damage and extreme statistics (issue 32), each against its independent truth:
// the ASTM standard's worked example, the S-N formula by hand, a hand computation of the Gumbel fit, and the
// closed-form most probable maximum of a narrow-band Gaussian process.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/analysis/Rainflow.hpp"
#include "tangle/analysis/ResponseStatistics.hpp"
#include "tangle/analysis/SnCurve.hpp"

namespace tangle::analysis {
namespace {

std::map<double, double> countsByRange(const std::vector<RainflowCycle>& cycles) {
  std::map<double, double> out;
  for (const RainflowCycle& c : cycles) out[c.range] += c.count;
  return out;
}

// ASTM E1049-85 (2017) Fig. 6 / Table 4: -2, 1, -3, 5, -1, 3, -4, 4, -2 gives ranges 3, 4, 6, 8, 9 with
// counts 0.5, 1.5, 0.5, 1.0, 0.5 (exact arithmetic: no tolerance).
TEST(Rainflow, AstmE1049ExampleGivesTheStandardsCounts) {
  const std::vector<RainflowCycle> cycles = rainflow({-2, 1, -3, 5, -1, 3, -4, 4, -2});
  const std::map<double, double> expected{{3.0, 0.5}, {4.0, 1.5}, {6.0, 0.5}, {8.0, 1.0}, {9.0, 0.5}};
  EXPECT_EQ(countsByRange(cycles), expected);
  // The one closed cycle is -1 -> 3 (mean 1); the rest are half cycles.
  int full = 0;
  for (const RainflowCycle& c : cycles)
    if (c.count == 1.0) {
      ++full;
      EXPECT_EQ(c.range, 4.0);
      EXPECT_EQ(c.mean, 1.0);
    }
  EXPECT_EQ(full, 1);
}

TEST(Rainflow, TurningPointsDropPlateausAndMonotoneRuns) {
  EXPECT_EQ(turningPoints({0, 1, 2, 2, 3, 1, 1, 0, 4}), (std::vector<double>{0, 3, 0, 4}));
}

TEST(Rainflow, SineOfConstantAmplitudeIsCyclesOfTwiceTheAmplitude) {
  std::vector<double> x;
  for (int i = 0; i <= 2000; ++i) x.push_back(3.0 * std::sin(2.0 * std::numbers::pi * i / 100.0));  // 20 periods
  double total = 0.0, atTwiceAmplitude = 0.0;
  for (const RainflowCycle& c : rainflow(x)) {
    total += c.count;
    if (std::abs(c.range - 6.0) < 1e-9) atTwiceAmplitude += c.count;
  }
  // 42 turning points (0, 20 peaks, 20 valleys, 0): 41 ranges, half cycles each when not closed. 39 of them
  // are 6 (19.5 cycles); the first and last quarter periods are half cycles of range 3.
  EXPECT_NEAR(atTwiceAmplitude, 19.5, 1e-12);
  EXPECT_NEAR(total, 20.5, 1e-12);
}

// DNV-RP-C203 curve D in air: log N = 12.164 - 3 log S up to 1e7 cycles, 15.606 - 5 log S beyond (S in MPa).
// By hand: S = 100 MPa -> N = 10^6.164 = 1.458814e6; S = 30 MPa -> 10^(15.606 - 5 log 30) = 1.661092e8;
// t = 50 mm, k = 0.2: S (50/25)^0.2 -> 9.624585e5.
TEST(SnCurve, DnvDCurveAgainstTheFormulaOnBothSlopes) {
  const SnCurve d = SnCurve::dnvD();
  EXPECT_NEAR(d.cyclesToFailure(100e6) / 1.4588142602753474e6, 1.0, 1e-12);
  EXPECT_NEAR(d.cyclesToFailure(30e6) / 1.6610921521300647e8, 1.0, 1e-12);
  EXPECT_NEAR(SnCurve::dnvD(0.050).cyclesToFailure(100e6) / 9.624584783908128e5, 1.0, 1e-12);
  // The knee: the table gives 52.63 MPa at 1e7 cycles; the rounded log a1 (3 decimals) puts it at
  // 10^((12.164 - 7) / 3) = 52.642 MPa, 2.3e-4 higher (a unit in the last decimal of log a is 7.7e-4 on S).
  const double knee = d.kneeRange();
  EXPECT_NEAR(knee / 1e6 / 52.63, 1.0, 7.7e-4);
  EXPECT_NEAR(d.cyclesToFailure(knee * (1.0 - 1e-9)) / d.cyclesToFailure(knee * (1.0 + 1e-9)), 1.0, 2e-3);
}

TEST(SnCurve, MinerDamageOfConstantAmplitudeIsNOverN) {
  const SnCurve d = SnCurve::dnvD();
  // 1000 periods of a 100 MPa sine: 999.5 cycles of 100 MPa and two half cycles of 50 MPa (the first and
  // last quarter periods), below the knee: N(50 MPa) = 10^(15.606 - 5 log 50) = 1.291550e7 by hand.
  std::vector<double> x;
  for (int i = 0; i <= 1000 * 20; ++i) x.push_back(50e6 * std::sin(2.0 * std::numbers::pi * i / 20.0));
  const double expected = 999.5 / 1.4588142602753474e6 + 1.0 / std::pow(10.0, 15.606 - 5.0 * std::log10(50.0));
  EXPECT_NEAR(minerDamage(rainflow(x), d) / expected, 1.0, 1e-9);
  // Two amplitudes across the knee: 1000 at 100 MPa and 1e5 at 30 MPa.
  const std::vector<RainflowCycle> mixed{{100e6, 0.0, 1000.0}, {30e6, 0.0, 1e5}};
  EXPECT_NEAR(minerDamage(mixed, d), 1000.0 / 1.4588142602753474e6 + 1e5 / 1.6610921521300647e8, 1e-15);
}

TEST(TnCurve, ChainDamageIsNRtoTheMOverAd) {
  // DNV-OS-E301 studless chain: a_D = 316, m = 3; 1e6 cycles of 5 % of the breaking strength:
  // D = 1e6 0.05^3 / 316 = 0.39557.
  const TnCurve chain{3.0, 316.0, 1.0e7};
  EXPECT_NEAR(minerDamage({{0.5e6, 0.0, 1e6}}, chain), 1e6 * 0.125e-3 / 316.0, 1e-12);
}

// Method of moments by hand on {10, 12, 11, 13, 14}: mean 12, s = sqrt(2.5) = 1.581139, scale
// s sqrt(6) / pi = 1.232809, mode 12 - 0.5772157 scale = 11.288403, 90 % value mode - scale ln(-ln 0.9)
// = 14.062676.
TEST(Gumbel, MethodOfMomentsAgainstAHandComputation) {
  const GumbelFit g = fitGumbel({10, 12, 11, 13, 14});
  EXPECT_NEAR(g.mean, 12.0, 1e-12);
  EXPECT_NEAR(g.standardDeviation, 1.5811388300841898, 1e-12);
  EXPECT_NEAR(g.scale, 1.2328088881229995, 1e-12);
  EXPECT_NEAR(g.mode, 11.288403397945563, 1e-12);
  EXPECT_NEAR(g.quantile(0.9), 14.062676240597945, 1e-12);
}

// A narrow-band Gaussian process (60 cosines of equal amplitude, random phases, frequencies within +-5 % of
// 0.1 Hz, seeded; 30 h at 0.25 s) has Rayleigh peaks: the most probable maximum of N peaks is
// sigma sqrt(2 ln N) above the mean (Longuet-Higgins 1952). The fit of the 30 h's peaks (~10 800), for a
// 3 h storm (N = 3 h / Tz), against that closed form with the record's own sigma: within 3 % (the Rayleigh
// estimate's sampling error is 1/sqrt(2 n) = 0.7 % on sigma; the band is not infinitely narrow, and 60
// components are not exactly Gaussian). The Weibull fit's shape is near 2.
TEST(ExtremeStatistics, NarrowBandGaussianMostProbableMaximumIsSigmaSqrtTwoLnN) {
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi), df(-0.005, 0.005);
  const int components = 60;
  std::vector<double> f(components), p(components);
  for (int k = 0; k < components; ++k) {
    f[k] = 0.1 + df(rng);
    p[k] = phase(rng);
  }
  const double a = 1.0;  // each component's amplitude: sigma^2 = components a^2 / 2
  std::vector<double> t, x;
  const double dt = 0.25, record = 30.0 * 3600.0, storm = 3.0 * 3600.0;
  for (double time = 0.0; time <= record; time += dt) {
    double v = 10.0;
    for (int k = 0; k < components; ++k) v += a * std::cos(2.0 * std::numbers::pi * f[k] * time + p[k]);
    t.push_back(time);
    x.push_back(v);
  }
  const PeakSet peaks = findPeaks(t, x);
  ASSERT_GT(peaks.peaks.size(), 9000u);
  EXPECT_NEAR(peaks.upcrossingPeriod, 10.0, 0.3);
  EXPECT_NEAR(peaks.standardDeviation / std::sqrt(components * a * a / 2.0), 1.0, 0.05);
  const double n = storm / peaks.upcrossingPeriod;
  const double expected = peaks.standardDeviation * std::sqrt(2.0 * std::log(n));
  EXPECT_NEAR((fitRayleigh(peaks).mostProbableMaximum(peaks.mean, n) - peaks.mean) / expected, 1.0, 0.03);
  const PeakFit weibull = fitWeibull(peaks);
  EXPECT_NEAR(weibull.shape, 2.0, 0.2);
  EXPECT_NEAR((weibull.mostProbableMaximum(peaks.mean, n) - peaks.mean) / expected, 1.0, 0.05);
  RecordProperty("rayleigh_mpm_ratio",
                 std::to_string((fitRayleigh(peaks).mostProbableMaximum(peaks.mean, n) - peaks.mean) / expected));
  RecordProperty("weibull_mpm_ratio", std::to_string((weibull.mostProbableMaximum(peaks.mean, n) - peaks.mean) / expected));
  RecordProperty("weibull_shape", std::to_string(weibull.shape));
}

/// A narrow-band Gaussian record (60 components about 0.1 Hz, sigma ~5.5) of `hours`, plus `trend` times the
/// time over the record [units per record], into a PeakTracker at 0.25 s.
PeakTracker narrowBandRecord(double seconds, double trend, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi), df(-0.005, 0.005);
  std::vector<double> f(60), p(60);
  for (std::size_t k = 0; k < f.size(); ++k) {
    f[k] = 0.1 + df(rng);
    p[k] = phase(rng);
  }
  PeakTracker tracker;
  for (double time = 0.0; time <= seconds; time += 0.25) {
    double v = 100.0 + trend * time / seconds;
    for (std::size_t k = 0; k < f.size(); ++k) v += std::cos(2.0 * std::numbers::pi * f[k] * time + p[k]);
    tracker.add(time, v);
  }
  return tracker;
}

// Issue 45: a storm extreme only where it is credible. A stationary narrow-band record of 1 h (about 360
// peaks) is quoted; the same with a trend of 4 standard deviations over the record (a drift) is a transient
// (mean shift near 4 / 2 = 2 standard deviations of the record, which the trend also widens); 120 s of it
// (about 12 peaks) are too few; a pure ramp has no peaks at all. Each doubt says why.
TEST(ExtremeCredibility, OnlyStationaryRecordsOfEnoughPeaksAreQuoted) {
  const double storm = 3.0 * 3600.0;
  const ExtremeEstimate stationary = extremeEstimate(narrowBandRecord(3600.0, 0.0, 7), storm);
  EXPECT_TRUE(stationary.credible()) << stationary.doubt;
  EXPECT_LT(std::abs(stationary.meanShift), 0.2);
  EXPECT_GT(stationary.weibullMpm, stationary.maximum);  // a 3 h storm from a 1 h record

  const ExtremeEstimate drift = extremeEstimate(narrowBandRecord(3600.0, 4.0 * 5.5, 7), storm);
  EXPECT_FALSE(drift.credible());
  EXPECT_GT(drift.meanShift, 1.0);
  EXPECT_NE(drift.doubt.find("not stationary"), std::string::npos) << drift.doubt;

  const ExtremeEstimate shortRecord = extremeEstimate(narrowBandRecord(120.0, 0.0, 7), storm);
  EXPECT_FALSE(shortRecord.credible());
  EXPECT_NE(shortRecord.doubt.find("fewer than 20"), std::string::npos) << shortRecord.doubt;

  PeakTracker ramp;
  for (int i = 0; i <= 1000; ++i) ramp.add(0.1 * i, 2.0 * i);
  const ExtremeEstimate monotonic = extremeEstimate(ramp, storm);
  EXPECT_FALSE(monotonic.credible());
  EXPECT_FALSE(monotonic.doubt.empty());
}

// The mean shift of a linear trend is sqrt(3) standard deviations (the halves' means are T/2 apart for a ramp
// of rise T, whose standard deviation is T / sqrt(12)); wiggles of 2 on a rise of 1000 (above the tracker's
// gate, so that there are turning points to split the record at) change that by under 1e-5.
TEST(ExtremeCredibility, MeanShiftOfALinearTrendIsSqrtThree) {
  PeakTracker tracker;
  for (int i = 0; i <= 100000; ++i) {
    const double t = 0.01 * i;
    tracker.add(t, t + 2.0 * std::sin(2.0 * std::numbers::pi * t));  // a 1000 s ramp with 1 s wiggles
  }
  EXPECT_NEAR(tracker.meanShift(), std::sqrt(3.0), 0.01);
}

}  // namespace
// A line of beams whose static bending moment is zero everywhere (a straight vertical riser in still water)
// gets moment statistics as every other result table does (LineSnapshot::hasBending); a cable line gets
// none. Until 2026-12-06 the statistics asked for a non-zero static moment somewhere, and the riser's
// dynamic moments had none (statistics.csv's moment columns empty, "a line without bending stiffness").
TEST(ResponseStatistics, ABeamLineStraightAtRestStillHasMomentStatistics) {
  solver::LineSnapshot riser, cable;
  for (solver::LineSnapshot* s : {&riser, &cable}) {
    s->tension.assign(5, 1.0e5);
    s->bendingMoment.assign(5, 0.0);
  }
  riser.hasBending = true;
  analysis::ResponseStatistics stats({riser, cable}, 0.0);
  ASSERT_EQ(stats.lines().size(), 2u);
  ASSERT_EQ(stats.lines()[0].moment.size(), 5u);
  EXPECT_TRUE(stats.lines()[1].moment.empty());
  riser.bendingMoment[2] = 2.5e3;  // the dynamics bends it
  stats.accumulate({riser, cable}, 0.1);
  EXPECT_EQ(stats.lines()[0].moment[2].maximum(), 2.5e3);
}

}  // namespace tangle::analysis

#pragma once
/// @file ExtremeStatistics.hpp
/// Extreme statistics of responses in irregular seas (docs/theory.md, "Extreme statistics"):
/// - the peaks of a time history (the largest value between two up-crossings of its mean) and the mean
///   up-crossing period;
/// - distributions fitted to the peaks' excess over the mean: Rayleigh (sigma^2 = sum a^2 / (2 n), the
///   maximum-likelihood estimate) and two-parameter Weibull (least squares on the Weibull plot
///   ln(-ln(1 - F)) against ln a, F = i / (n + 1));
/// - the most probable maximum (MPM) of N peaks: the mode of the largest of N, mean + a_N with
///   F(a_N) = 1 - 1/N (Rayleigh: sigma sqrt(2 ln N); Weibull: alpha (ln N)^(1/beta)), for a storm of
///   duration T with N = T / Tz (DNV-OS-E301 (2021) Ch.2 Sec.2, API RP 2SK (2005) 6.4);
/// - the Gumbel distribution of maxima over seeds by the method of moments (scale s sqrt(6) / pi, mode
///   mean - 0.5772 scale), its most probable maximum (the mode) and the value at a non-exceedance
///   probability q: mode - scale ln(-ln q).
/// Units: those of the history (N, m, N m, ...); times [s].

#include <algorithm>
#include <cmath>
#include <vector>

namespace tangle::analysis {

/// Peaks of a sampled history.
struct PeakSet {
  std::vector<double> peaks;     ///< the largest value between consecutive up-crossings of the mean
  double mean = 0.0;             ///< mean of the history
  double standardDeviation = 0.0;
  double upcrossingPeriod = 0.0;  ///< Tz: time between the first and last up-crossing / their intervals [s]
};

/// Peaks of `values` sampled at `times` [s] (same length, increasing).
PeakSet findPeaks(const std::vector<double>& times, const std::vector<double>& values);

/// The peaks of a history given one sample at a time, with bounded memory: a run tracks the tension and
/// bending moment at every node of every line at every step. It keeps the time-weighted mean and variance
/// of every sample and the turning points of the history with reversals smaller than a hysteresis gate
/// h = `gate` x (the range seen so far) left out (wiggles of the time integration or of higher modes that
/// would otherwise be stored and counted as up-crossings). peaks() then finds the largest value between
/// consecutive up-crossings of the mean among the turning points (exact for the peaks; the up-crossing
/// times are interpolated linearly between the turning points around them).
class PeakTracker {
 public:
  explicit PeakTracker(double gate = 1e-3) : m_gate(gate) {}
  /// Adds the sample `value` at `time` [s] (increasing). Inline: a run calls it for every node at every
  /// step (1.7 % of the mooring example's profile out of line).
  void add(double time, double value);
  /// Number of samples added.
  long samples() const { return m_samples; }
  /// Largest sample.
  double maximum() const { return m_max; }
  /// Time from the first to the last sample [s].
  double duration() const { return m_weight; }
  /// Turning points kept.
  std::size_t turningPoints() const { return m_points.size(); }
  /// The peaks, mean (time-weighted), standard deviation and Tz of what was added (the open extreme at the
  /// end counts as the last turning point).
  PeakSet peaks() const;
  /// The time-weighted mean of the second half of the record minus that of the first, in standard deviations
  /// of the whole record [-] (the halves split at the turning point nearest the middle): near 0 for a
  /// stationary record of many cycles, about 1.7 for a steady trend (a drift). 0 with fewer than three
  /// turning points or no spread.
  double meanShift() const;

 private:
  struct Point {
    double time, value;
    double weight, sum;  // the time-weighted sums up to this point (meanShift)
  };
  double m_gate;
  std::vector<Point> m_points;  // confirmed turning points (the first sample is the first)
  Point m_candidate{0.0, 0.0, 0.0, 0.0};  // the extreme since the last turning point
  int m_direction = 0;          // +1 rising to the candidate, -1 falling, 0 not yet moved beyond the gate
  double m_min = 0.0, m_max = 0.0;
  double m_lastTime = 0.0, m_lastValue = 0.0;
  double m_weight = 0.0, m_sum = 0.0, m_sumSquares = 0.0;  // time-weighted
  long m_samples = 0;
};

inline void PeakTracker::add(double time, double value) {
  if (m_samples == 0) {
    m_points.push_back({time, value, 0.0, 0.0});
    m_candidate = {time, value, 0.0, 0.0};
    m_min = m_max = value;
  } else {
    // Trapezoidal time weights: each interval counts the mean of its two samples.
    const double dt = time - m_lastTime;
    const double mid = 0.5 * (value + m_lastValue);
    m_weight += dt;
    m_sum += dt * mid;
    m_sumSquares += dt * 0.5 * (value * value + m_lastValue * m_lastValue);
    m_min = std::min(m_min, value);
    m_max = std::max(m_max, value);
    const double gate = m_gate * (m_max - m_min);
    if (m_direction == 0) {
      if (std::abs(value - m_points.back().value) > gate) {
        m_direction = value > m_points.back().value ? 1 : -1;
        m_candidate = {time, value, m_weight, m_sum};
      }
    } else if ((value - m_candidate.value) * m_direction >= 0.0) {
      m_candidate = {time, value, m_weight, m_sum};  // carries on beyond the candidate
    } else if (std::abs(value - m_candidate.value) > gate) {
      m_points.push_back(m_candidate);  // turned back by more than the gate: the candidate was a turning point
      m_candidate = {time, value, m_weight, m_sum};
      m_direction = -m_direction;
    }
  }
  m_lastTime = time;
  m_lastValue = value;
  ++m_samples;
}

/// A fitted distribution of the peaks' excess a over the mean, as a Weibull F(a) = 1 - exp(-(a / alpha)^beta)
/// (a Rayleigh of parameter sigma is alpha = sigma sqrt(2), beta = 2).
struct PeakFit {
  double scale = 0.0;  ///< alpha (units of the history)
  double shape = 2.0;  ///< beta [-]
  /// Most probable largest of `count` peaks, as a value of the history: mean + alpha (ln N)^(1/beta).
  double mostProbableMaximum(double mean, double count) const;
};

/// Rayleigh fit of the peaks' excess over the mean (peaks below the mean count with zero excess).
PeakFit fitRayleigh(const PeakSet& peaks);
/// Two-parameter Weibull fit of the positive excesses of the peaks over the mean.
PeakFit fitWeibull(const PeakSet& peaks);

/// Gumbel fit of a set of maxima (one per seed) by the method of moments.
struct GumbelFit {
  double mean = 0.0, standardDeviation = 0.0;  ///< of the maxima (sample standard deviation, n - 1)
  double scale = 0.0;                          ///< beta = s sqrt(6) / pi
  double mode = 0.0;                           ///< mu = mean - 0.5772 beta: the most probable maximum
  /// The value not exceeded with probability q (e.g. 0.9): mu - beta ln(-ln q).
  double quantile(double q) const;
};
GumbelFit fitGumbel(const std::vector<double>& maxima);

}  // namespace tangle::analysis

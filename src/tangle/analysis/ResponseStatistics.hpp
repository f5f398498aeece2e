#pragma once
/// @file ResponseStatistics.hpp
/// The peaks of a run's responses for their extreme statistics (docs/theory.md 13.3): the tension at both
/// ends of every line, the effective tension and bending moment at every node of every line, and any other
/// series the run adds (vessel offsets), each over every accepted step after the ramp (a PeakTracker per
/// series: bounded memory, however long the run).
/// Units: those of the series (N, N m, m); times [s].

#include <cmath>
#include <string>
#include <vector>

#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::analysis {

/// Peak trackers of the lines of a run.
class ResponseStatistics {
 public:
  /// The trackers of one line.
  struct Line {
    PeakTracker endA, endB;            ///< end tensions [N]
    std::vector<PeakTracker> tension;  ///< effective tension per node [N]
    std::vector<PeakTracker> moment;   ///< bending moment per node [N m] (empty for a cable line)
  };

  /// @param initial the lines at the start (node counts; lines without bending get no moment trackers)
  /// @param startTime samples before this time [s] are left out (the ramp)
  ResponseStatistics(const std::vector<solver::LineSnapshot>& initial, double startTime);

  /// Adds one accepted state of the lines at `time` [s].
  void accumulate(const std::vector<solver::LineSnapshot>& lines, double time);

  double startTime() const { return m_startTime; }
  const std::vector<Line>& lines() const { return m_lines; }

 private:
  double m_startTime;
  std::vector<Line> m_lines;
};

/// The extreme statistics of one series: its peaks, their Rayleigh and Weibull fits and the most probable
/// maximum of a storm of `stormDuration` [s] (N = stormDuration / Tz peaks); `valid` is false with fewer than
/// two peaks.
struct ExtremeEstimate {
  bool valid = false;  ///< at least two peaks: the fits exist
  /// Why the most probable maximum is not to be quoted, or empty when it is (credible()): fewer than
  /// kMinimumPeaks peaks; a Weibull shape outside [kShapeLow, kShapeHigh] (the peaks are not those of a
  /// narrow-band random response, and the extrapolation to a storm runs away: shape 0.35 gave 441 MN for a
  /// chain of 7 MN); a record that is not stationary (PeakTracker::meanShift beyond kMaximumMeanShift
  /// standard deviations: a transient such as a drift, a release or a start-up, whose peaks are no sample of
  /// a storm); or a most probable maximum below the largest value of a record shorter than the storm.
  std::string doubt;
  bool credible() const { return valid && doubt.empty(); }
  /// The record's mean moves between its halves by more than kMaximumMeanShift standard deviations.
  bool transient() const { return valid && std::abs(meanShift) > kMaximumMeanShift; }
  double meanShift = 0.0;  ///< PeakTracker::meanShift of the record [standard deviations]
  static constexpr int kMinimumPeaks = 20;
  static constexpr double kShapeLow = 1.5, kShapeHigh = 3.0;
  /// A steady trend gives 1.7 (sqrt(3)); the halves of a stationary record of 20 or more cycles differ by a
  /// small fraction of a standard deviation.
  static constexpr double kMaximumMeanShift = 0.5;
  PeakSet peaks;
  double maximum = 0.0;  ///< largest sample
  PeakFit rayleigh, weibull;
  double rayleighMpm = 0.0, weibullMpm = 0.0;
};
ExtremeEstimate extremeEstimate(const PeakTracker& tracker, double stormDuration);

}  // namespace tangle::analysis

#include "tangle/analysis/ResponseStatistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tangle::analysis {

ResponseStatistics::ResponseStatistics(const std::vector<solver::LineSnapshot>& initial, double startTime)
    : m_startTime(startTime), m_lines(initial.size()) {
  for (std::size_t l = 0; l < initial.size(); ++l) {
    const solver::LineSnapshot& s = initial[l];
    m_lines[l].tension.resize(s.tension.size());
    // A line of beams, as every other result table decides (LineSnapshot::hasBending): not by a non-zero
    // static moment somewhere, which a straight vertical riser in still water has nowhere, and whose
    // dynamic moments then had no statistics.
    if (s.hasBending) m_lines[l].moment.resize(s.bendingMoment.size());
  }
}

void ResponseStatistics::accumulate(const std::vector<solver::LineSnapshot>& lines, double time) {
  if (time < m_startTime - 1e-9) return;
  for (std::size_t l = 0; l < m_lines.size(); ++l) {
    Line& t = m_lines[l];
    const solver::LineSnapshot& s = lines[l];
    t.endA.add(time, s.endTensionA);
    t.endB.add(time, s.endTensionB);
    for (std::size_t i = 0; i < t.tension.size(); ++i) t.tension[i].add(time, s.tension[i]);
    for (std::size_t i = 0; i < t.moment.size(); ++i) t.moment[i].add(time, s.bendingMoment[i]);
  }
}

ExtremeEstimate extremeEstimate(const PeakTracker& tracker, double stormDuration) {
  ExtremeEstimate e;
  e.peaks = tracker.peaks();
  e.maximum = tracker.maximum();
  e.meanShift = tracker.meanShift();
  const std::size_t count = e.peaks.peaks.size();
  if (count < 2 || !(e.peaks.upcrossingPeriod > 0.0)) {
    e.doubt = fmt::format(
        "{} peak(s): the record crosses its mean upwards fewer than twice (a steady or monotonic "
        "response, or a record too short)",
        count);
    return e;
  }
  e.valid = true;
  const double n = stormDuration / e.peaks.upcrossingPeriod;
  e.rayleigh = fitRayleigh(e.peaks);
  e.weibull = fitWeibull(e.peaks);
  e.rayleighMpm = e.rayleigh.mostProbableMaximum(e.peaks.mean, n);
  e.weibullMpm = e.weibull.mostProbableMaximum(e.peaks.mean, n);
  if (e.transient())
    e.doubt = fmt::format(
        "not stationary: the mean of the record's second half differs from the first's by {:.2f} "
        "standard deviations (a transient, not a storm)",
        e.meanShift);
  else if (count < static_cast<std::size_t>(ExtremeEstimate::kMinimumPeaks))
    e.doubt = fmt::format("{} peaks, fewer than {}", count, ExtremeEstimate::kMinimumPeaks);
  else if (!(e.weibull.shape >= ExtremeEstimate::kShapeLow && e.weibull.shape <= ExtremeEstimate::kShapeHigh))
    e.doubt = fmt::format("Weibull shape {:.2f} outside [{}, {}]", e.weibull.shape,
                          ExtremeEstimate::kShapeLow, ExtremeEstimate::kShapeHigh);
  else if (tracker.duration() < stormDuration && std::min(e.rayleighMpm, e.weibullMpm) < e.maximum)
    e.doubt = "most probable maximum of the storm below the largest value of a shorter record";
  return e;
}

}  // namespace tangle::analysis

#include "tangle/analysis/ResponseStatistics.hpp"

#include <algorithm>

namespace tangle::analysis {

ResponseStatistics::ResponseStatistics(const std::vector<solver::LineSnapshot>& initial, double startTime)
    : m_startTime(startTime), m_lines(initial.size()) {
  for (std::size_t l = 0; l < initial.size(); ++l) {
    const solver::LineSnapshot& s = initial[l];
    m_lines[l].tension.resize(s.tension.size());
    const bool bending = std::any_of(s.bendingMoment.begin(), s.bendingMoment.end(), [](double m) { return m != 0.0; });
    if (bending) m_lines[l].moment.resize(s.bendingMoment.size());
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
  if (e.peaks.peaks.size() < 2 || !(e.peaks.upcrossingPeriod > 0.0)) return e;
  e.valid = true;
  const double n = stormDuration / e.peaks.upcrossingPeriod;
  e.rayleigh = fitRayleigh(e.peaks);
  e.weibull = fitWeibull(e.peaks);
  e.rayleighMpm = e.rayleigh.mostProbableMaximum(e.peaks.mean, n);
  e.weibullMpm = e.weibull.mostProbableMaximum(e.peaks.mean, n);
  return e;
}

}  // namespace tangle::analysis

#include "tangle/analysis/ExtremeStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace tangle::analysis {

namespace {

/// The peaks of a history given as `n` points (time(i) [s], value(i)) in time order, about `mean`: the
/// largest value between consecutive up-crossings (linear between the points), and Tz. Shared by the
/// sampled histories of findPeaks and the turning points of PeakTracker.
template <class Time, class Value>
void peaksBetweenUpcrossings(std::size_t n, Time time, Value value, PeakSet& out) {
  std::size_t crossings = 0;
  double first = 0.0, last = 0.0;
  double peak = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < n; ++i) {
    const double a = value(i - 1), b = value(i);
    if (a < out.mean && b >= out.mean) {
      if (crossings > 0) out.peaks.push_back(peak);
      const double t = time(i - 1) + (out.mean - a) / (b - a) * (time(i) - time(i - 1));
      if (crossings == 0) first = t;
      last = t;
      ++crossings;
      peak = -std::numeric_limits<double>::infinity();
    }
    peak = std::max(peak, b);
  }
  if (crossings >= 2) out.upcrossingPeriod = (last - first) / static_cast<double>(crossings - 1);
}

/// Mean and sample standard deviation (n - 1) of `x` (at least two values).
std::pair<double, double> meanAndDeviation(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  double mean = 0.0;
  for (const double v : x) mean += v / n;
  double var = 0.0;
  for (const double v : x) var += (v - mean) * (v - mean);
  return {mean, std::sqrt(var / (n - 1.0))};
}

}  // namespace

PeakSet findPeaks(const std::vector<double>& times, const std::vector<double>& values) {
  if (times.size() != values.size() || values.size() < 3)
    throw std::invalid_argument("findPeaks: times and values must have the same length, at least 3");
  PeakSet out;
  std::tie(out.mean, out.standardDeviation) = meanAndDeviation(values);
  peaksBetweenUpcrossings(values.size(), [&](std::size_t i) { return times[i]; },
                          [&](std::size_t i) { return values[i]; }, out);
  return out;
}

PeakSet PeakTracker::peaks() const {
  PeakSet out;
  if (m_samples == 0) return out;
  out.mean = m_weight > 0.0 ? m_sum / m_weight : m_lastValue;
  out.standardDeviation = m_weight > 0.0 ? std::sqrt(std::max(0.0, m_sumSquares / m_weight - out.mean * out.mean)) : 0.0;
  std::vector<Point> points = m_points;
  if (m_direction != 0) points.push_back(m_candidate);
  peaksBetweenUpcrossings(points.size(), [&](std::size_t i) { return points[i].time; },
                          [&](std::size_t i) { return points[i].value; }, out);
  return out;
}

double PeakTracker::meanShift() const {
  if (m_points.size() < 3 || !(m_weight > 0.0)) return 0.0;
  const double mean = m_sum / m_weight;
  const double sd = std::sqrt(std::max(0.0, m_sumSquares / m_weight - mean * mean));
  if (!(sd > 0.0)) return 0.0;
  // The turning point nearest the middle of the record (the first sample is m_points[0], at time 0 weight).
  const double middle = m_points.front().time + 0.5 * m_weight;
  const Point* split = &m_points.front();
  for (const Point& p : m_points)
    if (std::abs(p.time - middle) < std::abs(split->time - middle)) split = &p;
  if (!(split->weight > 0.0) || !(m_weight - split->weight > 0.0)) return 0.0;
  const double first = split->sum / split->weight;
  const double second = (m_sum - split->sum) / (m_weight - split->weight);
  return (second - first) / sd;
}

double PeakFit::mostProbableMaximum(double mean, double count) const {
  if (!(count > 1.0)) return mean;
  return mean + scale * std::pow(std::log(count), 1.0 / shape);
}

PeakFit fitRayleigh(const PeakSet& peaks) {
  PeakFit fit;
  double sum = 0.0;
  for (const double p : peaks.peaks) {
    const double a = std::max(0.0, p - peaks.mean);
    sum += a * a;
  }
  // sigma^2 = sum a^2 / (2 n) (maximum likelihood); alpha = sigma sqrt(2).
  const double sigma = peaks.peaks.empty() ? 0.0 : std::sqrt(sum / (2.0 * static_cast<double>(peaks.peaks.size())));
  fit.scale = sigma * std::sqrt(2.0);
  fit.shape = 2.0;
  return fit;
}

PeakFit fitWeibull(const PeakSet& peaks) {
  std::vector<double> a;
  for (const double p : peaks.peaks)
    if (p > peaks.mean) a.push_back(p - peaks.mean);
  PeakFit fit;
  if (a.size() < 3) return fitRayleigh(peaks);
  std::sort(a.begin(), a.end());
  // F(a) = 1 - exp(-(a / alpha)^beta): ln(-ln(1 - F)) = beta ln a - beta ln alpha, with F = i / (n + 1).
  const double n = static_cast<double>(a.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double f = static_cast<double>(i + 1) / (n + 1.0);
    const double x = std::log(a[i]), y = std::log(-std::log(1.0 - f));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double beta = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - beta * sx) / n;
  fit.shape = beta;
  fit.scale = std::exp(-intercept / beta);
  return fit;
}

double GumbelFit::quantile(double q) const { return mode - scale * std::log(-std::log(q)); }

GumbelFit fitGumbel(const std::vector<double>& maxima) {
  if (maxima.size() < 2) throw std::invalid_argument("fitGumbel: at least two maxima are needed");
  GumbelFit g;
  std::tie(g.mean, g.standardDeviation) = meanAndDeviation(maxima);
  constexpr double kEulerGamma = 0.5772156649015329;
  g.scale = g.standardDeviation * std::sqrt(6.0) / std::numbers::pi;
  g.mode = g.mean - kEulerGamma * g.scale;
  return g;
}

}  // namespace tangle::analysis

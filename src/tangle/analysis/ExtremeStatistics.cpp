#include "tangle/analysis/ExtremeStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tangle::analysis {

PeakSet findPeaks(const std::vector<double>& times, const std::vector<double>& values) {
  if (times.size() != values.size() || values.size() < 3)
    throw std::invalid_argument("findPeaks: times and values must have the same length, at least 3");
  PeakSet out;
  const double n = static_cast<double>(values.size());
  for (const double v : values) out.mean += v / n;
  double var = 0.0;
  for (const double v : values) var += (v - out.mean) * (v - out.mean);
  out.standardDeviation = std::sqrt(var / (n - 1.0));
  // Up-crossings of the mean: the time where the history passes it upwards (linear between samples).
  std::vector<double> crossings;
  std::vector<std::size_t> crossingIndex;
  for (std::size_t i = 1; i < values.size(); ++i)
    if (values[i - 1] < out.mean && values[i] >= out.mean) {
      const double f = (out.mean - values[i - 1]) / (values[i] - values[i - 1]);
      crossings.push_back(times[i - 1] + f * (times[i] - times[i - 1]));
      crossingIndex.push_back(i);
    }
  for (std::size_t k = 0; k + 1 < crossingIndex.size(); ++k)
    out.peaks.push_back(*std::max_element(values.begin() + static_cast<std::ptrdiff_t>(crossingIndex[k]),
                                          values.begin() + static_cast<std::ptrdiff_t>(crossingIndex[k + 1])));
  if (crossings.size() >= 2)
    out.upcrossingPeriod = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  return out;
}

PeakSet PeakTracker::peaks() const {
  PeakSet out;
  if (m_samples == 0) return out;
  out.mean = m_weight > 0.0 ? m_sum / m_weight : m_lastValue;
  out.standardDeviation = m_weight > 0.0 ? std::sqrt(std::max(0.0, m_sumSquares / m_weight - out.mean * out.mean)) : 0.0;
  std::vector<Point> points = m_points;
  if (m_direction != 0) points.push_back(m_candidate);
  std::vector<double> crossings;
  double peak = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point& a = points[i - 1];
    const Point& b = points[i];
    if (a.value < out.mean && b.value >= out.mean) {
      if (!crossings.empty()) out.peaks.push_back(peak);
      const double f = (out.mean - a.value) / (b.value - a.value);
      crossings.push_back(a.time + f * (b.time - a.time));
      peak = -std::numeric_limits<double>::infinity();
    }
    peak = std::max(peak, b.value);
  }
  if (crossings.size() >= 2)
    out.upcrossingPeriod = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  return out;
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
  const double n = static_cast<double>(maxima.size());
  for (const double x : maxima) g.mean += x / n;
  double var = 0.0;
  for (const double x : maxima) var += (x - g.mean) * (x - g.mean);
  g.standardDeviation = std::sqrt(var / (n - 1.0));
  constexpr double kEulerGamma = 0.5772156649015329;
  g.scale = g.standardDeviation * std::sqrt(6.0) / std::numbers::pi;
  g.mode = g.mean - kEulerGamma * g.scale;
  return g;
}

}  // namespace tangle::analysis

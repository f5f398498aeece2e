#pragma once
/// @file PiecewiseLinear.hpp
/// A function given by points (x_i, y_i), x increasing, linear between them and along the last segment beyond
/// the last point (a cable's tension-strain curve: line_types[].tension_strain, element::Bar).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "tangle/core/Error.hpp"

namespace tangle::core {

class PiecewiseLinear {
 public:
  /// @param x abscissae, strictly increasing, at least two; @param y ordinates, as many
  /// @throws Error when they are not
  PiecewiseLinear(std::vector<double> x, std::vector<double> y) : m_x(std::move(x)), m_y(std::move(y)) {
    if (m_x.size() < 2 || m_x.size() != m_y.size())
      throw Error("PiecewiseLinear: at least two points (x, y)");
    for (std::size_t i = 1; i < m_x.size(); ++i)
      if (!(m_x[i] > m_x[i - 1])) throw Error("PiecewiseLinear: the abscissae must increase strictly");
  }

  /// The value and the slope at x: of the segment holding x, the first one below x_0, the last one beyond
  /// x_n. At a point, the segment after it (the slope a load increasing through it meets).
  struct Sample {
    double value = 0.0;
    double slope = 0.0;
  };
  Sample at(double x) const {
    const auto it = std::upper_bound(m_x.begin(), m_x.end(), x);
    const std::size_t i =
        std::clamp<std::size_t>(static_cast<std::size_t>(it - m_x.begin()), 1, m_x.size() - 1) - 1;
    const double slope = (m_y[i + 1] - m_y[i]) / (m_x[i + 1] - m_x[i]);
    return {m_y[i] + slope * (x - m_x[i]), slope};
  }
  /// The largest and the smallest slope of the segments.
  double largestSlope() const { return extremeSlope(true); }
  double smallestSlope() const { return extremeSlope(false); }
  const std::vector<double>& x() const { return m_x; }
  const std::vector<double>& y() const { return m_y; }

 private:
  double extremeSlope(bool largest) const {
    double s = (m_y[1] - m_y[0]) / (m_x[1] - m_x[0]);
    for (std::size_t i = 2; i < m_x.size(); ++i) {
      const double t = (m_y[i] - m_y[i - 1]) / (m_x[i] - m_x[i - 1]);
      s = largest ? std::max(s, t) : std::min(s, t);
    }
    return s;
  }
  std::vector<double> m_x, m_y;
};

}  // namespace tangle::core

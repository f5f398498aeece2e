#pragma once
/// @file UpwardCrossings.hpp
/// The period of an oscillation from the times its signal crosses zero going up, each interpolated linearly
/// between the two samples around it (the verification tests of natural periods).

#include <cstddef>
#include <vector>

namespace tangle::test {

class UpwardCrossings {
 public:
  /// Adds a sample x [any unit] at time t [s] (times increasing).
  void add(double t, double x) {
    if (m_hasPrevious && m_previousX < 0.0 && x >= 0.0)
      m_times.push_back(m_previousT + (t - m_previousT) * (-m_previousX) / (x - m_previousX));
    m_hasPrevious = true;
    m_previousT = t;
    m_previousX = x;
  }
  /// The crossing times [s].
  const std::vector<double>& times() const { return m_times; }
  std::size_t count() const { return m_times.size(); }
  /// The mean period from the first to the last crossing [s] (needs two crossings).
  double meanPeriod() const {
    return (m_times.back() - m_times.front()) / static_cast<double>(m_times.size() - 1);
  }

 private:
  std::vector<double> m_times;
  bool m_hasPrevious = false;
  double m_previousT = 0.0, m_previousX = 0.0;
};

}  // namespace tangle::test

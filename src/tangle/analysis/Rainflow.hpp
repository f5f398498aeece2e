#pragma once
/// @file Rainflow.hpp
/// Rainflow cycle counting of a load or stress history (ASTM E1049-85 (2017), "Standard Practices for Cycle
/// Counting in Fatigue Analysis", section 5.4.4: the three-point method with the starting point, half cycles
/// kept) and Miner's damage sum against an S-N curve (SnCurve.hpp).

#include <cmath>
#include <cstddef>
#include <vector>

namespace tangle::analysis {

/// One counted cycle: range and mean in the units of the history, count 1 (a closed cycle) or 0.5 (a half
/// cycle: a range of the residue, or one that contains the starting point).
struct RainflowCycle {
  double range = 0.0;
  double mean = 0.0;
  double count = 1.0;
};

/// The turning points (peaks and valleys) of `history`, in order: the first and last values, and every value
/// where the history changes direction (plateaus collapse to one point). ASTM E1049-85 5.4.4 counts these.
std::vector<double> turningPoints(const std::vector<double>& history);

/// Rainflow counting of a history given one value at a time (ASTM E1049-85 5.4.4 as a stream): the
/// turning points are found as the values come and the points not yet discarded are the only memory (the
/// residue, a few dozen points for a stationary random history), so a run counts the stress at every point
/// of every line at every time step without keeping the histories. Counts exactly as rainflow() below.
class RainflowCounter {
 public:
  /// Adds the next value of the history; `sink(range, mean, count)` receives each cycle counted now.
  template <class Sink>
  void add(double value, Sink&& sink) {
    if (!m_started) {  // the starting point is a turning point
      m_started = true;
      m_candidate = value;
      pushTurningPoint(value, sink);
      m_pending = false;
      return;
    }
    if (value == m_candidate) return;  // a plateau is one point
    // The candidate is the last value seen since the last turning point; it becomes a turning point when
    // the history turns after it.
    if (m_pending && (m_candidate - m_lastTurningPoint) * (value - m_candidate) < 0.0)
      pushTurningPoint(m_candidate, sink);
    m_candidate = value;
    m_pending = true;
  }
  /// Ends the history: the last value is a turning point and the ranges of the residue are half cycles.
  /// The counter is then empty, ready for a new history.
  template <class Sink>
  void finish(Sink&& sink) {
    if (m_pending) pushTurningPoint(m_candidate, sink);
    for (std::size_t i = 0; i + 1 < m_stack.size(); ++i)
      sink(std::abs(m_stack[i + 1] - m_stack[i]), 0.5 * (m_stack[i] + m_stack[i + 1]), 0.5);
    m_stack.clear();
    m_started = m_pending = false;
  }
  /// Points not yet discarded (the residue so far).
  std::size_t residueSize() const { return m_stack.size(); }

 private:
  // X is the range of the two most recent points, Y the range before it. While X >= Y, Y is counted: as a
  // half cycle when it contains the starting point (the first point of the stack, then discarded), else as
  // a cycle (both its points are discarded).
  template <class Sink>
  void pushTurningPoint(double point, Sink& sink) {
    m_lastTurningPoint = point;
    m_stack.push_back(point);
    while (m_stack.size() >= 3) {
      const std::size_t n = m_stack.size();
      const double a = m_stack[n - 3], b = m_stack[n - 2];
      const double x = std::abs(m_stack[n - 1] - b);
      const double y = std::abs(b - a);
      if (x < y) break;
      if (n == 3) {
        sink(y, 0.5 * (a + b), 0.5);
        m_stack.erase(m_stack.begin());
      } else {
        sink(y, 0.5 * (a + b), 1.0);
        m_stack.erase(m_stack.end() - 3, m_stack.end() - 1);
      }
    }
  }

  std::vector<double> m_stack;
  double m_candidate = 0.0;
  double m_lastTurningPoint = 0.0;
  bool m_started = false;
  bool m_pending = false;  // m_candidate is a value after the last turning point
};

/// Rainflow cycles of `history` (ASTM E1049-85 5.4.4). For the standard's example (Fig. 6: -2, 1, -3, 5, -1,
/// 3, -4, 4, -2) the ranges 3, 4, 6, 8, 9 have counts 0.5, 1.5, 0.5, 1.0, 0.5. The total count is half the
/// number of turning points less one.
std::vector<RainflowCycle> rainflow(const std::vector<double>& history);

}  // namespace tangle::analysis

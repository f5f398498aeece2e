#include "tangle/analysis/Rainflow.hpp"

#include <cmath>
#include <cstddef>

namespace tangle::analysis {

std::vector<double> turningPoints(const std::vector<double>& history) {
  std::vector<double> points;
  for (const double x : history) {
    if (!points.empty() && x == points.back()) continue;  // a plateau is one point
    // The last point is a turning point only if the history turns there: drop it when x carries on in
    // the same direction.
    if (points.size() >= 2) {
      const double previous = points[points.size() - 2], last = points.back();
      if ((last - previous) * (x - last) > 0.0) points.pop_back();
    }
    points.push_back(x);
  }
  return points;
}

std::vector<RainflowCycle> rainflow(const std::vector<double>& history) {
  // ASTM E1049-85 5.4.4, with the stack of points not yet discarded: X is the range of the two most recent
  // points, Y the range before it. While X >= Y, Y is counted: as a half cycle when it contains the starting
  // point (the first point of the stack, which is then discarded), else as a cycle (both its points are
  // discarded). At the end the ranges left are half cycles.
  std::vector<RainflowCycle> cycles;
  std::vector<double> stack;
  const auto countY = [&](double count) {
    const double a = stack[stack.size() - 3], b = stack[stack.size() - 2];
    cycles.push_back({std::abs(b - a), 0.5 * (a + b), count});
  };
  for (const double point : turningPoints(history)) {
    stack.push_back(point);
    while (stack.size() >= 3) {
      const std::size_t n = stack.size();
      const double x = std::abs(stack[n - 1] - stack[n - 2]);
      const double y = std::abs(stack[n - 2] - stack[n - 3]);
      if (x < y) break;
      if (n == 3) {  // Y contains the starting point
        countY(0.5);
        stack.erase(stack.begin());
      } else {
        countY(1.0);
        stack.erase(stack.end() - 3, stack.end() - 1);
      }
    }
  }
  for (std::size_t i = 0; i + 1 < stack.size(); ++i)
    cycles.push_back({std::abs(stack[i + 1] - stack[i]), 0.5 * (stack[i] + stack[i + 1]), 0.5});
  return cycles;
}

}  // namespace tangle::analysis

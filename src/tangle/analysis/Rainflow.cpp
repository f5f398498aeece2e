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
  std::vector<RainflowCycle> cycles;
  const auto sink = [&](double range, double mean, double count) { cycles.push_back({range, mean, count}); };
  RainflowCounter counter;
  for (const double x : history) counter.add(x, sink);
  counter.finish(sink);
  return cycles;
}

}  // namespace tangle::analysis

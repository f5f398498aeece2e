#include "tangle/analysis/RangeGraphs.hpp"

#include <algorithm>
#include <limits>

namespace tangle::analysis {

RangeGraphs::RangeGraphs(const std::vector<solver::LineSnapshot>& initial) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const solver::LineSnapshot& s : initial) {
    const std::size_t n = s.arcLength.size();
    Range r;
    const auto reset = [&](std::vector<double>& min, std::vector<double>& max, std::vector<double>& sum) {
      min.assign(n, inf);
      max.assign(n, -inf);
      sum.assign(n, 0.0);
    };
    reset(r.tensionMin, r.tensionMax, r.tensionSum);
    reset(r.momentMin, r.momentMax, r.momentSum);
    reset(r.curvatureMin, r.curvatureMax, r.curvatureSum);
    if (!s.wallTension.empty()) reset(r.wallTensionMin, r.wallTensionMax, r.wallTensionSum);  // pipe lines
    r.endTensionMaxA = r.endTensionMaxB = -inf;
    r.endTensionMinA = r.endTensionMinB = inf;
    if (!s.tension.empty())
      r.retension = std::max(1.0, 0.01 * *std::max_element(s.tension.begin(), s.tension.end()));
    m_ranges.push_back(std::move(r));
  }
}

RangeGraphs::SeabedNodes RangeGraphs::seabedNodes(const model::Model& model) {
  SeabedNodes nodes;
  nodes.surface = model.sharedSeabedSurface();
  for (const model::Line& line : model.lines()) {
    std::vector<double>& radius = nodes.radius.emplace_back();
    for (int i = 0; i < line.nodeCount; ++i)
      radius.push_back(0.5 * model.nodeContactDiameter()[line.firstNode + i]);
  }
  return nodes;
}

void RangeGraphs::accumulate(const std::vector<solver::LineSnapshot>& lines, double dt) {
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    Range& r = m_ranges[l];
    for (std::size_t i = 0; i < s.arcLength.size(); ++i) {
      r.tensionMin[i] = std::min(r.tensionMin[i], s.tension[i]);
      r.tensionMax[i] = std::max(r.tensionMax[i], s.tension[i]);
      r.momentMin[i] = std::min(r.momentMin[i], s.bendingMoment[i]);
      r.momentMax[i] = std::max(r.momentMax[i], s.bendingMoment[i]);
      r.curvatureMin[i] = std::min(r.curvatureMin[i], s.curvature[i]);
      r.curvatureMax[i] = std::max(r.curvatureMax[i], s.curvature[i]);
      r.tensionSum[i] += dt * s.tension[i];
      r.momentSum[i] += dt * s.bendingMoment[i];
      r.curvatureSum[i] += dt * s.curvature[i];
    }
    if (!r.wallTensionSum.empty() && s.wallTension.size() == r.wallTensionSum.size())
      for (std::size_t i = 0; i < s.wallTension.size(); ++i) {
        r.wallTensionMin[i] = std::min(r.wallTensionMin[i], s.wallTension[i]);
        r.wallTensionMax[i] = std::max(r.wallTensionMax[i], s.wallTension[i]);
        r.wallTensionSum[i] += dt * s.wallTension[i];
      }
    r.endTensionMaxA = std::max(r.endTensionMaxA, s.endTensionA);
    r.endTensionMaxB = std::max(r.endTensionMaxB, s.endTensionB);
    r.endTensionMinA = std::min(r.endTensionMinA, s.endTensionA);
    r.endTensionMinB = std::min(r.endTensionMinB, s.endTensionB);
    // One clearance per node and step serves the seabed clearance range and the slack test.
    if (m_seabed.surface && r.seabedClearanceMin.empty())
      r.seabedClearanceMin.assign(s.position.size(), std::numeric_limits<double>::infinity());
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < s.tension.size(); ++i) {
      bool suspended = true;
      if (m_seabed.surface) {
        const double radius = m_seabed.radius[l][i];
        const double gap = m_seabed.surface->gap(s.position[i], radius);
        r.seabedClearanceMin[i] = std::min(r.seabedClearanceMin[i], std::max(0.0, gap));
        // Clear of the seabed by more than half a diameter: a laid chain pushed about by a current hops by
        // less.
        suspended = gap > radius;
      }
      if (suspended) lowest = std::min(lowest, s.tension[i]);
    }
    if (lowest < 0.0) {
      if (!r.slack) ++r.slackEvents;
      r.slack = true;
      r.slackTime += dt;
    } else if (lowest > r.retension) {
      r.slack = false;
    }
  }
  m_weight += dt;
  ++m_steps;
}

}  // namespace tangle::analysis

/// @file StaticContact.cpp
/// Statics hooks of the contact (increment limit, crossed-state rejection, commit) and the exclusions
/// (user pairs and zones, shared connection points). docs/theory.md 9.7 and 9.10.

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "tangle/contact/LineContact.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {

namespace {
/// Largest closing of a pair in one Newton iteration, as a fraction of the sum of the radii.
constexpr double kClosingFraction = 0.25;
/// Deepest penetration accepted in a converged static state, as a fraction of the sum of the radii.
constexpr double kRejectDepth = 0.5;
}  // namespace

bool LineContact::passedThrough(int elementA, int elementB, const geometry::SegmentDistanceResult& before,
                                const geometry::SegmentDistanceResult& after) const {
  // The separation vector of the closest points reversed, with the closest points after the move inside
  // both lines: strictly inside the segments, or at a node between two elements (lines crossing node on
  // node, where every element pair has its closest points at segment ends). Only at a line's free end
  // can the separation reverse without a crossing (a line going round the end of another).
  const auto inside = [&](int element, double w) {
    if (w > 0.0 && w < 1.0) return true;
    const model::Line& l = m_model->lines()[m_model->elements()[element].line];
    return w <= 0.0 ? element > l.firstElement : element < l.firstElement + l.elementCount - 1;
  };
  if (!inside(elementA, after.s) || !inside(elementB, after.t)) return false;
  return (before.closest0 - before.closest1).dot(after.closest0 - after.closest1) < 0.0;
}

double LineContact::limitIncrement(const model::State& state, const VecX& fullIncrement) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& elements = m_model->elements();
  const int nodes = m_model->nodeCount();
  std::vector<Vec3> move(nodes);
  double largest = 0.0;
  for (int n = 0; n < nodes; ++n) {
    move[n] = fullIncrement.segment<3>(dofs.firstDof(n));
    largest = std::max(largest, move[n].norm());
  }
  if (largest <= 0.0) return 1.0;
  // Candidates: pairs whose boxes, grown by the largest node move, come within the radii.
  const std::vector<CandidatePair> pairs = pairsWithin(state, m_maxRadius + largest);
  m_candidateTime = std::numeric_limits<double>::quiet_NaN();  // the proxies changed: refresh at the next assembly
  // The pairs' distances at `state` are recomputed for every trial fraction instead of stored: a large
  // increment makes most element pairs of a many-line model candidates (4.6 million for 150 lines of 60
  // elements), and a stored 100-byte record per pair was 0.6 GB (issue 30).
  const auto& proxies = m_proxies;
  auto admissible = [&](double alpha) {
    for (const CandidatePair& cp : pairs) {
      const SegmentProxy& a = proxies[cp.first];
      const SegmentProxy& b = proxies[cp.second];
      const double radii = a.radius + b.radius;
      const geometry::SegmentDistanceResult before = geometry::segmentDistance(a.a, a.b, b.a, b.b);
      const double gap0 = before.distance - radii;
      const model::LineElement& ea = elements[a.element];
      const model::LineElement& eb = elements[b.element];
      const geometry::SegmentDistanceResult d = geometry::segmentDistance(
          state.position[ea.node1] + alpha * move[ea.node1], state.position[ea.node2] + alpha * move[ea.node2],
          state.position[eb.node1] + alpha * move[eb.node1], state.position[eb.node2] + alpha * move[eb.node2]);
      const double gap = d.distance - radii;
      if (gap < std::min(gap0, 0.0) - kClosingFraction * radii) return false;
      if (passedThrough(a.element, b.element, before, d)) return false;
    }
    return true;
  };
  double alpha = 1.0;
  for (int i = 0; i < 40 && !admissible(alpha); ++i) alpha *= 0.5;
  return alpha;
}

std::string LineContact::rejectState(const model::State& state) {
  if (m_reference.empty()) m_reference = m_model->initialState().position;
  const auto& elements = m_model->elements();
  // Pairs within reach of each other now or at the reference state: the radii plus the largest move
  // of a node since the reference (a line that passed right through another is no longer near it).
  double largestMove = 0.0;
  for (int n = 0; n < m_model->nodeCount(); ++n)
    largestMove = std::max(largestMove, (state.position[n] - m_reference[n]).norm());
  const std::vector<CandidatePair> pairs = pairsWithin(state, m_maxRadius + largestMove);
  m_candidateTime = std::numeric_limits<double>::quiet_NaN();  // the proxies changed: refresh at the next assembly
  for (const CandidatePair& cp : pairs) {
    const SegmentProxy& a = m_proxies[cp.first];
    const SegmentProxy& b = m_proxies[cp.second];
    const double radii = a.radius + b.radius;
    const geometry::SegmentDistanceResult d = geometry::segmentDistance(a.a, a.b, b.a, b.b);
    const model::LineElement& ea = elements[a.element];
    const model::LineElement& eb = elements[b.element];
    const std::string where =
        fmt::format("lines '{}' and '{}' at arc lengths {:.2f} m and {:.2f} m", m_model->lines()[a.line].name,
                    m_model->lines()[b.line].name, arcOf(a.line, a.element, d.s), arcOf(b.line, b.element, d.t));
    if (d.distance - radii < -kRejectDepth * radii)
      return fmt::format("{} overlap by {:.3f} m, more than half the sum of their radii ({:.3f} m)", where,
                         radii - d.distance, radii);
    const geometry::SegmentDistanceResult r = geometry::segmentDistance(
        m_reference[ea.node1], m_reference[ea.node2], m_reference[eb.node1], m_reference[eb.node2]);
    if (r.distance > 0.5 * radii && r.distance < radii + largestMove && passedThrough(a.element, b.element, r, d))
      return fmt::format("{} have passed through each other", where);
  }
  return {};
}

void LineContact::commitIncrement(const model::State& state) {
  m_reference = state.position;
  commitFriction();
}

void LineContact::buildExclusions() {
  const int nLines = static_cast<int>(m_model->lines().size());
  auto index = [&](const std::string& name) {
    for (int l = 0; l < nLines; ++l)
      if (m_model->lines()[l].name == name) return l;
    return -1;
  };
  for (const auto& [first, second] : m_spec.exclude) {
    const int a = index(first), b = index(second);
    if (a >= 0 && b >= 0) m_allowed[a][b] = m_allowed[b][a] = false;
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const model::ContactSpec::ExclusionZone& z : m_spec.exclusionZones) {
    const int l = index(z.line);
    const int o = z.other.empty() ? -1 : index(z.other);
    if (l < 0) continue;
    m_zones[{l, o}].push_back({z.from, z.to, -inf, inf});
  }
  if (!m_spec.excludeConnections) return;
  // Shared connection points: two line ends on the same vessel, or two held ends, closer than a few
  // radii sums (fairlead groups, a hose and a pipe at one manifold). Along each line, the length from
  // that end over which the lines are within twice their radii in the initial shape, plus one element,
  // is excluded for that pair (the lines touch there by construction, not by a clash).
  const model::State initial = m_model->initialState();
  const auto& elements = m_model->elements();
  for (int a = 0; a < nLines; ++a)
    for (int b = a + 1; b < nLines; ++b) {
      if (!m_allowed[a][b]) continue;
      const model::Line& la = m_model->lines()[a];
      const model::Line& lb = m_model->lines()[b];
      const double radii = m_radius[la.firstElement] + m_radius[lb.firstElement];
      for (int endA = 0; endA < 2; ++endA)
        for (int endB = 0; endB < 2; ++endB) {
          const model::EndSpec& sa = endA == 0 ? la.spec->endA : la.spec->endB;
          const model::EndSpec& sb = endB == 0 ? lb.spec->endA : lb.spec->endB;
          const int na = endA == 0 ? la.firstNode : la.lastNode();
          const int nb = endB == 0 ? lb.firstNode : lb.lastNode();
          const bool sameVessel = sa.kind == model::EndKind::Vessel && sb.kind == model::EndKind::Vessel && sa.vessel == sb.vessel;
          const bool held = sa.kind != model::EndKind::Free && sb.kind != model::EndKind::Free;
          if (!(sameVessel || held)) continue;
          if ((initial.position[na] - initial.position[nb]).norm() > 4.0 * radii) continue;
          // Length along each line within 2 radii of the other line.
          auto reach = [&](const model::Line& l, int end, const model::Line& other) {
            double arc = 0.0;
            for (int k = 0; k < l.elementCount; ++k) {
              const int e = end == 0 ? l.firstElement + k : l.firstElement + l.elementCount - 1 - k;
              const model::LineElement& el = elements[e];
              double best = inf;
              for (int j = 0; j < other.elementCount; ++j) {
                const model::LineElement& ob = elements[other.firstElement + j];
                best = std::min(best, geometry::segmentDistance(initial.position[el.node1], initial.position[el.node2],
                                                                initial.position[ob.node1], initial.position[ob.node2])
                                          .distance);
              }
              arc += el.restLength;
              if (best > 2.0 * radii) break;
            }
            return std::min(arc, l.length);  // includes one element beyond the last close one
          };
          const double ra = reach(la, endA, lb), rb = reach(lb, endB, la);
          const std::array<double, 4> zone{endA == 0 ? 0.0 : la.length - ra, endA == 0 ? ra : la.length,
                                           endB == 0 ? 0.0 : lb.length - rb, endB == 0 ? rb : lb.length};
          m_zones[{a, b}].push_back(zone);
        }
    }
}

bool LineContact::elementPairAllowed(int eA, int eB) const {
  if (m_zones.empty()) return true;
  const auto& elements = m_model->elements();
  const int la = elements[eA].line, lb = elements[eB].line;
  const model::Line& A = m_model->lines()[la];
  const model::Line& B = m_model->lines()[lb];
  const double a0 = A.arcLength[eA - A.firstElement], a1 = A.arcLength[eA - A.firstElement + 1];
  const double b0 = B.arcLength[eB - B.firstElement], b1 = B.arcLength[eB - B.firstElement + 1];
  auto overlaps = [](double lo, double hi, double from, double to) { return hi > from && lo < to; };
  auto test = [&](int l, int o, double x0, double x1, double y0, double y1) {
    const auto it = m_zones.find({l, o});
    if (it == m_zones.end()) return false;
    for (const auto& z : it->second)
      if (overlaps(x0, x1, z[0], z[1]) && overlaps(y0, y1, z[2], z[3])) return true;
    return false;
  };
  return !(test(la, lb, a0, a1, b0, b1) || test(lb, la, b0, b1, a0, a1) || test(la, -1, a0, a1, b0, b1) ||
           test(lb, -1, b0, b1, a0, a1));
}

}  // namespace tangle::contact

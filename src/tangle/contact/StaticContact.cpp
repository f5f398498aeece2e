/// @file StaticContact.cpp
/// Statics hooks of the contact (increment limit, crossed-state rejection, commit) and the exclusions
/// (user pairs and zones, shared connection points). docs/theory.md 9.7 and 9.10.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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
  std::vector<Vec3>& move = m_move;
  move.resize(static_cast<std::size_t>(nodes));
  double largest2 = 0.0;  // [m^2] (one root, not one per node: the same largest move, sqrt being monotonic)
  for (int n = 0; n < nodes; ++n) {
    move[n] = fullIncrement.segment<3>(dofs.firstDof(n));
    largest2 = std::max(largest2, move[n].squaredNorm());
  }
  const double largest = std::sqrt(largest2);  // [m]
  if (largest <= 0.0) return 1.0;
  if (m_distributed && m_lastDynamic) {
    // Dynamics: this step's candidates (found at its first assembly; no contact arises outside them within
    // the step), so the parts of the model away from them stay valid.
    return m_distributed->limitIncrement(state, move, m_search, m_search.candidates(), false);
  }
  // Candidates: pairs whose boxes, grown by the largest node move, come within the radii.
  const std::vector<CandidatePair> pairs = m_search.pairsWithin(state, m_search.maxRadius() + largest);
  m_candidateTime =
      std::numeric_limits<double>::quiet_NaN();  // the proxies changed: refresh at the next assembly
  // The pairs' distances at `state` are recomputed for every trial fraction instead of stored: a large
  // increment makes most element pairs of a many-line model candidates (4.6 million for 150 lines of 60
  // elements), and a stored 100-byte record per pair was 0.6 GB (issue 30).
  if (m_distributed) return m_distributed->limitIncrement(state, move, m_search, pairs, true);
  const auto& proxies = m_search.proxies();
  auto admissible = [&](double alpha) {
    for (const CandidatePair& cp : pairs) {
      const SegmentProxy& a = proxies[cp.first];
      const SegmentProxy& b = proxies[cp.second];
      const double radii = a.radius + b.radius;
      const geometry::SegmentDistanceResult before = geometry::segmentDistance(a.a, a.b, b.a, b.b);
      const double gap0 = before.distance - radii;
      const model::LineElement& ea = elements[a.element];
      const model::LineElement& eb = elements[b.element];
      const geometry::SegmentDistanceResult d =
          geometry::segmentDistance(state.position[ea.node1] + alpha * move[ea.node1],
                                    state.position[ea.node2] + alpha * move[ea.node2],
                                    state.position[eb.node1] + alpha * move[eb.node1],
                                    state.position[eb.node2] + alpha * move[eb.node2]);
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
  if (m_distributed) {
    // At `state` itself (the last assembly may have been of a trial the solver did not keep).
    m_distributed->findSamples(state, m_search, false, false, m_reference);
    if (std::string why = m_distributed->rejectSamples(); !why.empty()) return why;
    if (std::string why = m_distributed->crossedSinceCommit(state); !why.empty()) return why;
  }
  const auto& elements = m_model->elements();
  // Pairs within reach of each other now or at the reference state: the radii plus the largest move
  // of a node since the reference (a line that passed right through another is no longer near it).
  double largestMove = 0.0;
  for (int n = 0; n < m_model->nodeCount(); ++n)
    largestMove = std::max(largestMove, (state.position[n] - m_reference[n]).norm());
  const std::vector<CandidatePair> pairs = m_search.pairsWithin(state, m_search.maxRadius() + largestMove);
  m_candidateTime =
      std::numeric_limits<double>::quiet_NaN();  // the proxies changed: refresh at the next assembly
  for (const CandidatePair& cp : pairs) {
    const SegmentProxy& a = m_search.proxies()[cp.first];
    const SegmentProxy& b = m_search.proxies()[cp.second];
    const double radii = a.radius + b.radius;
    const geometry::SegmentDistanceResult d = geometry::segmentDistance(a.a, a.b, b.a, b.b);
    const model::LineElement& ea = elements[a.element];
    const model::LineElement& eb = elements[b.element];
    const std::string where = fmt::format("lines '{}' and '{}' at arc lengths {:.2f} m and {:.2f} m",
                                          m_model->lines()[a.line].name, m_model->lines()[b.line].name,
                                          arcOf(a.line, a.element, d.s), arcOf(b.line, b.element, d.t));
    if (!m_distributed && d.distance - radii < -kRejectDepth * radii)
      return fmt::format("{} overlap by {:.3f} m, more than half the sum of their radii ({:.3f} m)", where,
                         radii - d.distance, radii);
    const geometry::SegmentDistanceResult r = geometry::segmentDistance(
        m_reference[ea.node1], m_reference[ea.node2], m_reference[eb.node1], m_reference[eb.node2]);
    bool crossed = r.distance > 0.5 * radii && r.distance < radii + largestMove &&
                   passedThrough(a.element, b.element, r, d);
    if (crossed && m_distributed) {
      // On the C1 centrelines the distributed formulation measures (see rejectStep).
      const CentrelineDistance c0 = centrelineDistance(*m_model, m_reference, a.element, b.element, r.s, r.t,
                                                       false, false, true, curves());
      const CentrelineDistance c1 = centrelineDistance(*m_model, state.position, a.element, b.element, d.s,
                                                       d.t, false, false, true, curves());
      crossed = c1.sFree && c1.tFree && (c0.pointA - c0.pointB).dot(c1.pointA - c1.pointB) < 0.0;
    }
    if (crossed) return fmt::format("{} have passed through each other", where);
  }
  return {};
}

void LineContact::commitIncrement(const model::State& state) {
  if (m_distributed) {
    if (m_reference.size() != state.position.size()) m_reference = state.position;
    m_distributed->findSamples(state, m_search, false, false, m_reference);
    for (const ContactSample& x : m_distributed->samples()) m_touched = m_touched || x.lineForce > 0.0;
    m_distributed->commitSamples();
  } else {
    // The point formulation's contacts at the last assembly: the converged state's.
    for (const ContactPoint& c : m_trial) m_touched = m_touched || c.normalForce > 0.0;
  }
  m_reference = state.position;
  commitFriction();
}

}  // namespace tangle::contact

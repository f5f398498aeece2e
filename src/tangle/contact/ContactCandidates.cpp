#include "tangle/contact/ContactCandidates.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {

ContactCandidates::ContactCandidates(const model::Model& model, const model::ContactSpec& spec,
                                     std::vector<double> radius)
    : m_model(&model), m_spec(spec), m_radius(std::move(radius)) {
  const int nLines = static_cast<int>(model.lines().size());
  m_lineEnabled.resize(nLines);
  for (int l = 0; l < nLines; ++l) m_lineEnabled[l] = model.lines()[l].spec->contact;
  for (const double r : m_radius) m_maxRadius = std::max(m_maxRadius, r);
  m_everyPair = spec.pairs.empty();
  if (!m_everyPair) {
    for (const auto& [first, second] : spec.pairs) {
      const int a = model.lineIndex(first), b = model.lineIndex(second);
      if (a < 0 || b < 0) continue;  // the reader has already rejected unknown names
      m_listed.insert(std::minmax(a, b));
    }
  }
  buildExclusions();
  BroadPhaseOptions options;
  options.selfContact = spec.selfContact;
  options.selfContactSkip = 1;
  options.linePairFilter = [this](int a, int b) { return pairAllowed(a, b); };
  m_broadPhase = BroadPhase(options);
}

std::vector<std::array<int, 2>> ContactCandidates::allowedPairs() const {
  std::vector<std::array<int, 2>> pairs;
  if (!m_everyPair) {
    for (const auto& [a, b] : m_listed)
      if (pairAllowed(a, b)) pairs.push_back({a, b});
    return pairs;
  }
  const int n = static_cast<int>(m_lineEnabled.size());
  for (int a = 0; a < n; ++a) {
    if (!m_lineEnabled[static_cast<std::size_t>(a)]) continue;
    for (int b = a; b < n; ++b)
      if (pairAllowed(a, b)) pairs.push_back({a, b});
  }
  return pairs;
}

std::vector<std::array<int, 2>> ContactCandidates::nearLinePairs(const model::State& state,
                                                                 double margin) const {
  struct Box {
    Vec3 lo, hi;
    int line;
  };
  std::vector<Box> boxes;
  for (int l = 0; l < static_cast<int>(m_model->lines().size()); ++l) {
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(l)];
    if (!m_lineEnabled[static_cast<std::size_t>(l)] || line.elementCount == 0) continue;
    Vec3 lo = state.position[static_cast<std::size_t>(line.firstNode)], hi = lo;
    for (int n = line.firstNode; n <= line.lastNode(); ++n) {
      lo = lo.cwiseMin(state.position[static_cast<std::size_t>(n)]);
      hi = hi.cwiseMax(state.position[static_cast<std::size_t>(n)]);
    }
    double radius = 0.0;
    for (int e = line.firstElement; e < line.firstElement + line.elementCount; ++e)
      radius = std::max(radius, m_radius[static_cast<std::size_t>(e)]);
    const Vec3 grow = Vec3::Constant(radius + 0.5 * margin);
    boxes.push_back({lo - grow, hi + grow, l});
  }
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.lo.x() < b.lo.x(); });
  std::vector<std::array<int, 2>> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box& a = boxes[i];
    if (pairAllowed(a.line, a.line)) pairs.push_back({a.line, a.line});
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lo.x() <= a.hi.x(); ++j) {
      const Box& b = boxes[j];
      if (b.lo.y() > a.hi.y() || a.lo.y() > b.hi.y() || b.lo.z() > a.hi.z() || a.lo.z() > b.hi.z()) continue;
      if (pairAllowed(a.line, b.line)) pairs.push_back({std::min(a.line, b.line), std::max(a.line, b.line)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::size_t ContactCandidates::allowedPairCount() const {
  if (!m_everyPair) return allowedPairs().size();
  std::size_t enabled = 0;
  for (const bool e : m_lineEnabled) enabled += e ? 1 : 0;
  std::size_t count = enabled * (enabled - (enabled > 0 ? 1 : 0)) / 2 + (m_spec.selfContact ? enabled : 0);
  // Excluded pairs that the rule would otherwise allow.
  for (const auto& [a, b] : m_excluded)
    if (m_lineEnabled[static_cast<std::size_t>(a)] && m_lineEnabled[static_cast<std::size_t>(b)] &&
        (a != b || m_spec.selfContact))
      --count;
  return count;
}

std::vector<CandidatePair> ContactCandidates::pairsWithin(const model::State& state, double margin) {
  // Verlet list (skin): the broad phase runs with a margin larger than asked for, and its pairs serve later
  // calls while no segment end has moved more than half the extra margin since. A box of margin m now lies
  // inside the box of margin m + 2 delta at the earlier positions when no end has moved more than delta,
  // so the earlier list holds every pair overlapping now; the box test below keeps exactly those, in the
  // broad phase's order: the same pairs as a fresh search. (The search runs twice per step:
  // docs/performance.md.)
  // margin + 2 moved <= the list's margin, on squares (no root per segment end), every end tested without
  // a branch (the list is reused at nearly every call). A non-finite end fails the test (its squared
  // distance from the list's finite end is NaN or infinite) and goes to the broad phase, which reports it.
  // The ends are the proxies' nodes: each is tested once, on the state. While no element has parted, the
  // proxies are every element of the enabled lines and only those of the list's pairs are brought to the
  // state (all of them were, at every call: 0.7 G instructions of drilling-riser-drift's run, where the list
  // holds a few pairs of 300 segments); once one may have, they are made again at every call, and the list
  // serves while it is of the same proxies (the same elements in the same order: its pairs are indices).
  const bool complete = m_proxiesComplete && !m_model->parted().any();
  if (!complete) buildProxies(state);
  const auto sameProxies = [&] {
    if (m_proxies.size() != m_verletElements.size()) return false;
    for (std::size_t i = 0; i < m_proxies.size(); ++i)
      if (m_proxies[i].element != m_verletElements[i]) return false;
    return true;
  };
  // (Complete now and the same count: complete then too, every element of the enabled lines in order.)
  bool reuse = m_verletMargin >= 0.0 && margin <= m_verletMargin &&
               (complete ? m_proxies.size() == m_verletElements.size() : sameProxies());
  if (reuse) {
    const double allowed = 0.5 * (m_verletMargin - margin), allowed2 = allowed * allowed;
    bool within = true;
    for (std::size_t k = 0; k < m_proxyNodes.size(); ++k)
      within &=
          (state.position[static_cast<std::size_t>(m_proxyNodes[k])] - m_verletPositions[k]).squaredNorm() <=
          allowed2;
    reuse = within;
  }
  if (reuse && complete) {
    const auto& elements = m_model->elements();
    for (const CandidatePair& c : m_verletPairs)
      for (const int i : {c.first, c.second}) {
        SegmentProxy& p = m_proxies[static_cast<std::size_t>(i)];
        const model::LineElement& el = elements[static_cast<std::size_t>(p.element)];
        p.a = state.position[el.node1];
        p.b = state.position[el.node2];
      }
  }
  if (!reuse) {
    if (complete) buildProxies(state);
    BroadPhaseOptions options = m_broadPhase.options();
    // The skin (the extra margin): three times the margin asked for, so that the list serves while no
    // segment end has moved 1.5 margins. With one margin (moves of half a margin) 12 lines moored round a
    // point, whose fairleads move 0.16 m per step against a 0.7 m margin, made the list again at 158 of 610
    // calls (2 M instructions each); the list's extra pairs cost one box test per call each.
    options.margin = 4.0 * margin;
    m_verletMargin = options.margin;
    m_verletPairs.clear();
    BroadPhase(options).findPairs(m_proxies, m_verletPairs);
    if (!m_zones.empty())
      m_verletPairs.erase(std::remove_if(m_verletPairs.begin(), m_verletPairs.end(),
                                         [&](const CandidatePair& c) {
                                           return !elementPairAllowed(m_proxies[c.first].element,
                                                                      m_proxies[c.second].element);
                                         }),
                          m_verletPairs.end());
    const auto& elements = m_model->elements();
    m_proxyNodes.clear();
    for (const SegmentProxy& p : m_proxies)
      for (const int n : {elements[static_cast<std::size_t>(p.element)].node1,
                          elements[static_cast<std::size_t>(p.element)].node2})
        m_proxyNodes.push_back(n);
    std::sort(m_proxyNodes.begin(), m_proxyNodes.end());
    m_proxyNodes.erase(std::unique(m_proxyNodes.begin(), m_proxyNodes.end()), m_proxyNodes.end());
    m_verletPositions.resize(m_proxyNodes.size());
    for (std::size_t k = 0; k < m_proxyNodes.size(); ++k)
      m_verletPositions[k] = state.position[static_cast<std::size_t>(m_proxyNodes[k])];
    m_verletElements.resize(m_proxies.size());
    for (std::size_t i = 0; i < m_proxies.size(); ++i) m_verletElements[i] = m_proxies[i].element;
  }
  std::vector<CandidatePair> pairs;
  for (const CandidatePair& c : m_verletPairs)
    if (boxesOverlap(proxyBox(m_proxies[c.first], margin), proxyBox(m_proxies[c.second], margin)))
      pairs.push_back(c);
  return pairs;
}

void ContactCandidates::markLoadedNodes(std::vector<char>& mark) const {
  const auto& elements = m_model->elements();
  const auto markAround = [&](int element) {
    const int line = m_model->lineOfNode(elements[static_cast<std::size_t>(element)].node1);
    const model::Line& l = m_model->lines()[static_cast<std::size_t>(line)];
    for (int e = std::max(element - 1, l.firstElement);
         e <= std::min(element + 1, l.firstElement + l.elementCount - 1); ++e) {
      mark[static_cast<std::size_t>(elements[static_cast<std::size_t>(e)].node1)] = 1;
      mark[static_cast<std::size_t>(elements[static_cast<std::size_t>(e)].node2)] = 1;
    }
  };
  // Every contact point and line-to-line sample comes from a candidate pair (findContacts' narrow phase).
  for (const CandidatePair& cp : m_candidates) {
    markAround(m_proxies[static_cast<std::size_t>(cp.first)].element);
    markAround(m_proxies[static_cast<std::size_t>(cp.second)].element);
  }
}

void ContactCandidates::buildProxies(const model::State& state) {
  // While no element of the model has parted the proxies are every element of the enabled lines, in the
  // same order: only their ends move (the build runs twice per time step).
  if (m_proxiesComplete && !m_model->parted().any()) {
    const auto& elements = m_model->elements();
    for (SegmentProxy& p : m_proxies) {
      const model::LineElement& el = elements[static_cast<std::size_t>(p.element)];
      p.a = state.position[el.node1];
      p.b = state.position[el.node2];
    }
    return;
  }
  m_proxiesComplete = !m_model->parted().any();
  m_proxies.clear();
  for (int l = 0; l < static_cast<int>(m_model->lines().size()); ++l) {
    if (!m_lineEnabled[l]) continue;
    const model::Line& line = m_model->lines()[l];
    for (int e = line.firstElement; e < line.firstElement + line.elementCount; ++e) {
      // A parted element (lines[].failure) is no segment: its nodes are the ends of two pieces.
      if (m_model->parted().parted(static_cast<std::size_t>(e), state.time)) continue;
      const model::LineElement& el = m_model->elements()[e];
      m_proxies.push_back({l, e, state.position[el.node1], state.position[el.node2], m_radius[e]});
    }
  }
}

void ContactCandidates::buildExclusions() {
  const int nLines = static_cast<int>(m_model->lines().size());
  const auto index = [&](const std::string& name) { return m_model->lineIndex(name); };
  for (const auto& [first, second] : m_spec.exclude) {
    const int a = index(first), b = index(second);
    if (a >= 0 && b >= 0) m_excluded.insert(std::minmax(a, b));
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const model::ContactSpec::ExclusionZone& z : m_spec.exclusionZones) {
    const int l = index(z.line);
    const int o = z.other.empty() ? -1 : index(z.other);
    if (l < 0) continue;
    m_zones[{l, o}].push_back({z.from, z.to, -inf, inf});
  }
  if (!m_spec.excludeConnections) return;
  // Shared connection points: two line ends on the same vessel or at the same point, or two held ends, closer
  // than a few radii sums (fairlead groups, a hose and a pipe at one manifold, a bridle's legs at their
  // apex). Along each line, the length from that end over which the lines are within twice their radii in the
  // initial shape, plus one element, is excluded for that pair (the lines touch there by construction, not by
  // a clash).
  const model::State initial = m_model->initialState();
  const auto& elements = m_model->elements();
  // The line pairs with two held or same-vessel ends within 4 radii sums of each other: the ends sorted by x
  // and swept (a window of 4 x twice the largest radius), not every pair of lines.
  struct End {
    double x;
    int line;
  };
  std::vector<End> ends;
  for (int l = 0; l < nLines; ++l) {
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(l)];
    if (line.elementCount == 0) continue;
    for (const int node : {line.firstNode, line.lastNode()}) ends.push_back({initial.position[node].x(), l});
  }
  std::sort(ends.begin(), ends.end(), [](const End& p, const End& q) { return p.x < q.x; });
  const double window = 8.0 * m_maxRadius;
  std::set<std::pair<int, int>> near;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size() && ends[j].x - ends[i].x <= window; ++j)
      if (ends[i].line != ends[j].line) near.insert(std::minmax(ends[i].line, ends[j].line));
  for (const auto& [a, b] : near) {
    if (!pairAllowed(a, b)) continue;
    const model::Line& la = m_model->lines()[a];
    const model::Line& lb = m_model->lines()[b];
    const double radii = m_radius[la.firstElement] + m_radius[lb.firstElement];
    for (int endA = 0; endA < 2; ++endA)
      for (int endB = 0; endB < 2; ++endB) {
        const model::EndSpec& sa = endA == 0 ? la.spec->endA : la.spec->endB;
        const model::EndSpec& sb = endB == 0 ? lb.spec->endA : lb.spec->endB;
        const int na = endA == 0 ? la.firstNode : la.lastNode();
        const int nb = endB == 0 ? lb.firstNode : lb.lastNode();
        const bool sameVessel =
            sa.kind == model::EndKind::Vessel && sb.kind == model::EndKind::Vessel && sa.vessel == sb.vessel;
        const bool samePoint =
            sa.kind == model::EndKind::Point && sb.kind == model::EndKind::Point && sa.point == sb.point;
        const auto isHeld = [](model::EndKind k) {
          return k != model::EndKind::Free && k != model::EndKind::Point;
        };
        const bool held = isHeld(sa.kind) && isHeld(sb.kind);
        if (!(sameVessel || samePoint || held)) continue;
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
              best = std::min(
                  best, geometry::segmentDistance(initial.position[el.node1], initial.position[el.node2],
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

bool ContactCandidates::hasExclusions(int lineA, int lineB) const {
  // The zones elementPairAllowed looks up for an element of each line.
  return m_zones.count({lineA, lineB}) > 0 || m_zones.count({lineB, lineA}) > 0 ||
         m_zones.count({lineA, -1}) > 0 || m_zones.count({lineB, -1}) > 0;
}

bool ContactCandidates::elementPairAllowed(int eA, int eB) const {
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

/// @file ClearanceEnvelope.cpp
/// Clearance envelopes along line pairs (definition in ClearanceEnvelope.hpp).

#include "tangle/contact/ClearanceEnvelope.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>

#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/core/PointArrays.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Accuracy of the dynamic envelope relative to its height above the pair's minimum [-] (record()).
constexpr double kEnvelopeTolerance = 1e-3;
/// How far a line may move before record()'s searches make its bounding spheres again, in its mean element
/// lengths [-] (nodeClearance's `travel`).
constexpr double kSphereSlack = 0.05;
/// Margin [m] of record()'s wake-up travel (Side::wake) under the room the node's own test left.
constexpr double kWakeMargin = 1e-9;

/// Distance of x from segment j of line b less the contact radius at its closest point (`clearance`; the
/// radius along the line, RadiusProfile), and less the segment's largest contact radius (`low`: 1-Lipschitz
/// in x and in the segment's nodes) [m].
struct ChordClearance {
  double clearance = kInf, low = kInf;
};
/// x less its nearest point on the chord of segment j of line b [m], and that point's parameter s in [0, 1].
Vec3 chordOffset(const std::vector<Vec3>& position, const model::Line& b, int j, const Vec3& x, double& s) {
  const Vec3& p = position[b.firstNode + j];
  const Vec3 axis = position[b.firstNode + j + 1] - p;
  const double l2 = axis.squaredNorm();
  s = l2 > 0.0 ? std::clamp((x - p).dot(axis) / l2, 0.0, 1.0) : 0.0;
  return x - (p + s * axis);
}
ChordClearance chordClearance(const std::vector<Vec3>& position, const RadiusProfile& profile,
                              const model::Line& b, int j, const Vec3& x) {
  double s = 0.0;
  const double distance = chordOffset(position, b, j, x, s).norm();
  const int element = b.firstElement + j;
  return {distance - profile.at(element, s), distance - profile.largest(element)};
}
}  // namespace

/// Which segments of line b node i of line a is assessed against: not a parted element's (lines[].failure:
/// nothing is near it), and not across an exclusion (a shared connection: lines at one fairlead or one point
/// touch there by construction; contact.exclude, exclusion_zones), as contact skips them: allowed when either
/// element at node i may touch segment j.
struct ClearanceEnvelope::SegmentRule {
  const ContactCandidates* exclusions;
  const model::PartedElements* parted;
  const model::Line* a;
  const model::Line* b;
  double time;     ///< [s]
  bool everyPair;  ///< no exclusion between the lines: allowed() is true without map look-ups
  bool allowed(int i, int j) const {
    if (everyPair) return true;
    const int eb = b->firstElement + j;
    return (i > 0 && exclusions->elementPairAllowed(a->firstElement + i - 1, eb)) ||
           (i < a->nodeCount - 1 && exclusions->elementPairAllowed(a->firstElement + i, eb));
  }
  bool assessed(int i, int j) const {
    return !parted->parted(static_cast<std::size_t>(b->firstElement + j), time) && allowed(i, j);
  }
  /// Whether segment i of line a and segment j of line b are measured against each other (the crossing
  /// pass): neither parted, and the element pair not excluded.
  bool segmentsAssessed(int i, int j) const {
    const int ea = a->firstElement + i, eb = b->firstElement + j;
    return !parted->parted(static_cast<std::size_t>(ea), time) &&
           !parted->parted(static_cast<std::size_t>(eb), time) &&
           (everyPair || exclusions->elementPairAllowed(ea, eb));
  }
};

ClearanceEnvelope::SegmentRule ClearanceEnvelope::segmentRule(const model::State& state, int line,
                                                              int other) const {
  // (Four map look-ups per segment measured otherwise, two calls each: 5.2 M calls in drilling-riser-drift.)
  return {m_exclusions.get(),
          &m_model->parted(),
          &m_model->lines()[static_cast<std::size_t>(line)],
          &m_model->lines()[static_cast<std::size_t>(other)],
          state.time,
          !m_exclusions->hasExclusions(line, other)};
}

double ClearanceEnvelope::smoothClearance(const model::State& state, const SegmentRule& rule, int i,
                                          int bestSegment, double best) const {
  const model::Line& a = *rule.a;
  const model::Line& b = *rule.b;
  const std::vector<double>& nodeRadius = m_profile.nodeRadius();
  // The distributed contact rounds cables as well as beams (DistributedContact.hpp).
  const bool smoothCables = m_model->spec().contact.smoothCables();
  if (bestSegment < 0 || !hasSmoothCentreline(*m_model, b.firstElement + bestSegment, smoothCables))
    return best;
  // A beam's surface (with the distributed formulation, a cable's too) is around its smooth centreline, the
  // one contact measures (SmoothCentreline.hpp), which lies off the chords by up to kappa L^2 / 8: 4 cm for a
  // flexible of 10 m elements near its touchdown, read as an overlap where contact saw 1 mm. Near the
  // surface, the distance to that curve on the nearest segment and its neighbours.
  const int n = a.firstNode + i;
  const Vec3& x = state.position[n];
  const double bulgeBound = 0.25 * m_model->elements()[b.firstElement + bestSegment].restLength;
  if (!(best < nodeRadius[static_cast<std::size_t>(n)] + bulgeBound)) return best;
  const int segments = b.nodeCount - 1;
  const int element = i + 1 < a.nodeCount ? a.firstElement + i : a.firstElement + i - 1;
  const double s = i + 1 < a.nodeCount ? 0.0 : 1.0;
  double smooth = kInf;
  for (int j = std::max(bestSegment - 1, 0); j <= std::min(bestSegment + 1, segments - 1); ++j) {
    // Not a parted neighbour (search's rule): its curve runs across the gap between the broken ends.
    if (!rule.assessed(i, j)) continue;
    const Vec3 axis = state.position[b.firstNode + j + 1] - state.position[b.firstNode + j];
    const double l2 = axis.squaredNorm();
    const double t0 =
        l2 > 0.0 ? std::clamp((x - state.position[b.firstNode + j]).dot(axis) / l2, 0.0, 1.0) : 0.0;
    const CentrelineDistance c = centrelineDistance(*m_model, state.position, element, b.firstElement + j, s,
                                                    t0, true, false, smoothCables);
    smooth = std::min(smooth, c.distance - m_profile.at(b.firstElement + j, c.t));
  }
  return std::isfinite(smooth) ? smooth : best;
}

ClearanceEnvelope::ClearanceEnvelope(const model::Model& model,
                                     const std::vector<std::array<int, 2>>& contactPairs)
    : m_model(&model),
      m_profile(model),
      m_required(model.spec().clearance.required),
      m_margin(std::max(model.spec().clearance.margin.value_or(model.spec().contact.clearanceMargin),
                        model.spec().clearance.required)) {
  m_exclusions = std::make_unique<ContactCandidates>(model, model.spec().contact, m_profile.sectionRadii());
  std::set<std::array<int, 2>> pairs;
  auto add = [&](int a, int b) {
    if (a < 0 || b < 0 || a == b) return;
    pairs.insert({std::min(a, b), std::max(a, b)});
  };
  const model::ClearanceSpec& spec = model.spec().clearance;
  if (!spec.pairs.empty()) {
    for (const auto& [a, b] : spec.pairs) add(model.lineIndex(a), model.lineIndex(b));
  } else if (!contactPairs.empty()) {
    for (const auto& p : contactPairs) add(p[0], p[1]);
  } else {
    for (const model::WakeSpec& w : model.spec().wakes)
      add(model.lineIndex(w.upstream), model.lineIndex(w.downstream));
  }
  // A pair designed to touch is assessed whether or not the contact's pairs hold it (more than 2000 pairs:
  // those within the clearance margin at the static equilibrium).
  if (spec.pairs.empty())
    for (const auto& [a, b] : spec.collisionAllowed) add(model.lineIndex(a), model.lineIndex(b));
  m_pairs.assign(pairs.begin(), pairs.end());
  m_collisionAllowed.assign(m_pairs.size(), 0);
  m_impacts.assign(m_pairs.size(), Impacts{});
  for (const auto& [a, b] : spec.collisionAllowed) {
    const std::array<int, 2> key{std::min(model.lineIndex(a), model.lineIndex(b)),
                                 std::max(model.lineIndex(a), model.lineIndex(b))};
    const auto at = std::find(m_pairs.begin(), m_pairs.end(), key);
    if (at != m_pairs.end()) m_collisionAllowed[static_cast<std::size_t>(at - m_pairs.begin())] = 1;
  }
  for (const auto& p : m_pairs)
    for (int k = 0; k < 2; ++k) {
      Side s;
      s.line = p[static_cast<std::size_t>(k)];
      s.other = p[static_cast<std::size_t>(1 - k)];
      const std::size_t n =
          static_cast<std::size_t>(model.lines()[static_cast<std::size_t>(s.line)].nodeCount);
      s.staticClearance.assign(n, std::nan(""));
      s.dynamicClearance.assign(n, kInf);
      s.timeOfMinimum.assign(n, std::nan(""));
      s.knownClearance.assign(n, -kInf);
      s.knownPosition.assign(n, Vec3::Zero());
      s.knownTravel.assign(n, 0.0);
      s.otherSegments.assign(n, -kInf);
      s.wake.assign(n, -kInf);
      m_sides.push_back(std::move(s));
    }
}

std::vector<double> ClearanceEnvelope::nodeClearance(const model::State& state, int line, int other,
                                                     const std::vector<double>* onlyBelow,
                                                     const std::vector<char>* skip,
                                                     std::vector<double>* lower) const {
  return search(state, line, other, onlyBelow, skip, lower, nullptr, nullptr);
}

std::vector<double> ClearanceEnvelope::nearestClearance(const model::State& state, int line) const {
  std::vector<double> nearest, below;
  for (const Side& side : m_sides) {
    if (side.line != line) continue;
    if (nearest.empty()) {
      const std::size_t nodes =
          static_cast<std::size_t>(m_model->lines()[static_cast<std::size_t>(line)].nodeCount);
      nearest.assign(nodes, kInf);
      below.assign(nodes, m_margin);
    }
    const std::vector<double> v = search(state, line, side.other, &below, nullptr, nullptr, nullptr, nullptr);
    for (std::size_t i = 0; i < nearest.size() && i < v.size(); ++i)
      if (v[i] < nearest[i]) {
        nearest[i] = v[i];
        below[i] = std::min(below[i], v[i]);
      }
  }
  for (double& c : nearest)
    if (c > m_margin) c = kInf;
  return nearest;
}

std::vector<double> ClearanceEnvelope::search(const model::State& state, int line, int other,
                                              const std::vector<double>* onlyBelow,
                                              const std::vector<char>* skip, std::vector<double>* lower,
                                              const double* travel, const Certificate* certificate) const {
  std::vector<double>* others = certificate ? certificate->others : nullptr;
  const model::Line& a = m_model->lines()[static_cast<std::size_t>(line)];
  const model::Line& b = m_model->lines()[static_cast<std::size_t>(other)];
  const std::vector<double>& nodeRadius = m_profile.nodeRadius();
  const SegmentRule rule = segmentRule(state, line, other);
  int node = 0;  // the node of line a whose clearance is being found
  // Surface distance from x to segment j of line b (the clearance before x's own radius); `low` is lowered to
  // the distance less the segment's larger contact radius, the bound record() carries from step to step.
  const auto segmentDistance = [&](const Vec3& x, int j, double& low) {
    if (!rule.assessed(node, j)) return kInf;
    const ChordClearance c = chordClearance(state.position, m_profile, b, j, x);
    low = std::min(low, c.low);
    return c.clearance;
  };
  // With `others`, a full search's segments and their `low` (the hint's, then those of the blocks searched).
  std::vector<std::pair<int, double>>& measured = m_work.measured;
  // Bounding spheres of blocks of kBlock segments: no segment of a block is nearer to x than
  // |x - centre| - sphere radius - the block's largest contact radius, so a block whose bound is not below
  // the best distance so far is skipped. The minimum is exactly the brute-force one (same expression on the
  // segments that can attain it). The segment nearest at the previous call (the lines move little between
  // steps) gives a first best distance close to the final one, so nearly every block is skipped on one
  // squared distance. The brute-force search was the run's largest cost (docs/performance.md).
  // With `travel` (record()), the spheres are those of an earlier call, each widened by how far line b has
  // moved since (every point of it within the old sphere grown by that distance: the same bound, a little
  // looser), and made again once that passes kSphereSlack of b's mean element length: building them took
  // 0.33 G of the 2.2 G instructions of the envelope's searches in drilling-riser-drift, where they were made
  // at every step.
  constexpr int kBlock = 8;
  const int segments = b.nodeCount - 1;
  const int blocks = (segments + kBlock - 1) / kBlock;
  LineSpheres made;
  LineSpheres& spheres = travel ? m_spheres[static_cast<std::size_t>(other)] : made;
  const double now = travel ? *travel : 0.0;  // [m]
  const double slack =
      kSphereSlack * (b.arcLength.back() - b.arcLength.front()) / std::max(segments, 1);  // [m]
  const std::vector<Vec3>& centre = spheres.centre;
  // The blocks' reach widened by b's travel since they were made [m].
  std::vector<double>& reach = m_work.reach;
  // Per segment: its middle and the radius of its bounding sphere plus its larger contact radius, made for
  // a block's segments when a node first searches the block (most blocks are never searched).
  const std::vector<Vec3>& segmentMiddle = spheres.segmentMiddle;
  const std::vector<double>& segmentReach = spheres.segmentReach;
  // Made when the first node is searched (the envelope's record() skips most nodes, often all of a side).
  bool blockSpheresMade = false;
  const auto makeBlockSpheres = [&] {
    if (blockSpheresMade) return;
    blockSpheresMade = true;
    const bool stale = spheres.travel < 0.0 || now - spheres.travel > slack ||
                       spheres.centre.size() != static_cast<std::size_t>(std::max(blocks, 0));
    if (!stale) {
      reach.resize(spheres.reach.size());
      for (std::size_t k = 0; k < reach.size(); ++k) reach[k] = spheres.reach[k] + (now - spheres.travel);
      return;
    }
    spheres.travel = now;
    spheres.centre.resize(static_cast<std::size_t>(std::max(blocks, 0)));
    spheres.reach.resize(spheres.centre.size());
    spheres.segmentMiddle.resize(static_cast<std::size_t>(std::max(segments, 0)));
    spheres.segmentReach.resize(spheres.segmentMiddle.size());
    spheres.segmentTravel.assign(spheres.centre.size(), -1.0);
    for (int k = 0; k < blocks; ++k) {
      const int first = b.firstNode + k * kBlock, last = b.firstNode + std::min((k + 1) * kBlock, segments);
      Vec3 lo = state.position[first], hi = lo;
      double contact = 0.0;
      for (int n = first; n <= last; ++n) {
        lo = lo.cwiseMin(state.position[n]);
        hi = hi.cwiseMax(state.position[n]);
      }
      for (int e = first - b.firstNode; e < last - b.firstNode; ++e)
        contact = std::max(contact, m_profile.largest(b.firstElement + e));
      const Vec3 c = 0.5 * (lo + hi);
      double r2 = 0.0;  // [m^2] (one root per block)
      for (int n = first; n <= last; ++n) r2 = std::max(r2, (state.position[n] - c).squaredNorm());
      spheres.centre[static_cast<std::size_t>(k)] = c;
      spheres.reach[static_cast<std::size_t>(k)] = std::sqrt(r2) + contact;
    }
    reach = spheres.reach;
  };
  // The widening of block k's segment spheres [m], made (again) when needed.
  const auto makeSegmentSpheres = [&](int k) {
    double& madeAt = spheres.segmentTravel[static_cast<std::size_t>(k)];
    if (madeAt >= 0.0 && now - madeAt <= slack) return now - madeAt;
    madeAt = now;
    for (int j = k * kBlock; j < std::min((k + 1) * kBlock, segments); ++j) {
      const int m1 = b.firstNode + j;
      const Vec3& p = state.position[m1];
      const Vec3& q = state.position[m1 + 1];
      spheres.segmentMiddle[static_cast<std::size_t>(j)] = 0.5 * (p + q);
      spheres.segmentReach[static_cast<std::size_t>(j)] =
          0.5 * (q - p).norm() + m_profile.largest(b.firstElement + j);
    }
    return 0.0;
  };
  std::vector<int>& hint = m_hint[{line, other}];
  if (hint.size() != static_cast<std::size_t>(a.nodeCount) && segments > 0) {
    // No hint yet (the static search): each node's from its neighbour's, walked down the chords' distance
    // along line b (the nodes of a line are near one another, and so are their nearest segments), node 0's
    // from every segment. Only a first guess (the search below is exact whatever it is), but a good one: with
    // segment 0 for every node the blocks' bounds left most of line b to be measured (12 lines of 200
    // elements: 0.67 G instructions for the static envelope).
    hint.assign(static_cast<std::size_t>(a.nodeCount), 0);
    const auto chordDistance2 = [&](const Vec3& x, int j) {
      double s = 0.0;
      return chordOffset(state.position, b, j, x, s).squaredNorm();
    };
    for (int i = 0; i < a.nodeCount; ++i) {
      const Vec3& x = state.position[a.firstNode + i];
      int h = 0;
      double d = chordDistance2(x, 0);
      if (i == 0) {
        for (int j = 1; j < segments; ++j)
          if (const double dj = chordDistance2(x, j); dj < d) {
            d = dj;
            h = j;
          }
      } else {
        h = hint[static_cast<std::size_t>(i - 1)];
        d = chordDistance2(x, h);
        for (const int direction : {1, -1})
          while (h + direction >= 0 && h + direction < segments) {
            const double next = chordDistance2(x, h + direction);
            if (!(next < d)) break;
            d = next;
            h += direction;
          }
      }
      hint[static_cast<std::size_t>(i)] = h;
    }
  }
  hint.resize(static_cast<std::size_t>(a.nodeCount), 0);
  std::vector<double> out(static_cast<std::size_t>(a.nodeCount), kInf);
  std::vector<char>& skipNode = m_work.skipNode;
  if (skip)
    skipNode = *skip;
  else
    skipNode.assign(static_cast<std::size_t>(a.nodeCount), 0);
  // Nodes in blocks of kBlock (a sphere (ca, ra) around them). With a threshold, a whole block is skipped
  // first when no node within its sphere is nearer to any segment block k than its threshold allows
  // (|ca - c_k| - ra - reach_k). Then a first best distance per node from its hint segment; a segment
  // block whose bound is above the largest of them cannot improve any node of the block and is left out
  // of their searches. One bound per node block and segment block instead of one per node (the envelope
  // searches most nodes at every step while lines close: their clearance falls, a new minimum each step).
  std::array<double, kBlock> hintDistance{}, hintLow{};
  if (lower) lower->assign(static_cast<std::size_t>(a.nodeCount), -kInf);
  if (others) others->assign(static_cast<std::size_t>(a.nodeCount), -kInf);
  if (certificate) {
    // The certificate (Side::otherSegments): at the node's last search every segment of line b but the
    // nearest and its neighbours was at least L from it (their `low`); each point of them has moved since by
    // at most b's travel, and the node by |x - x0|, so they are at least L - |x - x0| - travel since now.
    // When the nearest of the three is not farther than that, it is the nearest of all: the search's result
    // from three segments (the same expressions: the same bits). Tried first, node by node, so that a block
    // of nodes all certified needs none of the spheres below (the block bounds were 0.7 of the 0.86 G
    // instructions of the envelope's searches in the first 130 s of drilling-riser-drift, the lines apart).
    // The bound for the segments outside the new nearest one's three: the old one less the moves, and those
    // of the three that now lie outside. A node it does not settle is searched in full below.
    for (int i = 0; i < a.nodeCount && segments > 0; ++i) {
      if (skipNode[static_cast<std::size_t>(i)] ||
          !(certificate->side->otherSegments[static_cast<std::size_t>(i)] > -kInf))
        continue;
      node = i;
      const int n = a.firstNode + i;
      const Vec3& x = state.position[n];
      const int h = std::clamp(hint[static_cast<std::size_t>(i)], 0, segments - 1);
      double low = kInf;
      const double best = segmentDistance(x, h, low);
      const Side& known = *certificate->side;
      const double farther = known.otherSegments[static_cast<std::size_t>(i)] -
                             (x - known.knownPosition[static_cast<std::size_t>(i)]).norm() -
                             (*travel - known.knownTravel[static_cast<std::size_t>(i)]);
      std::array<double, 3> segmentLow{kInf, low, kInf};  // h - 1, h, h + 1
      double nearBest = best, nearLow = low;
      int nearSegment = std::isfinite(best) ? h : -1;
      for (const int j : {h - 1, h + 1}) {
        if (j < 0 || j >= segments) continue;
        double segmentLowJ = kInf;
        const double d = segmentDistance(x, j, segmentLowJ);
        segmentLow[static_cast<std::size_t>(j - h + 1)] = segmentLowJ;
        nearLow = std::min(nearLow, segmentLowJ);
        if (d < nearBest) {
          nearBest = d;
          nearSegment = j;
        }
      }
      if (nearSegment < 0 || nearBest > farther) continue;
      double outside = farther;
      for (int j = h - 1; j <= h + 1; ++j)
        if (std::abs(j - nearSegment) > 1)
          outside = std::min(outside, segmentLow[static_cast<std::size_t>(j - h + 1)]);
      (*others)[static_cast<std::size_t>(i)] = outside;
      hint[static_cast<std::size_t>(i)] = nearSegment;
      const double clearance = smoothClearance(state, rule, i, nearSegment, nearBest);
      out[static_cast<std::size_t>(i)] = clearance - nodeRadius[static_cast<std::size_t>(n)];
      if (lower)
        (*lower)[static_cast<std::size_t>(i)] =
            std::min({nearLow, farther, clearance}) - nodeRadius[static_cast<std::size_t>(n)];
      skipNode[static_cast<std::size_t>(i)] = 1;  // settled: the blocks below leave it as it is
    }
  }
  // A node found not below its threshold by the spheres alone, every segment's `low` at least `bound` [m]: no
  // exact clearance (out[i] +inf), but `bound` less its radius is a lower clearance of it now, and `bound` a
  // bound of every segment but any three (the certificate's). record() keeps them as the node's fresh
  // knowledge: kept without them, the bound carried from its last search went on falling with the lines'
  // moves, and the node was tried again at every step, to be found not below again (187 000 of the 580 000
  // nodes tried in the first 130 s of drilling-riser-drift, the lines apart).
  const auto settleWithoutSearch = [&](int i, double bound) {
    if (lower)
      (*lower)[static_cast<std::size_t>(i)] = bound - nodeRadius[static_cast<std::size_t>(a.firstNode + i)];
    if (others) (*others)[static_cast<std::size_t>(i)] = bound;
  };
  std::vector<int>& near = m_work.near;
  for (int start = 0; start < a.nodeCount; start += kBlock) {
    const int stop = std::min(start + kBlock, a.nodeCount);
    // Every node of the block skipped (out +inf, lower -inf: what the searches below would leave) or
    // certified.
    if (std::all_of(skipNode.begin() + start, skipNode.begin() + stop, [](char c) { return c != 0; }))
      continue;
    makeBlockSpheres();
    Vec3 lo = state.position[a.firstNode + start], hi = lo;
    for (int i = start; i < stop; ++i) {
      lo = lo.cwiseMin(state.position[a.firstNode + i]);
      hi = hi.cwiseMax(state.position[a.firstNode + i]);
    }
    const Vec3 ca = 0.5 * (lo + hi);
    double ra2 = 0.0;  // [m^2]
    for (int i = start; i < stop; ++i)
      ra2 = std::max(ra2, (state.position[a.firstNode + i] - ca).squaredNorm());
    const double ra = std::sqrt(ra2);
    if (onlyBelow &&
        std::any_of(skipNode.begin() + start, skipNode.begin() + stop, [](char c) { return c == 0; })) {
      double threshold = -kInf;
      for (int i = start; i < stop; ++i)
        threshold = std::max(threshold, (*onlyBelow)[static_cast<std::size_t>(i)] +
                                            nodeRadius[static_cast<std::size_t>(a.firstNode + i)]);
      if (std::isfinite(threshold)) {
        bool reachable = false;
        double bound = kInf;  // the smallest of the blocks' bounds [m]
        for (int k = 0; k < blocks && !reachable; ++k) {
          const double blockBound =
              (ca - centre[static_cast<std::size_t>(k)]).norm() - ra - reach[static_cast<std::size_t>(k)];
          reachable = blockBound < threshold;
          bound = std::min(bound, blockBound);
        }
        if (!reachable) {
          for (int i = start; i < stop; ++i)
            if (!skipNode[static_cast<std::size_t>(i)]) settleWithoutSearch(i, bound);
          std::fill(skipNode.begin() + start, skipNode.begin() + stop, 1);
        }
      }
    }
    double upper = -kInf;
    for (int i = start; i < stop; ++i) {
      const Vec3& x = state.position[a.firstNode + i];
      double best = kInf, low = kInf;
      if (!skipNode[static_cast<std::size_t>(i)] && segments > 0) {
        node = i;
        best = segmentDistance(x, std::clamp(hint[static_cast<std::size_t>(i)], 0, segments - 1), low);
        upper = std::max(upper, best);
      }
      hintDistance[static_cast<std::size_t>(i - start)] = best;
      hintLow[static_cast<std::size_t>(i - start)] = low;
    }
    if (upper == -kInf && segments > 0) continue;  // every node of the block skipped
    near.clear();
    double farBound = kInf;  // the blocks left out for every node here: their smallest bound [m]
    for (int k = 0; k < blocks; ++k) {
      const double bound =
          (ca - centre[static_cast<std::size_t>(k)]).norm() - ra - reach[static_cast<std::size_t>(k)];
      if (bound <= upper)
        near.push_back(k);
      else
        farBound = std::min(farBound, bound);
    }
    for (int i = start; i < stop; ++i) {
      if (skipNode[static_cast<std::size_t>(i)])
        continue;  // skipped (out[i] +inf: not a new minimum) or settled
      node = i;
      const int n = a.firstNode + i;
      const Vec3& x = state.position[n];
      if (onlyBelow) {
        // A node whose clearance cannot fall below its envelope so far needs no exact search: the bounds of
        // the blocks that may hold its nearest segment all reach the threshold (most nodes at most steps, as
        // the envelope settles).
        const double threshold =
            (*onlyBelow)[static_cast<std::size_t>(i)] + nodeRadius[static_cast<std::size_t>(n)];
        bool reachable = !std::isfinite(threshold);
        for (std::size_t m = 0; m < near.size() && !reachable; ++m) {
          const std::size_t k = static_cast<std::size_t>(near[m]);
          const double limit = threshold + reach[k];
          reachable = limit <= 0.0 || (x - centre[k]).squaredNorm() < limit * limit;
        }
        if (!reachable) {           // out[i] stays +inf: not a new minimum
          double bound = farBound;  // [m]
          for (const int k : near)
            bound = std::min(
                bound, (x - centre[static_cast<std::size_t>(k)]).norm() - reach[static_cast<std::size_t>(k)]);
          settleWithoutSearch(i, bound);
          continue;
        }
      }
      double best = hintDistance[static_cast<std::size_t>(i - start)];
      double low = hintLow[static_cast<std::size_t>(i - start)];
      int bestSegment = segments > 0 ? std::clamp(hint[static_cast<std::size_t>(i)], 0, segments - 1) : -1;
      measured.clear();
      if (others && bestSegment >= 0 && std::isfinite(low))
        measured.emplace_back(bestSegment, low);  // the hint's
      // For `others`: the blocks and segments left out by their spheres, as the smallest squared distance to
      // a centre and the largest reach (each one's |x - c| - reach is at least the root of the one less the
      // other) [m^2, m].
      double prunedBlock2 = kInf, prunedBlockReach = 0.0, prunedSegment2 = kInf, prunedSegmentReach = 0.0;
      for (const int k : near) {
        // Skip when |x - c| - reach >= best, tested on squares (no root) while best + reach > 0.
        const double limit = best + reach[static_cast<std::size_t>(k)];
        const double blockDistance2 = (x - centre[static_cast<std::size_t>(k)]).squaredNorm();
        if (limit > 0.0 && blockDistance2 >= limit * limit) {
          prunedBlock2 = std::min(prunedBlock2, blockDistance2);
          prunedBlockReach = std::max(prunedBlockReach, reach[static_cast<std::size_t>(k)]);
          continue;
        }
        const double widening = makeSegmentSpheres(k);  // [m]
        const int end = std::min((k + 1) * kBlock, segments);
        for (int j = k * kBlock; j < end; ++j) {
          // The same test on the segment's own bounding sphere (no root, no projection) before its distance.
          const double segmentReachNow = segmentReach[static_cast<std::size_t>(j)] + widening;
          const double segmentLimit = best + segmentReachNow;
          const double segmentDistance2 = (x - segmentMiddle[static_cast<std::size_t>(j)]).squaredNorm();
          if (segmentLimit > 0.0 && segmentDistance2 >= segmentLimit * segmentLimit) {
            prunedSegment2 = std::min(prunedSegment2, segmentDistance2);
            prunedSegmentReach = std::max(prunedSegmentReach, segmentReachNow);
            continue;
          }
          double segmentLow = kInf;
          const double d = segmentDistance(x, j, segmentLow);
          low = std::min(low, segmentLow);
          if (others) measured.emplace_back(j, segmentLow);
          if (d < best) {
            best = d;
            bestSegment = j;
          }
        }
      }
      hint[static_cast<std::size_t>(i)] = std::max(bestSegment, 0);
      if (others) {
        // A lower bound of every segment's `low` but the nearest one's and its neighbours' (record()'s
        // certificate): the measured ones' own, and the left-out blocks' and segments' sphere bounds.
        double bound = std::min({farBound, std::sqrt(prunedBlock2) - prunedBlockReach,
                                 std::sqrt(prunedSegment2) - prunedSegmentReach});
        for (const auto& [j, segmentLow] : measured)
          if (std::abs(j - bestSegment) > 1) bound = std::min(bound, segmentLow);
        (*others)[static_cast<std::size_t>(i)] = bound;
      }
      best = smoothClearance(state, rule, i, bestSegment, best);
      out[static_cast<std::size_t>(i)] = best - nodeRadius[static_cast<std::size_t>(n)];
      // Every segment that could be nearer with its larger radius was measured (each pruned one's bound
      // uses that radius and is not below best, so not below low): low is exact. With the smooth
      // centreline the clearance may be below the chords' (best replaced above).
      if (lower)
        (*lower)[static_cast<std::size_t>(i)] = std::min(low, best) - nodeRadius[static_cast<std::size_t>(n)];
    }
  }
  return out;
}

void ClearanceEnvelope::recordStatic(const model::State& state) {
  m_lineBulge.clear();  // bulgeBound's, of another state
  for (Side& s : m_sides) s.staticClearance = nodeClearance(state, s.line, s.other);
  for (std::size_t p = 0; p < m_pairs.size(); ++p) {
    const double nodes = minimum(p, false).clearance;
    const double bulge = bulgeBound(state, p);
    const Crossing c = onCurves(state, p, crossingSearch(state, p, nodes + bulge, {}, false), bulge);
    if (c.segmentA >= 0 && c.clearance < nodes) recordCrossing(state, p, c, false);
  }
}

ClearanceEnvelope::Crossing ClearanceEnvelope::crossingSearch(const model::State& state, std::size_t pair,
                                                              double searched, const CrossingWindow& window,
                                                              bool inside) const {
  const Side& sideA = m_sides[2 * pair];
  const model::Line& a = m_model->lines()[static_cast<std::size_t>(sideA.line)];
  const model::Line& b = m_model->lines()[static_cast<std::size_t>(sideA.other)];
  const SegmentRule rule = segmentRule(state, sideA.line, sideA.other);
  const int segmentsA = a.nodeCount - 1, segmentsB = b.nodeCount - 1;
  Crossing best;
  best.clearance = searched;
  // Segment i of a against segment j of b (the window decides which pairs are in this search).
  const auto measure = [&](int i, int j) {
    const bool near =
        std::abs(i - window.segmentA) <= kCrossingWindow && std::abs(j - window.segmentB) <= kCrossingWindow;
    if (window.segmentA >= 0 && near != inside) return;
    const int ea = a.firstElement + i, eb = b.firstElement + j;
    const double ra = m_profile.largest(ea), rb = m_profile.largest(eb);
    const Vec3 &a0 = state.position[a.firstNode + i], &a1 = state.position[a.firstNode + i + 1];
    const Vec3 &b0 = state.position[b.firstNode + j], &b1 = state.position[b.firstNode + j + 1];
    if (!(geometry::segmentBoxGap(a0, a1, b0, b1) - ra - rb < best.clearance)) return;
    if (!rule.segmentsAssessed(i, j)) return;
    const geometry::SegmentDistanceResult d = geometry::segmentDistance(a0, a1, b0, b1);
    const double clearance = d.distance - m_profile.at(ea, d.s) - m_profile.at(eb, d.t);
    if (clearance < best.clearance) best = {clearance, i, j, d.s, d.t};
  };
  if (inside && window.segmentA >= 0) {  // the window alone
    for (int i = std::max(window.segmentA - kCrossingWindow, 0);
         i <= std::min(window.segmentA + kCrossingWindow, segmentsA - 1); ++i)
      for (int j = std::max(window.segmentB - kCrossingWindow, 0);
           j <= std::min(window.segmentB + kCrossingWindow, segmentsB - 1); ++j)
        measure(i, j);
    return best;
  }
  if (segmentsA <= 0 || segmentsB <= 0) return best;
  // Blocks of segments on each line: two blocks whose boxes are at least the best clearance so far apart hold
  // no pair of segments below it (the box gap is a lower bound of the distance of any two points in them).
  constexpr int kBlock = kSegmentBlock;
  const std::vector<SegmentBlock> blocksA = segmentBlocks(state, a, segmentsA);
  const std::vector<SegmentBlock> blocksB = segmentBlocks(state, b, segmentsB);
  for (std::size_t ka = 0; ka < blocksA.size(); ++ka)
    for (std::size_t kb = 0; kb < blocksB.size(); ++kb) {
      if (!(blocksA[ka].gap(blocksB[kb]) < best.clearance)) continue;
      const int firstA = static_cast<int>(ka) * kBlock, lastA = std::min(firstA + kBlock, segmentsA);
      const int firstB = static_cast<int>(kb) * kBlock, lastB = std::min(firstB + kBlock, segmentsB);
      for (int i = firstA; i < lastA; ++i)
        for (int j = firstB; j < lastB; ++j) measure(i, j);
    }
  return best;
}

std::vector<ClearanceEnvelope::SegmentBlock> ClearanceEnvelope::segmentBlocks(const model::State& state,
                                                                              const model::Line& line,
                                                                              int segments) const {
  std::vector<SegmentBlock> blocks(static_cast<std::size_t>((segments + kSegmentBlock - 1) / kSegmentBlock));
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const int first = static_cast<int>(k) * kSegmentBlock, last = std::min(first + kSegmentBlock, segments);
    Vec3 lo = state.position[line.firstNode + first], hi = lo;
    double radius = 0.0;
    for (int j = first; j < last; ++j) {
      lo = lo.cwiseMin(state.position[line.firstNode + j + 1]);
      hi = hi.cwiseMax(state.position[line.firstNode + j + 1]);
      radius = std::max(radius, m_profile.largest(line.firstElement + j));
    }
    blocks[k] = {lo.array() - radius, hi.array() + radius};
  }
  return blocks;
}

ClearanceEnvelope::Crossing ClearanceEnvelope::onCurves(const model::State& state, std::size_t pair,
                                                        const Crossing& c, double bulge) const {
  const Side& sideA = m_sides[2 * pair];
  const model::Line& a = m_model->lines()[static_cast<std::size_t>(sideA.line)];
  const model::Line& b = m_model->lines()[static_cast<std::size_t>(sideA.other)];
  const bool smoothCables = m_model->spec().contact.smoothCables();
  if (c.segmentA < 0 || !(c.clearance < bulge)) return c;
  const bool curveA = hasSmoothCentreline(*m_model, a.firstElement + c.segmentA, smoothCables);
  const bool curveB = hasSmoothCentreline(*m_model, b.firstElement + c.segmentB, smoothCables);
  if (!curveA && !curveB) return c;
  // The curves the contact measures (SmoothCentreline.hpp) near the nearest chords: their joint minimum on
  // the chords' elements and their neighbours (a wire kinked over a riser at a node: 42 mm into it on the
  // chords, 6 mm on the curves, the contact's). A line on chords stays there (its parameter held at the
  // chords' closest point).
  const SegmentRule rule = segmentRule(state, sideA.line, sideA.other);
  if (m_curves.empty()) m_curves = elementCurves(*m_model, smoothCables);
  // Each pair's chords first: a curve lies within its searchRangeDeviationBound of its chord, so a pair whose
  // chords' clearance less both bounds is not below the best clearance on the curves so far cannot be the
  // minimum, and needs no minimisation on the curves (nine per step while two lines touch: 0.26 G
  // instructions of drilling-riser-drift's run). The chords' nearest pair is minimised first, for that
  // bound; the rest in the same order as before (the same minimum, the same pair at a tie).
  struct Candidate {
    bool measured = false;
    geometry::SegmentDistanceResult chords;
    double lower = kInf;  ///< the clearance on the curves is at least this [m]
    double clearance = kInf;
    double s = 0.0, t = 0.0;
  };
  const int firstA = std::max(c.segmentA - 1, 0), lastA = std::min(c.segmentA + 1, a.nodeCount - 2);
  const int firstB = std::max(c.segmentB - 1, 0), lastB = std::min(c.segmentB + 1, b.nodeCount - 2);
  std::array<Candidate, 9> candidates{};
  const auto slot = [&](int i, int j) -> Candidate& {
    return candidates[static_cast<std::size_t>(3 * (i - c.segmentA + 1) + (j - c.segmentB + 1))];
  };
  const auto curveClearance = [&](int i, int j, Candidate& k) {
    const int ea = a.firstElement + i, eb = b.firstElement + j;
    // Both on curves: their least distance (nearly parallel pieces: along the valley's floor).
    const CentrelineDistance d =
        curveA && curveB ? centrelineMinimum(*m_model, state.position, ea, eb, k.chords.s, k.chords.t,
                                             smoothCables, &m_curves)
                         : centrelineDistance(*m_model, state.position, ea, eb, k.chords.s, k.chords.t,
                                              !curveA, !curveB, smoothCables, &m_curves);
    k.s = std::clamp(d.s, 0.0, 1.0);
    k.t = std::clamp(d.t, 0.0, 1.0);
    k.clearance = ownPartsDistance(d, m_curves[static_cast<std::size_t>(ea)],
                                   m_curves[static_cast<std::size_t>(eb)], state.position) -
                  m_profile.at(ea, k.s) - m_profile.at(eb, k.t);
  };
  double threshold = kInf;  // the best clearance on the curves known [m]
  for (int i = firstA; i <= lastA; ++i)
    for (int j = firstB; j <= lastB; ++j) {
      if (!rule.segmentsAssessed(i, j)) continue;
      const int ea = a.firstElement + i, eb = b.firstElement + j;
      Candidate& k = slot(i, j);
      k.measured = true;
      const Vec3 &a0 = state.position[a.firstNode + i], &a1 = state.position[a.firstNode + i + 1];
      const Vec3 &b0 = state.position[b.firstNode + j], &b1 = state.position[b.firstNode + j + 1];
      k.chords = geometry::segmentDistance(a0, a1, b0, b1);
      k.lower = k.chords.distance - m_profile.largest(ea) - m_profile.largest(eb) -
                searchRangeDeviationBound(m_curves[static_cast<std::size_t>(ea)], state.position) -
                searchRangeDeviationBound(m_curves[static_cast<std::size_t>(eb)], state.position);
      if (i == c.segmentA && j == c.segmentB) {
        curveClearance(i, j, k);
        threshold = k.clearance;
      }
    }
  Crossing best = c;
  best.clearance = kInf;
  for (int i = firstA; i <= lastA; ++i)
    for (int j = firstB; j <= lastB; ++j) {
      Candidate& k = slot(i, j);
      if (!k.measured) continue;
      const bool centre = i == c.segmentA && j == c.segmentB;
      if (!centre) {
        if (k.lower >= std::min(threshold, best.clearance)) continue;
        curveClearance(i, j, k);
      }
      if (k.clearance < best.clearance) best = {k.clearance, i, j, k.s, k.t};
    }
  if (!std::isfinite(best.clearance)) return c;
  // The other pairs of pieces: where the lines lie along each other the nearest chords need not be where the
  // curves are nearest (a rope wrapped round a bollard on 0.1 m elements: 0.5 mm less overlap from the
  // neighbours alone, ClearanceEnvelopeTest). Blocks whose boxes are farther apart than the best less both
  // lines' bulge (`bulge`, each piece within it of its chord on [0, 1]) hold none below it; a pair whose
  // chords less both pieces' bounds are not below it is not either.
  const int segmentsA = a.nodeCount - 1, segmentsB = b.nodeCount - 1;
  const std::vector<SegmentBlock> blocksA = segmentBlocks(state, a, segmentsA);
  const std::vector<SegmentBlock> blocksB = segmentBlocks(state, b, segmentsB);
  for (std::size_t ka = 0; ka < blocksA.size(); ++ka)
    for (std::size_t kb = 0; kb < blocksB.size(); ++kb) {
      if (!(blocksA[ka].gap(blocksB[kb]) - bulge < best.clearance)) continue;
      const int iEnd = std::min(static_cast<int>(ka + 1) * kSegmentBlock, segmentsA);
      const int jEnd = std::min(static_cast<int>(kb + 1) * kSegmentBlock, segmentsB);
      for (int i = static_cast<int>(ka) * kSegmentBlock; i < iEnd; ++i)
        for (int j = static_cast<int>(kb) * kSegmentBlock; j < jEnd; ++j) {
          if (i >= firstA && i <= lastA && j >= firstB && j <= lastB) continue;  // measured above
          if (!rule.segmentsAssessed(i, j)) continue;
          const int ea = a.firstElement + i, eb = b.firstElement + j;
          Candidate k;
          k.chords =
              geometry::segmentDistance(state.position[a.firstNode + i], state.position[a.firstNode + i + 1],
                                        state.position[b.firstNode + j], state.position[b.firstNode + j + 1]);
          const double lower = k.chords.distance - m_profile.largest(ea) - m_profile.largest(eb) -
                               chordDeviationBound(m_curves[static_cast<std::size_t>(ea)], state.position) -
                               chordDeviationBound(m_curves[static_cast<std::size_t>(eb)], state.position);
          if (!(lower < best.clearance)) continue;
          curveClearance(i, j, k);
          if (k.clearance < best.clearance) best = {k.clearance, i, j, k.s, k.t};
        }
    }
  return best;
}

double ClearanceEnvelope::bulgeBound(const model::State& state, std::size_t pair) const {
  // How far a curve lies off its chord at most (chordDeviationBound: from the element's nodes and its
  // neighbours'), the largest of each line's elements measured on one, both lines together.
  const bool smoothCables = m_model->spec().contact.smoothCables();
  if (m_curves.empty()) m_curves = elementCurves(*m_model, smoothCables);
  // Each line's largest once per state (m_lineBulge, cleared by record and recordStatic): a line is in many
  // pairs (12 lines, 66 pairs: 0.15 G instructions in 30 s when made per pair).
  if (m_lineBulge.size() != m_model->lines().size())
    m_lineBulge.assign(m_model->lines().size(), std::nan(""));
  double bound = 0.0;
  for (const int l : {m_sides[2 * pair].line, m_sides[2 * pair].other}) {
    double& largest = m_lineBulge[static_cast<std::size_t>(l)];
    if (std::isnan(largest)) {
      const model::Line& line = m_model->lines()[static_cast<std::size_t>(l)];
      largest = 0.0;
      for (int e = line.firstElement; e < line.firstElement + line.elementCount; ++e)
        if (hasSmoothCentreline(*m_model, e, smoothCables))
          largest =
              std::max(largest, chordDeviationBound(m_curves[static_cast<std::size_t>(e)], state.position));
    }
    bound += largest;
  }
  return bound;
}

void ClearanceEnvelope::recordCrossing(const model::State& state, std::size_t pair, const Crossing& c,
                                       bool dynamic) {
  // The node of each line nearest the closest points.
  Side& sideA = m_sides[2 * pair];
  Side& sideB = m_sides[2 * pair + 1];
  const std::size_t nodeA = static_cast<std::size_t>(c.segmentA + (c.s > 0.5 ? 1 : 0));
  const std::size_t nodeB = static_cast<std::size_t>(c.segmentB + (c.t > 0.5 ? 1 : 0));
  for (const auto& [side, node] : {std::pair<Side*, std::size_t>{&sideA, nodeA}, {&sideB, nodeB}}) {
    if (!dynamic) {
      side->staticClearance[node] = std::min(side->staticClearance[node], c.clearance);
    } else if (c.clearance < side->dynamicClearance[node]) {
      side->dynamicClearance[node] = c.clearance;
      side->timeOfMinimum[node] = state.time;
    }
  }
  if (dynamic) m_pairMinimum[pair] = std::min(m_pairMinimum[pair], c.clearance);
}

void ClearanceEnvelope::record(const model::State& state) {
  m_dynamic = true;
  m_lineBulge.clear();  // bulgeBound's, of another state
  // How far each line has moved since the last call (an upper bound of any of its points' displacement).
  const auto& lines = m_model->lines();
  if (m_lastPosition.empty()) {
    m_travel.assign(lines.size(), 0.0);
  } else {
    for (std::size_t l = 0; l < lines.size(); ++l) {
      double largest = 0.0;
      for (int n = lines[l].firstNode; n < lines[l].firstNode + lines[l].nodeCount; ++n)
        largest = std::max(largest, (state.position[n] - m_lastPosition[n]).squaredNorm());
      m_travel[l] += std::sqrt(largest);
    }
  }
  core::copyPoints(state.position, m_lastPosition);
  std::vector<char>& skip = m_work.skip;
  std::vector<double>& lower = m_work.lower;
  std::vector<double>& others = m_work.others;
  // Each pair's smallest dynamic clearance so far, over both its sides [m] (kept as the envelope falls).
  if (m_pairMinimum.size() != m_pairs.size()) m_pairMinimum.assign(m_pairs.size(), kInf);
  const std::vector<double> pairMinimum = m_pairMinimum;
  for (std::size_t side = 0; side < m_sides.size(); ++side) {
    Side& s = m_sides[side];
    // The clearance of a node to a polyline is at least its lower clearance (each segment with its larger
    // contact radius: nodeClearance's `lower`), which is 1-Lipschitz in the node's position and in the
    // polyline's nodes (each point of a segment moves at most as far as its farther node). So since the
    // node's last search, where its lower clearance was c0, it is at least c0 - |x - x0| - (travel of the
    // other line since); a node whose bound is not below its envelope cannot set a new minimum and needs no
    // search (most nodes at most steps: the lines move millimetres per step). (With the clearance itself as
    // c0 less the largest radius jump of the other line, a 4 m LMRP at the end of a 0.46 m riser made the
    // bound 1.8 m too low for every node: all were searched at every step.)
    // While lines close, every node's clearance falls and would set a new minimum at every step (nodes
    // hundreds of metres away searched at every step: 10 % of a drifting riser's run). So a node is
    // searched again only once its bound is below its envelope e by more than kEnvelopeTolerance (e - P),
    // P the pair's smallest envelope so far: the envelope is never below the exact minimum, and above it by
    // at most that. The pair's minimum itself is exact: the node where it occurs has no tolerance at that
    // time, as a node above P by less than its tolerance would be above by less than itself.
    // A node let off by that test, with room to spare, is let off without it at the steps that follow while
    // the two lines' travel since (each point of line a has moved at most a's, and the bound fell at most by
    // b's) is within the spare room: Side::wake (the test, 40 instructions per node and step, was a quarter
    // of the envelope's time while the lines are apart).
    const model::Line& a = lines[static_cast<std::size_t>(s.line)];
    const double travel = m_travel[static_cast<std::size_t>(s.other)];
    const double bothTravel = m_travel[static_cast<std::size_t>(s.line)] + travel;  // [m]
    skip.assign(static_cast<std::size_t>(a.nodeCount), 0);
    std::vector<int>& tried = m_work.tried;  // the nodes not let off (search() may find their clearance)
    tried.clear();
    for (std::size_t i = 0; i < skip.size(); ++i) {
      if (bothTravel <= s.wake[i]) {
        skip[i] = 1;
        continue;
      }
      const Vec3& x = state.position[a.firstNode + static_cast<int>(i)];
      const double envelope = std::min(s.dynamicClearance[i], m_margin);
      const double above = envelope - std::min(pairMinimum[side / 2], m_margin);
      const double tolerance = std::isfinite(above) ? kEnvelopeTolerance * std::max(above, 0.0) : 0.0;
      // Skipped when the bound now, c0 - |x - x0| - travel since, is not below envelope - tolerance: when
      // |x - x0| <= room, tested on squares (no root per node). c0 = +inf: no segment may touch the node.
      const double room = s.knownClearance[i] - (travel - s.knownTravel[i]) - (envelope - tolerance);
      const double moved2 = (x - s.knownPosition[i]).squaredNorm();  // [m^2]
      skip[i] = s.knownClearance[i] == kInf || (room >= 0.0 && moved2 <= room * room) ? 1 : 0;
      if (skip[i])  // the room to spare, less a margin for the round-off of the two tests (1e-13 m at 1e3 m)
        s.wake[i] = bothTravel + (room - std::sqrt(moved2)) - kWakeMargin;
      else
        tried.push_back(static_cast<int>(i));
    }
    // Nothing to search: nothing changes (a sixth of drift-into-spread's 326 000 side calls).
    if (tried.empty()) continue;
    const auto newValue = [&](std::size_t i, double clearance) {
      if (clearance < s.dynamicClearance[i] && clearance <= m_margin) {
        s.dynamicClearance[i] = clearance;
        s.timeOfMinimum[i] = state.time;
        m_pairMinimum[side / 2] = std::min(m_pairMinimum[side / 2], clearance);
      }
    };
    const Certificate certificate{&s, &others};
    std::vector<double>& below = m_work.below;  // what a node's clearance must be below to be a new minimum
    below.resize(s.dynamicClearance.size());
    for (std::size_t i = 0; i < below.size(); ++i) below[i] = std::min(s.dynamicClearance[i], m_margin);
    const std::vector<double> c =
        search(state, s.line, s.other, &below, &skip, &lower, &travel, &certificate);
    for (const int node : tried) {  // the others: +inf and -inf, nothing to keep
      const std::size_t i = static_cast<std::size_t>(node);
      if (std::isfinite(lower[i])) {  // searched (its exact clearance), or settled by the spheres
        s.knownClearance[i] = lower[i];
        s.knownPosition[i] = state.position[a.firstNode + static_cast<int>(i)];
        s.knownTravel[i] = travel;
        s.otherSegments[i] = others[i];
        s.wake[i] = -kInf;  // the test above at the next step
      }
      newValue(i, c[i]);
    }
  }
  // The crossing pass (file comment), where the pair's chords may have come nearer than its minimum: its
  // last bound less how far both lines have moved since.
  // A whole search looks up to a slack above the minimum (a tenth of it, plus the two lines' largest contact
  // radii), and apart from the window of kCrossingWindow segments either side of the nearest pair, so that
  // while the lines have moved less than those bounds' room since, the pair is let off, or only its window
  // is searched (a whole search at every step, up to the minimum alone, was 3.6 % of drift-into-spread's run:
  // two lines in contact are at their minimum at every step).
  if (m_crossings.size() != m_pairs.size()) {
    m_crossings.assign(m_pairs.size(), CrossingBounds{});
    for (std::size_t p = 0; p < m_pairs.size(); ++p) {
      for (const int l : {m_sides[2 * p].line, m_sides[2 * p].other})
        m_crossings[p].slack += m_model->lines()[static_cast<std::size_t>(l)].contactRadius;
    }
  }
  for (std::size_t p = 0; p < m_pairs.size(); ++p) {
    CrossingBounds& k = m_crossings[p];
    const double travel = m_travel[static_cast<std::size_t>(m_sides[2 * p].line)] +
                          m_travel[static_cast<std::size_t>(m_sides[2 * p].other)];
    // The chords' bounds less how far the lines have moved since, and less how far their curves may lie
    // off them [m].
    const double room = travel - k.travel + k.bulge;
    const double minimum = std::min(m_pairMinimum[p], m_margin);
    if (k.bound - room >= minimum) continue;
    if (k.window.segmentA >= 0 && k.outside - room >= minimum) {
      const Crossing c =
          onCurves(state, p, crossingSearch(state, p, minimum + k.bulge, k.window, true), k.bulge);
      if (c.segmentA >= 0 && c.clearance < minimum) recordCrossing(state, p, c, true);
      continue;
    }
    k.bulge = bulgeBound(state, p);
    const double searched = minimum + 0.1 * std::max(minimum, 0.0) + k.slack + k.bulge;
    const Crossing nearest = crossingSearch(state, p, searched, {}, false);
    k.travel = travel;
    k.bound = nearest.clearance;
    k.window = {nearest.segmentA, nearest.segmentB};
    k.outside =
        nearest.segmentA >= 0 ? crossingSearch(state, p, searched, k.window, false).clearance : searched;
    const Crossing c = onCurves(state, p, nearest, k.bulge);
    if (c.segmentA >= 0 && c.clearance < minimum) recordCrossing(state, p, c, true);
  }
}

ClearanceEnvelope::Minimum ClearanceEnvelope::minimum(std::size_t pair, bool dynamic) const {
  // The first smallest node of line 1, then of line 2 (ties go to line 1); node 0 of line 1 to start.
  const Side& first = m_sides[2 * pair];
  Minimum m;
  m.clearance = (dynamic ? first.dynamicClearance : first.staticClearance)[0];
  m.line = first.line;
  m.arcLength = m_model->lines()[static_cast<std::size_t>(first.line)].arcLength[0];
  m.time = dynamic ? first.timeOfMinimum[0] : std::nan("");
  for (const Side* side : {&first, &m_sides[2 * pair + 1]}) {
    const std::vector<double>& c = dynamic ? side->dynamicClearance : side->staticClearance;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i] < m.clearance) {
        m.clearance = c[i];
        m.line = side->line;
        m.arcLength = m_model->lines()[static_cast<std::size_t>(side->line)].arcLength[i];
        m.time = dynamic ? side->timeOfMinimum[i] : std::nan("");
      }
  }
  return m;
}

void ClearanceEnvelope::write(const std::filesystem::path& dir) const {
  const std::filesystem::path out = dir / "clearance";
  std::filesystem::create_directories(out);
  const auto& lines = m_model->lines();
  {
    core::OutputFile file(out / "envelope.csv");
    file.write("line,other_line,arc_length_m,static_clearance_m,min_clearance_m,time_of_min_s\n");
    // One buffer of rows by compiled formats (a row per node and side: 26 500 for 12 lines and 66 pairs,
    // 0.11 G instructions as a string and a stream write per row).
    std::string rows;
    for (const Side& s : m_sides) {
      const model::Line& l = lines[static_cast<std::size_t>(s.line)];
      for (std::size_t i = 0; i < s.staticClearance.size(); ++i)
        fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{},{},{:.4f},{:.6e},{:.6e},{:.6f}\n"), l.name,
                       lines[static_cast<std::size_t>(s.other)].name, l.arcLength[i], s.staticClearance[i],
                       m_dynamic ? s.dynamicClearance[i] : std::nan(""), s.timeOfMinimum[i]);
      file.writeRows(rows);
    }
    file.writeRows(rows, true);
    file.close();
  }
  core::OutputFile summary(out / "summary.json");
  core::JsonWriter j(summary.stream());
  j.beginObject();
  j.field(
      "standard",
      "DNV-RP-F203 (2009) sec. 4: no collision (minimum clearance >= required), or collision allowed (the "
      "largest impact energy <= allowed_impact_energy)");
  // Pairs designed to touch (clearance.collision_allowed): assessed by their impacts instead ("criterion").
  if (m_model->spec().clearance.allowedImpactEnergy)
    j.field("allowed_impact_energy_J", *m_model->spec().clearance.allowedImpactEnergy);
  j.field("required_clearance_m", m_required);
  // The dynamic envelope is kept up to this clearance (clearance.margin or contact.clearance_margin); a node
  // or pair never within it has min_clearance_m null (+inf in envelope.csv).
  j.field("clearance_margin_m", m_margin);
  j.key("pairs");
  j.beginArray();
  for (std::size_t p = 0; p < m_pairs.size(); ++p) {
    const Side& a = m_sides[2 * p];
    const Side& b = m_sides[2 * p + 1];
    j.beginObject();
    j.field("line_1", lines[static_cast<std::size_t>(a.line)].name);
    j.field("line_2", lines[static_cast<std::size_t>(b.line)].name);
    const Minimum st = minimum(p, false);
    j.key("static");
    j.beginObject();
    j.field("min_clearance_m", st.clearance);
    j.field("line", lines[static_cast<std::size_t>(st.line)].name);
    j.field("arc_length_m", st.arcLength);
    j.endObject();
    double overall = st.clearance;
    if (m_dynamic) {
      const Minimum dy = minimum(p, true);
      overall = std::min(overall, dy.clearance);
      j.key("dynamic");
      j.beginObject();
      j.field("min_clearance_m", dy.clearance);
      j.field("line", lines[static_cast<std::size_t>(dy.line)].name);
      j.field("arc_length_m", dy.arcLength);
      j.field("time_s", dy.time);
      j.endObject();
    }
    j.field("min_clearance_m", overall);
    j.field("criterion", m_collisionAllowed[p] ? "collision allowed" : "no collision");
    if (m_collisionAllowed[p]) {
      j.field("impacts", m_impacts[p].count);
      j.field("max_impact_energy_J", m_impacts[p].maxEnergy);
    }
    if (const std::optional<bool> pass = passes(p, overall))
      j.field("pass", *pass);
    else
      j.field("pass", std::nan(""));  // null: not assessed
    j.endObject();
  }
  j.endArray();
  j.endObject();
  summary.close();
}

void ClearanceEnvelope::assessImpacts(const std::vector<ContactEvent>& events) {
  m_impacts.assign(m_pairs.size(), Impacts{});
  for (const ContactEvent& e : events) {
    if (!e.impact) continue;
    const std::array<int, 2> key{std::min(e.lineA, e.lineB), std::max(e.lineA, e.lineB)};
    const auto at = std::find(m_pairs.begin(), m_pairs.end(), key);
    if (at == m_pairs.end() || !m_collisionAllowed[static_cast<std::size_t>(at - m_pairs.begin())]) continue;
    Impacts& i = m_impacts[static_cast<std::size_t>(at - m_pairs.begin())];
    ++i.count;
    i.maxEnergy = std::max(i.maxEnergy, e.impactEnergy);
  }
}

std::optional<bool> ClearanceEnvelope::passes(std::size_t pair, double overall) const {
  if (!m_collisionAllowed[pair]) return overall >= m_required;
  const std::optional<double> allowed = m_model->spec().clearance.allowedImpactEnergy;
  if (!allowed) return std::nullopt;
  return m_impacts[pair].maxEnergy <= *allowed;
}

std::string ClearanceEnvelope::verdict(std::size_t pair, double overall) const {
  const std::optional<bool> pass = passes(pair, overall);
  if (!m_collisionAllowed[pair]) return *pass ? ": PASS" : ": FAIL";
  const Impacts& i = m_impacts[pair];
  std::string s = fmt::format(": collision allowed, {} impact(s)", i.count);
  if (i.count > 0) s += fmt::format(", largest energy {:.4g} J", i.maxEnergy);
  if (!pass) return s + " (not assessed: no clearance.allowed_impact_energy)";
  return s + fmt::format(" (allowed {:.4g} J): {}", *m_model->spec().clearance.allowedImpactEnergy,
                         *pass ? "PASS" : "FAIL");
}

std::string ClearanceEnvelope::terminalSummary() const {
  const auto& lines = m_model->lines();
  std::string s =
      m_required > 0.0
          ? fmt::format("clearance (DNV-RP-F203 no-collision check, required {:.3g} m):\n", m_required)
          : std::string("clearance (no clearance.required given: checked against contact, 0 m):\n");
  // Every pair of a small model; of a large one (hundreds of pairs) the kTerminalPairs with the smallest
  // clearance and a count of the rest (clearance/summary.json has them all).
  constexpr std::size_t kTerminalPairs = 20;
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t p = 0; p < m_pairs.size(); ++p) {
    const double st = minimum(p, false).clearance;
    order.emplace_back(m_dynamic ? std::min(st, minimum(p, true).clearance) : st, p);
  }
  const bool all = order.size() <= kTerminalPairs;
  if (!all) std::partial_sort(order.begin(), order.begin() + kTerminalPairs, order.end());
  std::size_t failed = 0;
  for (const auto& [overall, p] : order) failed += passes(p, overall) == std::optional<bool>(false) ? 1 : 0;
  for (std::size_t k = 0; k < (all ? order.size() : kTerminalPairs); ++k) {
    const auto [overall, p] = order[k];
    const Minimum st = minimum(p, false);
    s += fmt::format("  {} / {}: static min {:.3f} m",
                     lines[static_cast<std::size_t>(m_sides[2 * p].line)].name,
                     lines[static_cast<std::size_t>(m_sides[2 * p + 1].line)].name, st.clearance);
    if (m_dynamic) {
      const Minimum dy = minimum(p, true);
      if (std::isfinite(dy.clearance))
        s += fmt::format(", dynamic min (every step) {:.3f} m at t = {:.2f} s, {:.1f} m along '{}'",
                         dy.clearance, dy.time, dy.arcLength, lines[static_cast<std::size_t>(dy.line)].name);
      else
        s += fmt::format(", dynamically never within the {:.3g} m clearance margin", m_margin);
    }
    s += verdict(p, overall) + "\n";
  }
  if (!all)
    s += fmt::format(
        "  ... the {} pairs above have the smallest clearances of {}; {} of them all FAIL "
        "(clearance/summary.json lists every pair)\n",
        kTerminalPairs, order.size(), failed);
  return s;
}

}  // namespace tangle::contact

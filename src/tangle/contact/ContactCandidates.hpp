#pragma once
/// @file ContactCandidates.hpp
/// Which element pairs may touch, and which of them are close: the rules (contact.pairs, self-contact,
/// exclusions, exclusion zones, shared connection points) and the broad phase with its Verlet list. The
/// contact model (LineContact) asks it for candidate pairs and runs the narrow phase on them.

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "tangle/contact/BroadPhase.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {

/// The candidate element pairs of the contact search.
class ContactCandidates {
 public:
  /// @param radius contact radius of every element of the model [m]
  ContactCandidates(const model::Model& model, const model::ContactSpec& spec, std::vector<double> radius);
  ContactCandidates(const ContactCandidates&) = delete;  // the broad phase's filter points at this object
  ContactCandidates& operator=(const ContactCandidates&) = delete;

  /// Whether two lines may touch: by the rule (every pair of lines that take part) or the listed pairs,
  /// less the excluded ones. No table of line pairs is kept: a model of 20 000 lines would need 2e8 entries.
  bool pairAllowed(int lineA, int lineB) const {
    const std::pair<int, int> key = std::minmax(lineA, lineB);
    if (!m_excluded.empty() && m_excluded.contains(key)) return false;
    if (!m_everyPair) return m_listed.contains(key);
    return m_lineEnabled[static_cast<std::size_t>(lineA)] && m_lineEnabled[static_cast<std::size_t>(lineB)] &&
           (lineA != lineB || m_spec.selfContact);
  }
  /// Every pair of lines that may touch, as (a, b) with a <= b (a == b: self-contact), in index order
  /// (as many as allowedPairCount(): quadratic in the lines with every pair allowed).
  std::vector<std::array<int, 2>> allowedPairs() const;
  /// How many pairs allowedPairs() would give, without forming them.
  std::size_t allowedPairCount() const;
  /// The allowed pairs of contact-enabled lines (a <= b, index order) whose bounding boxes at `state`
  /// (their nodes, grown by their largest contact radius) come within `margin` [m] of each other: a sweep
  /// over the boxes sorted by x, not a test of every pair. No pair left out has a clearance below `margin`.
  std::vector<std::array<int, 2>> nearLinePairs(const model::State& state, double margin) const;
  /// Whether element eA (of its line) and eB may touch (not excluded by a pair, a zone or a shared
  /// connection point).
  bool elementPairAllowed(int eA, int eB) const;
  /// False when every element pair of lines a and b may touch (no zone or shared connection excludes any of
  /// them): callers skip elementPairAllowed then.
  bool hasExclusions(int lineA, int lineB) const;

  /// The element pairs whose boxes at `state` come within `margin` [m] of each other and may touch (exclusion
  /// zones applied). The proxies of those pairs (and of every pair of the Verlet list) are then at `state`;
  /// the others' positions may be older (their element, line and radius are always valid).
  std::vector<CandidatePair> pairsWithin(const model::State& state, double margin);
  /// candidates() = pairsWithin(state, margin).
  void refresh(const model::State& state, double margin) { m_candidates = pairsWithin(state, margin); }
  /// The candidate pairs of the last refresh (indices into proxies()).
  const std::vector<CandidatePair>& candidates() const { return m_candidates; }
  /// The segments of the contact-enabled lines (positions: see pairsWithin).
  const std::vector<SegmentProxy>& proxies() const { return m_proxies; }
  /// Largest contact radius of the model [m].
  double maxRadius() const { return m_maxRadius; }
  /// Sets mark[node] = 1 for the nodes of every candidate element and of its neighbours along its line
  /// (the smooth centreline's stencils reach one node further).
  void markLoadedNodes(std::vector<char>& mark) const;

 private:
  void buildExclusions();
  void buildProxies(const model::State& state);

  const model::Model* m_model;
  model::ContactSpec m_spec;
  std::vector<bool> m_lineEnabled;
  bool m_everyPair = true;                   // contact.pairs empty: every pair of enabled lines
  std::set<std::pair<int, int>> m_listed;    // contact.pairs (a <= b)
  std::set<std::pair<int, int>> m_excluded;  // contact.exclude (a <= b)
  std::vector<double> m_radius;              // contact radius per element [m]
  double m_maxRadius = 0.0;                  // largest of m_radius [m]
  std::map<std::pair<int, int>, std::vector<std::array<double, 4>>>
      m_zones;  // (lineA, lineB) -> zones on A [from, to] and B [from, to]
  BroadPhase m_broadPhase;
  std::vector<SegmentProxy> m_proxies;
  bool m_proxiesComplete = false;  // m_proxies holds every element of the enabled lines (none parted)
  std::vector<CandidatePair> m_candidates;
  /// Verlet list of pairsWithin: the pairs within m_verletMargin [m] (< 0: none made) of the proxies, as
  /// they were when it was made; the proxies' elements then, their nodes (ascending, each once) and those
  /// nodes' positions then [m] (the list's test is on them).
  std::vector<CandidatePair> m_verletPairs;
  double m_verletMargin = -1.0;
  std::vector<int> m_verletElements;
  std::vector<int> m_proxyNodes;
  std::vector<Vec3> m_verletPositions;
};

}  // namespace tangle::contact

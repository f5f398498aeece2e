#pragma once
/// @file ClearanceEnvelope.hpp
/// The no-collision check of DNV-RP-F203 ("Riser interference", 2009, sec. 4): for every pair of lines
/// assessed, the smallest surface-to-surface clearance at every node of each line to the other line,
/// in the static equilibrium and over every accepted step of the dynamics (with the time it occurs), and
/// a pass / fail against the required clearance of the model file (clearance.required).
///
/// Clearance at node i of line A to line B: min over the elements of B that may touch an element at node i
/// (the contact's rules: not across a shared connection, an `exclude` pair or an exclusion zone; a node whose
/// elements may touch none has no clearance, +inf) of the distance from x_i to the
/// element's chord, minus the contact radii (the radius along each line, RadiusProfile: node i's own, the
/// mean of the two sections' at a change of section, and the element's at the closest point); negative when
/// the surfaces overlap. Where B is a beam and x_i is within a
/// quarter element of its surface, the distance is taken to B's smooth centreline instead (on the
/// nearest element and its neighbours), the curve contact measures (SmoothCentreline.hpp).
/// Crossings: two lines that cross between nodes of both (a chain across a pipeline, risers crossing at an
/// angle) are nearest at points no node is near (two 0.3 m pipes crossing 0.3 m apart mid-element on 11 m
/// elements: 5.3 m from the nodes). So each pair's chords are also measured against each other (segment to
/// segment, less each element's contact radius at the closest points: the crossing pass), at the static state
/// and at every step where the pair may be nearer than its minimum so far, and a crossing below that minimum
/// is given to the node of each line nearest it: the pair's minimum (and the pass / fail) is then that of the
/// chords everywhere, and the envelope along each line is the clearance of the node or of the half elements
/// beside it (on chords there: a beam's curve between nodes may lie a chord deviation closer). Written to
/// clearance/envelope.csv and clearance/summary.json; a few lines for the terminal.
/// The dynamic envelope is kept up to the clearance margin (clearance.margin, else contact.clearance_margin,
/// 50 m by default, as the clash report's clearances; never below clearance.required): a node whose clearance
/// stays above it all the run has +inf there (and a pair whose every node does, a dynamic minimum of +inf:
/// "never within the margin"). A no-collision check asks for clearances of metres; the exact values hundreds
/// of metres out were most of the envelope's cost (12 lines moored round a point with contact on all 66
/// pairs: 10.6 of its 11.9 million node searches were of nodes 30 m or more from the other line).
/// Pairs designed to touch (clearance.collision_allowed: DNV-RP-F203 sec. 4's "collision allowed") are
/// measured alike but assessed by their impacts (assessImpacts: the contact's events): a pass when none
/// carries more than clearance.allowed_impact_energy, not assessed when that is not given.

#include <array>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tangle/contact/ContactCandidates.hpp"
#include "tangle/contact/ContactEvents.hpp"
#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::contact {

class ClearanceEnvelope {
 public:
  /// Pairs: clearance.pairs of the model; else the pairs allowed to touch when there is a contact block
  /// (`contactPairs`); else the line pairs of wake_interference (either order); else none.
  ClearanceEnvelope(const model::Model& model, const std::vector<std::array<int, 2>>& contactPairs);

  bool empty() const { return m_pairs.empty(); }
  /// The static clearance at every node (call once, at the static equilibrium).
  void recordStatic(const model::State& state);
  /// Updates the dynamic envelope with this state (call every accepted step). Each pair's minimum (value,
  /// place and time) is exact when within the clearance margin M; a node's dynamic minimum e is +inf when its
  /// exact one is above M, else never below the exact one and above it by at most 0.1 % of min(e, M) -
  /// min(P, M), P the pair's minimum (a node is searched again only when it may have closed by more than
  /// that: ClearanceEnvelope.cpp).
  void record(const model::State& state);
  /// Takes the impacts of the collision-allowed pairs from the contact's events of the run (call before
  /// write and terminalSummary; without it such a pair has none).
  void assessImpacts(const std::vector<ContactEvent>& events);
  /// Writes clearance/envelope.csv and clearance/summary.json.
  void write(const std::filesystem::path& dir) const;
  std::string terminalSummary() const;

  /// Clearance [m] of every node of line `line` to line `other` at a state (the quantity of the file
  /// comment). With `onlyBelow` (one value per node [m]), a node whose clearance is provably not below its
  /// value gets +inf instead of the exact clearance (the dynamic envelope needs only new minima).
  /// With `skip` (one flag per node), flagged nodes get +inf without any search.
  /// With `lower`, it gets per node searched its lower clearance [m] (each segment of `other` with its
  /// largest contact radius, and the clearance where less: a bound of the clearance that is 1-Lipschitz in
  /// the positions), for a node that `onlyBelow` lets off on its bounding spheres alone (+inf) a lower bound
  /// of it (the spheres'), -inf for the nodes not searched.
  std::vector<double> nodeClearance(const model::State& state, int line, int other,
                                    const std::vector<double>* onlyBelow = nullptr,
                                    const std::vector<char>* skip = nullptr,
                                    std::vector<double>* lower = nullptr) const;

  /// The clearance [m] of every node of `line` to the nearest line it is assessed against (the report's
  /// frames): +inf where that is above the clearance margin (margin()), the envelope's own limit. Empty when
  /// `line` is assessed against none. Each line after the first is searched only for the nodes it may bring
  /// nearer (nodeClearance's `onlyBelow`): exact values hundreds of metres out, for every pair, were 4.3 G of
  /// the 23 G instructions of 12 moored lines apart with the report on (docs/performance.md).
  std::vector<double> nearestClearance(const model::State& state, int line) const;

  struct Side {
    int line = -1, other = -1;
    std::vector<double> staticClearance;   ///< per node of `line` [m] (NaN before recordStatic)
    /// Per node, minimum over the run [m] (+inf before record, and while never within the clearance margin).
    std::vector<double> dynamicClearance;
    std::vector<double> timeOfMinimum;     ///< per node [s]
    // Lower clearance of each node at its last search (nodeClearance's `lower`; -inf: none yet), where the
    // node was then [m], and how far line `other` had travelled by then (m_travel) [m]: a lower bound of
    // the clearance now (record()).
    std::vector<double> knownClearance;
    std::vector<Vec3> knownPosition;
    std::vector<double> knownTravel;
    /// Per node, then too: a lower bound of the `lower` clearance-distance (before the node's radius) to
    /// every segment of `other` but its nearest one (m_hint's) and that one's neighbours [m] (-inf: none).
    /// While those three are nearer than it, less the moves since, one of them is the nearest (record()).
    std::vector<double> otherSegments;
    /// Per node: while line's and other's m_travel together are not above it, the node cannot have closed
    /// below its envelope by more than the tolerance since record() last tested it [m] (-inf: test it).
    std::vector<double> wake;
  };
  /// The clearance up to which the dynamic minima are kept [m] (m_margin).
  double margin() const { return m_margin; }
  const std::vector<Side>& sides() const { return m_sides; }  ///< two per pair (A to B, B to A)

 private:
  /// The smallest clearance of pair `pair` (static, or dynamic with its time) and where it occurs.
  struct Minimum {
    double clearance;  ///< [m]
    int line;
    double arcLength;  ///< [m]
    double time;       ///< [s] (NaN for the static one)
  };
  Minimum minimum(std::size_t pair, bool dynamic) const;
  /// A collision-allowed pair's impacts (assessImpacts).
  struct Impacts {
    int count = 0;
    double maxEnergy = 0.0;  ///< [J]
  };
  /// Per pair: designed to touch (clearance.collision_allowed), and then its impacts.
  std::vector<char> m_collisionAllowed;
  std::vector<Impacts> m_impacts;
  /// Whether pair `pair` passes: the smallest clearance `overall` [m] against the required one, or (collision
  /// allowed) its largest impact energy against the allowed one; nullopt: not assessed.
  std::optional<bool> passes(std::size_t pair, double overall) const;
  /// The verdict's words for the terminal (": PASS", ...).
  std::string verdict(std::size_t pair, double overall) const;
  /// record()'s certificate of a side's nodes (ClearanceEnvelope.cpp, search()): the side's knowledge
  /// (otherSegments, knownPosition, knownTravel), and where the nodes' new otherSegments bounds go (-inf for
  /// the nodes not found).
  struct Certificate {
    const Side* side;
    std::vector<double>* others;
  };
  /// nodeClearance, with the spheres that bound blocks of `other`'s segments kept from call to call when
  /// `travel` (how far line `other` has moved in all, m_travel [m]) is given, and with a `certificate` (and
  /// `travel`), the nodes whose nearest segment it proves found from three segments.
  std::vector<double> search(const model::State& state, int line, int other,
                             const std::vector<double>* onlyBelow, const std::vector<char>* skip,
                             std::vector<double>* lower, const double* travel,
                             const Certificate* certificate) const;
  struct SegmentRule;
  /// Which segments of `other` each node of `line` is assessed against (ClearanceEnvelope.cpp).
  SegmentRule segmentRule(const model::State& state, int line, int other) const;
  /// The clearance-distance `best` [m] of node i (of rule.a) from the chords of rule.b, nearest at segment
  /// `bestSegment`, taken to rule.b's smooth centreline there when near it (the file comment).
  double smoothClearance(const model::State& state, const SegmentRule& rule, int i, int bestSegment,
                         double best) const;
  /// Bounding spheres of a line's blocks of segments and of their segments, as made at some earlier call.
  struct LineSpheres {
    double travel = -1.0;       ///< the line's m_travel when the blocks' spheres were made [m] (< 0: never)
    std::vector<Vec3> centre;   ///< per block [m]
    std::vector<double> reach;  ///< per block: sphere radius plus its largest contact radius [m]
    std::vector<Vec3> segmentMiddle;   ///< per segment [m]
    std::vector<double> segmentReach;  ///< per segment: half its length plus its largest contact radius [m]
    /// Per block: the line's m_travel when its segments' spheres were made [m] (< 0: not made).
    std::vector<double> segmentTravel;
  };
  mutable std::map<std::size_t, LineSpheres> m_spheres;  ///< per line (record()'s searches)
  /// Work space of search() and record() (their vectors kept from call to call: no allocation per step).
  struct Workspace {
    std::vector<std::pair<int, double>> measured;
    std::vector<double> reach;
    std::vector<char> skipNode;
    std::vector<int> near;
    std::vector<char> skip;
    std::vector<int> tried;
    std::vector<double> lower, others, below;
  };
  mutable Workspace m_work;

  const model::Model* m_model;
  /// The radius along the lines, tapered at a change of section as the contact measures it (a node's own
  /// radius is the profile's there: the mean of the two sections').
  RadiusProfile m_profile;
  /// The contact's rules of which element pairs may touch (its exclusions and shared connections), for the
  /// pairs the envelope skips.
  std::unique_ptr<ContactCandidates> m_exclusions;
  std::vector<std::array<int, 2>> m_pairs;
  std::vector<Side> m_sides;
  bool m_dynamic = false;
  double m_required = 0.0;
  /// The dynamic envelope is kept up to this clearance [m]: clearance.margin, else contact.clearance_margin,
  /// or clearance.required when larger (a node is never passed without being measured).
  double m_margin = 0.0;
  /// Per (line, other): the segment of `other` nearest to each node of `line` at the last call (a first
  /// guess that lets nodeClearance skip most of `other`; a cache, not part of the result).
  mutable std::map<std::array<int, 2>, std::vector<int>> m_hint;
  /// Node positions at the last record() call, and per line the sum over calls of its largest node
  /// displacement [m]: no point of the line has moved farther since any earlier call than the difference.
  std::vector<Vec3> m_lastPosition;
  std::vector<double> m_travel;
  /// Per pair, the smallest dynamic clearance of its nodes so far [m] (record()).
  std::vector<double> m_pairMinimum;

  /// The crossing pass (file comment): the nearest pair of chords of the two lines.
  struct Crossing {
    double clearance = 0.0;            ///< surface clearance of the nearest chords found [m]
    int segmentA = -1, segmentB = -1;  ///< their segments (of the pair's first and second line; -1: none)
    double s = 0.0, t = 0.0;           ///< the closest points' parameters on them [-]
  };
  /// A window of segments: kCrossingWindow either side of segmentA and of segmentB (-1: none).
  struct CrossingWindow {
    int segmentA = -1, segmentB = -1;
  };
  /// Segments either side of the nearest pair in a window [-].
  static constexpr int kCrossingWindow = 2;
  /// The nearest chords of pair `pair` below `searched` [m] (clearance `searched` and segments -1 when none
  /// is): over the segment pairs inside `window` (inside) or outside it (or all when it is empty).
  Crossing crossingSearch(const model::State& state, std::size_t pair, double searched,
                          const CrossingWindow& window, bool inside) const;
  /// Boxes of blocks of kSegmentBlock segments of `line` (`segments` of them) grown by their largest contact
  /// radius: two blocks whose boxes are a distance d apart hold no pair of segments nearer than d.
  struct SegmentBlock {
    Vec3 lo, hi;
    /// The distance between this box and `other` [m] (0 when they overlap): no point of one is nearer than
    /// that to a point of the other.
    double gap(const SegmentBlock& other) const {
      return (lo - other.hi).cwiseMax(other.lo - hi).cwiseMax(0.0).norm();
    }
  };
  static constexpr int kSegmentBlock = 8;
  std::vector<SegmentBlock> segmentBlocks(const model::State& state, const model::Line& line,
                                          int segments) const;
  /// The crossing `c` (on the chords) measured on the curves the contact measures where a line has one
  /// (SmoothCentreline.hpp) and `c` is within `bulge` [m] (bulgeBound): the joint minimum on the chords'
  /// elements and their neighbours, then on every other pair of pieces whose chords less both pieces'
  /// distance from them may come nearer (lines along each other: a rope wrapped round a bollard). Otherwise
  /// `c`.
  Crossing onCurves(const model::State& state, std::size_t pair, const Crossing& c, double bulge) const;
  /// How far the curves of a pair's two lines lie off their chords at most, together, at a state [m] (0 on
  /// chords alone).
  double bulgeBound(const model::State& state, std::size_t pair) const;
  /// Every element's curve data (elementCurves), for bulgeBound (made at its first call).
  mutable std::vector<ElementCurve> m_curves;
  /// bulgeBound's largest deviation per line at the state of this record() or recordStatic() [m] (NaN: not
  /// yet; empty: none).
  mutable std::vector<double> m_lineBulge;
  /// Gives a crossing's clearance to the node of each line nearest its closest point (statics:
  /// staticClearance; dynamics: a new minimum of dynamicClearance with the time, and of the pair's minimum).
  void recordCrossing(const model::State& state, std::size_t pair, const Crossing& c, bool dynamic);
  /// Per pair, what the last whole crossing search (record()) proved: every segment pair at least `bound`
  /// [m], and every one outside `window` at least `outside` [m], on the chords, when the two lines' m_travel
  /// was `travel` [m]; `slack` [m] is the two lines' largest contact radii, `bulge` their bulgeBound then
  /// (the curves' bend changes little between whole searches: taken as it was).
  struct CrossingBounds {
    double bound = -std::numeric_limits<double>::infinity();
    double outside = -std::numeric_limits<double>::infinity();
    double travel = 0.0;
    double slack = 0.0;
    double bulge = 0.0;
    CrossingWindow window;
  };
  std::vector<CrossingBounds> m_crossings;
};

}  // namespace tangle::contact

#pragma once
/// @file BroadPhase.hpp
/// Broad phase of the line-to-line contact search: the pairs of elements (straight segments with
/// a contact radius) whose inflated axis-aligned bounding boxes overlap. Only these pairs go to
/// the narrow phase (geometry::segmentDistance).
///
/// Method: uniform grid (spatial hashing), chosen over sort-and-sweep on one axis.
/// Offshore lines are long and spread over the whole field: projected on any one axis (even the
/// one of largest spread) the boxes of a 2 km field overlap in large numbers, so the sweep tests
/// ~n^2 / (field size / element size) one-axis overlaps, quadratic in n for a given field. The grid
/// only tests boxes that share a cell in 3D. Steps:
///  1. every box is inflated (below) and mapped to the cells of edge h it touches;
///  2. the (cell, proxy) entries, m ~ 1..8 n of them, are grouped by cell with a counting sort
///     on a hash of the cell (spatial hashing, Teschner et al., "Optimized Spatial Hashing for
///     Collision Detection of Deformable Objects", VMV 2003): O(m), no dense grid in memory;
///  3. within each cell every two boxes are tested; a pair sharing several cells is reported only
///     in the cell that holds the minimum corner of the intersection of the two boxes, so it is
///     reported once without a set of reported pairs;
///  4. the pairs are sorted (first, second) so the output does not depend on the grid.
/// Cost O(n + k log k) for k reported pairs when the boxes are of similar size (the final sort of
/// the pairs is the only super-linear term; measured growth in bench_contact_search). The cell edge
/// h defaults to kCellSizeFactor times the mean of the largest extent of the boxes. Boxes touching
/// more than kMaxCellsPerBox cells are kept out of the grid and tested against every box (O(n)
/// each); a few very long elements are cheap, but many of them make the search quadratic.
/// (Uniform grids: C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann 2005, chapter 7,
/// "Spatial Partitioning".)
///
/// Inflation: the box of a proxy is [min(a, b) - w, max(a, b) + w] per axis with
/// w = radius + 0.5 * margin; two boxes overlap when lo_i <= hi_j and lo_j <= hi_i on all three
/// axes (touching counts). Hence every pair whose surfaces (segments swept by their radius) are
/// closer than `margin` is reported (and others whose boxes overlap).

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::contact {

/// Default ratio of the grid cell edge to the mean of the largest box extent [-] (tuned on the
/// benchmark bench_contact_search: 1.5 to 3 are within 20 % of each other, 1 is 1.6 times slower).
inline constexpr double kCellSizeFactor = 2.0;
/// Boxes that touch more cells than this are tested against every box instead of being put in
/// the grid [-].
inline constexpr std::int64_t kMaxCellsPerBox = 64;

/// One element as seen by the broad phase.
struct SegmentProxy {
  /// Line the element belongs to (any integer id, used by the exclusion rules and the filter).
  int line = 0;
  /// Index of the element along its line; consecutive elements differ by 1 [-].
  int element = 0;
  /// First end point [m].
  Vec3 a = Vec3::Zero();
  /// Second end point [m].
  Vec3 b = Vec3::Zero();
  /// Contact radius [m]: half the contact diameter of the element.
  double radius = 0.0;
};

/// Axis-aligned box of a proxy: its end points' bounds grown on every side by its radius plus half the
/// margin [m]. Two proxies are a broad-phase pair when their boxes overlap (touching counts).
struct ProxyBox {
  Vec3 lo, hi;
};
// Inline: ContactCandidates::pairsWithin tests every pair of its Verlet list with them at each call (60 M
// calls in drift-into-spread's 200 s).
inline ProxyBox proxyBox(const SegmentProxy& p, double margin) {
  const double w = p.radius + 0.5 * margin;
  return {p.a.cwiseMin(p.b).array() - w, p.a.cwiseMax(p.b).array() + w};
}
inline bool boxesOverlap(const ProxyBox& a, const ProxyBox& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() && b.lo.y() <= a.hi.y() &&
         a.lo.z() <= b.hi.z() && b.lo.z() <= a.hi.z();
}

/// A candidate pair: indices into the proxy array, first < second.
struct CandidatePair {
  /// Index of the first proxy.
  int first = 0;
  /// Index of the second proxy (> first).
  int second = 0;
  friend bool operator==(const CandidatePair&, const CandidatePair&) = default;
  /// Order by (first, second), the order of BroadPhase's output.
  friend bool operator<(const CandidatePair& x, const CandidatePair& y) {
    return x.first != y.first ? x.first < y.first : x.second < y.second;
  }
};

/// Filter on pairs of lines: called as filter(lineA, lineB) with lineA <= lineB; a pair of
/// elements is reported only if it returns true.
using LinePairFilter = std::function<bool(int lineA, int lineB)>;

/// A LinePairFilter that allows exactly the listed unordered pairs of lines ((i, j) and (j, i)
/// are the same pair; (i, i) allows self contact of line i when selfContact is on).
LinePairFilter allowLinePairs(const std::vector<std::pair<int, int>>& allowed);

/// Options of the broad phase.
struct BroadPhaseOptions {
  /// Extra surface-to-surface gap at which pairs are reported [m] (>= 0): each box is inflated
  /// by radius + margin / 2.
  double margin = 0.0;
  /// Whether two elements of the same line may form a pair.
  bool selfContact = false;
  /// With selfContact, elements i, j of the same line with |i - j| <= selfContactSkip are never a
  /// pair [-] (>= 1: adjacent elements share a node and always touch).
  int selfContactSkip = 1;
  /// Optional filter on line pairs (empty: every pair of lines is considered).
  LinePairFilter linePairFilter;
  /// Grid cell edge [m] (> 0), or 0 for automatic (kCellSizeFactor x mean largest box extent).
  /// Enlarged if needed so that the grid has at most 2^20 cells per axis. Affects the cost only,
  /// never the pairs found.
  double cellSize = 0.0;
};

/// Counters of the last findPairs call (for benchmarks and tests of the cost).
struct BroadPhaseStatistics {
  /// Number of proxies [-].
  std::size_t proxies = 0;
  /// Number of (cell, proxy) entries in the grid [-].
  std::size_t cellEntries = 0;
  /// Number of proxies too large for the grid, tested against all others [-].
  std::size_t oversizedProxies = 0;
  /// Number of pairs of boxes tested for overlap, after the same-line rules; a pair sharing
  /// several cells is counted once per cell [-].
  std::size_t boxTests = 0;
  /// Number of pairs reported [-].
  std::size_t pairs = 0;
  /// Grid cell edge used [m].
  double cellSize = 0.0;
};

/// Broad phase: finds the candidate pairs among a set of segment proxies (see the file comment
/// for the method). Not thread safe: findPairs reuses internal buffers between calls.
class BroadPhase {
 public:
  /// @throws tangle::Error if margin < 0, selfContactSkip < 1 or cellSize < 0 (or not finite).
  explicit BroadPhase(BroadPhaseOptions options = {});

  /// Replaces `out` by the pairs (first < second, sorted by (first, second)) of proxies whose
  /// inflated boxes overlap, excluding pairs of the same line unless options().selfContact,
  /// pairs of the same line closer than selfContactSkip + 1 in element index, and pairs of lines
  /// rejected by the filter.
  /// @throws tangle::Error if a proxy has a non-finite coordinate or a negative or non-finite
  /// radius (the message gives its index, line and element).
  void findPairs(const std::vector<SegmentProxy>& proxies, std::vector<CandidatePair>& out);

  /// The options given at construction.
  const BroadPhaseOptions& options() const { return m_options; }
  /// Counters of the last findPairs call.
  const BroadPhaseStatistics& statistics() const { return m_statistics; }

 private:
  // Inflated box of a proxy, with the proxy's line and element (kept together for locality).
  struct Box : ProxyBox {
    int line, element;
  };
  struct CellEntry {
    std::uint64_t key;
    int proxy;
  };

  void buildBoxes(const std::vector<SegmentProxy>& proxies);
  void chooseGrid();
  bool accept(int i, int j) const;

  BroadPhaseOptions m_options;
  BroadPhaseStatistics m_statistics;
  // Buffers reused between calls.
  std::vector<Box> m_boxes;
  std::vector<std::array<std::int64_t, 3>> m_cellLo;  // cell coordinates of each box's lo corner
  std::vector<CellEntry> m_entries;
  std::vector<CellEntry> m_sorted;           // m_entries grouped by hash bucket
  std::vector<std::uint32_t> m_bucketStart;  // first entry of each bucket in m_sorted
  std::vector<std::uint32_t> m_bucketFill;   // scatter cursor of each bucket
  std::vector<int> m_oversized;
  std::vector<char> m_isOversized;
  // Grid of the current call.
  Vec3 m_origin = Vec3::Zero();
  double m_invCell = 1.0;
  std::array<std::int64_t, 3> m_cellCount{1, 1, 1};
};

}  // namespace tangle::contact

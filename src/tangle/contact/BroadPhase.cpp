#include "tangle/contact/BroadPhase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tangle/core/Error.hpp"

namespace tangle::contact {
namespace {

/// Cells per axis are kept below 2^20 so that a cell key (3 x 20 bits) fits in 64 bits.
constexpr std::int64_t kMaxCellsPerAxis = std::int64_t{1} << 20;

std::string describe(const SegmentProxy& p, std::size_t index) {
  return "proxy " + std::to_string(index) + " (line " + std::to_string(p.line) + ", element " +
         std::to_string(p.element) + ")";
}

}  // namespace

LinePairFilter allowLinePairs(const std::vector<std::pair<int, int>>& allowed) {
  std::vector<std::pair<int, int>> sorted;
  sorted.reserve(allowed.size());
  for (const auto& [i, j] : allowed) sorted.emplace_back(std::min(i, j), std::max(i, j));
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  return [sorted = std::move(sorted)](int lineA, int lineB) {
    return std::binary_search(sorted.begin(), sorted.end(), std::make_pair(lineA, lineB));
  };
}

BroadPhase::BroadPhase(BroadPhaseOptions options) : m_options(std::move(options)) {
  if (!(m_options.margin >= 0.0) || !std::isfinite(m_options.margin)) {
    throw Error("BroadPhase: margin must be finite and >= 0, got " + std::to_string(m_options.margin));
  }
  if (m_options.selfContactSkip < 1) {
    throw Error("BroadPhase: selfContactSkip must be >= 1 (adjacent elements never pair), got " +
                std::to_string(m_options.selfContactSkip));
  }
  if (!(m_options.cellSize >= 0.0) || !std::isfinite(m_options.cellSize)) {
    throw Error("BroadPhase: cellSize must be finite and >= 0 (0 = automatic), got " +
                std::to_string(m_options.cellSize));
  }
}

void BroadPhase::buildBoxes(const std::vector<SegmentProxy>& proxies) {
  m_boxes.resize(proxies.size());
  for (std::size_t i = 0; i < proxies.size(); ++i) {
    const SegmentProxy& p = proxies[i];
    if (!p.a.allFinite() || !p.b.allFinite()) {
      throw Error("BroadPhase: " + describe(p, i) + " has a non-finite end point");
    }
    if (!(p.radius >= 0.0) || !std::isfinite(p.radius)) {
      throw Error("BroadPhase: " + describe(p, i) + " has an invalid contact radius " +
                  std::to_string(p.radius));
    }
    static_cast<ProxyBox&>(m_boxes[i]) = proxyBox(p, m_options.margin);
    m_boxes[i].line = p.line;
    m_boxes[i].element = p.element;
  }
}

void BroadPhase::chooseGrid() {
  const std::size_t n = m_boxes.size();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  double extentSum = 0.0;
  for (const Box& box : m_boxes) {
    lo = lo.cwiseMin(box.lo);
    hi = hi.cwiseMax(box.hi);
    extentSum += (box.hi - box.lo).maxCoeff();
  }
  const double span = (hi - lo).maxCoeff();
  double h =
      m_options.cellSize > 0.0 ? m_options.cellSize : kCellSizeFactor * extentSum / static_cast<double>(n);
  if (!(h > 0.0) || !std::isfinite(h)) {  // all boxes are points
    h = span > 0.0 ? span / std::cbrt(static_cast<double>(n)) : 1.0;
  }
  const double maxCells = static_cast<double>(kMaxCellsPerAxis - 2);
  if (span / h > maxCells) h = span / maxCells;
  m_origin = lo;
  m_invCell = 1.0 / h;
  for (int k = 0; k < 3; ++k) {
    m_cellCount[static_cast<std::size_t>(k)] =
        static_cast<std::int64_t>(std::floor((hi[k] - m_origin[k]) * m_invCell)) + 1;
  }
  m_statistics.cellSize = h;
}

bool BroadPhase::accept(int i, int j) const {
  const Box& bi = m_boxes[static_cast<std::size_t>(i)];
  const Box& bj = m_boxes[static_cast<std::size_t>(j)];
  if (bi.line != bj.line) return true;
  return m_options.selfContact &&
         std::abs(static_cast<std::int64_t>(bi.element) - bj.element) > m_options.selfContactSkip;
}

void BroadPhase::findPairs(const std::vector<SegmentProxy>& proxies, std::vector<CandidatePair>& out) {
  out.clear();
  m_statistics = BroadPhaseStatistics{};
  m_statistics.proxies = proxies.size();
  // Entry counts are 32-bit: at most 2^25 proxies of at most kMaxCellsPerBox = 64 entries each.
  if (proxies.size() > (std::size_t{1} << 25)) {
    throw Error("BroadPhase: too many proxies (" + std::to_string(proxies.size()) + ")");
  }
  buildBoxes(proxies);
  if (proxies.size() < 2) return;
  chooseGrid();

  const int n = static_cast<int>(proxies.size());
  auto overlap = [this](int i, int j) {
    return boxesOverlap(m_boxes[static_cast<std::size_t>(i)], m_boxes[static_cast<std::size_t>(j)]);
  };
  auto filterAccepts = [this](int i, int j) {
    if (!m_options.linePairFilter) return true;
    const int lineI = m_boxes[static_cast<std::size_t>(i)].line;
    const int lineJ = m_boxes[static_cast<std::size_t>(j)].line;
    return m_options.linePairFilter(std::min(lineI, lineJ), std::max(lineI, lineJ));
  };
  auto cellOf = [this](const Vec3& x) {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k) {
      c[static_cast<std::size_t>(k)] =
          static_cast<std::int64_t>(std::floor((x[k] - m_origin[k]) * m_invCell));
    }
    return c;
  };
  auto keyOf = [this](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::uint64_t>(c[0] + m_cellCount[0] * (c[1] + m_cellCount[1] * c[2]));
  };

  // 1. Cell entries; boxes touching too many cells are set aside.
  m_entries.clear();
  m_oversized.clear();
  m_isOversized.assign(proxies.size(), 0);
  m_cellLo.resize(proxies.size());
  for (int i = 0; i < n; ++i) {
    const Box& box = m_boxes[static_cast<std::size_t>(i)];
    const std::array<std::int64_t, 3> c0 = cellOf(box.lo);
    const std::array<std::int64_t, 3> c1 = cellOf(box.hi);
    m_cellLo[static_cast<std::size_t>(i)] = c0;
    const std::int64_t cells = (c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
    if (cells > kMaxCellsPerBox) {
      m_oversized.push_back(i);
      m_isOversized[static_cast<std::size_t>(i)] = 1;
      continue;
    }
    for (std::int64_t z = c0[2]; z <= c1[2]; ++z) {
      for (std::int64_t y = c0[1]; y <= c1[1]; ++y) {
        for (std::int64_t x = c0[0]; x <= c1[0]; ++x) m_entries.push_back({keyOf({x, y, z}), i});
      }
    }
  }
  m_statistics.cellEntries = m_entries.size();
  m_statistics.oversizedProxies = m_oversized.size();

  // 2. Counting sort of the entries into hash buckets of their cell (spatial hashing, Teschner et
  //    al. 2003), O(m). The scatter keeps the insertion order, so inside a bucket the proxies are in
  //    increasing order. Cells that collide in a bucket are told apart by their key.
  const std::size_t m = m_entries.size();
  int bucketBits = 1;
  while ((std::size_t{1} << bucketBits) < 2 * m) ++bucketBits;
  const std::size_t buckets = std::size_t{1} << bucketBits;
  auto bucketOf = [bucketBits](std::uint64_t key) {  // Fibonacci hashing (Knuth, TAOCP vol. 3, 6.4)
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> (64 - bucketBits));
  };
  m_bucketStart.assign(buckets + 1, 0);
  for (const CellEntry& entry : m_entries) ++m_bucketStart[bucketOf(entry.key) + 1];
  for (std::size_t b = 0; b < buckets; ++b) m_bucketStart[b + 1] += m_bucketStart[b];
  m_bucketFill.assign(m_bucketStart.begin(), m_bucketStart.end() - 1);
  m_sorted.resize(m);
  for (const CellEntry& entry : m_entries) m_sorted[m_bucketFill[bucketOf(entry.key)]++] = entry;

  // 3. Pairs inside each cell, reported only from the cell of the intersection's lo corner:
  //    floor is monotonic, so that cell is the componentwise max of the two lo cells.
  std::size_t boxTests = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = m_bucketStart[b];
    const std::size_t end = m_bucketStart[b + 1];
    for (std::size_t u = begin; u + 1 < end; ++u) {
      const std::uint64_t key = m_sorted[u].key;
      const int i = m_sorted[u].proxy;
      const std::array<std::int64_t, 3>& ci = m_cellLo[static_cast<std::size_t>(i)];
      for (std::size_t v = u + 1; v < end; ++v) {
        if (m_sorted[v].key != key) continue;  // another cell hashed to the same bucket
        const int j = m_sorted[v].proxy;
        if (!accept(i, j)) continue;
        ++boxTests;
        if (!overlap(i, j)) continue;
        const std::array<std::int64_t, 3>& cj = m_cellLo[static_cast<std::size_t>(j)];
        if (keyOf({std::max(ci[0], cj[0]), std::max(ci[1], cj[1]), std::max(ci[2], cj[2])}) != key) continue;
        if (!filterAccepts(i, j)) continue;
        out.push_back({i, j});
      }
    }
  }

  // Oversized boxes against every box (pairs of two oversized boxes once).
  for (const int o : m_oversized) {
    for (int j = 0; j < n; ++j) {
      if (j == o || (m_isOversized[static_cast<std::size_t>(j)] && j < o)) continue;
      if (!accept(o, j)) continue;
      ++boxTests;
      if (!overlap(o, j) || !filterAccepts(o, j)) continue;
      out.push_back({std::min(o, j), std::max(o, j)});
    }
  }
  m_statistics.boxTests = boxTests;

  // 4. Output independent of the grid.
  std::sort(out.begin(), out.end());
  m_statistics.pairs = out.size();
}

}  // namespace tangle::contact

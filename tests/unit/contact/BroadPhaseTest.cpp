/// Tests of tangle::contact::BroadPhase: exact agreement with an O(n^2) brute force on seeded
/// random layouts (replayable), the exclusion rules, the line-pair filter, the margin, the input
/// checks and the cost (box tests per proxy bounded at constant density).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "tangle/contact/BroadPhase.hpp"
#include "tangle/core/Error.hpp"

namespace tangle::contact {
namespace {

/// O(n^2) reference written from the documented specification (BroadPhase.hpp): box
/// [min(a,b) - w, max(a,b) + w], w = radius + 0.5 margin, overlap with <= on all axes, then the
/// exclusion rules and the filter. Same floating-point expressions as the specification, so the
/// comparison is exact (no tolerance).
std::vector<CandidatePair> bruteForcePairs(const std::vector<SegmentProxy>& proxies,
                                           const BroadPhaseOptions& o) {
  std::vector<CandidatePair> pairs;
  const int n = static_cast<int>(proxies.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const SegmentProxy& p = proxies[static_cast<std::size_t>(i)];
      const SegmentProxy& q = proxies[static_cast<std::size_t>(j)];
      if (p.line == q.line && (!o.selfContact || std::abs(p.element - q.element) <= o.selfContactSkip))
        continue;
      const double wp = p.radius + 0.5 * o.margin;
      const double wq = q.radius + 0.5 * o.margin;
      bool overlap = true;
      for (int k = 0; k < 3; ++k) {
        const double loP = std::min(p.a[k], p.b[k]) - wp, hiP = std::max(p.a[k], p.b[k]) + wp;
        const double loQ = std::min(q.a[k], q.b[k]) - wq, hiQ = std::max(q.a[k], q.b[k]) + wq;
        overlap = overlap && loP <= hiQ && loQ <= hiP;
      }
      if (!overlap) continue;
      if (o.linePairFilter && !o.linePairFilter(std::min(p.line, q.line), std::max(p.line, q.line))) continue;
      pairs.push_back({i, j});
    }
  }
  return pairs;
}

/// Random polylines: `lines` lines of `elements` elements each, random walks with steps of
/// 0.5..2 m in a cube of edge `size` [m], contact radii 0..0.3 m, arbitrary (non-contiguous) line
/// ids and element numbering, and the proxies shuffled so that array order means nothing.
std::vector<SegmentProxy> randomLayout(std::mt19937_64& rng, int lines, int elements, double size) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<SegmentProxy> proxies;
  for (int l = 0; l < lines; ++l) {
    Vec3 x(size * uniform(rng), size * uniform(rng), size * uniform(rng));
    Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const double radius = 0.3 * uniform(rng);
    const int firstElement = static_cast<int>(100 * uniform(rng));
    for (int e = 0; e < elements; ++e) {
      direction = (direction + 0.7 * Vec3(normal(rng), normal(rng), normal(rng))).normalized();
      const Vec3 next = x + (0.5 + 1.5 * uniform(rng)) * direction;
      proxies.push_back({7 * l + 3, firstElement + e, x, next, radius});
      x = next;
    }
  }
  std::shuffle(proxies.begin(), proxies.end(), rng);
  return proxies;
}

void expectSameAsBruteForce(const std::vector<SegmentProxy>& proxies, const BroadPhaseOptions& options) {
  BroadPhase broadPhase(options);
  std::vector<CandidatePair> pairs{{-1, -1}};  // must be replaced, not appended to
  broadPhase.findPairs(proxies, pairs);
  const std::vector<CandidatePair> reference = bruteForcePairs(proxies, options);
  ASSERT_EQ(pairs.size(), reference.size());
  EXPECT_TRUE(pairs == reference);
  EXPECT_EQ(broadPhase.statistics().pairs, pairs.size());
}

TEST(BroadPhase, RandomLayoutsMatchBruteForceExactly) {
  // Seeded: the trace gives seed and case so a failure can be replayed.
  constexpr std::uint64_t kSeed = 2007;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " trial " + std::to_string(trial));
    const int lines = 1 + static_cast<int>(12 * uniform(rng));
    const int elements = 1 + static_cast<int>(60 * uniform(rng));
    const double size = 5.0 + 60.0 * uniform(rng);
    const std::vector<SegmentProxy> proxies = randomLayout(rng, lines, elements, size);
    BroadPhaseOptions options;
    options.margin = uniform(rng) < 0.3 ? 0.0 : 2.0 * uniform(rng);
    options.selfContact = uniform(rng) < 0.5;
    options.selfContactSkip = 1 + static_cast<int>(3 * uniform(rng));
    if (uniform(rng) < 0.3) {
      // Allow a random subset of the line pairs.
      std::vector<std::pair<int, int>> allowed;
      for (int a = 0; a < lines; ++a) {
        for (int b = a; b < lines; ++b) {
          if (uniform(rng) < 0.5) allowed.emplace_back(7 * b + 3, 7 * a + 3);
        }
      }
      options.linePairFilter = allowLinePairs(allowed);
    }
    if (uniform(rng) < 0.2) options.cellSize = 0.05 + 20.0 * uniform(rng);  // user cell size
    expectSameAsBruteForce(proxies, options);
    if (HasFailure()) break;
  }
}

TEST(BroadPhase, DegenerateAndExtremeLayoutsMatchBruteForce) {
  std::mt19937_64 rng(42);
  BroadPhaseOptions selfContact;
  selfContact.selfContact = true;
  {
    // Empty, single proxy.
    expectSameAsBruteForce({}, {});
    expectSameAsBruteForce({{0, 0, Vec3::Zero(), Vec3::UnitX(), 0.1}}, {});
  }
  {
    // Zero-size boxes all at one point: every pair of different lines overlaps.
    std::vector<SegmentProxy> points;
    for (int i = 0; i < 40; ++i) points.push_back({i % 5, i / 5, Vec3(1, 2, 3), Vec3(1, 2, 3), 0.0});
    expectSameAsBruteForce(points, {});
    expectSameAsBruteForce(points, selfContact);
  }
  {
    // Flat layout (all z = 0, zero extent in z), far from the origin of coordinates.
    std::vector<SegmentProxy> flat = randomLayout(rng, 8, 40, 30.0);
    for (SegmentProxy& p : flat) {
      p.a.z() = 0.0;
      p.b.z() = 0.0;
      p.a += Vec3(1e6, -2e6, 0.0);
      p.b += Vec3(1e6, -2e6, 0.0);
    }
    expectSameAsBruteForce(flat, {});
    expectSameAsBruteForce(flat, selfContact);
  }
  {
    // A few very long elements (oversized boxes) among short ones.
    std::vector<SegmentProxy> mixed = randomLayout(rng, 6, 50, 40.0);
    mixed.push_back({100, 0, Vec3(-5, -5, -5), Vec3(50, 50, 50), 0.5});
    mixed.push_back({101, 0, Vec3(50, -5, 0), Vec3(-5, 50, 40), 0.5});
    mixed.push_back({101, 5, Vec3(0, 20, -5), Vec3(40, 20, 50), 0.5});
    BroadPhaseOptions options;
    options.margin = 0.5;
    BroadPhase broadPhase(options);
    std::vector<CandidatePair> pairs;
    broadPhase.findPairs(mixed, pairs);
    EXPECT_GE(broadPhase.statistics().oversizedProxies, 3U);
    EXPECT_TRUE(pairs == bruteForcePairs(mixed, options));
    expectSameAsBruteForce(mixed, selfContact);
  }
  {
    // Tiny user cell size (the grid is coarsened to keep 2^20 cells per axis) and one huge cell.
    const std::vector<SegmentProxy> proxies = randomLayout(rng, 5, 30, 20.0);
    BroadPhaseOptions tiny;
    tiny.cellSize = 1e-9;
    expectSameAsBruteForce(proxies, tiny);
    BroadPhaseOptions huge;
    huge.cellSize = 1e6;
    expectSameAsBruteForce(proxies, huge);
  }
}

TEST(BroadPhase, ReusedBuffersGiveFreshResults) {
  std::mt19937_64 rng(3);
  BroadPhase broadPhase;
  std::vector<CandidatePair> pairs;
  for (int call = 0; call < 5; ++call) {
    const std::vector<SegmentProxy> proxies = randomLayout(rng, 4 + call, 30 - 5 * call, 15.0);
    broadPhase.findPairs(proxies, pairs);
    EXPECT_TRUE(pairs == bruteForcePairs(proxies, broadPhase.options())) << "call " << call;
  }
}

// ------------------------------------------------------------------------------------------------
// Rules on hand-made layouts (exact binary coordinates, the expected pairs enumerated by hand).

/// Line 0 as a hairpin of unit elements, radius 0.1: elements 0..2 go out along y = 0 (element e
/// covers x in [e, e+1]) and elements 3..5 come back along y = 0.5 (element e covers x in
/// [5-e, 6-e]); the legs are not joined, only the element indices matter to the rules. Without
/// margin the legs' boxes do not overlap (0.5 > 0.1 + 0.1).
std::vector<SegmentProxy> hairpin() {
  std::vector<SegmentProxy> p;
  for (int e = 0; e < 3; ++e) p.push_back({0, e, Vec3(e, 0, 0), Vec3(e + 1, 0, 0), 0.1});
  for (int e = 3; e < 6; ++e) p.push_back({0, e, Vec3(6 - e, 0.5, 0), Vec3(5 - e, 0.5, 0), 0.1});
  return p;
}

TEST(BroadPhase, SameLinePairsOnlyWithSelfContactAndNeverAdjacent) {
  const std::vector<SegmentProxy> p = hairpin();
  std::vector<CandidatePair> pairs;
  BroadPhaseOptions options;
  options.margin = 0.5;  // boxes grow by 0.25 each: the legs (0.5 apart, radii 0.1) now overlap
  BroadPhase noSelf(options);
  noSelf.findPairs(p, pairs);
  EXPECT_TRUE(pairs.empty());  // one line and no self contact: nothing

  options.selfContact = true;
  options.selfContactSkip = 1;
  BroadPhase self(options);
  self.findPairs(p, pairs);
  // x-intervals: out e0 [0,1], e1 [1,2], e2 [2,3]; back e3 [2,3], e4 [1,2], e5 [0,1]; inflated by
  // 0.35 they overlap when the intervals are equal or adjacent. Same-leg neighbours are
  // adjacent in index (excluded); e2-e3 are adjacent (excluded). Cross-leg pairs with
  // |i - j| >= 2: e0-e4 (1 apart in x: [0,1],[1,2] touch), e0-e5, e1-e3, e1-e4, e1-e5, e2-e4.
  // e0-e3: [0,1] vs [2,3] separated by 1 > 2*0.35: no. e2-e5: [2,3] vs [0,1]: no.
  // e0-e2 (same leg, |i-j| = 2): [0,1] vs [2,3]: no.
  const std::vector<CandidatePair> expected{{0, 4}, {0, 5}, {1, 3}, {1, 4}, {1, 5}, {2, 4}};
  EXPECT_TRUE(pairs == expected);
  EXPECT_TRUE(pairs == bruteForcePairs(p, options));

  options.selfContactSkip = 2;  // now |i - j| <= 2 is excluded too: drops 0-2-type pairs 1-3, 2-4
  BroadPhase skip2(options);
  skip2.findPairs(p, pairs);
  const std::vector<CandidatePair> expected2{{0, 4}, {0, 5}, {1, 4}, {1, 5}};
  EXPECT_TRUE(pairs == expected2);
}

TEST(BroadPhase, LinePairFilterSelectsLines) {
  // Three lines crossing at the origin along x, y and z (radius 0.1): every two cross.
  const std::vector<SegmentProxy> p{{0, 0, Vec3(-1, 0, 0), Vec3(1, 0, 0), 0.1},
                                    {1, 0, Vec3(0, -1, 0), Vec3(0, 1, 0), 0.1},
                                    {2, 0, Vec3(0, 0, -1), Vec3(0, 0, 1), 0.1}};
  std::vector<CandidatePair> pairs;
  BroadPhase all;
  all.findPairs(p, pairs);
  EXPECT_TRUE(pairs == (std::vector<CandidatePair>{{0, 1}, {0, 2}, {1, 2}}));

  BroadPhaseOptions options;
  options.linePairFilter = allowLinePairs({{2, 0}});  // order of the listed pair does not matter
  BroadPhase only02(options);
  only02.findPairs(p, pairs);
  EXPECT_TRUE(pairs == (std::vector<CandidatePair>{{0, 2}}));

  // A custom filter always gets lineA <= lineB.
  bool ordered = true;
  options.linePairFilter = [&ordered](int lineA, int lineB) {
    ordered = ordered && lineA <= lineB;
    return lineA != 1 && lineB != 1;
  };
  BroadPhase no1(options);
  const std::vector<SegmentProxy> reversedIds{
      {2, 0, p[0].a, p[0].b, 0.1}, {1, 0, p[1].a, p[1].b, 0.1}, {0, 0, p[2].a, p[2].b, 0.1}};
  no1.findPairs(reversedIds, pairs);
  EXPECT_TRUE(ordered);
  EXPECT_TRUE(pairs == (std::vector<CandidatePair>{{0, 2}}));
}

TEST(BroadPhase, MarginIsTheSurfaceGapAtWhichPairsAppear) {
  // Two parallel elements along x, radii 0.25 and 0.5, axes 1.75 apart in y: surface gap exactly
  // 1. Boxes inflated by r + margin/2 touch exactly (in exact binary arithmetic) when margin = 1.
  const std::vector<SegmentProxy> p{{0, 0, Vec3(0, 0, 0), Vec3(4, 0, 0), 0.25},
                                    {1, 0, Vec3(1, 1.75, 0), Vec3(3, 1.75, 0), 0.5}};
  auto count = [&](double margin) {
    BroadPhaseOptions options;
    options.margin = margin;
    BroadPhase broadPhase(options);
    std::vector<CandidatePair> pairs;
    broadPhase.findPairs(p, pairs);
    return pairs.size();
  };
  EXPECT_EQ(count(0.0), 0U);
  EXPECT_EQ(count(0.999), 0U);
  EXPECT_EQ(count(1.0), 1U);  // touching boxes count
  EXPECT_EQ(count(1.001), 1U);
}

TEST(BroadPhase, InvalidOptionsAndProxiesThrow) {
  BroadPhaseOptions negativeMargin;
  negativeMargin.margin = -1.0;
  EXPECT_THROW(BroadPhase{negativeMargin}, Error);
  BroadPhaseOptions zeroSkip;
  zeroSkip.selfContactSkip = 0;
  EXPECT_THROW(BroadPhase{zeroSkip}, Error);
  BroadPhaseOptions badCell;
  badCell.cellSize = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(BroadPhase{badCell}, Error);

  BroadPhase broadPhase;
  std::vector<CandidatePair> pairs;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
      broadPhase.findPairs(
          {{0, 0, Vec3(nan, 0, 0), Vec3(1, 0, 0), 0.1}, {1, 0, Vec3::Zero(), Vec3::UnitY(), 0.1}}, pairs),
      Error);
  EXPECT_THROW(
      broadPhase.findPairs(
          {{0, 0, Vec3::Zero(), Vec3(1, 0, 0), -0.1}, {1, 0, Vec3::Zero(), Vec3::UnitY(), 0.1}}, pairs),
      Error);
}

TEST(BroadPhase, BoxTestsPerProxyStayBoundedAtConstantDensity) {
  // Cost check without timing: n short random elements (0.5..2 m, radius <= 0.3 m) uniformly in a
  // cube whose volume grows with n, i.e. at constant density. A quadratic method tests n^2/2 box
  // pairs; the grid's tests per proxy must stay about constant. Measured: 4.5, 4.5, 4.7 tests
  // per proxy for n = 1000, 8000, 64000; we allow 1.5 times the smallest-n value (only sampling
  // noise and boundary effects change it) and, at n = 64000, fewer than 1e-3 n^2/2 tests.
  std::mt19937_64 rng(99);
  double testsPerProxyAtSmallest = 0.0;
  for (const int n : {1000, 8000, 64000}) {
    const double size = 2.0 * std::cbrt(static_cast<double>(n));  // 8 m^3 per element
    const std::vector<SegmentProxy> proxies = randomLayout(rng, n, 1, size);
    BroadPhase broadPhase;
    std::vector<CandidatePair> pairs;
    broadPhase.findPairs(proxies, pairs);
    const double perProxy = static_cast<double>(broadPhase.statistics().boxTests) / n;
    if (testsPerProxyAtSmallest == 0.0) testsPerProxyAtSmallest = perProxy;
    EXPECT_LT(perProxy, 1.5 * testsPerProxyAtSmallest) << n << " proxies";
    if (n == 64000) {
      EXPECT_LT(static_cast<double>(broadPhase.statistics().boxTests), 1e-3 * n * (n / 2.0));
    }
  }
}

}  // namespace
}  // namespace tangle::contact

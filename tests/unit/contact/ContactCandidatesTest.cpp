// The rules of which lines may touch (issue 45: kept as a rule and two short lists, not a table of every
// line pair) and the line pairs that are near each other (a sweep over the lines' boxes), against brute
// force over every pair.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/contact/ContactCandidates.hpp"
#include "tangle/geometry/SegmentDistance.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {
namespace {

constexpr int kLines = 40;
constexpr double kRadius = 0.1;  // [m]

/// kLines straight wires of 3 elements scattered over a 200 m square at depths 20-80 m, in directions that
/// vary with the index (a deterministic scatter: a low-discrepancy sequence); line 7 takes no part in
/// contact.
model::ModelSpec scatter() {
  model::ModelSpec spec;
  spec.sourceFile = "scatter (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["w"] = test::cableType("w", 2.0 * kRadius, 10.0, 1e8);
  for (int i = 0; i < kLines; ++i) {
    const double u = std::fmod(0.6180339887 * i, 1.0), v = std::fmod(0.7548776662 * i, 1.0);
    const double w = std::fmod(0.5698402910 * i, 1.0);
    const Vec3 a(200.0 * u, 200.0 * v, -20.0 - 60.0 * w);
    const double angle = 2.399963 * i;
    const Vec3 b = a + Vec3(25.0 * std::cos(angle), 25.0 * std::sin(angle), 5.0 * (w - 0.5));
    spec.lines.push_back(test::simpleLine("l" + std::to_string(i), "w", (b - a).norm(), 3,
                                          model::EndKind::Pinned, a, model::EndKind::Pinned, b));
  }
  spec.lines[7].contact = false;
  spec.contact.enabled = true;
  spec.contact.excludeConnections = false;
  return spec;
}

TEST(ContactCandidates, EveryPairRuleCountsWithoutATable) {
  model::ModelSpec spec = scatter();
  spec.contact.exclude = {{"l1", "l2"}, {"l3", "l7"}, {"l5", "l4"}};
  const model::Model m(std::move(spec));
  const ContactCandidates c(m, m.spec().contact, std::vector<double>(m.elements().size(), kRadius));
  std::size_t count = 0;
  for (int a = 0; a < kLines; ++a)
    for (int b = a; b < kLines; ++b) {
      const bool expected = a != b && a != 7 && b != 7 && !(a == 1 && b == 2) && !(a == 4 && b == 5);
      EXPECT_EQ(c.pairAllowed(a, b), expected) << a << ", " << b;
      EXPECT_EQ(c.pairAllowed(b, a), expected) << b << ", " << a;
      count += expected ? 1 : 0;
    }
  EXPECT_EQ(c.allowedPairCount(), count);  // 39 * 38 / 2 - 2 = 739 (l3-l7 is not allowed anyway)
  EXPECT_EQ(count, 739u);
  EXPECT_EQ(c.allowedPairs().size(), count);
}

TEST(ContactCandidates, ListedPairsAndSelfContact) {
  model::ModelSpec spec = scatter();
  spec.contact.pairs = {{"l3", "l1"}, {"l4", "l4"}, {"l6", "l9"}};
  spec.contact.exclude = {{"l9", "l6"}};
  const model::Model m(std::move(spec));
  const ContactCandidates c(m, m.spec().contact, std::vector<double>(m.elements().size(), kRadius));
  EXPECT_TRUE(c.pairAllowed(1, 3));
  EXPECT_TRUE(c.pairAllowed(4, 4));
  EXPECT_FALSE(c.pairAllowed(6, 9));
  EXPECT_FALSE(c.pairAllowed(1, 2));
  EXPECT_EQ(c.allowedPairCount(), 2u);
  const std::vector<std::array<int, 2>> pairs = c.allowedPairs();
  EXPECT_EQ(pairs, (std::vector<std::array<int, 2>>{{1, 3}, {4, 4}}));
}

TEST(ContactCandidates, NearLinePairsAreExactlyThePairsWhoseGrownBoxesOverlap) {
  const model::Model m(scatter());
  const ContactCandidates c(m, m.spec().contact, std::vector<double>(m.elements().size(), kRadius));
  const model::State state = m.initialState();
  for (const double margin : {0.0, 5.0, 20.0, 60.0}) {
    std::vector<std::array<int, 2>> expected;
    for (int a = 0; a < kLines; ++a)
      for (int b = a + 1; b < kLines; ++b) {
        if (!c.pairAllowed(a, b)) continue;
        // Brute force: the boxes of the two lines' nodes grown by radius + margin / 2 overlap.
        const auto box = [&](int l) {
          const model::Line& line = m.lines()[static_cast<std::size_t>(l)];
          Vec3 lo = state.position[static_cast<std::size_t>(line.firstNode)], hi = lo;
          for (int n = line.firstNode; n <= line.lastNode(); ++n) {
            lo = lo.cwiseMin(state.position[static_cast<std::size_t>(n)]);
            hi = hi.cwiseMax(state.position[static_cast<std::size_t>(n)]);
          }
          const Vec3 grow = Vec3::Constant(kRadius + 0.5 * margin);
          return std::array<Vec3, 2>{lo - grow, hi + grow};
        };
        const auto [loA, hiA] = box(a);
        const auto [loB, hiB] = box(b);
        if ((loA.array() <= hiB.array()).all() && (loB.array() <= hiA.array()).all()) {
          expected.push_back({a, b});
        } else {
          // A pair left out is farther apart than the margin (surface to surface).
          double gap = std::numeric_limits<double>::infinity();
          const model::Line& la = m.lines()[static_cast<std::size_t>(a)];
          const model::Line& lb = m.lines()[static_cast<std::size_t>(b)];
          for (int i = la.firstNode; i < la.lastNode(); ++i)
            for (int j = lb.firstNode; j < lb.lastNode(); ++j)
              gap = std::min(gap, geometry::segmentDistance(state.position[static_cast<std::size_t>(i)],
                                                            state.position[static_cast<std::size_t>(i + 1)],
                                                            state.position[static_cast<std::size_t>(j)],
                                                            state.position[static_cast<std::size_t>(j + 1)])
                                          .distance -
                                      2.0 * kRadius);
          EXPECT_GT(gap, margin) << a << ", " << b;
        }
      }
    EXPECT_EQ(c.nearLinePairs(state, margin), expected) << "margin " << margin;
    if (margin == 60.0) {
      EXPECT_GT(expected.size(), 100u);  // the test sees many pairs of either kind
    }
    if (margin == 0.0) {
      EXPECT_LT(expected.size(), 60u);
    }
  }
}

TEST(ContactCandidates, PairsWithinFromTheKeptListAreThoseOfAFreshSearch) {
  // pairsWithin keeps the broad phase's pairs within a larger margin (the skin) and serves later calls from
  // them while no segment end has moved far enough to bring in a pair the list lacks. Contract: at every
  // call the same pairs, in the same order, as a search made afresh (a new object, no list) at that state.
  // The lines drift towards and through one another, 0.05-1.5 m per call, with jumps of 20 m that defeat
  // the list; margins 0.5-3 m.
  const model::Model m(scatter());
  const std::vector<double> radius(m.elements().size(), kRadius);
  ContactCandidates kept(m, m.spec().contact, radius);
  model::State state = m.initialState();
  int nonEmpty = 0;
  for (int call = 0; call < 120; ++call) {
    const double margin = 0.5 + 2.5 * std::fmod(0.618 * call, 1.0);
    const double step = call % 40 == 39 ? 20.0 : 0.05 + 1.45 * std::fmod(0.754 * call, 1.0);  // [m]
    for (int n = 0; n < m.nodeCount(); ++n) {
      const double phase = 0.37 * n + 0.11 * call;
      state.position[static_cast<std::size_t>(n)] +=
          step * Vec3(std::cos(phase), std::sin(1.3 * phase), 0.2 * std::sin(phase)).normalized();
    }
    ContactCandidates fresh(m, m.spec().contact, radius);
    const std::vector<CandidatePair> expected = fresh.pairsWithin(state, margin);
    const std::vector<CandidatePair> got = kept.pairsWithin(state, margin);
    ASSERT_EQ(got.size(), expected.size()) << "call " << call;
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].first, expected[k].first) << "call " << call;
      EXPECT_EQ(got[k].second, expected[k].second) << "call " << call;
    }
    nonEmpty += expected.empty() ? 0 : 1;
  }
  EXPECT_GT(nonEmpty, 20);  // the test sees pairs
}

}  // namespace
}  // namespace tangle::contact

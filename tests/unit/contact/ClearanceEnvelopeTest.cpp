/// Tests of tangle::contact::ClearanceEnvelope::nodeClearance, whose search skips blocks of segments by
/// bounding spheres and starts from the previous nearest segment: it must give exactly the brute-force
/// minimum over all segments (same expression, so no tolerance), whatever the previous call left as a
/// first guess; with a threshold per node (`onlyBelow`) a node may get +inf only when its brute-force
/// clearance is not below its threshold, and a finite value is the exact one. And record(), which searches
/// a node only when it may have closed on its envelope by more than its tolerance, against the brute force
/// at every step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "support/ModelFactory.hpp"
#include "support/WrappedRope.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/geometry/SegmentDistance.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {
namespace {

/// Surface-to-surface clearance of node i of `line` to `other` over all segments (the definition in
/// ClearanceEnvelope.hpp: the segment's contact radius at its closest point, then the node's own radius,
/// both the radius along the line's: RadiusProfile).
std::vector<double> bruteForce(const model::Model& m, const model::State& s, int line, int other) {
  const model::Line& a = m.lines()[static_cast<std::size_t>(line)];
  const model::Line& b = m.lines()[static_cast<std::size_t>(other)];
  const RadiusProfile profile(m);  // tested on its own in RadiusProfileTest
  std::vector<double> out;
  for (int i = 0; i < a.nodeCount; ++i) {
    const Vec3& x = s.position[a.firstNode + i];
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j + 1 < b.nodeCount; ++j) {
      const int m1 = b.firstNode + j, m2 = m1 + 1;
      const Vec3& p = s.position[m1];
      const Vec3 axis = s.position[m2] - p;
      const double l2 = axis.squaredNorm();
      const double t = l2 > 0.0 ? std::clamp((x - p).dot(axis) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, (x - (p + t * axis)).norm() - profile.at(b.firstElement + j, t));
    }
    out.push_back(best - profile.nodeRadius()[static_cast<std::size_t>(a.firstNode + i)]);
  }
  return out;
}

/// The smallest surface clearance of the two lines' chords [m] (segment to segment, less each element's
/// contact radius at the closest points: the crossing pass of ClearanceEnvelope.hpp, on chords for cables
/// without contact).
double chordMinimum(const model::Model& m, const model::State& s, int line, int other) {
  const model::Line& a = m.lines()[static_cast<std::size_t>(line)];
  const model::Line& b = m.lines()[static_cast<std::size_t>(other)];
  const RadiusProfile profile(m);  // tested on its own in RadiusProfileTest
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 1 < a.nodeCount; ++i)
    for (int j = 0; j + 1 < b.nodeCount; ++j) {
      const geometry::SegmentDistanceResult d =
          geometry::segmentDistance(s.position[a.firstNode + i], s.position[a.firstNode + i + 1],
                                    s.position[b.firstNode + j], s.position[b.firstNode + j + 1]);
      best = std::min(best,
                      d.distance - profile.at(a.firstElement + i, d.s) - profile.at(b.firstElement + j, d.t));
    }
  return best;
}

/// Two lines of 37 and 53 elements (block remainders on both), different diameters.
model::ModelSpec twoLines() {
  model::ModelSpec spec;
  spec.sourceFile = "clearance (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["thin"] = test::cableType("thin", 0.1, 10.0, 1e8);
  spec.lineTypes["thick"] = test::cableType("thick", 0.5, 50.0, 1e9);
  spec.lines = {test::simpleLine("a", "thin", 40.0, 37, model::EndKind::Pinned, Vec3(0, 0, -50),
                                 model::EndKind::Pinned, Vec3(40, 0, -50)),
                test::simpleLine("b", "thick", 60.0, 53, model::EndKind::Pinned, Vec3(0, 5, -60),
                                 model::EndKind::Pinned, Vec3(60, 5, -60))};
  return spec;
}

/// Random wavy shapes of both lines (a new layout per seed, lines crossing and running side by side).
void shuffle(const model::Model& m, model::State& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const model::Line& line : m.lines()) {
    const Vec3 start(10.0 * u(rng), 10.0 * u(rng), -50.0 + 10.0 * u(rng));
    const Vec3 dir = Vec3(1.0, 0.3 * u(rng), 0.3 * u(rng)).normalized();
    const double amplitude = 3.0 * (1.0 + u(rng)), wavelength = 5.0 + 20.0 * (1.0 + u(rng));
    for (int i = 0; i < line.nodeCount; ++i) {
      const double arc = 1.1 * i;
      s.position[line.firstNode + i] =
          start + arc * dir +
          Vec3(0, amplitude * std::sin(arc / wavelength), amplitude * std::cos(arc / wavelength)) +
          0.2 * Vec3(u(rng), u(rng), u(rng));
    }
  }
}

TEST(ClearanceEnvelope, NodeClearanceEqualsTheBruteForceMinimumWhateverTheFirstGuess) {
  const model::Model m(twoLines());
  model::State s = m.initialState();
  ClearanceEnvelope envelope(m, {{0, 1}});
  std::mt19937 rng(20261125);
  for (int trial = 0; trial < 40; ++trial) {
    shuffle(m, s, rng);  // the hints of the previous trial are unrelated to this layout
    for (int side = 0; side < 2; ++side) {
      const std::vector<double> reference = bruteForce(m, s, side, 1 - side);
      const std::vector<double> got = envelope.nodeClearance(s, side, 1 - side);
      ASSERT_EQ(got.size(), reference.size());
      for (std::size_t i = 0; i < got.size(); ++i)
        ASSERT_EQ(got[i], reference[i]) << "trial " << trial << ", line " << side << ", node " << i;
    }
  }
}

// A node of line a over the gap a parted element of line b left (lines[].failure): its clearance is to what
// is left of b, not to the parted element, whose curve still runs between the broken ends. Two beams of
// 0.1 m crossing at right angles, b along x on 1 m elements with element 5 (x = 5 to 6 m) parted from the
// start; a's middle node 0.15 m above x = 5.2 m. To the parted element the clearance is 0.15 - 0.1 =
// 0.05 m; to the broken end at x = 5 m it is sqrt(0.2^2 + 0.15^2) - 0.1 = 0.15 m (to round-off: the smooth
// check near the surface measures the element before the end on its curve, here straight). Until
// 2026-12-06 that check measured the nearest segment's neighbours whether parted or not: 0.05 m.
TEST(ClearanceEnvelope, ANodeOverAPartedElementIsMeasuredToWhatIsLeft) {
  model::ModelSpec spec;
  spec.sourceFile = "clearance (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["rod"] = test::solidRodType("rod", 0.1, 2.1e11, 7850.0);
  spec.lines = {test::simpleLine("a", "rod", 10.0, 10, model::EndKind::Pinned, Vec3(5.2, -5, -59.85),
                                 model::EndKind::Pinned, Vec3(5.2, 5, -59.85)),
                test::simpleLine("b", "rod", 10.0, 10, model::EndKind::Pinned, Vec3(0, 0, -60),
                                 model::EndKind::Pinned, Vec3(10, 0, -60))};
  const model::Model m(spec);
  m.parted().part(static_cast<std::size_t>(m.lines()[1].firstElement + 5),
                  -std::numeric_limits<double>::infinity());
  const model::State s = m.initialState();
  const ClearanceEnvelope envelope(m, {{0, 1}});
  const std::vector<double> clearance = envelope.nodeClearance(s, 0, 1);
  ASSERT_EQ(clearance.size(), 11u);
  EXPECT_NEAR(clearance[5], std::hypot(0.2, 0.15) - 0.1, 1e-6);
}

TEST(ClearanceEnvelope, ThresholdSkipsOnlyNodesThatCannotSetANewMinimum) {
  const model::Model m(twoLines());
  model::State s = m.initialState();
  ClearanceEnvelope envelope(m, {{0, 1}});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int skipped = 0, exact = 0;
  for (int trial = 0; trial < 40; ++trial) {
    shuffle(m, s, rng);
    for (int side = 0; side < 2; ++side) {
      const std::vector<double> reference = bruteForce(m, s, side, 1 - side);
      // Thresholds around the true clearances (some nodes above, some below), some +inf (first call).
      std::vector<double> threshold(reference.size());
      for (std::size_t i = 0; i < reference.size(); ++i)
        threshold[i] =
            u(rng) < 0.1 ? std::numeric_limits<double>::infinity() : reference[i] + 4.0 * (u(rng) - 0.5);
      const std::vector<double> got = envelope.nodeClearance(s, side, 1 - side, &threshold);
      for (std::size_t i = 0; i < got.size(); ++i) {
        if (std::isinf(got[i])) {
          ++skipped;
          ASSERT_GE(reference[i], threshold[i])
              << "trial " << trial << ": a new minimum was skipped at node " << i;
        } else {
          ++exact;
          ASSERT_EQ(got[i], reference[i]) << "trial " << trial << ", node " << i;
        }
        if (reference[i] < threshold[i]) {
          ASSERT_FALSE(std::isinf(got[i]));
        }
      }
    }
  }
  // Both branches are exercised (the thresholds straddle the clearances; the bounds are conservative, so
  // fewer nodes are skipped than have a clearance above their threshold: 83 of ~3600 here).
  EXPECT_GT(skipped, 20);
  EXPECT_GT(exact, 100);
}

/// Line b of twoLines with a short thick end (a riser's LMRP: 4 m against 0.5 m), the radius jump that
/// made the envelope's bound search every node at every step.
model::ModelSpec twoLinesOneWithAThickEnd() {
  model::ModelSpec spec = twoLines();
  spec.lineTypes["lump"] = test::cableType("lump", 4.0, 500.0, 1e9);
  spec.lines[1].sections = {{"thick", 56.0, 49}, {"lump", 4.0, 4}};
  return spec;
}

/// Records `steps` + 1 states (`move` sets the positions of step k) and checks the dynamic envelope against
/// the brute-force minimum of every node over the same states, and of the chords (the crossing pass). The
/// contract (ClearanceEnvelope.hpp): the pair's minimum is the exact smaller of the nodes' and the chords'
/// minima, with its time; a node is never below its exact minimum unless the crossing pass gave it a
/// crossing's clearance (then not below the chords' minimum), and above it by at most 1e-3 (min(e, M) -
/// min(P, M)), M the clearance margin (ClearanceEnvelope::margin); a node whose exact minimum is above M has
/// +inf, and one below M by more than its tolerance a finite value. Returns how many nodes end above their
/// exact minimum (the tolerance used).
int checkEnvelope(const model::Model& m, int steps, const std::function<void(int, model::State&)>& move) {
  model::State s = m.initialState();
  ClearanceEnvelope envelope(m, {{0, 1}});
  std::vector<std::vector<double>> exact(2), when(2);
  for (int side = 0; side < 2; ++side) {
    const std::size_t n = static_cast<std::size_t>(m.lines()[static_cast<std::size_t>(side)].nodeCount);
    exact[static_cast<std::size_t>(side)].assign(n, std::numeric_limits<double>::infinity());
    when[static_cast<std::size_t>(side)].assign(n, 0.0);
  }
  double chords = std::numeric_limits<double>::infinity(), chordsWhen = 0.0;
  for (int step = 0; step <= steps; ++step) {
    move(step, s);
    envelope.record(s);
    for (int side = 0; side < 2; ++side) {
      const std::vector<double> c = bruteForce(m, s, side, 1 - side);
      for (std::size_t i = 0; i < c.size(); ++i)
        if (c[i] < exact[static_cast<std::size_t>(side)][i]) {
          exact[static_cast<std::size_t>(side)][i] = c[i];
          when[static_cast<std::size_t>(side)][i] = s.time;
        }
    }
    const double c = chordMinimum(m, s, 0, 1);
    if (c < chords) {
      chords = c;
      chordsWhen = s.time;
    }
  }
  double nodes = std::numeric_limits<double>::infinity();
  for (const auto& e : exact) nodes = std::min(nodes, *std::min_element(e.begin(), e.end()));
  const double pairMinimum = std::min(nodes, chords);
  double recordedMinimum = std::numeric_limits<double>::infinity();
  const double margin = envelope.margin();  // [m]
  const double inf = std::numeric_limits<double>::infinity();
  int above = 0;
  for (int side = 0; side < 2; ++side) {
    const ClearanceEnvelope::Side& got = envelope.sides()[static_cast<std::size_t>(side)];
    const std::vector<double>& e = exact[static_cast<std::size_t>(side)];
    for (std::size_t i = 0; i < e.size(); ++i) {
      const double d = got.dynamicClearance[i];
      recordedMinimum = std::min(recordedMinimum, d);
      const double tolerance = 1e-3 * (std::min(d, margin) - std::min(pairMinimum, margin));  // [m]
      if (d == inf) {
        EXPECT_GT(e[i], margin - tolerance - 1e-12) << "side " << side << ", node " << i;
        continue;
      }
      EXPECT_LE(d, margin) << "side " << side << ", node " << i;
      EXPECT_GE(d, std::min(e[i], chords)) << "side " << side << ", node " << i;
      EXPECT_LE(d - e[i], tolerance + 1e-12) << "side " << side << ", node " << i;
      if (d == pairMinimum) {
        EXPECT_EQ(got.timeOfMinimum[i],
                  nodes <= chords ? when[static_cast<std::size_t>(side)][i] : chordsWhen)
            << "side " << side << ", node " << i;
      }
      if (d > e[i]) ++above;
    }
  }
  EXPECT_EQ(recordedMinimum, pairMinimum);
  ::testing::Test::RecordProperty("crossing_below_nodes_m", std::to_string(nodes - chords));
  return above;
}

TEST(ClearanceEnvelope, RecordKeepsThePairMinimumExactAndEveryNodeWithinItsTolerance) {
  // 5000 steps of two lines closing until they cross (line a, turned 22 degrees across line b and 10 m above
  // it, lowered onto it; both sway), checked as checkEnvelope says. The steps move the nodes millimetres (as
  // a drifting unit's lines do), so the far nodes use the tolerance.
  const model::Model m(twoLinesOneWithAThickEnd());
  const model::State start = m.initialState();
  constexpr int kSteps = 5000;
  constexpr double kDt = 0.01;                // [s]
  constexpr double kDuration = kSteps * kDt;  // [s]
  const int above = checkEnvelope(m, kSteps, [&](int step, model::State& s) {
    const double t = step * kDt;
    s.time = t;
    for (const model::Line& line : m.lines())
      for (int i = 0; i < line.nodeCount; ++i) {
        const int n = line.firstNode + i;
        const double arc = 1.1 * i;
        const bool a = line.firstNode == 0;
        const double lowered = a ? 0.5 * (1.0 - std::cos(M_PI * t / kDuration)) : 0.0;
        const double across = a ? 0.4 * (arc - 20.0) : 0.0;
        s.position[n] = start.position[n] + lowered * Vec3(0.0, 5.0, -10.0) + Vec3(0.0, across, 0.0) +
                        Vec3(0.0, 0.05 * std::sin(0.7 * t + 0.2 * arc), 0.05 * std::cos(0.9 * t + 0.1 * arc));
      }
  });
  EXPECT_GT(above, 5);  // the tolerance is used (the nodes far from the crossing)
  RecordProperty("nodes_above_their_exact_minimum", above);
}

/// Lines in a V: `a` along x, `b` leaving it at 22 degrees, so that a's nodes lie 3-59 m from b and b's
/// 3-63 m from a. a's node at x lies 3 cos(22 deg) + x sin(22 deg) from b's axis, b's node at u along it
/// 3 + u sin(22 deg) from a's.
model::ModelSpec veeSpec(double contactMargin) {
  model::ModelSpec spec;
  spec.sourceFile = "clearance margin (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["thin"] = test::cableType("thin", 0.1, 10.0, 1e8);
  spec.lines = {test::simpleLine("a", "thin", 150.0, 75, model::EndKind::Pinned, Vec3(0, 0, -50),
                                 model::EndKind::Pinned, Vec3(150, 0, -50)),
                test::simpleLine("b", "thin", 160.0, 80, model::EndKind::Pinned, Vec3(0, 3, -50),
                                 model::EndKind::Pinned, Vec3(148.3, 62.9, -50))};
  spec.contact.clearanceMargin = contactMargin;
  return spec;
}

/// The V of veeSpec, both lines swaying by 0.3 m, checked by checkEnvelope.
int checkVee(model::ModelSpec spec) {
  const model::Model m(std::move(spec));
  const model::State start = m.initialState();
  return checkEnvelope(m, 400, [&](int step, model::State& s) {
    const double t = 0.05 * step;
    s.time = t;
    for (const model::Line& line : m.lines())
      for (int i = 0; i < line.nodeCount; ++i)
        s.position[line.firstNode + i] = start.position[line.firstNode + i] +
                                         Vec3(0.0, 0.3 * std::sin(0.8 * t + 0.05 * i + line.firstNode),
                                              0.3 * std::cos(0.6 * t + 0.03 * i));
  });
}

/// How many nodes of the V at rest have a finite dynamic minimum (within the envelope's margin), and that
/// margin [m].
std::pair<int, double> finiteVeeNodes(model::ModelSpec spec) {
  const model::Model m(std::move(spec));
  ClearanceEnvelope envelope(m, {{0, 1}});
  envelope.record(m.initialState());
  int finite = 0;
  for (const ClearanceEnvelope::Side& side : envelope.sides())
    for (const double d : side.dynamicClearance) finite += std::isfinite(d) ? 1 : 0;
  return {finite, envelope.margin()};
}

TEST(ClearanceEnvelope, NodesNeverWithinTheClearanceMarginKeepNoDynamicMinimum) {
  // At the default 50 m margin the nodes beyond it have +inf, the others and the pair's minimum their values
  // (checkEnvelope); at 1000 m every node has its value. Both within the same tolerance.
  checkVee(veeSpec(50.0));
  checkVee(veeSpec(1000.0));
  // Within 50 m: a's nodes up to x = 126 m (64 of its 76 nodes), b's up to u = 125 m (63 of its 81).
  const int within50 = finiteVeeNodes(veeSpec(50.0)).first;
  const int within1000 = finiteVeeNodes(veeSpec(1000.0)).first;
  EXPECT_EQ(within1000, 76 + 81);
  EXPECT_EQ(within50, 64 + 63);
  RecordProperty("nodes_within_50_m", within50);
}

TEST(ClearanceEnvelope, NearestClearanceIsTheNearestAssessedLineWithinTheMargin) {
  // The report's frames (nearestClearance): per node of `a`, the smaller of its brute-force clearances to
  // `b` (the V: 3-59 m) and to `c` (parallel to a, 25 m off on the other side, so nearer than b beyond
  // x = 58 m), +inf above the 40 m margin. Exact: the searches it skips are those that cannot lower it.
  model::ModelSpec spec = veeSpec(40.0);
  spec.lines.push_back(test::simpleLine("c", "thin", 150.0, 75, model::EndKind::Pinned, Vec3(0, -25, -50),
                                        model::EndKind::Pinned, Vec3(150, -25, -50)));
  const model::Model m(std::move(spec));
  model::State s = m.initialState();
  for (int n = 0; n < static_cast<int>(s.position.size()); ++n)  // off the straight lines by 0.3 m
    s.position[n] += Vec3(0.0, 0.3 * std::sin(0.37 * n), 0.3 * std::cos(0.23 * n));
  ClearanceEnvelope envelope(m, {{0, 1}, {0, 2}});
  const std::vector<double> toB = bruteForce(m, s, 0, 1), toC = bruteForce(m, s, 0, 2);
  const std::vector<double> nearest = envelope.nearestClearance(s, 0);
  ASSERT_EQ(nearest.size(), toB.size());
  int byB = 0, byC = 0, beyond = 0;
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    const double expected = std::min(toB[i], toC[i]);
    if (expected > 40.0) {
      EXPECT_EQ(nearest[i], std::numeric_limits<double>::infinity()) << "node " << i;
      ++beyond;
    } else {
      EXPECT_EQ(nearest[i], expected) << "node " << i;
      (toB[i] < toC[i] ? byB : byC) += 1;
    }
  }
  EXPECT_GT(byB, 10);
  EXPECT_GT(byC, 10);
  EXPECT_EQ(beyond, 0);  // c is 25 m from every node of a
  // b and c are assessed against a alone: b's nodes beyond 40 m of a are +inf.
  const std::vector<double> fromB = envelope.nearestClearance(s, 1), bToA = bruteForce(m, s, 1, 0);
  int bBeyond = 0;
  for (std::size_t i = 0; i < fromB.size(); ++i) {
    EXPECT_EQ(fromB[i], bToA[i] > 40.0 ? std::numeric_limits<double>::infinity() : bToA[i]) << "node " << i;
    bBeyond += bToA[i] > 40.0 ? 1 : 0;
  }
  EXPECT_GT(bBeyond, 10);
  // A line assessed against none gets no values.
  ClearanceEnvelope onlyAB(m, {{0, 1}});
  EXPECT_TRUE(onlyAB.nearestClearance(s, 2).empty());
}

TEST(ClearanceEnvelope, MarginIsTheClearanceBlocksAndNeverBelowTheRequiredClearance) {
  // clearance.margin overrides contact.clearance_margin for the envelope; a required clearance above the
  // margin widens it (a node within the requirement is always measured: otherwise the check would pass nodes
  // it never looked at). Within 20 m: a's nodes up to x = (20 - 2.78) / sin(22 deg) = 46.0 m (24 nodes, 2 m
  // apart), b's up to u = 17 / sin(22 deg) = 45.4 m (23 nodes).
  model::ModelSpec ownMargin = veeSpec(50.0);
  ownMargin.clearance.margin = 20.0;
  model::ModelSpec required = veeSpec(5.0);
  required.clearance.required = 20.0;
  for (const model::ModelSpec& spec : {ownMargin, required}) {
    const auto [count, marginUsed] = finiteVeeNodes(spec);
    EXPECT_EQ(marginUsed, 20.0);
    EXPECT_EQ(count, 24 + 23);
    checkVee(spec);
  }
}

TEST(ClearanceEnvelope, RecordStaysExactWhileTheNearestSegmentsSlideAlong) {
  // Line a, straight, slides 25 m along line b, a wave of 1.5 m amplitude and 9 m length (8 segments a wave)
  // beneath it, while it is lowered from 3.5 m above b's crests to 0.6 m into them: every node's nearest
  // segment of b changes every few steps (and b's nearest node of a), and its clearance rises and falls as
  // crests pass under it, a new minimum at most of them. record() finds most of those from the nearest
  // segment and its neighbours, when the rest of the line is provably farther (Side::otherSegments); the
  // contract is a full search's (checkEnvelope).
  const model::Model m(twoLines());
  const model::State start = m.initialState();
  constexpr int kSteps = 3000;
  constexpr double kDt = 0.01;  // [s]
  const int above = checkEnvelope(m, kSteps, [&](int step, model::State& s) {
    const double f = static_cast<double>(step) / kSteps;
    s.time = step * kDt;
    const model::Line& a = m.lines()[0];
    const model::Line& b = m.lines()[1];
    for (int i = 0; i < b.nodeCount; ++i) {
      const double x = 60.0 * i / (b.nodeCount - 1);
      s.position[b.firstNode + i] = Vec3(x, 5.0, -60.0 + 1.5 * std::sin(2.0 * M_PI * x / 9.0));
    }
    const double aboveCrests = 3.5 - 4.1 * f;  // [m]
    for (int i = 0; i < a.nodeCount; ++i)
      s.position[a.firstNode + i] =
          start.position[a.firstNode + i] + Vec3(10.0 + 25.0 * f, 5.0, -10.0 + 1.5 + aboveCrests);
  });
  RecordProperty("nodes_above_their_exact_minimum", above);
}

// Two straight lines crossing at right angles between nodes of both (11 elements of 10 m / 11 and 9 of
// 9 m / 9: no node of either within 4.5 m of the crossing), 0.6 m apart on their axes, 0.1 and 0.5 m
// thick: their surfaces are 0.3 m apart, which the nodes see as 4.5 m and more. recordStatic and record()
// must find the crossing (the pair's minimum, the pass / fail against a required 0.5 m), and record() the
// time it is nearest while line a is swept across b.
TEST(ClearanceEnvelope, FindsACrossingBetweenTheNodesOfBothLines) {
  model::ModelSpec spec = twoLines();
  spec.lines = {test::simpleLine("a", "thin", 10.0, 11, model::EndKind::Pinned, Vec3(-5, 0, -50),
                                 model::EndKind::Pinned, Vec3(5, 0, -50)),
                test::simpleLine("b", "thick", 9.0, 9, model::EndKind::Pinned, Vec3(0, -4.5, -50.6),
                                 model::EndKind::Pinned, Vec3(0, 4.5, -50.6))};
  spec.clearance.required = 0.5;
  const model::Model m(spec);
  model::State s = m.initialState();
  const model::Line& a = m.lines()[0];
  const model::Line& b = m.lines()[1];
  for (int i = 0; i < a.nodeCount; ++i) s.position[a.firstNode + i] = Vec3(-5.0 + 10.0 * i / 11.0, 0, -50);
  for (int i = 0; i < b.nodeCount; ++i) s.position[b.firstNode + i] = Vec3(0, -4.5 + 9.0 * i / 9.0, -50.6);
  ClearanceEnvelope envelope(m, {{0, 1}});
  envelope.recordStatic(s);
  double staticMinimum = std::numeric_limits<double>::infinity();
  for (const auto& side : envelope.sides())
    staticMinimum =
        std::min(staticMinimum, *std::min_element(side.staticClearance.begin(), side.staticClearance.end()));
  EXPECT_NEAR(staticMinimum, 0.3, 1e-12);
  EXPECT_NE(envelope.terminalSummary().find("static min 0.300 m: FAIL"), std::string::npos)
      << envelope.terminalSummary();
  // Swept 2 m along b and back down by 0.2 m, nearest at t = 1 s: the node-based minimum stays 4.4 m off.
  const model::State start = s;
  const int above = checkEnvelope(m, 200, [&](int step, model::State& x) {
    const double t = 0.01 * step;
    x.time = t;
    x.position = start.position;
    for (int i = 0; i < a.nodeCount; ++i)
      x.position[a.firstNode + i] += Vec3(0.0, 2.0 * (t - 1.0), -0.2 * std::cos(0.5 * M_PI * (t - 1.0)));
  });
  (void)above;
}

// The pair's minimum on the smooth centrelines where two lines lie along each other (the rope wrapped round a
// bollard of support/WrappedRope.hpp): the nearest chords and their neighbours alone left it 0.5 mm above
// the curves' on a new user's capstan, above the clash report's at an output time (2026-12-07).
TEST(ClearanceEnvelope, ThePairsMinimumIsOnTheCurvesWhereLinesLieAlongEachOther) {
  const model::ModelSpec spec = io::readModelString(test::wrappedRopeYaml(), "wrap.yaml");
  const model::Model m(spec);
  model::State s = m.initialState();
  std::mt19937 random(11);
  for (int trial = 0; trial < 10; ++trial) {
    test::wrapRope(m, s, random);
    ClearanceEnvelope envelope(m, {{0, 1}});
    envelope.record(s);
    double recorded = std::numeric_limits<double>::infinity();
    for (const auto& side : envelope.sides())
      recorded =
          std::min(recorded, *std::min_element(side.dynamicClearance.begin(), side.dynamicClearance.end()));
    EXPECT_NEAR(recorded, test::wrappedRopeClearance(m, s), 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace tangle::contact

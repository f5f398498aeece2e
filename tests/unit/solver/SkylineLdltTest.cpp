// Unit tests of the envelope LDL^T (SkylineLdlt) and of LinearSolver's choice between it and the general
// sparse LDL^T. Reference: Eigen's dense LDL^T / the residual of the solve, to round-off (1e-12 relative:
// the matrices are well conditioned, condition numbers below 1e4).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/SkylineLdlt.hpp"

namespace tangle {
namespace {

/// The n x n sparse matrix of the triplets `t` (duplicates summed), compressed.
SparseMatrix fromTriplets(int n, const std::vector<Triplet>& t) {
  SparseMatrix k(n, n);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;
}

/// A symmetric matrix from dense blocks along the diagonal (a "line" of nodes with `dofsPerNode` DOFs,
/// neighbours coupled), positive definite by diagonal dominance, plus optional couplings (i, j).
SparseMatrix lineMatrix(int nodes, int dofsPerNode, const std::vector<std::pair<int, int>>& extra, unsigned seed,
                        bool indefinite = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = nodes * dofsPerNode;
  std::vector<Triplet> t;
  auto sym = [&](int i, int j, double v) {
    t.emplace_back(i, j, v);
    if (i != j) t.emplace_back(j, i, v);
  };
  for (int a = 0; a < nodes; ++a)
    for (int b = a; b <= std::min(a + 1, nodes - 1); ++b)
      for (int i = 0; i < dofsPerNode; ++i)
        for (int j = 0; j < dofsPerNode; ++j) {
          const int r = a * dofsPerNode + i, c = b * dofsPerNode + j;
          if (a == b && j < i) continue;
          if (a == b && i == j) continue;
          sym(r, c, u(rng));
        }
  for (const auto& [i, j] : extra) sym(i, j, u(rng));
  for (int i = 0; i < n; ++i) {
    const double d = 4.0 * dofsPerNode + 2.0 + u(rng);
    t.emplace_back(i, i, indefinite && i % 7 == 3 ? -d : d);
  }
  return fromTriplets(n, t);
}

/// Couplings of the last node of a line of `nodes` nodes to its first (an arrow: two lines joined at a vessel
/// numbered last), DOF by DOF.
std::vector<std::pair<int, int>> lastToFirst(int nodes, int dofsPerNode) {
  std::vector<std::pair<int, int>> extra;
  for (int i = 0; i < dofsPerNode; ++i) extra.emplace_back((nodes - 1) * dofsPerNode + i, i);
  return extra;
}

double relativeResidual(const SparseMatrix& k, const VecX& x, const VecX& b) { return (k * x - b).norm() / b.norm(); }

TEST(SkylineLdlt, BarLineIsABandWithFiveSubDiagonals) {
  const SparseMatrix k = lineMatrix(200, 3, {}, 1);
  solver::SkylineLdlt s;
  const std::size_t stored = s.analyzePattern(k);
  // Row 3a + i reaches back to column 3(a - 1): 3 + i entries below the diagonal (a >= 1), i in the node.
  EXPECT_EQ(stored, 600u + 199u * (3u + 4u + 5u) + 3u);
  ASSERT_TRUE(s.factorize(k));
  VecX b = VecX::LinSpaced(600, -1.0, 2.0);
  VecX x = b;
  s.solveInPlace(x);
  EXPECT_LT(relativeResidual(k, x, b), 1e-13);
}

TEST(SkylineLdlt, EqualsDenseLdltOnBeamLineWithArrowCoupling) {
  // 6 DOFs per node; the last node coupled to the first (two lines joined at a vessel numbered last).
  const SparseMatrix k = lineMatrix(60, 6, lastToFirst(60, 6), 2);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_TRUE(s.factorize(k));
  const VecX b = VecX::Random(360);
  VecX x = b;
  s.solveInPlace(x);
  const Eigen::MatrixXd dense(k);
  const VecX reference = dense.ldlt().solve(b);
  EXPECT_LT((x - reference).norm() / reference.norm(), 1e-12);
}

TEST(SkylineLdlt, FixedWidthBandOfLinesEqualsDenseLdlt) {
  // Bar line (3 DOFs per node: band 5) and beam line (6: band 11) solve on the fixed-width band; both agree
  // with the dense LDL^T, also for a range of blocks solved alone (reads stay inside the range: the
  // entries of the other blocks are NaN here and must not leak in).
  for (const int dofsPerNode : {3, 6}) {
    const int nodes = 40, n = 40 * dofsPerNode;
    const SparseMatrix k = lineMatrix(nodes, dofsPerNode, {}, 3);
    solver::SkylineLdlt s;
    s.analyzePattern(k);
    EXPECT_EQ(s.bandWidth(), 2 * dofsPerNode - 1);
    ASSERT_TRUE(s.factorize(k));
    const VecX b = VecX::Random(n);
    VecX x = b;
    s.solveInPlace(x);
    const VecX reference = Eigen::MatrixXd(k).ldlt().solve(b);
    EXPECT_LT((x - reference).norm() / reference.norm(), 1e-12) << dofsPerNode << " DOFs per node";
  }
  // Two independent bar lines: the second block alone, the first one's entries NaN.
  const SparseMatrix one = lineMatrix(30, 3, {}, 4);
  std::vector<Triplet> t;
  for (int copy = 0; copy < 2; ++copy)
    for (int c = 0; c < one.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(one, c); it; ++it)
        t.emplace_back(copy * 90 + static_cast<int>(it.row()), copy * 90 + static_cast<int>(it.col()),
                       it.value());
  const SparseMatrix k = fromTriplets(180, t);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.blockCount(), 2);
  EXPECT_EQ(s.bandWidth(), 5);
  ASSERT_TRUE(s.factorize(k));
  VecX b = VecX::Random(180);
  b.head(90).setConstant(std::numeric_limits<double>::quiet_NaN());
  const VecX rhs = b.tail(90);
  s.solveBlocksInPlace(b, {1});
  const VecX x = b.tail(90);
  const VecX reference = Eigen::MatrixXd(one).ldlt().solve(rhs);
  EXPECT_TRUE(x.allFinite());
  EXPECT_LT((x - reference).norm() / reference.norm(), 1e-12);
}

/// A symmetric band matrix of n equations with every entry within `width` of the diagonal set (random in
/// [-1, 1]), positive definite by diagonal dominance unless `indefinite` (then every 5th pivot negative).
SparseMatrix bandMatrix(int n, int width, unsigned seed, bool indefinite = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - width); j < i; ++j) {
      const double v = u(rng);
      t.emplace_back(i, j, v);
      t.emplace_back(j, i, v);
    }
    const double d = 2.0 * width + 2.0 + u(rng);
    t.emplace_back(i, i, indefinite && i % 5 == 2 ? -d : d);
  }
  return fromTriplets(n, t);
}

TEST(SkylineLdlt, TwistedBlocksEqualDenseLdlt) {
  // A block of at least kMinTwistedBlock band widths is factorised from both ends and solved twisted; one
  // shorter stays top-down. Every band width the fixed-width band takes (1-12), lengths at and around the
  // threshold (odd and even, so the two parts differ by one row or not), definite and indefinite.
  for (int width = 1; width <= solver::SkylineLdlt::kMaxBandWidth; ++width) {
    const int threshold = solver::SkylineLdlt::kMinTwistedBlock * width;
    for (const int n : {threshold - 1, threshold, threshold + 1, threshold + width, 3 * threshold + 7}) {
      for (const bool indefinite : {false, true}) {
        const SparseMatrix k = bandMatrix(n, width, static_cast<unsigned>(100 * width + n), indefinite);
        solver::SkylineLdlt s;
        s.analyzePattern(k);
        ASSERT_EQ(s.bandWidth(), width);
        ASSERT_TRUE(s.factorize(k)) << "width " << width << ", " << n << " equations";
        EXPECT_EQ(s.twistedBlockCount(), n >= threshold ? 1 : 0) << "width " << width << ", " << n;
        const VecX b = VecX::Random(n);
        VecX x = b;
        s.solveInPlace(x);
        const VecX reference = Eigen::MatrixXd(k).ldlt().solve(b);
        EXPECT_LT((x - reference).norm() / reference.norm(), 1e-12)
            << "width " << width << ", " << n << " equations" << (indefinite ? ", indefinite" : "");
      }
    }
  }
}

TEST(SkylineLdlt, VanishingPivotOfTheTwistFallsBackToTopDown) {
  // Tridiagonal (band width 1), 8 equations: twisted at the threshold. Its trailing 2 x 2 block
  // [[1, 1], [1, 1]] is singular, so the factorisation from the bottom meets a zero pivot at row 6, while the
  // top-down pivots (4, 3.75, ..., 0.732, -0.366) do not vanish: the block is factorised top-down.
  const double diagonal[8] = {4, 4, 4, 4, 4, 4, 1, 1};
  std::vector<Triplet> t;
  for (int i = 0; i < 8; ++i) {
    t.emplace_back(i, i, diagonal[i]);
    if (i > 0) {
      t.emplace_back(i, i - 1, 1.0);
      t.emplace_back(i - 1, i, 1.0);
    }
  }
  const SparseMatrix k = fromTriplets(8, t);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.bandWidth(), 1);
  ASSERT_TRUE(s.factorize(k));
  EXPECT_EQ(s.twistedBlockCount(), 0);
  const VecX b = VecX::Random(8);
  VecX x = b;
  s.solveInPlace(x);
  EXPECT_LT(relativeResidual(k, x, b), 1e-13);
}

TEST(SkylineLdlt, WideEnvelopeKeepsTheEnvelopeSubstitutions) {
  // An arrow coupling (last node to first) makes the last rows span the matrix: no fixed-width band.
  const SparseMatrix k = lineMatrix(40, 3, lastToFirst(40, 3), 5);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  EXPECT_EQ(s.bandWidth(), 0);
}

TEST(SkylineLdlt, IndefiniteMatrixWithoutZeroPivotsIsSolved) {
  const SparseMatrix k = lineMatrix(50, 3, {}, 3, true);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_TRUE(s.factorize(k));
  const VecX b = VecX::Random(150);
  VecX x = b;
  s.solveInPlace(x);
  EXPECT_LT(relativeResidual(k, x, b), 1e-12);
}

TEST(SkylineLdlt, ZeroPivotIsReportedNotSolved) {
  // [[1, 1], [1, 1]]: the second pivot is 0.
  std::vector<Triplet> t{{0, 0, 1.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 1.0}};
  const SparseMatrix k = fromTriplets(2, t);
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  EXPECT_FALSE(s.factorize(k));
}

/// The matrices along the diagonal of one matrix, plus optional couplings (i, j) between them.
SparseMatrix blockDiagonal(const std::vector<SparseMatrix>& blocks,
                           const std::vector<std::pair<int, int>>& extra) {
  std::vector<Triplet> t;
  int offset = 0;
  for (const SparseMatrix& b : blocks) {
    for (int c = 0; c < b.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(b, c); it; ++it)
        t.emplace_back(offset + it.row(), offset + it.col(), it.value());
    offset += static_cast<int>(b.rows());
  }
  for (const auto& [i, j] : extra) {
    t.emplace_back(i, j, 0.1);
    t.emplace_back(j, i, 0.1);
  }
  return fromTriplets(offset, t);
}

TEST(SkylineLdlt, IndependentLinesAreBlocksSolvedAlone) {
  // Three lines not coupled to each other (moorings with prescribed fairleads); the second has an arrow
  // (its last node coupled to its first), which keeps it one block.
  std::vector<std::pair<int, int>> arrow;
  for (int i = 0; i < 3; ++i) arrow.emplace_back(39 * 3 + i, i);
  const SparseMatrix k =
      blockDiagonal({lineMatrix(30, 3, {}, 11), lineMatrix(40, 3, arrow, 12), lineMatrix(20, 3, {}, 13)}, {});
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.blockCount(), 3);
  EXPECT_EQ(s.blockStart(0), 0);
  EXPECT_EQ(s.blockStart(1), 90);
  EXPECT_EQ(s.blockStart(2), 210);
  EXPECT_EQ(s.blockStart(3), 270);
  ASSERT_TRUE(s.factorize(k));
  const VecX b = VecX::Random(270);
  VecX whole = b;
  s.solveInPlace(whole);
  EXPECT_LT(relativeResidual(k, whole, b), 1e-13);
  // Blocks 0 and 2: their entries are the whole solve's, bit for bit (the same arithmetic); block 1 keeps b.
  VecX part = b;
  s.solveBlocksInPlace(part, {0, 2});
  for (int i = 0; i < 270; ++i) {
    if (i >= 90 && i < 210)
      EXPECT_EQ(part[i], b[i]) << i;
    else
      EXPECT_EQ(part[i], whole[i]) << i;
  }
  // Consecutive blocks in one call, and all blocks: the whole solve.
  VecX all = b;
  s.solveBlocksInPlace(all, {0, 1, 2});
  EXPECT_EQ((all - whole).cwiseAbs().maxCoeff(), 0.0);
  VecX last = b;
  s.solveBlocksInPlace(last, {1, 2});
  EXPECT_EQ((last.tail(180) - whole.tail(180)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((last.head(90) - b.head(90)).cwiseAbs().maxCoeff(), 0.0);
}

TEST(SkylineLdlt, CouplingAcrossLinesJoinsTheBlocksBetween) {
  // Lines 1 and 3 coupled (a contact): the envelope of line 3's rows reaches into line 1, so lines 1-3 are
  // one block (blocks are ranges of equations); a fourth, free line stays a block of its own.
  const SparseMatrix k = blockDiagonal({lineMatrix(10, 3, {}, 21), lineMatrix(10, 3, {}, 22),
                                        lineMatrix(10, 3, {}, 23), lineMatrix(10, 3, {}, 24)},
                                       {{75, 3}});
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.blockCount(), 2);
  EXPECT_EQ(s.blockStart(1), 90);
  ASSERT_TRUE(s.factorize(k));
  const VecX b = VecX::Random(120);
  VecX x = b;
  s.solveBlocksInPlace(x, {0, 1});
  EXPECT_LT(relativeResidual(k, x, b), 1e-13);
}

TEST(SkylineLdlt, TwistedAndTopDownBlocksSolvedAlone) {
  // Lines of 60, 10 and 50 bar nodes: the first and last blocks twisted, the short one top-down. Any set of
  // blocks is solved alone: the others' entries (NaN here) are neither read nor written.
  const SparseMatrix k =
      blockDiagonal({lineMatrix(60, 3, {}, 31), lineMatrix(10, 3, {}, 32), lineMatrix(50, 3, {}, 33)}, {});
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.blockCount(), 3);
  ASSERT_EQ(s.bandWidth(), 5);
  ASSERT_TRUE(s.factorize(k));
  EXPECT_EQ(s.twistedBlockCount(), 2);
  const VecX b = VecX::Random(360);
  VecX whole = b;
  s.solveInPlace(whole);
  EXPECT_LT(relativeResidual(k, whole, b), 1e-13);
  const std::vector<std::vector<int>> subsets{{0}, {1}, {2}, {0, 1}, {1, 2}, {0, 2}};
  for (const std::vector<int>& blocks : subsets) {
    VecX x = VecX::Constant(360, std::numeric_limits<double>::quiet_NaN());
    for (const int block : blocks) {
      const int begin = s.blockStart(block), end = s.blockStart(block + 1);
      x.segment(begin, end - begin) = b.segment(begin, end - begin);
    }
    s.solveBlocksInPlace(x, blocks);
    for (int block = 0; block < 3; ++block) {
      const int begin = s.blockStart(block), end = s.blockStart(block + 1);
      const bool solved = std::find(blocks.begin(), blocks.end(), block) != blocks.end();
      for (int i = begin; i < end; ++i) {
        if (solved)
          EXPECT_EQ(x[i], whole[i]) << "block " << block << ", equation " << i;
        else
          EXPECT_TRUE(std::isnan(x[i])) << "block " << block << ", equation " << i;
      }
    }
  }
}

/// Largest difference between the solutions of K x = b with `s`'s factors and with a whole factorisation of
/// `changed` (0: bit for bit), for a random b; also checks the residual of `s`'s solution.
double differenceFromWholeFactorisation(const solver::SkylineLdlt& s, const SparseMatrix& changed) {
  solver::SkylineLdlt whole;
  whole.analyzePattern(changed);
  EXPECT_TRUE(whole.factorize(changed));
  const VecX b = VecX::Random(changed.rows());
  VecX x = b, y = b;
  s.solveInPlace(x);
  whole.solveInPlace(y);
  EXPECT_LT(relativeResidual(changed, x, b), 1e-13);
  return (x - y).cwiseAbs().maxCoeff();
}

TEST(SkylineLdlt, BlocksFactorisedAgainEqualAWholeFactorisation) {
  // GeneralizedAlpha's refresh of slow lines: the changed blocks factorised again, the others kept, solve as
  // a whole factorisation of the changed matrix does, bit for bit (the same arithmetic per block). On the
  // fixed-width band of bar lines (width 5) and beam lines (width 11), each with a twisted and a top-down
  // block, and on the envelope (an arrow in the middle block).
  struct Case {
    int dofsPerNode;
    bool envelope;
  };
  for (const Case c : {Case{3, false}, Case{6, false}, Case{3, true}}) {
    const int d = c.dofsPerNode;
    std::vector<std::pair<int, int>> arrow;
    if (c.envelope)
      for (int i = 0; i < d; ++i) arrow.emplace_back(9 * d + i, i);
    const std::array<int, 3> nodes{60, 10, 50};
    const auto lines = [&](const std::vector<int>& changed) {
      std::vector<SparseMatrix> out;
      for (int b = 0; b < 3; ++b) {
        const bool isChanged = std::find(changed.begin(), changed.end(), b) != changed.end();
        out.push_back(lineMatrix(nodes[static_cast<std::size_t>(b)], d, b == 1 ? arrow : std::vector<std::pair<int, int>>{},
                                 (isChanged ? 100u : 40u) + static_cast<unsigned>(b)));
      }
      return blockDiagonal(out, {});
    };
    const SparseMatrix k = lines({});
    solver::SkylineLdlt s;
    s.analyzePattern(k);
    ASSERT_EQ(s.blockCount(), 3);
    ASSERT_EQ(s.bandWidth(), c.envelope ? 0 : 2 * d - 1);
    EXPECT_FALSE(s.factorizeBlocks(k, {0})) << "no factorisation to keep yet";
    ASSERT_TRUE(s.factorize(k));
    if (!c.envelope) {
      EXPECT_EQ(s.twistedBlockCount(), 2);
    }
    for (const std::vector<int>& changed : std::vector<std::vector<int>>{{0}, {1}, {0, 2}, {0, 1, 2}}) {
      const SparseMatrix changedMatrix = lines(changed);
      ASSERT_TRUE(s.factorize(k));
      ASSERT_TRUE(s.factorizeBlocks(changedMatrix, changed));
      EXPECT_EQ(differenceFromWholeFactorisation(s, changedMatrix), 0.0)
          << d << " DOFs per node" << (c.envelope ? ", envelope" : "") << ", first changed block " << changed.front();
    }
  }
}

TEST(SkylineLdlt, StretchFactorisedAgainEqualsAWholeFactorisation) {
  // GeneralizedAlpha's refresh of a line's touchdown zone: K changed in the rows and columns of a stretch of
  // one block; the rows it reaches factorised again solve as a whole factorisation of the changed matrix,
  // bit for bit. Bar (width 5) and beam (width 11) lines: a twisted block of 60 nodes (stretches in its top
  // part, across its separator, in its bottom part, at either end), a top-down one of 10.
  for (const int d : {3, 6}) {
    const SparseMatrix k = blockDiagonal({lineMatrix(60, d, {}, 61), lineMatrix(10, d, {}, 62)}, {});
    const int n = static_cast<int>(k.rows());
    solver::SkylineLdlt s;
    s.analyzePattern(k);
    ASSERT_EQ(s.blockCount(), 2);
    ASSERT_TRUE(s.factorize(k));
    ASSERT_EQ(s.twistedBlockCount(), 1);
    struct Stretch {
      int block, firstNode, nodes;
    };
    for (const Stretch st : {Stretch{0, 10, 5}, Stretch{0, 28, 4}, Stretch{0, 45, 6}, Stretch{0, 0, 3},
                             Stretch{0, 57, 3}, Stretch{1, 3, 2}}) {
      const int begin = s.blockStart(st.block) + st.firstNode * d, end = begin + st.nodes * d;
      SparseMatrix changed = k;
      for (int c = 0; c < n; ++c)
        for (SparseMatrix::InnerIterator it(changed, c); it; ++it) {
          const int r = static_cast<int>(it.row());
          if ((r >= begin && r < end) || (c >= begin && c < end)) it.valueRef() += 0.1 * std::sin(r + c);
        }
      ASSERT_TRUE(s.factorize(k));
      ASSERT_TRUE(s.factorizeRows(changed, st.block, begin, end));
      EXPECT_EQ(differenceFromWholeFactorisation(s, changed), 0.0)
          << d << " DOFs per node, block " << st.block << ", stretch from node " << st.firstNode;
    }
  }
}

TEST(SkylineLdlt, EnvelopeRowsFactorisedAgainEqualAWholeFactorisation) {
  // NewtonIteration's refresh of the lines from one on in a block of lines coupled by a contact (a riser
  // resting across a flowline): K changed in the rows and columns from `begin` on; the envelope's rows from
  // there, and its columns' copy of L before it (the coupling's rows reach back along the envelope), made
  // again solve as a whole factorisation of the changed matrix, bit for bit. Two beam lines of 30 nodes
  // coupled node 20 to node 8 (DOF by DOF): one block, no fixed-width band. Changes from the second line's
  // first row (the part of a refresh of that line), from the middle of the first line, and at the last node.
  const int d = 6, nodes = 30;
  std::vector<std::pair<int, int>> contact;
  for (int i = 0; i < 3; ++i) contact.emplace_back((nodes + 8) * d + i, 20 * d + i);
  const SparseMatrix k = blockDiagonal({lineMatrix(nodes, d, {}, 71), lineMatrix(nodes, d, {}, 72)}, contact);
  const int n = static_cast<int>(k.rows());
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_EQ(s.blockCount(), 1);
  ASSERT_EQ(s.bandWidth(), 0);
  for (const int firstNode : {nodes, 12, 2 * nodes - 1}) {
    const int begin = firstNode * d;
    SparseMatrix changed = k;
    for (int c = 0; c < n; ++c)
      for (SparseMatrix::InnerIterator it(changed, c); it; ++it) {
        const int r = static_cast<int>(it.row());
        if (r >= begin || c >= begin) it.valueRef() += 0.1 * std::sin(r + c);
      }
    ASSERT_TRUE(s.factorize(k));
    ASSERT_TRUE(s.factorizeRows(changed, 0, begin, n));
    EXPECT_EQ(differenceFromWholeFactorisation(s, changed), 0.0) << "changed from node " << firstNode;
  }
}

TEST(SkylineLdlt, VanishingPivotInABlockFactorisedAgainIsReported) {
  const SparseMatrix k = blockDiagonal({lineMatrix(10, 3, {}, 51), lineMatrix(10, 3, {}, 52)}, {});
  solver::SkylineLdlt s;
  s.analyzePattern(k);
  ASSERT_TRUE(s.factorize(k));
  SparseMatrix singular = k;
  for (int c = 30; c < 60; ++c)
    for (SparseMatrix::InnerIterator it(singular, c); it; ++it) it.valueRef() = 0.0;
  EXPECT_FALSE(s.factorizeBlocks(singular, {1}));
  EXPECT_FALSE(s.factorizeBlocks(k, {1})) << "the factors were touched: a whole factorisation comes first";
  ASSERT_TRUE(s.factorize(k));
  EXPECT_TRUE(s.factorizeBlocks(k, {1}));
}

TEST(LinearSolver, BandedForLinesGeneralForScatteredCouplings) {
  // A band: the banded method.
  const SparseMatrix band = lineMatrix(200, 3, {}, 4);
  solver::LinearSolver banded(true);
  ASSERT_TRUE(banded.factorize(band));
  EXPECT_TRUE(banded.usedBanded());
  const VecX b = VecX::Random(600);
  EXPECT_LT(relativeResidual(band, banded.solve(b), b), 1e-13);
  // Couplings between distant equations everywhere (two lines side by side in contact along their length,
  // numbered one after the other): the envelope fills, the general method is used, same solution.
  std::vector<std::pair<int, int>> contacts;
  for (int a = 0; a < 100; a += 2) contacts.emplace_back(300 + 3 * a, 3 * a);
  const SparseMatrix scattered = lineMatrix(200, 3, contacts, 5);
  solver::LinearSolver chooser(true);
  ASSERT_TRUE(chooser.factorize(scattered));
  EXPECT_FALSE(chooser.usedBanded());
  EXPECT_LT(relativeResidual(scattered, chooser.solve(b), b), 1e-12);
  // Not allowed: the general method even for a band.
  solver::LinearSolver general(false);
  ASSERT_TRUE(general.factorize(band));
  EXPECT_FALSE(general.usedBanded());
  // Blocks: the banded method reports the envelope's; the general method one block, the whole system,
  // and solving it (its only block) is the whole solve.
  EXPECT_EQ(banded.blockCount(), 1);
  EXPECT_EQ(general.blockCount(), 1);
  EXPECT_EQ(general.blockStart(0), 0);
  EXPECT_EQ(general.blockStart(1), 600);
  VecX x = b;
  general.solveBlocksInPlace(x, {0});
  EXPECT_LT(relativeResidual(band, x, b), 1e-12);
  const SparseMatrix two = blockDiagonal({lineMatrix(50, 3, {}, 6), lineMatrix(50, 3, {}, 7)}, {});
  ASSERT_TRUE(banded.factorize(two));
  ASSERT_TRUE(banded.usedBanded());
  EXPECT_EQ(banded.blockCount(), 2);
  EXPECT_EQ(banded.blockStart(1), 150);
}

TEST(LinearSolver, GeneralMethodIsEigensSimplicialLdltToTheBit) {
  // The general method factorises P K P^T, permuted through a map made once per pattern, instead of letting
  // Eigen permute K at every factorisation: the same factor and solution to the bit as Eigen's
  // SimplicialLDLT<Lower, AMDOrdering> (the reference here), for full and lower-only storage, new values on
  // the same pattern, and a new pattern (a contact made: couplings added).
  const auto sameBits = [](const VecX& x, const VecX& y) {
    return x.size() == y.size() &&
           std::equal(x.data(), x.data() + x.size(), y.data(),
                      [](double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; });
  };
  std::vector<std::pair<int, int>> contacts;
  for (int a = 0; a < 60; a += 3) contacts.emplace_back(300 + 3 * a, 3 * a + 1);
  solver::LinearSolver general(false);
  const VecX b = VecX::Random(600);
  for (const unsigned seed : {11u, 12u}) {
    for (const bool coupled : {false, true}) {
      const SparseMatrix full =
          lineMatrix(200, 3, coupled ? contacts : std::vector<std::pair<int, int>>{}, seed);
      for (const bool lowerOnly : {false, true}) {
        SparseMatrix k = full;
        if (lowerOnly) {
          k = full.triangularView<Eigen::Lower>();
          k.makeCompressed();
        }
        Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> reference(k);
        ASSERT_EQ(reference.info(), Eigen::Success);
        ASSERT_TRUE(general.factorize(k));
        ASSERT_FALSE(general.usedBanded());
        EXPECT_TRUE(sameBits(general.solve(b), reference.solve(b)))
            << "seed " << seed << " coupled " << coupled;
      }
    }
  }
}

TEST(LinearSolver, SingularMatrixFallsBackAndReportsFailure) {
  std::vector<Triplet> t{{0, 0, 1.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 1.0}};
  const SparseMatrix k = fromTriplets(2, t);
  solver::LinearSolver s(true);
  EXPECT_FALSE(s.factorize(k));
}

}  // namespace
}  // namespace tangle

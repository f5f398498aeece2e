// SystemMatrix: an assembly that replays the recorded sequence of calls (values summed straight into the
// built matrix's positions) must give exactly the matrix a fresh assembly gives, and a changed pattern, a
// changed entry order, fewer calls or another target matrix must still give it (issue 8). Exact equality:
// the values are summed in the same order either way.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>

#include "tangle/model/DofMap.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle {
namespace {

model::DofMap threeNodes() {
  model::DofMap dofs;
  for (int n = 0; n < 3; ++n) dofs.addNode(3);
  dofs.constrain(0);  // one constrained DOF: its entries are dropped
  dofs.finalize();
  return dofs;
}

void fill(solver::SystemMatrix& m, double scale, bool extra, bool reordered = false, bool fewer = false) {
  m.clear();
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  m.add3x3(0, 0, scale * block);
  m.add3x3(3, 3, block);
  m.add3x3(0, 3, scale * block);  // duplicates summed with the next one
  m.add3x3(0, 3, block);
  if (reordered) {
    m.add3x3(6, 6, block);
    m.add3x3(3, 0, block.transpose());
  } else {
    m.add3x3(3, 0, block.transpose());
    if (!fewer) m.add3x3(6, 6, block);
  }
  if (extra) m.add3x3(6, 3, 2.0 * block);
}

/// The same assembly in a new SystemMatrix (recorded from scratch, built by setFromTriplets).
Eigen::MatrixXd fresh(const model::DofMap& dofs, double scale, bool extra, bool reordered = false,
                      bool fewer = false) {
  solver::SystemMatrix m(dofs);
  fill(m, scale, extra, reordered, fewer);
  EXPECT_FALSE(m.replaying());
  SparseMatrix k;
  m.build(k);
  return Eigen::MatrixXd(k);
}

TEST(SystemMatrix, ReplayedAssemblyGivesTheSameMatrixAsAFreshOne) {
  const model::DofMap dofs = threeNodes();
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  fill(m, 1.0, false);
  EXPECT_FALSE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 1.0, false));
  // Same calls, new values: replayed into the existing pattern.
  fill(m, -3.5, false);
  EXPECT_TRUE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, -3.5, false));
  // A new entry at the end (the pattern grows): recorded again from there.
  fill(m, 2.0, true);
  EXPECT_FALSE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 2.0, true));
  fill(m, 2.5, true);
  EXPECT_TRUE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 2.5, true));
  // Fewer calls (the last block left out): the shorter sequence, the smaller pattern.
  fill(m, 7.0, false);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 7.0, false));
  // Into another matrix object, then into the first one, from one assembly.
  fill(m, 1.5, false);
  EXPECT_TRUE(m.replaying());
  SparseMatrix other;
  m.build(other);
  EXPECT_EQ(Eigen::MatrixXd(other), fresh(dofs, 1.5, false));
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 1.5, false));
  // The same entries in another order: recorded again at the first call that differs.
  fill(m, 0.5, false, true);
  EXPECT_FALSE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 0.5, false, true));
  // A sequence that stops early.
  fill(m, 0.5, false, false, true);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(dofs, 0.5, false, false, true));
}

/// Blocks of whole free nodes (one call each), a block over a constrained DOF (nine calls), scalar calls
/// into the same entries, a 6x6 element block; `variant` 1 gives one block's values as nine scalar calls
/// instead, 2 a scalar call as a block: the same matrix, another sequence.
void fillMixed(solver::SystemMatrix& m, double scale, int variant) {
  m.clear();
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  m.add3x3(3, 3, scale * block);
  if (variant == 1) {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) m.add(6 + i, 3 + j, 2.0 * block(i, j));
  } else {
    m.add3x3(6, 3, 2.0 * block);
  }
  m.add3x3(0, 0, block);  // node 0 has a constrained DOF
  if (variant == 2)
    m.add3x3(3, 3, Mat3(scale * Mat3::Identity()));
  else
    for (int i = 0; i < 3; ++i) m.add(3 + i, 3 + i, scale);
  Eigen::Matrix<double, 6, 6> element;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) element(i, j) = 1.0 + i + 10.0 * j;
  const int map[6] = {3, 4, 5, 6, 7, 8};
  m.addBlock(map, 6, element, scale);
}

TEST(SystemMatrix, BlockCallsReplayAsTheirScalarSums) {
  const model::DofMap dofs = threeNodes();
  const auto freshMixed = [&](double scale, int variant) {
    solver::SystemMatrix m(dofs);
    fillMixed(m, scale, variant);
    SparseMatrix k;
    m.build(k);
    return Eigen::MatrixXd(k);
  };
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  fillMixed(m, 1.0, 0);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), freshMixed(1.0, 0));
  fillMixed(m, 2.5, 0);
  EXPECT_TRUE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), freshMixed(2.5, 0));
  // A block given as scalar calls, then a scalar call given as a block: recorded again from there.
  for (const int variant : {1, 2, 0}) {
    fillMixed(m, -1.5, variant);
    m.build(k);
    EXPECT_EQ(Eigen::MatrixXd(k), freshMixed(-1.5, variant)) << "variant " << variant;
    fillMixed(m, 0.75, variant);
    EXPECT_TRUE(m.replaying()) << "variant " << variant;
    m.build(k);
    EXPECT_EQ(Eigen::MatrixXd(k), freshMixed(0.75, variant)) << "variant " << variant;
  }
}

/// Two independent "lines" of two nodes each (nodes 0-1: equations 0-5 with full DOF 1 constrained, so
/// 0-4; nodes 2-3: equations 5-10), each line's calls scaled on its own.
model::DofMap twoLines() {
  model::DofMap dofs;
  for (int n = 0; n < 4; ++n) dofs.addNode(3);
  dofs.constrain(1);
  dofs.finalize();
  return dofs;
}

void fillLine(solver::SystemMatrix& m, int first, double scale) {
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  m.add3x3(first, first, scale * block);
  m.add3x3(first + 3, first + 3, block);
  m.add3x3(first, first + 3, scale * block);
  m.add3x3(first + 3, first, scale * block.transpose());
  m.add(first + 2, first + 5, 0.25 * scale);  // a scalar call summed with a block's entry
}

Eigen::MatrixXd freshLines(const model::DofMap& dofs, double scaleA, double scaleB) {
  solver::SystemMatrix m(dofs);
  m.clear();
  fillLine(m, 0, scaleA);
  fillLine(m, 6, scaleB);
  SparseMatrix k;
  m.build(k);
  return Eigen::MatrixXd(k);
}

TEST(SystemMatrix, PatchOfABlockReplacesItsEntriesOnly) {
  // A refresh of one independent block (NewtonIteration::refreshBlocks): the block's calls alone give its
  // entries of a whole assembly; the other block keeps the last build's.
  const model::DofMap dofs = twoLines();
  const int secondLine = dofs.equation(6);
  ASSERT_EQ(secondLine, 5);
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  m.clear();
  fillLine(m, 0, 1.0);
  fillLine(m, 6, 1.0);
  m.build(k);
  ASSERT_TRUE(m.beginPatch(secondLine, dofs.equationCount()));
  fillLine(m, 6, -3.0);
  ASSERT_TRUE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), freshLines(dofs, 1.0, -3.0));
  // The first block, then both: each patch starts from the last matrix.
  ASSERT_TRUE(m.beginPatch(0, secondLine));
  fillLine(m, 0, 2.0);
  ASSERT_TRUE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), freshLines(dofs, 2.0, -3.0));
  ASSERT_TRUE(m.beginPatch(0, dofs.equationCount()));
  fillLine(m, 0, 0.5);
  fillLine(m, 6, 0.5);
  ASSERT_TRUE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), freshLines(dofs, 0.5, 0.5));
  // A whole assembly after patches still replays the recorded sequence.
  m.clear();
  fillLine(m, 0, 1.5);
  fillLine(m, 6, 1.5);
  EXPECT_TRUE(m.replaying());
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), freshLines(dofs, 1.5, 1.5));
}

TEST(SystemMatrix, PatchRefusesCallsOutsideItsBlocksOrPattern) {
  const model::DofMap dofs = twoLines();
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  const auto assembleBoth = [&] {
    m.clear();
    fillLine(m, 0, 1.0);
    fillLine(m, 6, 1.0);
  };
  assembleBoth();
  // No build since the last clear: nothing to patch.
  EXPECT_FALSE(m.beginPatch(5, 11));
  m.build(k);
  const Eigen::MatrixXd built(k);
  // A call coupling the block to the other one (a call within the other block alone is ignored: not an
  // entry of the patch).
  ASSERT_TRUE(m.beginPatch(5, 11));
  fillLine(m, 6, 2.0);
  m.add(0, 0, 1.0);
  m.add(0, 6, 1.0);
  EXPECT_FALSE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), built);
  // The values are no longer a build: a patch is refused until the next whole assembly.
  EXPECT_FALSE(m.beginPatch(5, 11));
  assembleBoth();
  m.build(k);
  // An entry outside the built pattern (a contact made since the build) within the block.
  ASSERT_TRUE(m.beginPatch(5, 11));
  fillLine(m, 6, 2.0);
  m.add(6, 11, 1.0);
  EXPECT_FALSE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), built);
  // Fewer calls than the block's recorded ones (an element left out).
  assembleBoth();
  m.build(k);
  ASSERT_TRUE(m.beginPatch(5, 11));
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  m.add3x3(6, 6, block);
  EXPECT_FALSE(m.endPatch(k));
  EXPECT_EQ(Eigen::MatrixXd(k), built);
  // A target that is not the last build.
  assembleBoth();
  m.build(k);
  SparseMatrix other(3, 3);
  ASSERT_TRUE(m.beginPatch(5, 11));
  fillLine(m, 6, 2.0);
  EXPECT_FALSE(m.endPatch(other));
}

/// A line of four nodes: elements (n, n + 1) with their own scales, then a diagonal term per node.
void fillChain(solver::SystemMatrix& m, const std::array<double, 3>& elementScale,
               const std::array<double, 4>& nodeScale, int firstElement = 0, int lastElement = 2,
               int firstNode = 0, int lastNode = 3) {
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  for (int e = firstElement; e <= lastElement; ++e) {
    const double s = elementScale[static_cast<std::size_t>(e)];
    const int a = 3 * e, b = 3 * e + 3;
    m.add3x3(a, a, s * block);
    m.add3x3(a, b, -s * block);
    m.add3x3(b, a, -s * block.transpose());
    m.add3x3(b, b, s * block);
  }
  for (int n = firstNode; n <= lastNode; ++n) m.addDiagonal3(3 * n, nodeScale[static_cast<std::size_t>(n)]);
}

TEST(SystemMatrix, PatchOfAStretchReplacesTheEntriesOfItsRowsAndColumns) {
  // A refresh of a stretch of a line (node 1 of four): the part's calls (its elements and their nodes, as
  // Assembler::selectPart gives them) set every entry in node 1's rows and columns to a whole assembly's;
  // the other entries keep the last build's, also where the part's calls reach them (node 0's and 2's own
  // blocks, which elements outside the part also load).
  model::DofMap dofs;
  for (int n = 0; n < 4; ++n) dofs.addNode(3);
  dofs.finalize();
  const std::array<double, 3> oldElements{1.0, 2.0, 3.0}, newElements{-1.5, 0.5, 7.0};
  const std::array<double, 4> oldNodes{10.0, 20.0, 30.0, 40.0}, newNodes{11.0, 21.0, 31.0, 41.0};
  const auto fresh = [&](const std::array<double, 3>& e, const std::array<double, 4>& n) {
    solver::SystemMatrix f(dofs);
    f.clear();
    fillChain(f, e, n);
    SparseMatrix k;
    f.build(k);
    return Eigen::MatrixXd(k);
  };
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  m.clear();
  fillChain(m, oldElements, oldNodes);
  m.build(k);
  ASSERT_TRUE(m.beginPatch(3, 6));
  fillChain(m, newElements, newNodes, 0, 2, 0, 2);  // the part: elements 0-2 and nodes 0-2
  ASSERT_TRUE(m.endPatch(k));
  Eigen::MatrixXd expected = fresh(oldElements, oldNodes);
  const Eigen::MatrixXd updated = fresh(newElements, newNodes);
  expected.block(3, 0, 3, 12) = updated.block(3, 0, 3, 12);
  expected.block(0, 3, 12, 3) = updated.block(0, 3, 12, 3);
  EXPECT_EQ(Eigen::MatrixXd(k), expected);
  // A part that leaves out an element at the stretch: refused.
  ASSERT_TRUE(m.beginPatch(3, 6));
  fillChain(m, newElements, newNodes, 1, 2, 0, 2);
  EXPECT_FALSE(m.endPatch(k));
}

}  // namespace
}  // namespace tangle

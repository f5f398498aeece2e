// SystemMatrix::build: the scatter map reused for entries in the same order must give exactly the
// matrix a fresh setFromTriplets gives, and a changed pattern, a changed entry order or another target
// matrix must fall back to a full build (issue 8). Exact equality: the values are summed in the same
// order either way.

#include <gtest/gtest.h>

#include <Eigen/Dense>

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

Eigen::MatrixXd fresh(const solver::SystemMatrix& m, int n) {
  SparseMatrix k(n, n);
  k.setFromTriplets(m.triplets().begin(), m.triplets().end());
  return Eigen::MatrixXd(k);
}

void fill(solver::SystemMatrix& m, double scale, bool extra) {
  m.clear();
  Mat3 block;
  block << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  m.add3x3(0, 0, scale * block);
  m.add3x3(3, 3, block);
  m.add3x3(0, 3, scale * block);  // duplicates summed with the next one
  m.add3x3(0, 3, block);
  m.add3x3(3, 0, block.transpose());
  if (extra) m.add3x3(6, 3, 2.0 * block);
}

TEST(SystemMatrix, ReusedPatternGivesTheSameMatrixAsAFreshBuild) {
  const model::DofMap dofs = threeNodes();
  const int n = dofs.equationCount();
  solver::SystemMatrix m(dofs);
  SparseMatrix k;
  fill(m, 1.0, false);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(m, n));
  // Same entries, new values: scattered into the existing pattern.
  fill(m, -3.5, false);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(m, n));
  // A new entry (the pattern grows): a full build.
  fill(m, 2.0, true);
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(m, n));
  // Back to the smaller pattern, and into another matrix object.
  fill(m, 7.0, false);
  SparseMatrix other;
  m.build(other);
  EXPECT_EQ(Eigen::MatrixXd(other), fresh(m, n));
  m.build(k);
  EXPECT_EQ(Eigen::MatrixXd(k), fresh(m, n));
}

}  // namespace
}  // namespace tangle

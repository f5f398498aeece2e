#pragma once
/// @file SystemMatrix.hpp
/// Collects matrix contributions given in full-DOF numbering into a sparse matrix over the
/// equations (constrained DOFs dropped), and assembles residual vectors.

#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/DofMap.hpp"

namespace tangle::solver {

/// Triplet collector over equation numbers.
class SystemMatrix {
 public:
  explicit SystemMatrix(const model::DofMap& dofs) : m_dofs(&dofs) {}
  /// Removes all entries (keeps capacity).
  void clear() { m_triplets.clear(); }
  /// Adds v at (full DOF row, full DOF column); ignored when either DOF is constrained.
  void add(int row, int col, double v) {
    const int r = m_dofs->equation(row);
    const int c = m_dofs->equation(col);
    // Exact zeros are kept: dropping them would make the sparsity pattern depend on the values (e.g.
    // two grounded nodes at the same height) and force a new symbolic factorisation.
    if (r >= 0 && c >= 0) m_triplets.emplace_back(r, c, v);
  }
  /// Adds a dense block: rows/cols are the full DOF indices of the block's rows/columns.
  template <class Derived>
  void addBlock(const int* dofs, int n, const Eigen::MatrixBase<Derived>& block, double scale = 1.0) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) add(dofs[i], dofs[j], scale * block(i, j));
  }
  /// Adds s * I (3x3) at the translational DOFs of a node starting at full DOF `first`.
  void addDiagonal3(int first, double s) {
    for (int k = 0; k < 3; ++k) add(first + k, first + k, s);
  }
  /// Adds a 3x3 block at (rowFirst.., colFirst..).
  void add3x3(int rowFirst, int colFirst, const Mat3& m, double scale = 1.0) {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) add(rowFirst + i, colFirst + j, scale * m(i, j));
  }
  /// Builds the compressed sparse matrix (duplicates summed). When the entries come in the same
  /// positions as at the last build into the same matrix (the usual case: elements do not change,
  /// contacts rarely), the values are scattered into the existing pattern through a map computed once,
  /// instead of sorting the triplets again (issue 8: the rebuild cost more than the factorisation).
  void build(SparseMatrix& out) const;
  const std::vector<Triplet>& triplets() const { return m_triplets; }

 private:
  const model::DofMap* m_dofs;
  std::vector<Triplet> m_triplets;
  // Scatter cache of the last build: the (row, column) of every triplet, its index in the value array
  // of `m_built`, and that matrix's number of non-zeros.
  mutable std::vector<int> m_rows, m_cols, m_scatter;
  mutable const SparseMatrix* m_built = nullptr;
  mutable Eigen::Index m_builtNonZeros = -1;
};

}  // namespace tangle::solver

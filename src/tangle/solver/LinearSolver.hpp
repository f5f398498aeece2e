#pragma once
/// @file LinearSolver.hpp
/// Sparse direct solve of the Newton systems. Uses Eigen's simplicial LDL^T with AMD ordering
/// (the systems are symmetric apart from friction terms, whose non-symmetric part is dropped: Newton
/// then converges linearly instead of quadratically where friction slides) and falls back to sparse
/// LU when the factorisation fails. The symbolic analysis is reused while the sparsity pattern does
/// not change.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "tangle/core/Types.hpp"

namespace tangle::solver {

/// Factorises and solves K x = b.
class LinearSolver {
 public:
  /// Factorises k. Returns false if the matrix is singular for both methods.
  bool factorize(const SparseMatrix& k);
  /// Solves with the last factorisation.
  VecX solve(const VecX& b) const;

 private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> m_ldlt;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> m_lu;
  bool m_useLu = false;
  bool m_analysed = false;
  Eigen::Index m_rows = -1;
  std::vector<int> m_outer;
  std::vector<int> m_inner;
};

}  // namespace tangle::solver

#pragma once
/// @file LinearSolver.hpp
/// Sparse direct solve of the Newton systems. Two methods:
/// - Banded (dynamics, by choice of the caller): an envelope LDL^T in the equation order (SkylineLdlt),
///   used when the envelope is small against the matrix (lines numbered node after node, coupled at their
///   ends, through vessels or by a few contacts); one factorisation and solve cost a few passes over the
///   band (issue 8; docs/performance.md).
/// - General: Eigen's simplicial LDL^T with AMD ordering, for any pattern (and when the banded
///   factorisation meets a vanishing pivot). The systems are symmetric apart from friction terms, whose
///   non-symmetric part is dropped: Newton then converges linearly instead of quadratically where
///   friction slides. Falls back to sparse LU when the factorisation fails.
/// The symbolic analysis is reused while the sparsity pattern does not change.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/solver/SkylineLdlt.hpp"

namespace tangle::solver {

/// Factorises and solves K x = b.
class LinearSolver {
 public:
  /// `allowBanded`: use the envelope LDL^T when the pattern suits it (see the class comment).
  explicit LinearSolver(bool allowBanded = false) : m_allowBanded(allowBanded) {}
  /// Factorises k. Returns false if the matrix is singular for every method.
  bool factorize(const SparseMatrix& k);
  /// Factorises again the listed independent blocks of the last factorisation (blockCount; ascending) from
  /// `k`, whose other blocks must equal the last factorised matrix's: SkylineLdlt::factorizeBlocks. False
  /// (the caller factorises the whole matrix) unless the last factorisation is the banded one of k's pattern.
  bool factorizeBlocks(const SparseMatrix& k, const std::vector<int>& blocks);
  /// Factorises again what changes in block `block` of the last factorisation when k's entries in the rows
  /// and columns [begin, end) changed (SkylineLdlt::factorizeRows); the same conditions as factorizeBlocks
  /// (and the fixed-width band).
  bool factorizeRows(const SparseMatrix& k, int block, int begin, int end);
  /// Solves with the last factorisation.
  VecX solve(const VecX& b) const;
  /// Overwrites b with the solution (no allocation on the banded path).
  void solveInPlace(VecX& b) const;
  /// Allows or forbids the banded method from the next analysis on (the pattern is analysed again).
  void setAllowBanded(bool allow) {
    m_allowBanded = allow;
    m_analysed = false;
  }
  /// Treats the next matrices as non-symmetric (statics with the drag's follower stiffness): a sparse LU
  /// with COLAMD ordering, its symbolic analysis reused while the pattern does not change. The symmetric
  /// methods read one triangle only, so they must not see a non-symmetric matrix.
  void setNonSymmetric(bool nonSymmetric) {
    if (nonSymmetric != m_nonSymmetric) m_analysed = false;
    m_nonSymmetric = nonSymmetric;
  }
  /// Independent blocks of the last factorisation (SkylineLdlt::blockCount): consecutive equation ranges
  /// not coupled to each other. With the general methods one block, the whole system.
  int blockCount() const { return m_method == Method::Banded ? m_skyline.blockCount() : 1; }
  /// First equation of block k (k = blockCount(): the equation count).
  int blockStart(int k) const {
    if (m_method == Method::Banded) return m_skyline.blockStart(k);
    return k == 0 ? 0 : static_cast<int>(m_rows);
  }
  /// Overwrites the listed blocks' entries of b (ascending block indices) with those of the solution; the
  /// others are left as they are. Solving all blocks is solveInPlace.
  void solveBlocksInPlace(VecX& b, const std::vector<int>& blocks) const {
    if (m_method == Method::Banded)
      m_skyline.solveBlocksInPlace(b, blocks);
    else if (!blocks.empty())
      solveInPlace(b);
  }
  /// True when the last factorisation is the banded one.
  bool usedBanded() const { return m_method == Method::Banded; }
  /// True when factorizeRows can follow: the last factorisation is on the fixed-width band.
  bool canFactorizeRows() const { return m_method == Method::Banded && m_skyline.bandWidth() > 0; }
  /// True when factorizeRows can follow on the envelope (the rows from its `begin` to the block's end).
  bool canFactorizeEnvelopeRows() const { return m_method == Method::Banded && m_skyline.bandWidth() == 0; }

 private:
  enum class Method { Banded, Ldlt, Lu };
  /// True when the last factorisation is the banded one and k has its pattern (factorizeBlocks,
  /// factorizeRows).
  bool samePatternAsBanded(const SparseMatrix& k) const;
  bool m_allowBanded;
  Method m_method = Method::Ldlt;
  SkylineLdlt m_skyline;
  bool m_bandedSuits = false;  // the envelope of the analysed pattern is small enough
  /// The general LDL^T: Eigen's simplicial factorisation of P K P^T (upper triangle), P the AMD ordering of K
  /// as Eigen's SimplicialLDLT<Lower, AMDOrdering> computes it. The permuted matrix's structure is made once
  /// per pattern and its values copied in at each factorisation through m_permutedSource: the same matrix,
  /// in the same entry order, as Eigen's own permutation of K at every factorisation (twistedBy, 0.26 G of
  /// drilling-riser-drift's 53 G instructions), so the same factor to the bit.
  void analyzeLdlt(const SparseMatrix& k);
  /// x = (L D L^T)^-1 x with m_ldlt's factors (its ordering applied by the caller).
  void solveLdltInPlace(VecX& x) const;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> m_ldlt;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> m_ldltP, m_ldltPinv;
  SparseMatrix m_permuted;            // upper triangle of P K P^T
  std::vector<int> m_permutedSource;  // per stored entry of m_permuted: the index of its value in K's
  mutable VecX m_ldltWork;            // P b and the solution before P^-1 (solveInPlace)
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> m_lu;
  bool m_analysed = false;      // pattern recorded (and the envelope analysed when allowed)
  bool m_ldltAnalysed = false;  // Eigen's symbolic analysis done for the recorded pattern
  bool m_luAnalysed = false;    // the LU's symbolic analysis done for the recorded pattern
  bool m_nonSymmetric = false;
  Eigen::Index m_rows = -1;
  std::vector<int> m_outer;
  std::vector<int> m_inner;
};

}  // namespace tangle::solver

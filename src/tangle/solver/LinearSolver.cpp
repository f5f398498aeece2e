#include "tangle/solver/LinearSolver.hpp"

#include <algorithm>

namespace tangle::solver {

bool LinearSolver::factorize(const SparseMatrix& k) {
  // Re-analyse only when the pattern changed (contacts appear and vanish; elements do not).
  const bool samePattern = m_analysed && k.rows() == m_rows &&
                           static_cast<int>(m_inner.size()) == k.nonZeros() &&
                           std::equal(m_outer.begin(), m_outer.end(), k.outerIndexPtr()) &&
                           std::equal(m_inner.begin(), m_inner.end(), k.innerIndexPtr());
  if (!samePattern) {
    m_rows = k.rows();
    m_outer.assign(k.outerIndexPtr(), k.outerIndexPtr() + k.outerSize() + 1);
    m_inner.assign(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros());
    m_analysed = true;
    m_ldltAnalysed = false;
    m_luAnalysed = false;
    m_bandedSuits = false;
    if (m_allowBanded && !m_nonSymmetric && k.rows() > 0) {
      // The envelope suits when one factorisation costs no more than a few multiply-adds per stored
      // entry of the matrix (a band: ~3 per entry), i.e. the coupling between distant equations is rare.
      m_skyline.analyzePattern(k);
      m_bandedSuits = m_skyline.factorizationCost() <= 8.0 * static_cast<double>(k.nonZeros()) + 64.0;
    }
  }
  if (m_nonSymmetric) {
    m_method = Method::Lu;
    if (!m_luAnalysed) {
      m_lu.analyzePattern(k);
      m_luAnalysed = true;
    }
    m_lu.factorize(k);
    return m_lu.info() == Eigen::Success;
  }
  if (m_bandedSuits && m_skyline.factorize(k)) {
    m_method = Method::Banded;
    return true;
  }
  if (!m_ldltAnalysed) {
    analyzeLdlt(k);
    m_ldltAnalysed = true;
  }
  double* permuted = m_permuted.valuePtr();
  const double* values = k.valuePtr();
  for (std::size_t i = 0; i < m_permutedSource.size(); ++i) permuted[i] = values[m_permutedSource[i]];
  m_ldlt.factorize(m_permuted);
  bool useLu = m_ldlt.info() != Eigen::Success;
  if (!useLu) {
    // LDL^T without pivoting can "succeed" on a numerically singular matrix: check the pivots.
    const VecX d = m_ldlt.vectorD();
    const double dmax = d.cwiseAbs().maxCoeff();
    useLu = d.size() > 0 && d.cwiseAbs().minCoeff() <= 1e-14 * dmax;
  }
  if (useLu) {
    m_method = Method::Lu;
    m_lu.compute(k);
    m_luAnalysed = true;
    return m_lu.info() == Eigen::Success;
  }
  m_method = Method::Ldlt;
  return true;
}

void LinearSolver::analyzeLdlt(const SparseMatrix& k) {
  // The ordering as SimplicialCholeskyBase::ordering makes it (Eigen 3.4): AMD of the full symmetric matrix
  // from K's lower triangle, P its inverse.
  {
    SparseMatrix full;
    full = k.selfadjointView<Eigen::Lower>();
    Eigen::AMDOrdering<int> amd;
    amd(full, m_ldltPinv);
  }
  if (m_ldltPinv.size() > 0)
    m_ldltP = m_ldltPinv.inverse();
  else
    m_ldltP.resize(0);
  // The permuted structure, with each entry's source found by permuting the indices (1-based, exact in a
  // double) instead of the values.
  SparseMatrix index = k;
  for (Eigen::Index i = 0; i < index.nonZeros(); ++i) index.valuePtr()[i] = static_cast<double>(i + 1);
  m_permuted.resize(k.rows(), k.cols());
  m_permuted.selfadjointView<Eigen::Upper>() = index.selfadjointView<Eigen::Lower>().twistedBy(m_ldltP);
  m_permutedSource.resize(static_cast<std::size_t>(m_permuted.nonZeros()));
  for (std::size_t i = 0; i < m_permutedSource.size(); ++i)
    m_permutedSource[i] = static_cast<int>(m_permuted.valuePtr()[i]) - 1;
  m_ldlt.analyzePattern(m_permuted);
}

bool LinearSolver::samePatternAsBanded(const SparseMatrix& k) const {
  // The pattern's outer index only: a changed pattern changes it (entries in other columns) or the
  // count; an identical count and column layout with other rows would need a contact made and another
  // released between two refreshes, which a refresh of the whole matrix handles anyway (SystemMatrix's patch
  // fails on an entry outside the built pattern).
  return m_method == Method::Banded && k.rows() == m_rows &&
         static_cast<int>(m_inner.size()) == k.nonZeros() &&
         std::equal(m_outer.begin(), m_outer.end(), k.outerIndexPtr());
}

bool LinearSolver::factorizeBlocks(const SparseMatrix& k, const std::vector<int>& blocks) {
  // On false the factors are partly overwritten: the caller factorises the whole matrix before solving.
  return samePatternAsBanded(k) && m_skyline.factorizeBlocks(k, blocks);
}

bool LinearSolver::factorizeRows(const SparseMatrix& k, int block, int begin, int end) {
  return samePatternAsBanded(k) && m_skyline.factorizeRows(k, block, begin, end);
}

void LinearSolver::solveLdltInPlace(VecX& x) const {
  const bool offDiagonal = m_ldlt.matrixL().nestedExpression().nonZeros() > 0;
  if (offDiagonal) m_ldlt.matrixL().solveInPlace(x);
  const VecX& d = m_ldlt.vectorD();
  if (d.size() > 0)
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = (1.0 / d[i]) * x[i];  // D^-1 as a diagonal product
  if (offDiagonal) m_ldlt.matrixU().solveInPlace(x);
}

VecX LinearSolver::solve(const VecX& b) const {
  VecX x = b;
  solveInPlace(x);
  return x;
}

void LinearSolver::solveInPlace(VecX& b) const {
  switch (m_method) {
    case Method::Banded: m_skyline.solveInPlace(b); return;
    case Method::Ldlt:
      // x = P^-1 (LDL^T)^-1 P b, as SimplicialLDLT's own solve with its ordering, step by step in a kept
      // vector (SimplicialLDLT::_solve_impl's operations in its order: the same bits; the two temporaries
      // of the expression were allocated and copied at every solve, 0.1 G instructions of
      // drilling-riser-drift's run).
      if (m_ldltP.size() > 0) {
        VecX& w = m_ldltWork;
        w.resize(b.size());
        const int* p = m_ldltP.indices().data();
        for (Eigen::Index i = 0; i < b.size(); ++i) w[p[i]] = b[i];
        solveLdltInPlace(w);
        const int* pinv = m_ldltPinv.indices().data();
        for (Eigen::Index i = 0; i < b.size(); ++i) b[pinv[i]] = w[i];
      } else {
        solveLdltInPlace(b);
      }
      return;
    case Method::Lu: b = m_lu.solve(b); return;
  }
}

}  // namespace tangle::solver

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
    m_ldlt.analyzePattern(k);
    m_ldltAnalysed = true;
  }
  m_ldlt.factorize(k);
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

VecX LinearSolver::solve(const VecX& b) const {
  VecX x = b;
  solveInPlace(x);
  return x;
}

void LinearSolver::solveInPlace(VecX& b) const {
  switch (m_method) {
    case Method::Banded: m_skyline.solveInPlace(b); return;
    case Method::Ldlt: b = m_ldlt.solve(b); return;
    case Method::Lu: b = m_lu.solve(b); return;
  }
}

}  // namespace tangle::solver

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
    m_ldlt.analyzePattern(k);
    m_rows = k.rows();
    m_outer.assign(k.outerIndexPtr(), k.outerIndexPtr() + k.outerSize() + 1);
    m_inner.assign(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros());
    m_analysed = true;
  }
  m_ldlt.factorize(k);
  m_useLu = m_ldlt.info() != Eigen::Success;
  if (!m_useLu) {
    // LDL^T without pivoting can "succeed" on a numerically singular matrix: check the pivots.
    const VecX d = m_ldlt.vectorD();
    const double dmax = d.cwiseAbs().maxCoeff();
    m_useLu = d.size() > 0 && d.cwiseAbs().minCoeff() <= 1e-14 * dmax;
  }
  if (m_useLu) {
    m_lu.compute(k);
    return m_lu.info() == Eigen::Success;
  }
  return true;
}

VecX LinearSolver::solve(const VecX& b) const { return m_useLu ? VecX(m_lu.solve(b)) : VecX(m_ldlt.solve(b)); }

}  // namespace tangle::solver

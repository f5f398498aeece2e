#include "tangle/solver/SystemMatrix.hpp"

#include <algorithm>

namespace tangle::solver {

void SystemMatrix::clear() {
  m_triplets.clear();
  m_cursor = 0;
  m_replaying = m_recorded;
  m_replayCount = m_replaying ? m_calls.size() : 0;
  if (m_replaying)
    std::fill(m_values.begin(), m_values.end(), 0.0);
  else
    m_calls.clear();
}

void SystemMatrix::addRecorded(int row, int col, double v) {
  if (m_replaying) startRecording();
  m_calls.push_back({row, col, -1});
  const int r = m_dofs->equation(row);
  const int c = m_dofs->equation(col);
  // Exact zeros are kept: dropping them would make the sparsity pattern depend on the values (e.g.
  // two grounded nodes at the same height) and force a new symbolic factorisation.
  if (r >= 0 && c >= 0) m_triplets.emplace_back(r, c, v);
}

void SystemMatrix::startRecording() {
  // The entries the replayed calls summed, once each (in the order of their first call; the sums are
  // already formed, so build adds nothing else to them).
  m_triplets.clear();
  std::vector<char> taken(m_values.size(), 0);
  for (std::size_t k = 0; k < m_cursor; ++k) {
    const int p = m_calls[k].position;
    if (p < 0 || taken[static_cast<std::size_t>(p)]) continue;
    taken[static_cast<std::size_t>(p)] = 1;
    m_triplets.emplace_back(m_dofs->equation(m_calls[k].row), m_dofs->equation(m_calls[k].col),
                            m_values[static_cast<std::size_t>(p)]);
  }
  m_calls.resize(m_cursor);
  m_replaying = false;
  m_replayCount = 0;
  m_recorded = false;
}

void SystemMatrix::build(SparseMatrix& out) {
  const int n = m_dofs->equationCount();
  if (m_replaying && m_cursor < m_calls.size()) startRecording();  // fewer calls than recorded
  if (m_replaying) {
    const bool samePattern = out.rows() == n && out.cols() == n && out.isCompressed() &&
                             out.nonZeros() == static_cast<Eigen::Index>(m_values.size()) &&
                             std::equal(m_outer.begin(), m_outer.end(), out.outerIndexPtr()) &&
                             std::equal(m_inner.begin(), m_inner.end(), out.innerIndexPtr());
    if (samePattern) {
      std::copy(m_values.begin(), m_values.end(), out.valuePtr());
    } else {
      out = Eigen::Map<const SparseMatrix>(n, n, static_cast<Eigen::Index>(m_values.size()), m_outer.data(),
                                           m_inner.data(), m_values.data());
    }
    return;
  }
  out.resize(n, n);
  out.setFromTriplets(m_triplets.begin(), m_triplets.end());
  out.makeCompressed();
  // The sequence for the next assemblies: where each call's entry lies in the value array.
  m_outer.assign(out.outerIndexPtr(), out.outerIndexPtr() + n + 1);
  m_inner.assign(out.innerIndexPtr(), out.innerIndexPtr() + out.nonZeros());
  m_values.assign(out.valuePtr(), out.valuePtr() + out.nonZeros());
  for (Call& call : m_calls) {
    const int r = m_dofs->equation(call.row), c = m_dofs->equation(call.col);
    if (r < 0 || c < 0) {
      call.position = -1;
      continue;
    }
    const int* found = std::lower_bound(m_inner.data() + m_outer[c], m_inner.data() + m_outer[c + 1], r);
    call.position = static_cast<int>(found - m_inner.data());
  }
  m_recorded = true;
}

}  // namespace tangle::solver

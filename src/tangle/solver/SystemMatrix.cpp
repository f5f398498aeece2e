#include "tangle/solver/SystemMatrix.hpp"

#include <algorithm>

namespace tangle::solver {

void SystemMatrix::build(SparseMatrix& out) const {
  const int n = m_dofs->equationCount();
  const std::size_t count = m_triplets.size();
  bool reuse = m_built == &out && out.rows() == n && out.cols() == n && out.nonZeros() == m_builtNonZeros &&
               out.isCompressed() && m_rows.size() == count;
  for (std::size_t k = 0; reuse && k < count; ++k)
    reuse = m_rows[k] == m_triplets[k].row() && m_cols[k] == m_triplets[k].col();
  if (reuse) {
    double* values = out.valuePtr();
    std::fill(values, values + out.nonZeros(), 0.0);
    for (std::size_t k = 0; k < count; ++k) values[m_scatter[k]] += m_triplets[k].value();
    return;
  }
  out.resize(n, n);
  out.setFromTriplets(m_triplets.begin(), m_triplets.end());
  out.makeCompressed();
  // The map for the next builds: position of each triplet's (row, column) in the column-major arrays.
  m_rows.resize(count);
  m_cols.resize(count);
  m_scatter.resize(count);
  const int* outer = out.outerIndexPtr();
  const int* inner = out.innerIndexPtr();
  for (std::size_t k = 0; k < count; ++k) {
    const int r = m_triplets[k].row(), c = m_triplets[k].col();
    m_rows[k] = r;
    m_cols[k] = c;
    const int* found = std::lower_bound(inner + outer[c], inner + outer[c + 1], r);
    m_scatter[k] = static_cast<int>(found - inner);
  }
  m_built = &out;
  m_builtNonZeros = out.nonZeros();
}

}  // namespace tangle::solver

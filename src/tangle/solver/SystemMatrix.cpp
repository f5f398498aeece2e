#include "tangle/solver/SystemMatrix.hpp"

#include <algorithm>

namespace tangle::solver {

void SystemMatrix::clear() {
  m_built = false;
  m_patch = nullptr;
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
  if (m_patch) {
    addPatched(row, col, v);
    return;
  }
  if (m_replaying) startRecording();
  m_calls.push_back({row, col, {-1, -1, -1}, false});
  const int r = m_dofs->equation(row);
  const int c = m_dofs->equation(col);
  // Exact zeros are kept: dropping them would make the sparsity pattern depend on the values (e.g.
  // two grounded nodes at the same height) and force a new symbolic factorisation.
  if (r >= 0 && c >= 0) m_triplets.emplace_back(r, c, v);
}

void SystemMatrix::add3x3Recorded(int rowFirst, int colFirst, const Mat3& m) {
  if (m_patch) {
    add3x3Patched(rowFirst, colFirst, m);
    return;
  }
  if (m_replaying) startRecording();
  const int r = m_dofs->equation(rowFirst), c = m_dofs->equation(colFirst);
  bool whole = r >= 0 && c >= 0;
  for (int k = 1; k < 3 && whole; ++k)
    whole = m_dofs->equation(rowFirst + k) == r + k && m_dofs->equation(colFirst + k) == c + k;
  if (!whole) {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) addRecorded(rowFirst + i, colFirst + j, m(i, j));
    return;
  }
  m_calls.push_back({rowFirst, colFirst, {-1, -1, -1}, true});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m_triplets.emplace_back(r + i, c + j, m(i, j));
}

void SystemMatrix::startRecording() {
  // The entries the replayed calls summed, once each (in the order of their first call; the sums are
  // already formed, so build adds nothing else to them).
  m_triplets.clear();
  std::vector<char> taken(m_values.size(), 0);
  const auto take = [&](int p, int row, int col) {
    if (p < 0 || taken[static_cast<std::size_t>(p)]) return;
    taken[static_cast<std::size_t>(p)] = 1;
    m_triplets.emplace_back(m_dofs->equation(row), m_dofs->equation(col),
                            m_values[static_cast<std::size_t>(p)]);
  };
  for (std::size_t k = 0; k < m_cursor; ++k) {
    const Call& call = m_calls[k];
    if (!call.block) {
      take(call.position[0], call.row, call.col);
      continue;
    }
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        take(call.position[static_cast<std::size_t>(j)] + i, call.row + i, call.col + j);
  }
  m_calls.resize(m_cursor);
  m_patchSequences.clear();
  m_stretchValid = false;
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
    m_built = true;
    return;
  }
  out.resize(n, n);
  out.setFromTriplets(m_triplets.begin(), m_triplets.end());
  out.makeCompressed();
  // The sequence for the next assemblies: where each call's entry lies in the value array.
  m_outer.assign(out.outerIndexPtr(), out.outerIndexPtr() + n + 1);
  m_inner.assign(out.innerIndexPtr(), out.innerIndexPtr() + out.nonZeros());
  m_values.assign(out.valuePtr(), out.valuePtr() + out.nonZeros());
  const auto positionOf = [&](int r, int c) {
    const int* found = std::lower_bound(m_inner.data() + m_outer[c], m_inner.data() + m_outer[c + 1], r);
    return static_cast<int>(found - m_inner.data());
  };
  m_patchSequences.clear();
  m_stretchValid = false;
  for (Call& call : m_calls) {
    const int r = m_dofs->equation(call.row), c = m_dofs->equation(call.col);
    if (call.block) {
      // Rows r, r + 1, r + 2 are in each of the columns, consecutive in its sorted row list.
      for (int j = 0; j < 3; ++j) call.position[static_cast<std::size_t>(j)] = positionOf(r, c + j);
      continue;
    }
    call.position[0] = r < 0 || c < 0 ? -1 : positionOf(r, c);
  }
  m_recorded = true;
  m_built = true;
}

void SystemMatrix::selectPatchCalls(const std::vector<std::size_t>* from, int begin, int end,
                                    PatchSequence& sequence) const {
  // A block call's rows and columns are one node's: in the range together.
  sequence.begin = begin;
  sequence.end = end;
  sequence.calls.clear();
  sequence.positions.clear();
  const auto inRange = [&](int dof) {
    const int e = m_dofs->equation(dof);
    return e >= begin && e < end;
  };
  const std::size_t count = from ? from->size() : m_calls.size();
  for (std::size_t q = 0; q < count; ++q) {
    const std::size_t k = from ? (*from)[q] : q;
    const Call& call = m_calls[k];
    if ((!call.block && call.position[0] < 0) || !(inRange(call.row) || inRange(call.col))) continue;
    sequence.calls.push_back(k);
    if (!call.block) {
      sequence.positions.push_back(call.position[0]);
      continue;
    }
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        sequence.positions.push_back(call.position[static_cast<std::size_t>(j)] + i);
  }
}

bool SystemMatrix::beginPatch(int begin, int end, int blockBegin, int blockEnd) {
  if (!m_built || m_patch) return false;
  auto block = std::find_if(m_patchSequences.begin(), m_patchSequences.end(), [&](const PatchSequence& p) {
    return p.begin == blockBegin && p.end == blockEnd;
  });
  if (block == m_patchSequences.end()) {
    // The block's calls from the whole sequence, once (a scan of every call: 67 000 on 12 mooring lines).
    if (m_patchSequences.size() >= kKeptPatchSequences) m_patchSequences.clear();
    m_patchSequences.emplace_back();
    selectPatchCalls(nullptr, blockBegin, blockEnd, m_patchSequences.back());
    block = m_patchSequences.end() - 1;
  }
  if (begin == blockBegin && end == blockEnd) {
    m_patch = &*block;
  } else {
    // The last stretch's calls are kept while the sequence is (the same range again: the lines from one on
    // in a block of lines coupled by a contact, refreshed at nearly every step; selected anew each time
    // they were 6.5 % of examples/flexibles-at-touchdown's instructions).
    if (!m_stretchValid || m_stretch.begin != begin || m_stretch.end != end ||
        m_stretchBlock != std::array<int, 2>{blockBegin, blockEnd}) {
      selectPatchCalls(&block->calls, begin, end, m_stretch);
      m_stretchBlock = {blockBegin, blockEnd};
      m_stretchValid = true;
    }
    m_patch = &m_stretch;
  }
  for (const int p : m_patch->positions) m_values[static_cast<std::size_t>(p)] = 0.0;
  // The inline add and add3x3 replay while m_cursor < m_replayCount: with no count they come to
  // addRecorded / add3x3Recorded, which replay the patch's subsequence.
  m_replayCountBeforePatch = m_replayCount;
  m_replayCount = 0;
  m_patchCursor = 0;
  m_patchFailed = false;
  return true;
}

void SystemMatrix::addPatched(int row, int col, double v) {
  if (m_patchCursor < m_patch->calls.size()) {
    const Call& c = m_calls[m_patch->calls[m_patchCursor]];
    if (!c.block && c.row == row && c.col == col) {
      ++m_patchCursor;
      m_values[static_cast<std::size_t>(c.position[0])] += v;
      return;
    }
  }
  const int r = m_dofs->equation(row), c = m_dofs->equation(col);
  if (r < 0 || c < 0) return;  // no entry, as in an assembly
  if ((r < m_patch->begin || r >= m_patch->end) && (c < m_patch->begin || c >= m_patch->end)) return;
  m_patchFailed = true;
}

void SystemMatrix::add3x3Patched(int rowFirst, int colFirst, const Mat3& m) {
  if (m_patchCursor < m_patch->calls.size()) {
    const Call& c = m_calls[m_patch->calls[m_patchCursor]];
    if (c.block && c.row == rowFirst && c.col == colFirst) {
      ++m_patchCursor;
      for (int j = 0; j < 3; ++j) {
        double* v = m_values.data() + c.position[static_cast<std::size_t>(j)];
        for (int i = 0; i < 3; ++i) v[i] += m(i, j);
      }
      return;
    }
  }
  // Not the next call of the patch: ignored when every row and column of the block lies outside the patch (a
  // part's other entries: the elements beside a contact's nodes in a refresh of the lines coupled to them,
  // 2.5 % of examples/flexibles-at-touchdown's instructions entry by entry), else entry by entry (a failed
  // patch, or constrained DOFs).
  const auto outside = [&](int dof) {
    const int e = m_dofs->equation(dof);
    return e < m_patch->begin || e >= m_patch->end;  // also a constrained DOF (-1)
  };
  if (outside(rowFirst) && outside(rowFirst + 1) && outside(rowFirst + 2) && outside(colFirst) &&
      outside(colFirst + 1) && outside(colFirst + 2))
    return;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) addPatched(rowFirst + i, colFirst + j, m(i, j));
}

bool SystemMatrix::endPatch(SparseMatrix& out) {
  if (!m_patch) return false;
  const PatchSequence& patch = *m_patch;
  m_patch = nullptr;
  m_replayCount = m_replayCountBeforePatch;
  const int n = m_dofs->equationCount();
  const bool ok = !m_patchFailed && m_patchCursor == patch.calls.size() && out.rows() == n &&
                  out.cols() == n && out.isCompressed() &&
                  out.nonZeros() == static_cast<Eigen::Index>(m_values.size()) &&
                  std::equal(m_outer.begin(), m_outer.end(), out.outerIndexPtr());
  if (!ok) {
    m_built = false;  // the values are neither the last build nor a whole assembly
    return false;
  }
  double* target = out.valuePtr();
  for (const int p : patch.positions) target[p] = m_values[static_cast<std::size_t>(p)];
  return true;
}

}  // namespace tangle::solver

#pragma once
/// @file PendingSum.hpp
/// Scatter-adds into a vector with the last entry's running sum held in registers.
///
/// An assembly loop over a line's elements adds each element's terms to its two nodes, and element e's
/// second node is element e + 1's first: `f[d] += a` then, one element later, `f[d] += b`. The second add
/// must wait until the first store has been forwarded to its load (about 5 cycles) and its own add done (4):
/// where the terms are cheap to compute (the weight, the inertia), that chain through memory was most of
/// the loop's time (a coupled host's chain, docs/performance.md). PendingSum keeps the block last added to in
/// registers and stores it when a different block is added to (or at the end), so that a run of adds to one
/// block is a chain of register adds. The sums are formed in the same order as the plain scatter, so the
/// results are the same bits.

#include <array>

namespace tangle {

/// Adds blocks of N consecutive entries into `data` (f[i + k] += v[k]), deferring the store of the block
/// last added to until another block is added to or flush() (also called by the destructor). Reads of
/// `data` by others between adds see the pending block's old values: flush first.
template <int N>
class PendingSum {
 public:
  explicit PendingSum(double* data) : m_data(data) {}
  PendingSum(const PendingSum&) = delete;
  PendingSum& operator=(const PendingSum&) = delete;
  ~PendingSum() { flush(); }

  /// data[index + k] += v[k] for k < N, in the order of the calls.
  template <class Block>
  void add(int index, const Block& v) {
    if (index != m_index) {
      flush();
      m_index = index;
      for (int k = 0; k < N; ++k) m_sum[k] = m_data[index + k];
    }
    for (int k = 0; k < N; ++k) m_sum[k] += v[k];
  }
  /// data[index] += v (N = 1).
  void add(int index, double v) {
    static_assert(N == 1, "a scalar add is for blocks of one entry");
    add(index, std::array<double, 1>{v});
  }
  /// Stores the pending block.
  void flush() {
    if (m_index < 0) return;
    for (int k = 0; k < N; ++k) m_data[m_index + k] = m_sum[k];
    m_index = -1;
  }

 private:
  double* m_data;
  int m_index = -1;  // the first entry of the pending block, -1 for none
  std::array<double, N> m_sum{};
};

}  // namespace tangle

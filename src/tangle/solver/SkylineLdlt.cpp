#include "tangle/solver/SkylineLdlt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace tangle::solver {

namespace {
constexpr std::ptrdiff_t kUpper = std::numeric_limits<std::ptrdiff_t>::min();

/// sum_k a[k] b[k] over k in [0, n), in four independent partial sums: the rows of a line's band are 3 to
/// 11 long, and one running sum makes each product wait for the previous one (the forward substitution
/// was latency-bound).
inline double dot(const double* a, const double* b, std::ptrdiff_t n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::ptrdiff_t k = 0;
  for (; k + 3 < n; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < n; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

/// Calls f(std::integral_constant<int, W>{}) for the band width w in [1, SkylineLdlt::kMaxBandWidth] (the
/// kernels are compiled per width: their rows' products a fixed count).
template <class F>
decltype(auto) withBandWidth(int w, F&& f) {
  switch (w) {
    case 1:
      return f(std::integral_constant<int, 1>{});
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    case 7:
      return f(std::integral_constant<int, 7>{});
    case 8:
      return f(std::integral_constant<int, 8>{});
    case 9:
      return f(std::integral_constant<int, 9>{});
    case 10:
      return f(std::integral_constant<int, 10>{});
    case 11:
      return f(std::integral_constant<int, 11>{});
    default:
      return f(std::integral_constant<int, 12>{});
  }
}

/// One row of the forward substitution L y = b on a band of fixed width W: row i's entries L(i, i + Direction
/// d) at rows[i W + W - d] (Direction -1: top-down, +1: the mirror, from the bottom), `reach` of them; the
/// unknown found just before (`previous`, distance 1) held apart, so one multiply-add lies on the chain from
/// one unknown to the next. A full row (reach W) takes a loop of constant count: one loop over the varying
/// reach for all rows made the solve 45 % slower (4.8 -> 7.1 ns per equation, bar line). Returns y_i.
template <int W, int Direction>
inline double forwardRow(const double* rows, double* x, int i, int reach, double previous) {
  const double* row = rows + static_cast<std::ptrdiff_t>(i) * W;
  double sum = 0.0;
  if (reach == W) {
    for (int d = W; d >= 2; --d) sum += row[W - d] * x[i + Direction * d];
  } else {
    for (int d = reach; d >= 2; --d) sum += row[W - d] * x[i + Direction * d];
  }
  const double y = reach >= 1 ? (x[i] - sum) - row[W - 1] * previous : x[i];
  x[i] = y;
  return y;
}

/// One row of the backward substitution L^T x = z on the same band: x_i = z_i - sum_d L(i - Direction d, i)
/// x_{i - Direction d}, the entries read from the rows after (Direction -1) or before (+1) row i, `reach` of
/// them, the one at distance 1 (`next`) held apart. Returns x_i.
template <int W, int Direction>
inline double backwardRow(const double* rows, double* x, int i, int reach, double next) {
  const auto entry = [&](int d) { return rows[static_cast<std::ptrdiff_t>(i - Direction * d) * W + W - d]; };
  double sum = 0.0;
  if (reach == W) {
    for (int d = 2; d <= W; ++d) sum += entry(d) * x[i - Direction * d];
  } else {
    for (int d = 2; d <= reach; ++d) sum += entry(d) * x[i - Direction * d];
  }
  const double xi = reach >= 1 ? (x[i] - sum) - entry(1) * next : x[i];
  x[i] = xi;
  return xi;
}

/// Both substitutions over equations [begin, end) with L stored as a band of fixed width W: row i holds
/// L(i, i - W) ... L(i, i - 1) at band[i W + 0 .. W - 1], zero outside the envelope. The rows' products
/// have a fixed count (no loop over a row's varying length, no index array for the columns), and the
/// unknown found just before is held apart as in SkylineLdlt::solveRange. Reads stay inside [begin, end).
template <int W>
void bandSubstitutions(double* x, int begin, int end, const double* band, const double* inverseDiagonal) {
  double previous = 0.0;
  for (int i = begin; i < end; ++i)
    previous = forwardRow<W, -1>(band, x, i, std::min(W, i - begin), previous);
  for (int i = begin; i < end; ++i) x[i] *= inverseDiagonal[i];
  double next = 0.0;
  for (int i = end - 1; i >= begin; --i)
    next = backwardRow<W, -1>(band, x, i, std::min(W, end - 1 - i), next);
}

/// Both substitutions of a block [b0, b1) factorised from both ends (SkylineLdlt::factorize, "twisted"):
/// rows [b0, m) top-down with L in `band` (row i: L(i, i - d) at band[i W + W - d]), rows [m + W, b1)
/// bottom-up with L' in `bandUp` (row j: L'(j, j + d) at bandUp[j W + W - d]), the W rows [m, m + W) last,
/// their Schur complement's unit lower factor in `twist` (as a band of width W: row a holds L_S(a, a - d) at
/// twist[a W + W - d]) and its pivots' inverses in
/// inverseDiagonal with the others. The two ends' rows are independent chains, walked side by side: the
/// substitution of one row waits on the row before it (a multiply and a subtraction), so two chains
/// interleaved take about the time of one (bench/bench_linear_solve.cpp, same run: 5.5 -> 3.1 ns per equation
/// on a 201-node bar line, 8.6 -> 5.4 on a 100-node beam line). Block elimination: George & Liu 1981,
/// sec. 6.2 (a one-way dissection with one separator); the twisted factorisation of band matrices, e.g.
/// Meurant 1992, SIAM J. Matrix Anal. Appl. 13(3), 707-728.
template <int W>
void twistedSubstitutions(double* x, int b0, int b1, int m, const double* band, const double* bandUp,
                          const double* twist, const double* inverseDiagonal) {
  const int t1 = m + W;  // first row of the bottom part
  const int lenT = m - b0, lenB = b1 - t1;
  const int common = std::min(lenT, lenB);
  double previousTop = 0.0, previousBottom = 0.0;
  const auto forwardTop = [&](int i) {
    previousTop = forwardRow<W, -1>(band, x, i, std::min(W, i - b0), previousTop);
  };
  const auto forwardBottom = [&](int j) {
    previousBottom = forwardRow<W, 1>(bandUp, x, j, std::min(W, b1 - 1 - j), previousBottom);
  };
  for (int k = 0; k < common; ++k) {
    forwardTop(b0 + k);
    forwardBottom(b1 - 1 - k);
  }
  for (int k = common; k < lenT; ++k) forwardTop(b0 + k);
  for (int k = common; k < lenB; ++k) forwardBottom(b1 - 1 - k);
  // The separator: its rows' entries in the two parts' columns, then its own factor.
  for (int a = 0; a < W; ++a) {
    const int t = m + a;
    double y = x[t];
    const double* row = band + static_cast<std::ptrdiff_t>(t) * W;
    for (int k = std::max(t - W, b0); k < m; ++k) y -= row[W - (t - k)] * x[k];
    const double* up = bandUp + static_cast<std::ptrdiff_t>(t) * W;
    for (int k = t1; k <= std::min(t + W, b1 - 1); ++k) y -= up[W - (k - t)] * x[k];
    for (int c = 0; c < a; ++c) y -= twist[a * W + W - (a - c)] * x[m + c];
    x[t] = y;
  }
  for (int i = b0; i < b1; ++i) x[i] *= inverseDiagonal[i];
  for (int a = W - 1; a >= 0; --a) {
    double z = x[m + a];
    for (int c = a + 1; c < W; ++c) z -= twist[c * W + W - (c - a)] * x[m + c];
    x[m + a] = z;
  }
  for (int k = std::max(m - W, b0); k < m; ++k) {
    double z = x[k];
    for (int t = m; t <= std::min(k + W, t1 - 1); ++t)
      z -= band[static_cast<std::ptrdiff_t>(t) * W + W - (t - k)] * x[t];
    x[k] = z;
  }
  for (int k = t1; k < std::min(t1 + W, b1); ++k) {
    double z = x[k];
    for (int t = std::max(k - W, m); t < t1; ++t)
      z -= bandUp[static_cast<std::ptrdiff_t>(t) * W + W - (k - t)] * x[t];
    x[k] = z;
  }
  // Back from the separator to both ends, side by side.
  double nextTop = 0.0, nextBottom = 0.0;
  const auto backwardTop = [&](int i) {
    nextTop = backwardRow<W, -1>(band, x, i, std::min(W, m - 1 - i), nextTop);
  };
  const auto backwardBottom = [&](int j) {
    nextBottom = backwardRow<W, 1>(bandUp, x, j, std::min(W, j - t1), nextBottom);
  };
  for (int k = 0; k < common; ++k) {
    backwardTop(m - 1 - k);
    backwardBottom(t1 + k);
  }
  for (int k = common; k < lenT; ++k) backwardTop(m - 1 - k);
  for (int k = common; k < lenB; ++k) backwardBottom(t1 + k);
}

/// One row i of the band LDL^T (the envelope's Crout row with a fixed count of products and one division per
/// row: the entries of L multiplied by 1 / D). Direction -1: top-down, rows[i W + W - d] = K(i, i - d) on
/// entry and L(i, i - d) on return; +1: from the bottom, the mirror (entries (i, i + d), using the rows after
/// i). Columns at distance d in [first, reach] only (a separator row's entries in one part's columns); rows
/// further than `reach` are not read. Without `pivot`, the row's own pivot is not formed (a separator row).
/// False on |D(i)| <= tiny (or NaN).
template <int W, int Direction>
inline bool bandRow(double* rows, double* diagonal, double* inverseDiagonal, int i, int first, int reach,
                    bool pivot, double tiny) {
  double* row = rows + static_cast<std::ptrdiff_t>(i) * W;
  // row[W - d] <- w = L(i, n(d)) D(n(d)) = K(i, n(d)) - sum_{d' > d} w(n(d')) L(n(d), n(d')), n(d) = i +
  // Direction d
  for (int d = reach; d >= first; --d) {
    const double* neighbour = rows + static_cast<std::ptrdiff_t>(i + Direction * d) * W;
    double v = row[W - d];
    for (int e = reach; e > d; --e) v -= row[W - e] * neighbour[W - (e - d)];
    row[W - d] = v;
  }
  double d0 = diagonal[i];
  for (int d = reach; d >= first; --d) {
    const double l = row[W - d] * inverseDiagonal[i + Direction * d];
    d0 -= l * row[W - d];
    row[W - d] = l;
  }
  if (!pivot) return true;
  if (!(std::abs(d0) > tiny)) return false;
  diagonal[i] = d0;
  inverseDiagonal[i] = 1.0 / d0;
  return true;
}

/// Top-down row i of a block starting at `low` (bandRow), up to column `lastColumn`.
template <int W>
inline bool bandRowDown(double* band, double* diagonal, double* inverseDiagonal, int i, int low,
                        int lastColumn, bool pivot, double tiny) {
  return bandRow<W, -1>(band, diagonal, inverseDiagonal, i, std::max(1, i - lastColumn), std::min(W, i - low),
                        pivot, tiny);
}

/// Bottom-up row j of a block ending at `high` (bandRow), from column `firstColumn`: its entries L'(j, j + d)
/// at up[j W + W - d], started from K (original[k W + W - (k - j)] = K(k, j)).
template <int W>
inline bool bandRowUp(double* up, const double* original, double* diagonal, double* inverseDiagonal, int j,
                      int high, int firstColumn, bool pivot, double tiny) {
  const int reach = std::min(W, high - j);
  const int first = std::max(1, firstColumn - j);
  double* row = up + static_cast<std::ptrdiff_t>(j) * W;
  for (int d = reach; d >= first; --d) row[W - d] = original[static_cast<std::ptrdiff_t>(j + d) * W + W - d];
  return bandRow<W, 1>(up, diagonal, inverseDiagonal, j, first, reach, pivot, tiny);
}

/// Top-down LDL^T of the rows [begin, end) (a block) on the band (bandRowDown).
template <int W>
bool bandFactorizeRows(double* band, double* diagonal, double* inverseDiagonal, int begin, int end,
                       double tiny) {
  for (int i = begin; i < end; ++i)
    if (!bandRowDown<W>(band, diagonal, inverseDiagonal, i, begin, i - 1, true, tiny)) return false;
  return true;
}

/// The two ends of a twisted block [b0, b1) with separator [m, m + W), side by side (two independent chains
/// of rows, as twistedSubstitutions): rows [b0, m) and the separator rows' entries in their columns
/// top-down into `band`, rows [m + W, b1) and the separator rows' entries in theirs bottom-up into `up`, the
/// pivots of both parts into diagonal / inverseDiagonal. False on a vanishing pivot.
template <int W>
bool twistedFactorizeEnds(double* band, double* up, const double* original, double* diagonal,
                          double* inverseDiagonal, int b0, int b1, int m, double tiny) {
  const int t1 = m + W;
  const int lenTop = t1 - b0, lenBottom = b1 - m;
  const int count = std::max(lenTop, lenBottom);
  for (int k = 0; k < count; ++k) {
    if (k < lenTop) {
      const int i = b0 + k;
      if (!bandRowDown<W>(band, diagonal, inverseDiagonal, i, b0, std::min(i, m) - 1, i < m, tiny))
        return false;
    }
    if (k < lenBottom) {
      const int j = b1 - 1 - k;
      if (!bandRowUp<W>(up, original, diagonal, inverseDiagonal, j, b1 - 1, t1, j >= t1, tiny)) return false;
    }
  }
  return true;
}
/// Stored value p of K (`value`) summed into `lower` (at the index `map` gives a lower entry) or `diagonal`
/// (map -1 - row); an upper-triangle value (kUpper) skipped.
inline void scatterValue(const std::vector<std::ptrdiff_t>& map, std::ptrdiff_t p, double value,
                         std::vector<double>& lower, std::vector<double>& diagonal) {
  const std::ptrdiff_t m = map[static_cast<std::size_t>(p)];
  if (m >= 0)
    lower[static_cast<std::size_t>(m)] += value;
  else if (m != kUpper)
    diagonal[static_cast<std::size_t>(-1 - m)] += value;
}
/// K's stored values summed into `lower` and `diagonal` (scatterValue), both zeroed first.
void scatterValues(const SparseMatrix& k, const std::vector<std::ptrdiff_t>& map, std::vector<double>& lower,
                   std::vector<double>& diagonal) {
  std::fill(lower.begin(), lower.end(), 0.0);
  std::fill(diagonal.begin(), diagonal.end(), 0.0);
  const double* a = k.valuePtr();
  for (std::size_t p = 0; p < map.size(); ++p)
    scatterValue(map, static_cast<std::ptrdiff_t>(p), a[p], lower, diagonal);
}
}  // namespace

std::size_t SkylineLdlt::analyzePattern(const SparseMatrix& k) {
  m_n = static_cast<int>(k.rows());
  m_first.resize(m_n);
  for (int i = 0; i < m_n; ++i) m_first[i] = i;
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const int* nnzPerColumn = k.isCompressed() ? nullptr : k.innerNonZeroPtr();
  auto columnEnd = [&](int c) { return nnzPerColumn ? outer[c] + nnzPerColumn[c] : outer[c + 1]; };
  for (int c = 0; c < m_n; ++c)
    for (int p = outer[c]; p < columnEnd(c); ++p) {
      const int r = inner[p];
      if (r > c) m_first[r] = std::min(m_first[r], c);
    }
  m_start.resize(m_n + 1);
  m_start[0] = 0;
  for (int i = 0; i < m_n; ++i) m_start[i + 1] = m_start[i] + static_cast<std::size_t>(i - m_first[i]);
  m_values.assign(m_start[m_n], 0.0);
  m_diagonal.assign(m_n, 0.0);
  m_map.assign(outer[m_n], kUpper);
  for (int c = 0; c < m_n; ++c)
    for (int p = outer[c]; p < columnEnd(c); ++p) {
      const int r = inner[p];
      if (r == c) m_map[p] = -1 - r;
      else if (r > c) m_map[p] = static_cast<std::ptrdiff_t>(m_start[r] + static_cast<std::size_t>(c - m_first[r]));
    }
  // Independent blocks: a block starts at b when no row at or after b reaches back before b (the factor
  // keeps that structure: L has no entry outside the envelope).
  m_blockStart.clear();
  {
    int reach = m_n;  // smallest first column of the rows from i on
    std::vector<int> starts;
    for (int i = m_n - 1; i >= 0; --i) {
      reach = std::min(reach, m_first[i]);
      if (reach == i) starts.push_back(i);
    }
    m_blockStart.assign(starts.rbegin(), starts.rend());
    m_blockStart.push_back(m_n);
  }
  // The envelope by columns (rows ascending within a column) for the backward substitution: its
  // structure here, the values copied by factorize.
  m_columnStart.assign(static_cast<std::size_t>(m_n) + 1, 0);
  for (int i = 0; i < m_n; ++i)
    for (int j = m_first[i]; j < i; ++j) ++m_columnStart[static_cast<std::size_t>(j) + 1];
  for (int j = 0; j < m_n; ++j) m_columnStart[j + 1] += m_columnStart[j];
  m_columnRow.resize(m_values.size());
  m_columnSource.resize(m_values.size());
  m_columnValue.assign(m_values.size(), 0.0);
  {
    std::vector<std::size_t> next(m_columnStart.begin(), m_columnStart.end() - 1);
    for (int i = 0; i < m_n; ++i) {
      const std::ptrdiff_t rowI = rowBase(i);
      for (int j = m_first[i]; j < i; ++j) {
        const std::size_t q = next[static_cast<std::size_t>(j)]++;
        m_columnRow[q] = i;
        m_columnSource[q] = static_cast<std::size_t>(rowI + j);
      }
    }
  }
  // A narrow band (lines: 5 for bar nodes, 11 for beam nodes) is also kept as a fixed-width band for the
  // substitutions, when its padding costs at most as much storage as the envelope itself.
  int width = 0;
  for (int i = 0; i < m_n; ++i) width = std::max(width, i - m_first[i]);
  m_bandWidth = width >= 1 && width <= kMaxBandWidth &&
                        static_cast<std::size_t>(width) * static_cast<std::size_t>(m_n) <= 2 * m_values.size()
                    ? width
                    : 0;
  m_band.assign(static_cast<std::size_t>(m_bandWidth) * static_cast<std::size_t>(m_n), 0.0);
  // Where each stored value of the input lies in the band (factorize's band path): as m_map, with the
  // band's index of a lower entry.
  m_bandMap.clear();
  if (m_bandWidth > 0) {
    m_bandMap.assign(m_map.size(), kUpper);
    for (int c = 0; c < m_n; ++c)
      for (int p = outer[c]; p < columnEnd(c); ++p) {
        const int r = inner[p];
        if (r == c)
          m_bandMap[p] = -1 - r;
        else if (r > c)
          m_bandMap[p] = static_cast<std::ptrdiff_t>(r) * m_bandWidth + (m_bandWidth - (r - c));
      }
  }
  // Cost: for each entry (i, j) of the envelope, a dot product over the overlap of rows i and j.
  m_cost = 0.0;
  for (int i = 0; i < m_n; ++i)
    for (int j = m_first[i]; j < i; ++j) m_cost += static_cast<double>(j - std::max(m_first[i], m_first[j])) + 2.0;
  return m_values.size() + static_cast<std::size_t>(m_n);
}

void SkylineLdlt::setBlockLargest(int block) {
  m_blockLargest.resize(static_cast<std::size_t>(blockCount()), 0.0);
  double largest = 0.0;
  for (int i = blockStart(block); i < blockStart(block + 1); ++i)
    largest = std::max(largest, std::abs(m_originalDiagonal[static_cast<std::size_t>(i)]));
  m_blockLargest[static_cast<std::size_t>(block)] = largest;
}

double SkylineLdlt::blockPivotThreshold() const {
  double largest = 0.0;
  for (const double d : m_blockLargest) largest = std::max(largest, d);
  return 1e-14 * largest;
}

bool SkylineLdlt::factorize(const SparseMatrix& k) {
  m_factorized = false;
  if (m_bandWidth > 0) return m_factorized = factorizeBand(k);
  scatterValues(k, m_map, m_values, m_diagonal);
  m_originalDiagonal = m_diagonal;
  for (int block = 0; block < blockCount(); ++block) setBlockLargest(block);
  m_inverseDiagonal.resize(m_n);
  return m_factorized = factorizeEnvelopeRows(0, m_n, blockPivotThreshold());
}

bool SkylineLdlt::factorizeEnvelopeRows(int begin, int end, double tiny) {
  double* v = m_values.data();
  for (int i = begin; i < end; ++i) {
    const int fi = m_first[i];
    const std::ptrdiff_t rowI = rowBase(i);  // v[rowI + j] = entry (i, j), j in [fi, i)
    // v[rowI + j] <- w_j = L(i, j) D(j) = A(i, j) - sum_{k < j} w_k L(j, k)  (Crout, row by row)
    for (int j = fi; j < i; ++j) {
      const int fj = m_first[j];
      const std::ptrdiff_t rowJ = rowBase(j);
      const int q0 = std::max(fi, fj);
      v[rowI + j] -= dot(v + rowI + q0, v + rowJ + q0, j - q0);
    }
    // D(i) = A(i, i) - sum_j w_j L(i, j); L(i, j) = w_j / D(j).
    double d = m_diagonal[i];
    for (int j = fi; j < i; ++j) {
      const double l = v[rowI + j] / m_diagonal[j];
      d -= l * v[rowI + j];
      v[rowI + j] = l;
    }
    if (!(std::abs(d) > tiny)) return false;  // also NaN
    m_diagonal[i] = d;
  }
  // L by columns for the backward substitution (see solveInPlace; the structure is the pattern's, set by
  // analyzePattern: the columns of rows [begin, end) are those columns, a union of blocks) and 1 / D.
  for (std::size_t q = m_columnStart[static_cast<std::size_t>(begin)];
       q < m_columnStart[static_cast<std::size_t>(end)]; ++q)
    m_columnValue[q] = v[m_columnSource[q]];
  for (int i = begin; i < end; ++i) m_inverseDiagonal[i] = 1.0 / m_diagonal[i];
  return true;
}

bool SkylineLdlt::factorizeBlocks(const SparseMatrix& k, const std::vector<int>& blocks) {
  if (!m_factorized || k.rows() != m_n || !k.isCompressed()) return false;
  m_factorized = false;
  const int* outer = k.outerIndexPtr();
  const double* a = k.valuePtr();
  const bool band = m_bandWidth > 0;
  const std::vector<std::ptrdiff_t>& map = band ? m_bandMap : m_map;
  std::vector<double>& lower = band ? m_band : m_values;
  // K's values of the blocks (scatterValues on their columns, which hold their rows only): into the band's
  // copy of K (m_original) or the envelope, the other blocks' entries kept.
  for (const int block : blocks) {
    const int b0 = blockStart(block), b1 = blockStart(block + 1);
    const auto width = static_cast<std::ptrdiff_t>(m_bandWidth);
    const std::ptrdiff_t lo = band ? b0 * width : static_cast<std::ptrdiff_t>(m_start[b0]);
    const std::ptrdiff_t hi = band ? b1 * width : static_cast<std::ptrdiff_t>(m_start[b1]);
    std::fill(lower.begin() + lo, lower.begin() + hi, 0.0);
    std::fill(m_originalDiagonal.begin() + b0, m_originalDiagonal.begin() + b1, 0.0);
    for (int p = outer[b0]; p < outer[b1]; ++p) scatterValue(map, p, a[p], lower, m_originalDiagonal);
    if (band) {
      std::copy(m_band.begin() + lo, m_band.begin() + hi, m_original.begin() + lo);
    }
    std::copy(m_originalDiagonal.begin() + b0, m_originalDiagonal.begin() + b1, m_diagonal.begin() + b0);
    setBlockLargest(block);
  }
  const double tiny = blockPivotThreshold();
  for (const int block : blocks) {
    const bool ok = band ? withBandWidth(m_bandWidth,
                                         [&](auto width) {
                                           return factorizeBandBlock<decltype(width)::value>(block, tiny);
                                         })
                         : factorizeEnvelopeRows(blockStart(block), blockStart(block + 1), tiny);
    if (!ok) return false;
  }
  m_factorized = true;
  return true;
}

bool SkylineLdlt::factorizeBand(const SparseMatrix& k) {
  // The envelope's Crout rows on the fixed-width band (bandRowDown): a fixed count of products per row and
  // one division per row, where the envelope's loops over varying row lengths took a division per entry. A
  // long block is factorised from both ends at once (twisted, see twistedSubstitutions): two independent
  // chains of rows, as the substitutions.
  scatterValues(k, m_bandMap, m_band, m_diagonal);
  m_original = m_band;  // K itself: the bottom-up rows read it, and a failed twist starts again from it
  m_originalDiagonal = m_diagonal;
  for (int block = 0; block < blockCount(); ++block) setBlockLargest(block);
  const double tiny = blockPivotThreshold();
  m_inverseDiagonal.resize(m_n);
  return withBandWidth(m_bandWidth,
                       [&](auto width) { return factorizeBandBlocks<decltype(width)::value>(tiny); });
}

template <int W>
bool SkylineLdlt::factorizeBandBlocks(double tiny) {
  const int blocks = blockCount();
  m_twistRow.assign(static_cast<std::size_t>(blocks), -1);
  m_bandUp.resize(m_band.size());
  m_twistFactor.resize(static_cast<std::size_t>(blocks) * static_cast<std::size_t>(W * W));
  for (int block = 0; block < blocks; ++block)
    if (!factorizeBandBlock<W>(block, tiny)) return false;
  return true;
}

template <int W>
bool SkylineLdlt::factorizeBandBlock(int block, double tiny) {
  double* band = m_band.data();
  double* diagonal = m_diagonal.data();
  double* inverse = m_inverseDiagonal.data();
  const int b0 = blockStart(block), b1 = blockStart(block + 1);
  m_twistRow[static_cast<std::size_t>(block)] = -1;
  if (b1 - b0 >= kMinTwistedBlock * W) {
    const int m = b0 + (b1 - b0 - W) / 2;
    if (twistedFactorizeEnds<W>(band, m_bandUp.data(), m_original.data(), diagonal, inverse, b0, b1, m,
                                tiny) &&
        factorizeSeparator<W>(block, m, tiny)) {
      m_twistRow[static_cast<std::size_t>(block)] = m;
      return true;
    }
    // A vanishing pivot in the twisted order: the block top-down, from K again.
    const auto from = static_cast<std::ptrdiff_t>(b0) * W, to = static_cast<std::ptrdiff_t>(b1) * W;
    std::copy(m_original.begin() + from, m_original.begin() + to, m_band.begin() + from);
    std::copy(m_originalDiagonal.begin() + b0, m_originalDiagonal.begin() + b1, m_diagonal.begin() + b0);
  }
  return bandFactorizeRows<W>(band, diagonal, inverse, b0, b1, tiny);
}

bool SkylineLdlt::factorizeRows(const SparseMatrix& k, int block, int begin, int end) {
  if (!m_factorized || k.rows() != m_n || !k.isCompressed() || block < 0 || block >= blockCount())
    return false;
  if (m_bandWidth == 0) return m_factorized = factorizeEnvelopeFrom(k, block, begin);
  m_factorized = withBandWidth(m_bandWidth, [&](auto width) {
    return factorizeBandRows<decltype(width)::value>(k, block, begin, end);
  });
  return m_factorized;
}

bool SkylineLdlt::factorizeEnvelopeFrom(const SparseMatrix& k, int block, int begin) {
  // Rows before `begin` hold no changed entry (K's lower triangle: a changed column c >= begin has its
  // entries in rows >= c) and depend on none: their rows of L and D stand. The rows from `begin` to the
  // block's end are made again from K (Crout, as factorize: the same arithmetic), and with them the columns'
  // copy of L, whose columns before `begin` hold entries of those rows too (a contact's coupling reaches back
  // along the envelope).
  const int b0 = blockStart(block), b1 = blockStart(block + 1);
  if (begin < b0 || begin >= b1) return false;
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const double* a = k.valuePtr();
  std::fill(m_values.begin() + static_cast<std::ptrdiff_t>(m_start[begin]),
            m_values.begin() + static_cast<std::ptrdiff_t>(m_start[b1]), 0.0);
  std::fill(m_originalDiagonal.begin() + begin, m_originalDiagonal.begin() + b1, 0.0);
  for (int c = b0; c < b1; ++c)
    for (int p = outer[c]; p < outer[c + 1]; ++p)
      if (inner[p] >= begin) scatterValue(m_map, p, a[p], m_values, m_originalDiagonal);
  std::copy(m_originalDiagonal.begin() + begin, m_originalDiagonal.begin() + b1, m_diagonal.begin() + begin);
  setBlockLargest(block);
  if (!factorizeEnvelopeRows(begin, b1, blockPivotThreshold())) return false;
  for (std::size_t q = m_columnStart[static_cast<std::size_t>(b0)];
       q < m_columnStart[static_cast<std::size_t>(begin)]; ++q)
    m_columnValue[q] = m_values[m_columnSource[q]];
  return true;
}

template <int W>
bool SkylineLdlt::factorizeBandRows(const SparseMatrix& k, int block, int begin, int end) {
  const int b0 = blockStart(block), b1 = blockStart(block + 1);
  begin = std::max(begin, b0);
  end = std::min(end, b1);
  if (begin >= end) return true;
  // K's entries in rows and columns [begin, end) changed: in the lower triangle, rows [begin, last) (a row
  // reaches back W columns). Those rows of K again into m_original (the others hold K as last factorised).
  const int last = std::min(end + W, b1);
  const auto rowFrom = static_cast<std::ptrdiff_t>(begin) * W, rowTo = static_cast<std::ptrdiff_t>(last) * W;
  std::fill(m_original.begin() + rowFrom, m_original.begin() + rowTo, 0.0);
  std::fill(m_originalDiagonal.begin() + begin, m_originalDiagonal.begin() + last, 0.0);
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const double* a = k.valuePtr();
  for (int c = std::max(b0, begin - W); c < last; ++c)
    for (int p = outer[c]; p < outer[c + 1]; ++p) {
      const int r = inner[p];
      if (r >= begin && r < last) scatterValue(m_bandMap, p, a[p], m_original, m_originalDiagonal);
    }
  setBlockLargest(block);
  const double tiny = blockPivotThreshold();
  double* band = m_band.data();
  double* diagonal = m_diagonal.data();
  double* inverse = m_inverseDiagonal.data();
  const int twist = m_twistRow[static_cast<std::size_t>(block)];
  // The rows of one end that read a changed row are those after it in that end's order: from `begin` on
  // top-down (rows before it keep their factor), from last - 1 back bottom-up. Each restarts from K.
  const auto topDownFrom = [&](int from, int to) {
    const auto rowsFrom = static_cast<std::ptrdiff_t>(from) * W, rowsTo = static_cast<std::ptrdiff_t>(to) * W;
    std::copy(m_original.begin() + rowsFrom, m_original.begin() + rowsTo, m_band.begin() + rowsFrom);
    std::copy(m_originalDiagonal.begin() + from, m_originalDiagonal.begin() + to, m_diagonal.begin() + from);
  };
  if (twist < 0) {
    topDownFrom(begin, b1);
    for (int i = begin; i < b1; ++i)
      if (!bandRowDown<W>(band, diagonal, inverse, i, b0, i - 1, true, tiny)) return false;
    return true;
  }
  const int m = twist, t1 = twist + W;
  if (begin < t1) {
    topDownFrom(begin, t1);
    for (int i = begin; i < t1; ++i)
      if (!bandRowDown<W>(band, diagonal, inverse, i, b0, std::min(i, m) - 1, i < m, tiny)) return false;
  }
  if (last > m) {
    for (int j = last - 1; j >= m; --j) {
      if (j >= t1) diagonal[j] = m_originalDiagonal[static_cast<std::size_t>(j)];
      if (!bandRowUp<W>(m_bandUp.data(), m_original.data(), diagonal, inverse, j, b1 - 1, t1, j >= t1, tiny))
        return false;
    }
  }
  return factorizeSeparator<W>(block, m, tiny);
}

template <int W>
bool SkylineLdlt::factorizeSeparator(int block, int m, double tiny) {
  // The separator [m, m + W) takes the Schur complement of both ends,
  //   S = K_ss - sum_{k < m} L(s, k) D_k L(s', k) - sum_{k >= m + W} L'(s, k) D'_k L'(s', k),
  // held as a band of width W (row a: S(a, a - d) at factor[a W + W - d]; dense: every row reaches back to
  // the first) and factorised by the band's own Crout rows (bandRow); its unit lower factor stays there, its
  // pivots go into m_diagonal / m_inverseDiagonal with the others.
  const int b0 = blockStart(block), b1 = blockStart(block + 1);
  const int t1 = m + W;
  double* factor = m_twistFactor.data() + static_cast<std::ptrdiff_t>(block) * W * W;
  for (int a = 0; a < W; ++a)
    for (int b = 0; b <= a; ++b) {
      const int s = m + a, r = m + b;
      double v = originalEntry(s, r);
      const double* rowS = m_band.data() + static_cast<std::ptrdiff_t>(s) * W;
      const double* rowR = m_band.data() + static_cast<std::ptrdiff_t>(r) * W;
      for (int k = std::max(s - W, b0); k < m; ++k)
        v -= rowS[W - (s - k)] * m_diagonal[static_cast<std::size_t>(k)] * rowR[W - (r - k)];
      const double* upS = m_bandUp.data() + static_cast<std::ptrdiff_t>(s) * W;
      const double* upR = m_bandUp.data() + static_cast<std::ptrdiff_t>(r) * W;
      for (int k = t1; k <= std::min(r + W, b1 - 1); ++k)
        v -= upS[W - (k - s)] * m_diagonal[static_cast<std::size_t>(k)] * upR[W - (k - r)];
      if (a == b)
        m_diagonal[static_cast<std::size_t>(s)] = v;
      else
        factor[a * W + W - (a - b)] = v;
    }
  for (int a = 0; a < W; ++a)
    if (!bandRow<W, -1>(factor, m_diagonal.data() + m, m_inverseDiagonal.data() + m, a, 1, a, true, tiny))
      return false;
  return true;
}

double SkylineLdlt::originalEntry(int i, int j) const {
  if (i == j) return m_originalDiagonal[static_cast<std::size_t>(i)];
  if (i < j) std::swap(i, j);
  const int w = m_bandWidth;
  return i - j <= w ? m_original[static_cast<std::size_t>(i) * static_cast<std::size_t>(w) +
                                 static_cast<std::size_t>(w - (i - j))]
                    : 0.0;
}

void SkylineLdlt::solveInPlace(VecX& b) const { solveRange(b.data(), 0, m_n); }

void SkylineLdlt::solveBlocksInPlace(VecX& b, const std::vector<int>& blocks) const {
  // Consecutive blocks are solved as one range (the same arithmetic: no entry crosses a block boundary).
  std::size_t k = 0;
  while (k < blocks.size()) {
    std::size_t last = k;
    while (last + 1 < blocks.size() && blocks[last + 1] == blocks[last] + 1) ++last;
    solveRange(b.data(), blockStart(blocks[k]), blockStart(blocks[last] + 1));
    k = last + 1;
  }
}

void SkylineLdlt::solveRange(double* x, int begin, int end) const {
  if (m_bandWidth > 0) {
    // The same substitutions on the fixed-width band (bandSubstitutions): 25 % faster on a bar line
    // (bench/bench_linear_solve.cpp: 6.2 -> 4.6 ns per equation on 201 nodes); a long block factorised from
    // both ends by twistedSubstitutions. Block by block from the block holding `begin`.
    int block = static_cast<int>(std::upper_bound(m_blockStart.begin(), m_blockStart.end(), begin) -
                                 m_blockStart.begin()) -
                1;
    const auto plain = [&](int from, int to) {
      withBandWidth(m_bandWidth, [&](auto width) {
        bandSubstitutions<decltype(width)::value>(x, from, to, m_band.data(), m_inverseDiagonal.data());
      });
    };
    int plainFrom = begin;  // consecutive blocks without a twist go to bandSubstitutions as one range
    for (; block < blockCount() && blockStart(block) < end; ++block) {
      const int m = m_twistRow.empty() ? -1 : m_twistRow[static_cast<std::size_t>(block)];
      if (m < 0) continue;
      const int b0 = blockStart(block), b1 = blockStart(block + 1);
      if (plainFrom < b0) plain(plainFrom, b0);
      withBandWidth(m_bandWidth, [&](auto width) {
        constexpr int W = decltype(width)::value;
        twistedSubstitutions<W>(x, b0, b1, m, m_band.data(), m_bandUp.data(),
                                m_twistFactor.data() + static_cast<std::ptrdiff_t>(block) * W * W,
                                m_inverseDiagonal.data());
      });
      plainFrom = b1;
    }
    if (plainFrom < end) plain(plainFrom, end);
    return;
  }
  const double* v = m_values.data();
  // Both substitutions as dot products in which the unknown found just before is held apart: the rest of
  // the row (unknowns found two or more rows earlier) is summed while that one is still being computed, so
  // the chain from one unknown to the next is a single multiply-add. Written as plain row (or column)
  // sweeps, each unknown waited for the store and reload of the previous one, or for a whole dot product:
  // the solve was latency-bound (docs/performance.md).
  // L y = b by rows of L, then z = D^-1 y. (Rows of [begin, end) reach no column before begin; the first
  // row of a block has an empty row, so `previous` is never read across a block boundary.)
  double previous = 0.0;
  for (int i = begin; i < end; ++i) {
    const std::ptrdiff_t rowI = rowBase(i);
    const int fi = m_first[i];
    double y = x[i];
    if (fi < i) {
      y -= dot(v + rowI + fi, x + fi, i - 1 - fi);
      y -= v[rowI + i - 1] * previous;
    }
    x[i] = y;
    previous = y;
  }
  for (int i = begin; i < end; ++i) x[i] *= m_inverseDiagonal[i];
  // L^T x = z by columns of L (rows of L^T), rows ascending within each column (all inside the range).
  const std::size_t* start = m_columnStart.data();
  const int* row = m_columnRow.data();
  const double* value = m_columnValue.data();
  double next = 0.0;
  for (int i = end - 1; i >= begin; --i) {
    std::size_t q = start[i];
    const std::size_t stop = start[i + 1];
    double xi = x[i];
    double nextTerm = 0.0;
    if (q < stop && row[q] == i + 1) nextTerm = value[q++] * next;
    double sum = 0.0;
    for (; q < stop; ++q) sum += value[q] * x[row[q]];
    xi -= sum;
    xi -= nextTerm;
    x[i] = xi;
    next = xi;
  }
}

}  // namespace tangle::solver

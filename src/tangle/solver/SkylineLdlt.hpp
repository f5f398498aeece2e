#pragma once
/// @file SkylineLdlt.hpp
/// Envelope (skyline, profile) LDL^T factorisation of a symmetric matrix in its own ordering, without
/// pivoting: the storage of a line's equations, which are numbered node after node along the line, is
/// banded (a bar line has 5 sub-diagonals, a beam line 11), and lines coupled only at their ends or
/// through a vessel keep that form with a few long rows (an "arrow"). The factor has no fill outside
/// the envelope (George & Liu 1981, "Computer solution of large sparse positive definite systems",
/// ch. 4; the row-oriented Crout form of Bathe's active-column solver, Bathe 1996, "Finite element
/// procedures", sec. 8.2.3), so one factorisation costs sum_i sum_{j in row i} (overlap of rows i and j)
/// and one solve two passes over the envelope: for a 200-bar line 3 000 numbers against a general sparse
/// LDL^T's permutations and elimination tree.
///
/// Contract: analyzePattern with the matrix's pattern first (only the lower triangle, row >= column, is
/// read; the matrix is stored full or lower); factorize then solve with matrices of that pattern. No
/// pivoting: factorize fails (returns false) on a pivot that is zero or below 1e-14 of the largest
/// diagonal entry, and the caller then uses a pivoting method.

#include <cstddef>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::solver {

/// LDL^T of a symmetric matrix stored by rows within its envelope.
class SkylineLdlt {
 public:
  /// Envelope of the lower triangle of `k` (square, compressed column storage). Returns the number of
  /// stored entries (diagonal included).
  std::size_t analyzePattern(const SparseMatrix& k);
  /// Widest envelope row (i - first column) kept also as a fixed-width band for the substitutions.
  static constexpr int kMaxBandWidth = 12;
  /// Width of the fixed-width band the substitutions use (0: they run on the envelope). A line's pattern
  /// gives 5 (bar nodes) or 11 (beam nodes); kept when at most kMaxBandWidth and its padding at most
  /// doubles the envelope's storage.
  int bandWidth() const { return m_bandWidth; }
  /// A block of at least kMinTwistedBlock band widths of equations on the fixed-width band is also
  /// factorised and solved from both ends at once (twisted; see factorizeBandBlocks).
  static constexpr int kMinTwistedBlock = 8;
  /// Blocks solved twisted after the last factorize [-].
  int twistedBlockCount() const {
    int count = 0;
    for (const int m : m_twistRow) count += m >= 0 ? 1 : 0;
    return count;
  }
  /// Entries inside the envelope [-] (0 before analyzePattern).
  std::size_t envelopeSize() const { return m_values.size(); }
  /// Multiply-adds one factorisation takes with this envelope [-] (a cost estimate for choosing a method).
  double factorizationCost() const { return m_cost; }
  /// Factorises `k` (same pattern as analysed). False on a vanishing pivot (see the file comment).
  bool factorize(const SparseMatrix& k);
  /// Factorises again the listed independent blocks (ascending block indices) from `k` (the analysed
  /// pattern; its other blocks' values are not read) and keeps the others' factors: after a factorize, when
  /// only those blocks' entries changed. The same arithmetic as factorize on those blocks, with the
  /// vanishing-pivot threshold of the whole matrix as now stored. False on a vanishing pivot or without a
  /// preceding successful factorize (then factorize the whole matrix).
  bool factorizeBlocks(const SparseMatrix& k, const std::vector<int>& blocks);
  /// Factorises again the part of independent block `block` that changes when K's entries in the rows and
  /// columns [begin, end) change (a stretch of a line: GeneralizedAlpha's refresh of its touchdown zone) from
  /// `k` (the analysed pattern; its other entries must equal the last factorised matrix's): the rows from
  /// `begin` on of a block factorised top-down, or of a twisted block the rows between the change and the
  /// separator from either end, and the separator. On the envelope (no fixed-width band: lines coupled by a
  /// contact), the rows from `begin` to the block's end (factorizeEnvelopeFrom). The same arithmetic as
  /// factorize. False on a vanishing pivot or without a preceding successful factorize (then factorize the
  /// whole matrix).
  bool factorizeRows(const SparseMatrix& k, int block, int begin, int end);
  /// Overwrites b with the solution x of K x = b.
  void solveInPlace(VecX& b) const;

  /// Independent blocks of the analysed pattern: consecutive equation ranges [blockStart(k),
  /// blockStart(k + 1)) with no entry coupling one block to another (lines not coupled to each other, e.g.
  /// moorings with prescribed fairleads). K is block diagonal, so each block's part of x depends on its
  /// part of b only. At least one block (the whole matrix) once analysed.
  int blockCount() const { return static_cast<int>(m_blockStart.size()) - 1; }
  /// First equation of block k; blockStart(blockCount()) is the equation count.
  int blockStart(int k) const { return m_blockStart[static_cast<std::size_t>(k)]; }
  /// Solves K x = b for the listed blocks only (ascending block indices): their entries of b become those
  /// of x, the other entries are left as they are. The same arithmetic as solveInPlace on those entries.
  void solveBlocksInPlace(VecX& b, const std::vector<int>& blocks) const;

 private:
  /// The substitutions over equations [begin, end), a union of whole blocks.
  void solveRange(double* x, int begin, int end) const;
  /// factorizeBand's blocks, band width W: long ones twisted (twistedFactorizeEnds and factorizeSeparator;
  /// m_twistRow, m_bandUp, m_twistFactor), the others top-down.
  template <int W>
  bool factorizeBandBlocks(double tiny);
  /// One block of factorizeBandBlocks (its work space sized by it).
  template <int W>
  bool factorizeBandBlock(int block, double tiny);
  /// factorizeRows on the envelope: rows `begin` to the end of block `block` again from k.
  bool factorizeEnvelopeFrom(const SparseMatrix& k, int block, int begin);
  /// factorizeRows on the band of width W.
  template <int W>
  bool factorizeBandRows(const SparseMatrix& k, int block, int begin, int end);
  /// The envelope's Crout rows [begin, end) (a union of blocks; envelope mode), then their columns of L for
  /// the backward substitution and 1 / D. False on |D(i)| <= tiny (or NaN).
  bool factorizeEnvelopeRows(int begin, int end, double tiny);
  /// m_blockLargest[block] from m_originalDiagonal's rows of the block.
  void setBlockLargest(int block);
  /// 1e-14 of the largest |diagonal entry| of K as last factorised (m_originalDiagonal): the vanishing-pivot
  /// threshold, from the blocks' largest entries (m_blockLargest), so that a factorisation of some blocks or
  /// rows again finds it without a pass over every row (on 12 mooring lines of independent blocks, refreshed
  /// a block or a stretch at a time, that pass was 1.1 % of the run).
  double blockPivotThreshold() const;
  /// The separator of twisted block `block` at rows [m, m + w): Schur complement and its dense LDL^T. False
  /// on a vanishing pivot.
  template <int W>
  bool factorizeSeparator(int block, int m, double tiny);
  /// factorize on the fixed-width band (m_bandWidth > 0): m_band, m_diagonal and m_inverseDiagonal.
  bool factorizeBand(const SparseMatrix& k);
  /// Entry (i, j) of K as factorised (0 outside the band; band mode only).
  double originalEntry(int i, int j) const;
  /// Offset o of row i such that entry (i, j) of L is m_values[o + j].
  std::ptrdiff_t rowBase(int i) const { return static_cast<std::ptrdiff_t>(m_start[i]) - m_first[i]; }

  int m_n = 0;
  std::vector<int> m_first;           // first column of the envelope of each row
  std::vector<std::size_t> m_start;   // offset of each row in m_values (entries first..i-1, then unused)
  std::vector<double> m_values;       // L(i, j) for j in [first_i, i), row after row; D in m_diagonal
  std::vector<double> m_diagonal;     // D
  std::vector<std::ptrdiff_t> m_map;  // each stored value of the input: index in m_values, -1 - row for the
                                      // diagonal, or a value below -m_n - 1 for the upper triangle (skipped)
  double m_cost = 0.0;
  bool m_factorized = false;           // the last factorize succeeded (factorizeBlocks may follow)
  std::vector<int> m_blockStart;  // first equation of each independent block, then m_n
  // L by columns (compressed: rows and values of column j at [m_columnStart[j], m_columnStart[j + 1]); the
  // structure set by analyzePattern, the values by factorize) and
  // 1 / D, for solveInPlace (the backward pass reads L by columns).
  std::vector<std::size_t> m_columnStart;
  std::vector<int> m_columnRow;
  std::vector<double> m_columnValue;
  std::vector<std::size_t> m_columnSource;  // index in m_values of each column-ordered entry
  std::vector<double> m_inverseDiagonal;
  // L as a band of fixed width m_bandWidth (0: not kept; the envelope is too wide or too ragged): row i
  // holds L(i, i - w) ... L(i, i - 1), zero outside the envelope (solveRange).
  int m_bandWidth = 0;
  std::vector<double> m_band;
  // Twisted blocks: per block the first separator row m (-1: solved top-down), the bottom part's factor L'
  // (row j: L'(j, j + d) at m_bandUp[j w + w - d], separator rows hold their entries in the bottom part's
  // columns) and the separator's unit lower factor (w x w per block); K's envelope and diagonal.
  std::vector<int> m_twistRow;
  std::vector<double> m_bandUp;
  std::vector<double> m_twistFactor;
  std::vector<double> m_original;  // K's band (as m_band): the bottom-up rows read it
  std::vector<double> m_originalDiagonal;  // K's diagonal as last factorised (band and envelope modes)
  std::vector<double> m_blockLargest;      // per block, its largest |entry| of m_originalDiagonal
  std::vector<std::ptrdiff_t> m_bandMap;  // as m_map, with a lower entry's index in the band
};

}  // namespace tangle::solver

#pragma once
/// @file SystemMatrix.hpp
/// Collects matrix contributions given in full-DOF numbering into a sparse matrix over the
/// equations (constrained DOFs dropped), and assembles residual vectors.

#include <array>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/DofMap.hpp"

namespace tangle::solver {

/// Sparse matrix assembly over equation numbers, in two modes (issue 8: rebuilding the matrix cost more
/// than factorising it):
/// - recording: every add() is kept as a triplet and the (row, column) of every call in order; build()
///   sums the triplets (setFromTriplets) and remembers, for each call, where its entry lies in the built
///   matrix's value array;
/// - replaying: after a build, the next assembly usually makes the same calls in the same order (elements do
///   not change, contacts rarely). Each add() is then checked against the recorded call and its value
///   summed straight into that position; build() copies the values. The values are summed in call order
///   either way, so both modes give the same matrix bit for bit. A call that differs from the recorded one
///   (a contact appears, a pattern changes) turns the assembly back into recording, with the entries
///   summed so far as triplets.
/// And a third, patching, for a refresh of an independent block of the matrix or of a stretch of it
/// (NewtonIteration::refreshBlocks): after a build, beginPatch zeroes the built matrix's entries in the rows
/// and columns of the patched equations, and the calls that follow (the elements and nodes there) replay
/// the recorded sequence's subsequence of those entries; endPatch copies them into the built matrix. The
/// recorded sequence is left as it was.
class SystemMatrix {
 public:
  explicit SystemMatrix(const model::DofMap& dofs) : m_dofs(&dofs) {}
  /// Starts a new assembly: no entries (keeps capacity; replays the last recorded sequence if any).
  void clear();
  /// Adds v at (full DOF row, full DOF column); ignored when either DOF is constrained.
  void add(int row, int col, double v) {
    // The replayed call inline (a few loads and one sum); anything else out of line.
    if (m_cursor < m_replayCount) {
      const Call& c = m_calls[m_cursor];
      if (!c.block && c.row == row && c.col == col) {
        ++m_cursor;
        if (c.position[0] >= 0) m_values[static_cast<std::size_t>(c.position[0])] += v;
        return;
      }
    }
    addRecorded(row, col, v);
  }
  /// Adds a dense block: rows/cols are the full DOF indices of the block's rows/columns. A block of whole
  /// nodes' translations or rotations (n a multiple of 3, each 3 consecutive DOFs) goes in 3x3 blocks.
  template <class Derived>
  void addBlock(const int* dofs, int n, const Eigen::MatrixBase<Derived>& block, double scale = 1.0) {
    bool triples = n % 3 == 0;
    for (int a = 0; a < n && triples; a += 3)
      triples = dofs[a + 1] == dofs[a] + 1 && dofs[a + 2] == dofs[a] + 2;
    if (triples) {
      for (int b = 0; b < n; b += 3)
        for (int a = 0; a < n; a += 3) add3x3(dofs[a], dofs[b], block.template block<3, 3>(a, b), scale);
      return;
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) add(dofs[i], dofs[j], scale * block(i, j));
  }
  /// Adds s * I (3x3) at the translational DOFs of a node starting at full DOF `first`.
  void addDiagonal3(int first, double s) {
    for (int k = 0; k < 3; ++k) add(first + k, first + k, s);
  }
  /// Adds a 3x3 block at (rowFirst.., colFirst..). One call of the sequence when its three rows and three
  /// columns are free equations numbered consecutively (a node's translations or rotations): replayed as
  /// nine sums at three recorded positions, one per column (issue 8: nine calls checked one by one were
  /// most of a matrix assembly); otherwise nine scalar calls. Either way each entry sums the same values in
  /// the same order.
  template <class Derived>
  void add3x3(int rowFirst, int colFirst, const Eigen::MatrixBase<Derived>& m, double scale = 1.0) {
    if (m_cursor < m_replayCount) {
      const Call& c = m_calls[m_cursor];
      if (c.block && c.row == rowFirst && c.col == colFirst) {
        ++m_cursor;
        for (int j = 0; j < 3; ++j) {
          double* v = m_values.data() + c.position[static_cast<std::size_t>(j)];
          for (int i = 0; i < 3; ++i) v[i] += scale * m(i, j);
        }
        return;
      }
      if (!c.block) {  // recorded as scalar calls (a constrained DOF), or a changed sequence
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) add(rowFirst + i, colFirst + j, scale * m(i, j));
        return;
      }
    }
    const Mat3 scaled = scale * m;
    add3x3Recorded(rowFirst, colFirst, scaled);
  }
  /// Builds the compressed sparse matrix of this assembly (duplicates summed; may be called more than once,
  /// into any matrix).
  void build(SparseMatrix& out);
  /// True while the current assembly replays the recorded sequence (for tests).
  bool replaying() const { return m_replaying; }

  /// Starts a patch of the entries in the rows and columns of the equations [begin, end) (whole nodes): those
  /// entries of the last built matrix are zeroed, and the calls until endPatch sum into them. The calls must
  /// hold the recorded sequence's calls with a row or a column there, in their order (an assembly of the
  /// elements and nodes at those equations, e.g. a part of the model made of their nodes); calls whose row
  /// and column both lie outside (the part's other entries) and calls at constrained DOFs are ignored. The
  /// subsequence of [blockBegin, blockEnd) (an independent block holding [begin, end), or the whole matrix)
  /// is kept, and a stretch's is taken from it. False (nothing changed) when there is no built matrix to
  /// patch (no build since the last clear).
  bool beginPatch(int begin, int end, int blockBegin, int blockEnd);
  /// A patch of a whole block (or of a union of blocks).
  bool beginPatch(int begin, int end) { return beginPatch(begin, end, begin, end); }
  /// Ends the patch: copies the patched entries into `out`, which must hold the last build. False when the
  /// calls of the patch were not the subsequence (a contact made since the build, a changed pattern) or
  /// `out` is not the last build: `out` is left as it was and the matrix must be assembled whole (clear()).
  bool endPatch(SparseMatrix& out);

 private:
  /// One call of the sequence: full DOF row and column, and the position of its entry in the recorded
  /// matrix's value array (-1: a constrained DOF; set by build).
  struct Call {
    int row;  // a block's first row and column
    int col;
    std::array<int, 3> position;  // a block: the position of (row, col + j) for each column j
    bool block;
  };
  /// add() outside a replay: leaves the replay if one was running (the call differs from the recorded
  /// one), then keeps the call and, unless a DOF is constrained, a triplet.
  [[gnu::noinline]] void addRecorded(int row, int col, double v);
  /// add3x3 outside a replay: leaves the replay if one was running, then keeps one block call (three free
  /// consecutive rows and columns) or nine scalar calls. `m` holds the scaled values.
  [[gnu::noinline]] void add3x3Recorded(int rowFirst, int colFirst, const Mat3& m);
  /// The recorded calls of a patch: those with an entry in a row or a column of [begin, end) (indices into
  /// m_calls, in order) and the entries they sum into (zeroed and copied).
  struct PatchSequence {
    int begin;
    int end;
    std::vector<std::size_t> calls;
    std::vector<int> positions;  // the entries the calls sum into (zeroed and copied)
  };
  /// A scalar call of a patch: the next call of the patch's subsequence, or ignored (outside the patch).
  void addPatched(int row, int col, double v);
  /// A 3x3 call of a patch (`m` scaled): the next block call of the subsequence, else nine scalar calls.
  void add3x3Patched(int rowFirst, int colFirst, const Mat3& m);
  /// The calls among `from` (indices into m_calls, ascending) with an entry in a row or a column of
  /// [begin, end), into `sequence` (calls and positions; its range set).
  void selectPatchCalls(const std::vector<std::size_t>* from, int begin, int end,
                        PatchSequence& sequence) const;
  /// Leaves replaying at the current call: the calls replayed so far stay in the sequence and their
  /// summed entries become triplets.
  void startRecording();

  const model::DofMap* m_dofs;
  bool m_replaying = false;
  std::size_t m_cursor = 0;         // next call of the sequence (replaying)
  std::size_t m_replayCount = 0;    // calls to replay (0 while recording)
  std::vector<Call> m_calls;        // every call, in order
  std::vector<Triplet> m_triplets;  // recording: the entries
  // The recorded sequence's matrix: pattern (compressed columns) and the values summed while replaying;
  // m_recorded once a build ended a sequence.
  std::vector<int> m_outer, m_inner;
  std::vector<double> m_values;
  bool m_recorded = false;
  bool m_built = false;  // m_values hold the last build (no clear since)
  // Patching: the subsequence of each patched block (kept until the recorded sequence changes), a stretch's
  // (taken from its block's), the current one and its cursor, the replay count set aside meanwhile, and
  // whether a call missed.
  static constexpr std::size_t kKeptPatchSequences = 64;  // ranges kept (more: all dropped, made again)
  std::vector<PatchSequence> m_patchSequences;
  PatchSequence m_stretch;  // a stretch's, taken from its block's
  std::array<int, 2> m_stretchBlock{-1, -1};  // that block's [begin, end)
  bool m_stretchValid = false;                // m_stretch is of the current sequence
  const PatchSequence* m_patch = nullptr;
  std::size_t m_patchCursor = 0;
  bool m_patchFailed = false;
  std::size_t m_replayCountBeforePatch = 0;
};

}  // namespace tangle::solver

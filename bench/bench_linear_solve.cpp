/// @file bench_linear_solve.cpp
/// The substitutions of the envelope LDL^T (SkylineLdlt::solveInPlace) on the patterns of lines, the
/// inner loop of every modified-Newton iteration (issue 8):
///  - BM_SkylineSolveBarLine/n: a bar line of n nodes (3 DOFs each, neighbours coupled: the mooring example
///    has 201 nodes, 600 equations);
///  - BM_SkylineSolveBeamLine/n: a beam line of n nodes (6 DOFs each: the drilling riser has ~100);
///  - BM_SkylineSolveArrow: two bar lines of 100 nodes joined at a 6-DOF vessel node numbered last (an
///    arrow: the vessel's rows reach back to both lines' ends).
/// Wall time per solve (nanoseconds) and per equation. The matrices are random, symmetric and diagonally
/// dominant with the pattern of the line (the values do not change the work).
///
/// Measured (release build, this 2-core machine): 4.4 us per solve of the 603-equation bar line (7.4 ns per
/// equation), 6.4 us for the 600-equation beam line, 6.6 us for the arrow. Fixed-size kernels per node (3x3
/// and 6x6 blocks, unrolled, the backward pass by rows) gained 6 % on the bar line and 12 % on the beam line
/// and lost 20 % on the arrow, and were dropped.
/// Stop 25: the envelope's rows stored again as a fixed-width band (SkylineLdlt::bandWidth: 5 for bar
/// lines, 11 for beam lines; every row's products a fixed count, no column index array): 6.2 -> 4.6 ns per
/// equation on the bar line, 9.1 -> 7.5 on the beam line, measured side by side (same build, the band
/// switched off and on); the arrow keeps the envelope. Tried and dropped: the chain's multiply and
/// subtraction as one fused multiply-add (a run-time dispatched FMA build of the kernel): slower on both
/// storages (6.2 -> 7.1, 4.6 -> 5.5 ns), so the chain's latency is not all that bounds the solve.
/// Stop 26: a long block solved twisted (from both ends at once, SkylineLdlt::kMinTwistedBlock): 5.5 -> 3.1
/// ns per equation on the bar line, 8.6 -> 5.4 on the beam line (same run, the commit before against this
/// one). BM_SkylineFactorize*: one factorisation (SkylineLdlt::factorize, the refresh of the kept matrix).
/// Stop 26: on the band (one division per row) and twisted (both ends' rows side by side): 35.8 -> 19.5 us on
/// the bar line of 201 nodes, 78.8 -> 42.0 us on the beam line of 100 (same run, envelope against band); the
/// fill from the compressed matrix and the copy of K for the bottom-up rows are part of it.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/solver/SkylineLdlt.hpp"

namespace {

using tangle::SparseMatrix;
using tangle::Triplet;
using tangle::VecX;

/// Lines of `nodes` nodes with `dofs` DOFs each, one after the other; with `vesselDofs` > 0 a last node
/// coupled to the first node of every line.
SparseMatrix linesMatrix(int lines, int nodes, int dofs, int vesselDofs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triplet> t;
  const int n = lines * nodes * dofs + vesselDofs;
  auto sym = [&](int i, int j) {
    const double v = u(rng);
    t.emplace_back(i, j, v);
    t.emplace_back(j, i, v);
  };
  for (int l = 0; l < lines; ++l)
    for (int a = 0; a < nodes; ++a) {
      const int base = (l * nodes + a) * dofs;
      for (int i = 0; i < dofs; ++i)
        for (int j = 0; j < i; ++j) sym(base + i, base + j);
      if (a + 1 < nodes)
        for (int i = 0; i < dofs; ++i)
          for (int j = 0; j < dofs; ++j) sym(base + dofs + i, base + j);
      if (vesselDofs > 0 && a == 0)
        for (int i = 0; i < vesselDofs; ++i)
          for (int j = 0; j < dofs; ++j) sym(lines * nodes * dofs + i, base + j);
    }
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, 4.0 * (dofs + 2) + u(rng));
  SparseMatrix k(n, n);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;
}

void runSolve(benchmark::State& state, const SparseMatrix& k) {
  tangle::solver::SkylineLdlt s;
  s.analyzePattern(k);
  if (!s.factorize(k)) {
    state.SkipWithError("factorisation failed");
    return;
  }
  const VecX b = VecX::LinSpaced(k.rows(), -1.0, 1.0);
  VecX x = b;
  for (auto _ : state) {
    x = b;
    s.solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  state.counters["equations"] = static_cast<double>(k.rows());
  state.counters["ns_per_equation"] =
      benchmark::Counter(static_cast<double>(k.rows()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void runFactorize(benchmark::State& state, const SparseMatrix& k) {
  tangle::solver::SkylineLdlt s;
  s.analyzePattern(k);
  for (auto _ : state) {
    if (!s.factorize(k)) {
      state.SkipWithError("factorisation failed");
      return;
    }
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_equation"] =
      benchmark::Counter(static_cast<double>(k.rows()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_SkylineSolveBarLine(benchmark::State& state) {
  runSolve(state, linesMatrix(1, static_cast<int>(state.range(0)), 3, 0));
}
void BM_SkylineSolveBeamLine(benchmark::State& state) {
  runSolve(state, linesMatrix(1, static_cast<int>(state.range(0)), 6, 0));
}
void BM_SkylineSolveArrow(benchmark::State& state) { runSolve(state, linesMatrix(2, 100, 3, 6)); }
void BM_SkylineFactorizeBarLine(benchmark::State& state) {
  runFactorize(state, linesMatrix(1, static_cast<int>(state.range(0)), 3, 0));
}
void BM_SkylineFactorizeBeamLine(benchmark::State& state) {
  runFactorize(state, linesMatrix(1, static_cast<int>(state.range(0)), 6, 0));
}

}  // namespace

BENCHMARK(BM_SkylineSolveBarLine)->Arg(201)->Arg(801);
BENCHMARK(BM_SkylineSolveBeamLine)->Arg(100);
BENCHMARK(BM_SkylineSolveArrow);
BENCHMARK(BM_SkylineFactorizeBarLine)->Arg(201);
BENCHMARK(BM_SkylineFactorizeBeamLine)->Arg(100);

BENCHMARK_MAIN();

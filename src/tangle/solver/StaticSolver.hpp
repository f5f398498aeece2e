#pragma once
/// @file StaticSolver.hpp
/// Static equilibrium by Newton-Raphson with load incrementation, a Levenberg-Marquardt style
/// regularisation (a pseudo-time viscous term, the implicit counterpart of the dynamic relaxation
/// the seed paper's authors use) when the tangent is singular, and increment limiting (the largest nodal
/// translation and rotation per iteration are capped).

#include <string>

#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::solver {

/// Outcome of a static solve.
struct StaticResult {
  bool converged = false;
  int iterations = 0;            ///< Newton iterations in all
  double loadFraction = 0.0;     ///< largest load fraction at which equilibrium was reached [-]
  double residual = 0.0;         ///< final max out-of-balance force [N]
  int worstNode = -1;            ///< global node with the largest out-of-balance force
  std::string message;           ///< human-readable summary
};

/// Static analysis driver.
class StaticSolver {
 public:
  StaticSolver(Assembler& assembler, const model::StaticSpec& settings) : m_assembler(&assembler), m_settings(settings) {}

  /// Solves for equilibrium starting from `state` (modified in place: on success it is the
  /// equilibrium; on failure the last equilibrium reached at a lower load fraction).
  StaticResult solve(model::State& state, double time = 0.0);

 private:
  /// Newton at a fixed load fraction. Returns true on convergence.
  bool newton(model::State& state, double loadFraction, double time, int maxIterations, StaticResult& result);

  Assembler* m_assembler;
  model::StaticSpec m_settings;
};

}  // namespace tangle::solver

#pragma once
/// @file ContactNewton.hpp
/// A small load-incremented Newton solver for the contact statics tests, using the statics hooks of
/// LoadContributor (limitIncrement, rejectState, commitStatic) the way the reworked StaticSolver is to
/// use them. TODO(issue 14): once src/tangle/solver/StaticSolver uses the hooks, the tests can call
/// Simulation::solveStatics() instead.

#include <Eigen/SparseLU>

#include <cmath>
#include <string>

#include "tangle/analysis/Simulation.hpp"

namespace tangle::test {

struct NewtonReport {
  bool converged = false;
  std::string message;
  int iterations = 0;             ///< total
  int lastIncrementIterations = 0;
  std::vector<double> lastResiduals;  ///< residual norms of the last increment
};

/// Solves statics from the current state of `sim`, ramping weight (loadFactor) over `increments` steps.
/// Convergence: max |F| over the equations < tol.
inline NewtonReport contactNewton(analysis::Simulation& sim, int increments, double tol, int maxIterations = 60) {
  NewtonReport report;
  solver::Assembler& assembler = sim.assembler();
  contact::LineContact* contact = sim.contact();
  const model::DofMap& dofs = sim.model().dofs();
  model::State& state = sim.state();
  const int n = dofs.equationCount();
  for (int inc = 1; inc <= increments; ++inc) {
    solver::AssemblyRequest request;
    request.loadFactor = static_cast<double>(inc) / increments;
    assembler.beginStep();
    bool converged = false;
    report.lastResiduals.clear();
    for (int it = 0; it < maxIterations; ++it) {
      VecX force;
      solver::SystemMatrix matrix(dofs);
      assembler.assemble(state, request, force, &matrix);
      VecX rhs(n);
      for (int d = 0; d < dofs.fullDofCount(); ++d)
        if (dofs.equation(d) >= 0) rhs[dofs.equation(d)] = -force[d];
      const double residual = rhs.cwiseAbs().maxCoeff();
      report.lastResiduals.push_back(residual);
      if (residual < tol) {
        if (assembler.updateActiveSet()) continue;
        converged = true;
        report.lastIncrementIterations = it;
        break;
      }
      SparseMatrix k;
      matrix.build(k);
      Eigen::SparseLU<SparseMatrix> lu;
      lu.compute(k);
      if (lu.info() != Eigen::Success) {
        report.message = "singular matrix";
        return report;
      }
      const VecX x = lu.solve(rhs);
      VecX full = VecX::Zero(dofs.fullDofCount());
      for (int d = 0; d < dofs.fullDofCount(); ++d)
        if (dofs.equation(d) >= 0) full[d] = x[dofs.equation(d)];
      const double alpha = contact ? contact->limitIncrement(state, full) : 1.0;
      state.applyIncrement(dofs, alpha * full);
      ++report.iterations;
    }
    if (!converged) {
      report.message = "increment " + std::to_string(inc) + " did not converge";
      return report;
    }
    if (contact) {
      const std::string why = contact->rejectState(state);
      if (!why.empty()) {
        report.message = why;
        return report;
      }
      contact->commitStatic(state);
    }
  }
  report.converged = true;
  return report;
}

}  // namespace tangle::test

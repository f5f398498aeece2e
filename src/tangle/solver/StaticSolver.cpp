#include "tangle/solver/StaticSolver.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "tangle/core/Error.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/ResidualNorm.hpp"
#include <cstdlib>
#include <iostream>

namespace tangle::solver {

StaticResult StaticSolver::solve(model::State& state, double time) {
  StaticResult result;
  if (m_assembler->model().dofs().equationCount() == 0) {
    result.converged = true;
    result.loadFraction = 1.0;
    result.message = "no free degrees of freedom";
    return result;
  }
  // Load incrementation: first try the full load from the (catenary) starting shape; on failure go
  // back to the last equilibrium and take smaller load increments.
  double reached = 0.0;
  double increment = 1.0;
  const model::State start = state;
  model::State lastGood = state;
  bool haveEquilibrium = false;
  int budget = m_settings.maxIterations;
  while (reached < 1.0 && budget > 0) {
    const double target = std::min(1.0, reached + increment);
    model::State trial = lastGood;
    StaticResult attempt;
    const int allowed = std::min(budget, target >= 1.0 && increment >= 1.0 ? budget / 2 : 60);
    bool ok = false;
    try {
      ok = newton(trial, target, time, allowed, attempt);
    } catch (const Error&) {
      ok = false;  // an element could not be evaluated at the start of this increment
    }
    budget -= attempt.iterations;
    result.iterations += attempt.iterations;
    result.residual = attempt.residual;
    result.worstNode = attempt.worstNode;
    if (ok) {
      lastGood = trial;
      haveEquilibrium = true;
      reached = target;
      increment = std::min(1.0, increment * 2.0);
    } else {
      increment *= 0.25;
      if (increment < 1e-3) break;
      if (!haveEquilibrium && reached == 0.0) {
        // Start the ramp from zero load: the starting shape itself.
        lastGood = start;
      }
    }
  }
  result.loadFraction = reached;
  result.converged = reached >= 1.0;
  state = haveEquilibrium ? lastGood : start;
  const model::Model& model = m_assembler->model();
  if (result.converged) {
    result.message = fmt::format("static equilibrium found in {} iterations (max out-of-balance {:.3g} N)",
                                 result.iterations, result.residual);
  } else {
    const std::string where = model.describeNode(result.worstNode);
    result.message = fmt::format(
        "static analysis did not converge: load fraction reached {:.3f}, {} iterations, largest out-of-balance "
        "force {:.4g} N at {}",
        result.loadFraction, result.iterations, result.residual, where);
  }
  return result;
}

bool StaticSolver::newton(model::State& state, double loadFraction, double time, int maxIterations,
                          StaticResult& result) {
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const int neq = dofs.equationCount();
  const auto& eqDofs = dofs.equationDofs();
  const double fref = m_assembler->referenceForce();
  double lref = 0.0;
  for (const auto& line : model.lines()) lref = std::max(lref, line.length);
  lref = std::max(lref, 1.0);
  double minElement = lref;
  for (const auto& el : model.elements()) minElement = std::min(minElement, el.restLength);
  // Largest nodal translation [m] and rotation [rad] per iteration: keeps Newton from jumping across
  // the solution on slack lines, where the tangent is nearly singular.
  const double maxTranslation = std::max(0.05 * lref, 2.0 * minElement);
  const double maxRotation = 0.5;

  AssemblyRequest request;
  request.time = time;
  request.loadFactor = loadFraction;
  request.dynamic = false;
  SystemMatrix matrix(dofs);
  SparseMatrix k;
  LinearSolver solver;
  VecX force;
  VecX r(neq);
  m_assembler->beginStep();
  m_assembler->assemble(state, request, force, &matrix);
  double norm = residualNorm(model, force, ResidualIndexing::FullDofs, &result.worstNode);
  result.residual = norm;
  int growing = 0;
  double best = norm;
  // Regularisation factor relative to the diagonal: 0 normally (pure Newton); raised only when the
  // tangent cannot be factorised (a slack line with no stiffness in some direction).
  double mu = 0.0;

  for (int it = 0; it < maxIterations; ++it) {
    result.iterations = it + 1;
    if (!std::isfinite(norm)) return false;
    for (int i = 0; i < neq; ++i) r[i] = force[eqDofs[i]];
    matrix.build(k);
    const VecX diag = k.diagonal().cwiseAbs();
    const double dmax = std::max(diag.maxCoeff(), 1e-12);
    // The shift is relative to each diagonal entry: one scaled by the largest entry (a vessel's link)
    // would soften every line DOF and make Newton converge only linearly.
    for (int i = 0; i < neq; ++i)
      k.coeffRef(i, i) += (mu > 0.0 ? mu : 1e-8) * std::max(diag[i], 1e-9 * dmax);
    if (!solver.factorize(k)) {
      mu = std::max(1e-3, mu * 10.0);
      if (mu > 1e3) return false;
      continue;
    }
    const VecX dq = -solver.solve(r);
    double largestT = 0.0, largestR = 0.0;
    for (int n = 0; n < dofs.nodeCount(); ++n) {
      const int d = dofs.firstDof(n);
      for (int c = 0; c < dofs.dofCount(n); ++c) {
        const int eq = dofs.equation(d + c);
        if (eq < 0) continue;
        (c < 3 ? largestT : largestR) = std::max(c < 3 ? largestT : largestR, std::abs(dq[eq]));
      }
    }
    double scale = 1.0;
    if (largestT > maxTranslation) scale = std::min(scale, maxTranslation / largestT);
    if (largestR > maxRotation) scale = std::min(scale, maxRotation / largestR);
    VecX full = VecX::Zero(dofs.fullDofCount());
    for (int i = 0; i < neq; ++i) full[eqDofs[i]] = scale * dq[i];
    state.applyIncrement(dofs, full);
    try {
      m_assembler->assemble(state, request, force, &matrix);
    } catch (const Error&) {
      return false;  // an element folded on itself: this load increment is too large
    }
    const double previous = norm;
    norm = residualNorm(model, force, ResidualIndexing::FullDofs, &result.worstNode);
    result.residual = norm;
    const double step = scale * largestT;
    if (std::getenv("TANGLE_DEBUG_STATICS"))
      std::cerr << fmt::format("  lambda {:.3f} it {:3d} |r| {:.4e} step {:.3e} scale {:.3g} mu {:.2e}\n",
                               loadFraction, it, norm, step, scale, mu);
    // Converged: forces balanced and either the last correction was negligible or the residual has
    // reached round-off level (it no longer halves; stiff elements carry force noise ~ EA * 1e-16).
    if (norm <= std::max(m_settings.tolerance * fref, 10.0 * m_assembler->roundoffForce()) &&
        (step <= m_settings.displacementTolerance * lref || norm <= 1e-9 * fref || norm > 0.5 * previous)) {
      if (!m_assembler->updateActiveSet()) return true;
      // A contact was released: the residual changed, iterate on.
      m_assembler->assemble(state, request, force, &matrix);
      norm = residualNorm(model, force, ResidualIndexing::FullDofs, &result.worstNode);
      best = norm;
      growing = 0;
      continue;
    }
    // Divergence watch: Newton may be non-monotone at first, but a residual that keeps growing means
    // the load increment is too large.
    if (norm < best) {
      best = norm;
      growing = 0;
    } else if (++growing > 8) {
      return false;
    }
    mu *= 0.1;
    if (mu < 1e-6) mu = 0.0;
  }
  return false;
}

}  // namespace tangle::solver

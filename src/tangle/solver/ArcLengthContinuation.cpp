#include "tangle/solver/ArcLengthContinuation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/solver/IncrementLimits.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/ResidualNorm.hpp"

namespace tangle::solver {

namespace {
/// Hyperplane residual accepted at convergence, relative to the arc length [-].
constexpr double kConstraintTolerance = 1e-6;
/// Corrections without a new smallest out-of-balance force before an arc step is cut.
constexpr int kPatience = 10;
/// Corrections without a new smallest out-of-balance force after which they are damped (halved, quartered,
/// ...).
constexpr int kDampAfter = 3;
/// Backtracking of a correction (see the corrector): from an iterate within this many tolerances, a
/// correction whose out-of-balance force exceeds kBacktrackGrowth times the iterate's (or the tolerance) is
/// halved, at most kBacktracks times.
constexpr double kBacktrackBelow = 10.0;
constexpr double kBacktrackGrowth = 2.0;
constexpr int kBacktracks = 6;
}  // namespace

ArcLengthContinuation::ArcLengthContinuation(Assembler& assembler, Settings settings,
                                             ParameterSetter setParameter, Finisher finish)
    : m_assembler(&assembler),
      m_settings(settings),
      m_setParameter(std::move(setParameter)),
      m_finish(std::move(finish)) {}

void ArcLengthContinuation::assembleResidual(const model::State& state, double lambda, VecX& r,
                                             SystemMatrix* matrix) {
  const auto& eqDofs = m_assembler->model().dofs().equationDofs();
  AssemblyRequest request;
  request.dynamic = false;
  request.wantMatrix = matrix != nullptr;
  m_setParameter(lambda, request);
  VecX force;
  m_assembler->assemble(state, request, force, matrix);
  r.resize(static_cast<Eigen::Index>(eqDofs.size()));
  for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = force[eqDofs[static_cast<std::size_t>(i)]];
}

bool ArcLengthContinuation::evaluate(const model::State& state, double lambda, VecX& r, VecX& drdl,
                                     SystemMatrix* matrix, std::string& why) {
  // The second point half a unit away, towards 0.5 (inside the loads the path sees); the matrix assembly
  // last, so that the contributors' trial data are those of (state, lambda).
  const double other = lambda < 0.5 ? lambda + 0.5 : lambda - 0.5;
  try {
    assembleResidual(state, other, drdl, nullptr);
    assembleResidual(state, lambda, r, matrix);
  } catch (const Error& e) {
    why = fmt::format("an element cannot be evaluated ({})", e.what());
    return false;
  }
  drdl = (drdl - r) / (other - lambda);
  if (!r.allFinite() || !drdl.allFinite()) {
    why = "the out-of-balance force is not finite";
    return false;
  }
  return true;
}

ArcLengthContinuation::Outcome ArcLengthContinuation::run(model::State& state, double lambda0, int& budget) {
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const auto& eqDofs = dofs.equationDofs();
  const int neq = dofs.equationCount();
  const double maxTranslation = translationCap(model);
  Outcome out;
  out.lambda = lambda0;
  double lambda = lambda0;
  SystemMatrix matrix(dofs);
  SparseMatrix k;
  LinearSolver solver;
  solver.setNonSymmetric(m_settings.nonSymmetricTangent);
  VecX r, drdl;
  std::string why;

  // The first direction: the tangent (dq/dlambda, 1) at the starting equilibrium. psi makes both parts of
  // it equal in the norm, so that lambda counts as much as the motion it causes.
  m_assembler->beginStep();
  if (!evaluate(state, lambda, r, drdl, &matrix, why)) {
    out.failure = why;
    return out;
  }
  matrix.build(k);
  if (!solver.factorize(k)) {
    out.failure = "the stiffness matrix is singular at the start of the arc-length continuation";
    return out;
  }
  VecX tq = -solver.solve(drdl);
  const double psi2 = std::max(tq.squaredNorm(), 1e-12);
  double tl = 1.0;
  const double norm0 = std::sqrt(tq.squaredNorm() + psi2);
  tq /= norm0;
  tl /= norm0;
  double ds = m_settings.firstIncrement * norm0;  // arc length of a lambda step of firstIncrement
  const double dsMin = 1e-6 * ds;
  const double dsMax = 20.0 * ds;

  auto fullOf = [&](const VecX& eq) {
    VecX full = VecX::Zero(dofs.fullDofCount());
    for (int i = 0; i < neq; ++i) full[eqDofs[static_cast<std::size_t>(i)]] = eq[i];
    return full;
  };
  // The largest fraction of the increment `full` at `from` the contributors accept (no line through another).
  auto contributorLimit = [&](const model::State& from, const VecX& full) {
    double s = 1.0;
    for (LoadContributor* c : m_assembler->contributors()) s = std::min(s, c->limitIncrement(from, full));
    return std::max(s, 0.0);
  };

  VecX rTrial;  // the out-of-balance force of a backtracking's try

  for (int step = 0; step < m_settings.maxSteps && budget > 0; ++step) {
    // Near the target: the predictor's point at lambda = target, then Newton there (the finisher).
    if (tl > 0.0 && lambda + ds * tl >= m_settings.target) {
      const double h = (m_settings.target - lambda) / tl;
      model::State trial = state;
      VecX full = fullOf(h * tq);
      full *= contributorLimit(state, full);
      trial.applyIncrement(dofs, full);
      if (m_finish(trial)) {
        state = trial;
        out.reached = true;
        out.lambda = m_settings.target;
        return out;
      }
      if (m_settings.debug) std::cerr << "  arc length: Newton at the target failed; shorter arc steps\n";
      m_assembler->beginStatics(state);
      ds = std::min(ds, 0.5 * h);
      if (ds < dsMin) {
        out.failure = "Newton at the target load fails from every point near it on the path";
        return out;
      }
    }

    // Predictor, cut where it would push a line through another.
    VecX acc = ds * tq;
    double accLambda = ds * tl;
    {
      const VecX full = fullOf(acc);
      const double s = contributorLimit(state, full);
      acc *= s;
      accLambda *= s;
    }
    model::State trial = state;
    trial.applyIncrement(dofs, fullOf(acc));
    double trialLambda = lambda + accLambda;
    m_assembler->beginStep();

    // Corrector on the hyperplane t . (increment) = ds.
    bool converged = false;
    int corrections = 0;
    double best = std::numeric_limits<double>::infinity();
    int sinceBest = 0;
    int activeSetChanges = 0;
    why.clear();
    for (;;) {
      // The path may pass through lambda < 0 (a snap-through whose unstable branch needs the load reversed,
      // the apex of a shallow arch past its supports' line); beyond the reversed full load it has wandered.
      if (trialLambda < -std::abs(m_settings.target)) {
        why = "the path runs to the reversed full load";
        break;
      }
      if (!evaluate(trial, trialLambda, r, drdl, &matrix, why)) break;
      out.residual = residualNorm(model, r, ResidualIndexing::Equations, &out.worstNode, kStaticMomentLever);
      const double g = tq.dot(acc) + psi2 * tl * accLambda - ds;
      if (m_settings.debug) {  // each correction: the out-of-balance force, where, and its components
        std::cerr << fmt::format("     correction {} lambda {:.6f} |r| {:.4g} N at {}", corrections,
                                 trialLambda, out.residual,
                                 out.worstNode >= 0 ? model.describeNode(out.worstNode) : "-");
        if (out.worstNode >= 0) {
          const int first = dofs.firstDof(out.worstNode);
          auto component = [&](int dof) {
            const int e = dofs.equation(dof);
            return e >= 0 ? r[e] : 0.0;
          };
          const Vec3& x = trial.position[out.worstNode];
          std::cerr << fmt::format(" ({:.4f}, {:.4f}, {:.4f}) m: ({:.3g}, {:.3g}, {:.3g}) N", x.x(), x.y(),
                                   x.z(), component(first), component(first + 1), component(first + 2));
        }
        std::cerr << '\n';
      }
      if (out.residual <= m_settings.tolerance && std::abs(g) <= kConstraintTolerance * ds) {
        if (!m_assembler->updateActiveSet()) {
          converged = true;
          break;
        }
        if (++activeSetChanges > m_settings.maxCorrections) {
          why = "a contributor's active set keeps changing";
          break;
        }
        continue;  // a contact released: correct again
      }
      if (corrections >= m_settings.maxCorrections || budget <= 0) {
        why = fmt::format("not converged in {} corrections (out-of-balance {:.3g} N)", corrections,
                          out.residual);
        break;
      }
      if (out.residual < best) {
        best = out.residual;
        sinceBest = 0;
      } else if (++sinceBest > kPatience) {
        why = fmt::format("the out-of-balance force stopped decreasing ({:.3g} N)", out.residual);
        break;
      }
      ++corrections;
      --budget;
      matrix.build(k);
      if (!solver.factorize(k)) {
        why = "the stiffness matrix is singular";
        break;
      }
      const VecX a = -solver.solve(r);
      const VecX b = -solver.solve(drdl);
      const double denominator = tq.dot(b) + psi2 * tl;
      if (!(std::abs(denominator) > 1e-12 * (std::abs(tq.dot(b)) + psi2 * std::abs(tl)))) {
        why = "the hyperplane is tangent to the path";
        break;
      }
      const double dLambda = -(g + tq.dot(a)) / denominator;
      const VecX dq = a + dLambda * b;
      // The statics trust regions, and the contributors' limits; lambda scaled with the rest.
      double largestT = 0.0, largestR = 0.0;
      for (int i = 0; i < neq; ++i) {
        const int dof = eqDofs[static_cast<std::size_t>(i)];
        double& largest = dof - dofs.firstDof(dofs.nodeOf(dof)) < 3 ? largestT : largestR;
        largest = std::max(largest, std::abs(dq[i]));
      }
      // Damped once the corrections stop lowering the out-of-balance force: full steps cycle about a kink of
      // the force (where a contact's radius tapers between sections, theory 9.11), halved ones contract.
      double scale = sinceBest >= kDampAfter ? std::pow(0.5, std::min(sinceBest - kDampAfter + 1, 4)) : 1.0;
      if (largestT > maxTranslation) scale = std::min(scale, maxTranslation / largestT);
      if (largestR > kRotationCap) scale = std::min(scale, kRotationCap / largestR);
      VecX full = fullOf(scale * dq);
      const double limit = contributorLimit(trial, full);
      full *= limit;
      scale *= limit;
      const double strain = strainStepRatio(model, *m_assembler, trial, full);
      if (strain > 1.0) {
        full /= strain;
        scale /= strain;
      }
      // From a nearly balanced iterate, a correction that raises the out-of-balance force many times over is
      // cut back by halves (to the best of up to kBacktracks halvings): near a grazing contact or a fold the
      // tangent lacks what the next millimetre brings (a patch about to touch, whose law starts with no
      // stiffness), and the full correction drove a line into the other (two lazy waves in each other's wake
      // at their first touch: 0.96 N -> 295 N, then a linear creep out that never came back within the
      // tolerance); cut back to 1/16 or 1/64 there, the next corrections converge. Each try is one assembly
      // of the out-of-balance force, not counted in the corrections' budget.
      if (out.residual <= kBacktrackBelow * m_settings.tolerance) {
        const double allowed = kBacktrackGrowth * std::max(out.residual, m_settings.tolerance);
        double bestNorm = std::numeric_limits<double>::infinity(), bestFactor = 1.0, factor = 1.0;
        for (int halving = 0; halving <= kBacktracks; ++halving, factor *= 0.5) {
          model::State candidate = trial;
          candidate.applyIncrement(dofs, factor * full);
          double norm = std::numeric_limits<double>::infinity();
          try {
            assembleResidual(candidate, trialLambda + factor * scale * dLambda, rTrial, nullptr);
            if (rTrial.allFinite())
              norm = residualNorm(model, rTrial, ResidualIndexing::Equations, nullptr, kStaticMomentLever);
          } catch (const Error&) {
            // an element cannot be evaluated at this try: a smaller one is tried
          }
          if (norm < bestNorm) {
            bestNorm = norm;
            bestFactor = factor;
          }
          if (norm <= allowed) break;
        }
        if (m_settings.debug && bestFactor < 1.0)
          std::cerr << fmt::format("     correction cut back to {} of itself\n", bestFactor);
        full *= bestFactor;
        scale *= bestFactor;
      }
      trial.applyIncrement(dofs, full);
      trialLambda += scale * dLambda;
      acc += scale * dq;
      accLambda += scale * dLambda;
    }
    out.iterations += corrections;
    if (converged) {
      const std::string rejected = m_assembler->rejectState(trial);
      if (!rejected.empty()) {
        converged = false;
        why = rejected;
      }
    }
    if (m_settings.debug)
      std::cerr << fmt::format(
          "  arc length: step {} lambda {:.5f} -> {:.5f}, ds {:.4g}, {} corrections{}\n", step, lambda,
          trialLambda, ds, corrections,
          converged
              ? ""
              : fmt::format(": {} at {}", why, out.worstNode >= 0 ? model.describeNode(out.worstNode) : "-"));
    if (!converged) {
      m_assembler->beginStatics(state);  // from the last point on the path, re-laid (theory 7.1)
      ds *= 0.25;
      if (ds < dsMin) {
        out.failure = fmt::format("arc length continuation stalled at lambda {:.4f} ({})", lambda, why);
        return out;
      }
      continue;
    }
    m_assembler->commitIncrement(trial);
    state = std::move(trial);
    lambda = trialLambda;
    out.lambda = lambda;
    ++out.steps;
    if (m_settings.onPoint) m_settings.onPoint(state, lambda);
    // The secant of this step is the next direction: it turns with the path at a fold.
    const double norm = std::sqrt(acc.squaredNorm() + psi2 * accLambda * accLambda);
    tq = acc / norm;
    tl = accLambda / norm;
    if (corrections <= 4)
      ds = std::min(dsMax, 1.5 * ds);
    else if (corrections > 10)
      ds *= 0.5;
  }
  out.failure = budget <= 0
                    ? "the iteration budget is used up"
                    : fmt::format("{} arc-length steps did not reach the target", m_settings.maxSteps);
  return out;
}

}  // namespace tangle::solver

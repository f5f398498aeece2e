// Arc-length continuation past a fold (solver/ArcLengthContinuation, docs/theory.md 7.1 stage 2c): a shallow
// two-member arch (the von Mises truss) in a vertical plane, pinned at z0 +- a on the x = 0 axis, its apex
// at x = -h, loaded at the apex by the current's drag on both members (current along +x). The apex load is
// lambda q a^3 / l^2 (q = rho Cd D U^2 / 2; each member's drag per length q (a / l)^3 along x, half of its
// length l lumped at the apex; theory 6.4), the members' axial force N = EA (l - l0) / l0 (theory 3.2), so
// the equilibrium path in closed form is
//   lambda(u) = 2 N(u) u l(u) / (q a^3),   l(u) = sqrt(a^2 + u^2),   u the apex's x.
// It rises from 0 at u = -h to a limit point (a fold) near u = -h / sqrt(3), falls through 0 at u = 0 (the
// unstable branch, members in compression) to a minimum near u = +h / sqrt(3) (a load against the current:
// lambda < 0, the current reversed, speed factor -sqrt(-lambda)) and rises again through 0 at u = +h (members
// in tension). With the
// limit value near 0.5, continuation in lambda stalls at the fold; the path in arc length goes round it and
// reaches the snapped-through equilibrium at lambda = 1. Members are neutrally buoyant beams with a bending
// stiffness of 1 N m^2 (moments of 0.01 N m at the apex against apex forces of 1.5 kN: the truss law to
// about 1e-6).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/ArcLengthContinuation.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LinearSolver.hpp"
#include "tangle/solver/ResidualNorm.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle {
namespace {

constexpr double kHalfSpan = 10.0;  // a [m]
constexpr double kRise = 1.0;       // h [m]
constexpr double kDepth = -100.0;   // z0 [m]
constexpr double kDiameter = 0.5;   // D [m]
constexpr double kDrag = 1.2;       // Cd [-]
constexpr double kSpeed = 1.0;      // U [m/s]
constexpr double kRho = 1025.0;     // [kg/m^3]
constexpr double kEA = 4.0e6;       // [N]

double dragScale() { return 0.5 * kRho * kDrag * kDiameter * kSpeed * kSpeed; }  // q [N/m]
double memberLength() { return std::hypot(kHalfSpan, kRise); }                   // l0 [m]

/// lambda on the closed-form equilibrium path at apex position u [m].
double lambdaOf(double u) {
  const double l = std::hypot(kHalfSpan, u);
  const double n = kEA * (l - memberLength()) / memberLength();
  return 2.0 * n * u * l / (dragScale() * std::pow(kHalfSpan, 3));
}

/// The limit point (u, lambda) on (-h, 0): golden-section search for the largest lambda.
std::pair<double, double> limitPoint() {
  double lo = -kRise, hi = 0.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double u1 = hi - g * (hi - lo), u2 = lo + g * (hi - lo);
    if (lambdaOf(u1) > lambdaOf(u2))
      hi = u2;
    else
      lo = u1;
  }
  const double u = 0.5 * (lo + hi);
  return {u, lambdaOf(u)};
}

/// The snapped-through equilibrium at lambda = 1 (u > h), by bisection.
double snappedApex() {
  double lo = kRise, hi = 5.0 * kRise;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lambdaOf(mid) < 1.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::string archModel() {
  const double neutral = kRho * std::numbers::pi * 0.25 * kDiameter * kDiameter;
  return fmt::format(R"(environment:
  water_depth: 200
  water_density: {rho}
  current: [{{z: 0, speed: {u}, azimuth: 0}}, {{z: -200, speed: {u}, azimuth: 0}}]
line_types:
  - {{name: member, outer_diameter: {d}, mass_per_length: {m:.17g}, axial_stiffness: {ea}, bending_stiffness: 1,
     drag_normal: {cd}, drag_axial: 0, added_mass_normal: 1}}
lines:
  - name: arch
    end_a: {{type: pinned, position: [0, 0, {zlo}]}}
    end_b: {{type: pinned, position: [0, 0, {zhi}]}}
    sections: [{{type: member, length: {len:.17g}, elements: 2}}]
    start_shape: [[{x}, 0, {z0}]]
statics: {{max_iterations: 200}}
)",
                     fmt::arg("rho", kRho), fmt::arg("u", kSpeed), fmt::arg("d", kDiameter),
                     fmt::arg("m", neutral), fmt::arg("ea", kEA), fmt::arg("cd", kDrag),
                     fmt::arg("zlo", kDepth - kHalfSpan), fmt::arg("zhi", kDepth + kHalfSpan),
                     fmt::arg("len", 2.0 * memberLength()), fmt::arg("x", -kRise), fmt::arg("z0", kDepth));
}

/// The apex: the node of the line farthest from the x = 0 axis in the start shape.
int apexNode(const model::State& state) {
  int best = 0;
  for (int n = 0; n < static_cast<int>(state.position.size()); ++n)
    if (std::abs(state.position[n].x()) > std::abs(state.position[best].x())) best = n;
  return best;
}

TEST(ArcLengthSnapThrough, ClosedFormPathHasAFoldBelowFullLoad) {
  // The premise of the test: a limit point below lambda = 1 and a unique equilibrium at lambda = 1.
  const auto [uLimit, lambdaLimit] = limitPoint();
  EXPECT_GT(lambdaLimit, 0.3);
  EXPECT_LT(lambdaLimit, 0.7);
  EXPECT_NEAR(uLimit, -kRise / std::sqrt(3.0), 0.02 * kRise);  // the shallow-truss value
  EXPECT_GT(snappedApex(), kRise);
}

TEST(ArcLengthSnapThrough, PathGoesRoundTheFoldToTheSnappedEquilibrium) {
  const model::Model model(io::readModelString(archModel(), "arch.yaml"));
  solver::Assembler assembler(model);
  hydro::HydroLoads hydro(model);
  assembler.addContributor(&hydro);
  model::State state = model.initialState();
  const int apex = apexNode(state);
  ASSERT_NEAR(state.position[apex].x(), -kRise, 1e-9);
  assembler.beginStatics(state);

  const double tolerance = 0.05;  // [N]: 6e-6 m of apex travel at the snapped state's 8 kN/m
  auto setParameter = [](double lambda, solver::AssemblyRequest& request) {
    request.currentFactor = std::copysign(std::sqrt(std::abs(lambda)), lambda);
  };
  // At lambda = 1: plain Newton from the predicted point.
  auto finish = [&](model::State& trial) {
    const model::DofMap& dofs = model.dofs();
    solver::SystemMatrix matrix(dofs);
    SparseMatrix k;
    solver::LinearSolver linear;
    solver::AssemblyRequest request;
    request.dynamic = false;
    setParameter(1.0, request);
    VecX force;
    VecX r(dofs.equationCount());
    for (int it = 0; it < 30; ++it) {
      assembler.assemble(trial, request, force, &matrix);
      for (int i = 0; i < dofs.equationCount(); ++i) r[i] = force[dofs.equationDofs()[i]];
      if (solver::residualNorm(model, r, solver::ResidualIndexing::Equations, nullptr, 1.0) <= tolerance)
        return true;
      matrix.build(k);
      if (!linear.factorize(k)) return false;
      const VecX dq = -linear.solve(r);
      VecX full = VecX::Zero(dofs.fullDofCount());
      for (int i = 0; i < dofs.equationCount(); ++i) full[dofs.equationDofs()[i]] = dq[i];
      trial.applyIncrement(dofs, full);
    }
    return false;
  };
  std::vector<std::pair<double, double>> path;  // (apex x [m], lambda)
  solver::ArcLengthContinuation::Settings settings;
  settings.tolerance = tolerance;
  settings.firstIncrement = 0.05;
  settings.debug = solver::StaticSolver::debugOutput();
  settings.onPoint = [&](const model::State& s, double lambda) {
    path.emplace_back(s.position[apex].x(), lambda);
  };
  solver::ArcLengthContinuation arc(assembler, settings, setParameter, finish);
  int budget = 2000;
  const solver::ArcLengthContinuation::Outcome outcome = arc.run(state, 0.0, budget);
  ASSERT_TRUE(outcome.reached) << outcome.failure;

  // Every point of the path is an equilibrium: on the closed-form curve. The apex force's sensitivity to
  // lambda is q a^3 / l^2 ~ 3 kN, so the 0.05 N tolerance is 2e-5 in lambda; 1e-4 leaves room for the
  // apex's z and the beams' bending (1e-6).
  for (const auto& [u, lambda] : path) EXPECT_NEAR(lambda, lambdaOf(u), 1e-4) << "apex at x = " << u;
  // The path passes the fold: its largest lambda before the snap is the limit value (sampled by the step
  // control, not placed on the fold: within 3 % below it), and it has points on the unstable branch between
  // the folds, where the apex moves on while lambda falls.
  const auto [uLimit, lambdaLimit] = limitPoint();
  double largest = 0.0;
  bool unstable = false;
  for (const auto& [u, lambda] : path) {
    if (u < 0.0) largest = std::max(largest, lambda);  // before the snap (beyond it lambda rises past 1)
    unstable = unstable || (u > uLimit + 0.1 * kRise && u < -uLimit - 0.1 * kRise);
  }
  EXPECT_LE(largest, lambdaLimit + 1e-4);
  EXPECT_GE(largest, 0.97 * lambdaLimit);
  EXPECT_TRUE(unstable) << "no point of the path on the unstable branch";
  // The snapped-through equilibrium at full current: the apex 8 kN/m stiff there, 0.05 N is 6e-6 m.
  EXPECT_NEAR(state.position[apex].x(), snappedApex(), 1e-4);
  EXPECT_NEAR(state.position[apex].z(), kDepth, 1e-4);
}

TEST(ArcLengthSnapThrough, StaticSolverReachesTheSnappedEquilibrium) {
  // The whole statics (the current continued from still water, round the fold): the same equilibrium.
  analysis::Simulation sim(io::readModelString(archModel(), "arch.yaml"));
  const int apex = apexNode(sim.state());
  const solver::StaticResult result = sim.solveStatics();
  ASSERT_TRUE(result.converged) << result.message;
  EXPECT_NEAR(sim.state().position[apex].x(), snappedApex(), 1e-3) << result.message;
  EXPECT_NEAR(sim.state().position[apex].z(), kDepth, 1e-3);
}

}  // namespace
}  // namespace tangle

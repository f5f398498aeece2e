/// @file WakeInterferenceTest.cpp
/// The geometry of WakeInterference (WakeInterference.hpp) at single points: where the wake starts behind
/// the upstream line, how it passes a change of the upstream line's section and a kink of its axis, and how
/// it fades past the line's end. The deficit formula itself
/// is hydro::wakeAt, tested against hand values in WakeModelTest; the whole static analysis against a
/// shooting solution in tests/validation/hydro/WakeInterferenceTest.cpp.
///
/// Set-up: an upstream line along z through the origin (x = y = 0), 20 m in 20 elements, of diameter 0.2 m
/// below z = -110 m and 0.6 m above (drag coefficients 1.0 and 1.5); a uniform 1 m/s current along +x; a
/// downstream line of one short element along z whose midpoint is put where the wake is probed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/hydro/CurrentProfile.hpp"
#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/hydro/WakeInterference.hpp"
#include "tangle/hydro/WakeModel.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle::hydro {
namespace {

constexpr double kJunction = -110.0;  // [m] z of the upstream line's section change (a node)

model::ModelSpec tandem() {
  model::ModelSpec spec;
  spec.sourceFile = "wake geometry (test)";
  spec.environment.waterDepth = 200.0;
  section::LineType thin = test::cableType("thin", 0.2, 50.0, 1e9),
                    thick = test::cableType("thick", 0.6, 50.0, 1e9);
  thin.dragNormal = 1.0;
  thick.dragNormal = 1.5;
  spec.lineTypes["thin"] = thin;
  spec.lineTypes["thick"] = thick;
  model::LineSpec up = test::simpleLine("up", "thin", 10.0, 10, model::EndKind::Fixed, Vec3(0, 0, -120),
                                        model::EndKind::Fixed, Vec3(0, 0, -100));
  up.sections = {{"thin", 10.0, 10}, {"thick", 10.0, 10}};
  spec.lines = {up, test::simpleLine("down", "thin", 0.02, 1, model::EndKind::Fixed, Vec3(3, 0, -110.01),
                                     model::EndKind::Fixed, Vec3(3, 0, -109.99))};
  model::WakeSpec w;
  w.upstream = "up";
  w.downstream = "down";
  spec.wakes = {w};
  return spec;
}

/// The deficit u / U [-] at the downstream element's midpoint `p`.
struct Probe {
  model::Model model{tandem()};
  model::State state{model.initialState()};
  CurrentProfile current{CurrentProfile::uniform(1.0, 0.0)};
  WakeInterference wake{model, current};
  double deficitAt(const Vec3& p) {
    const model::Line& down = model.lines()[1];
    state.position[down.firstNode] = p - Vec3(0, 0, 0.01);
    state.position[down.firstNode + 1] = p + Vec3(0, 0, 0.01);
    std::vector<ElementWake> out;
    wake.evaluate(state, 1025.0, out);
    return out[static_cast<std::size_t>(down.firstElement)].deficit;
  }
};

TEST(WakeInterference, StartsSmoothlyAtTheUpstreamCylindersRearSurface) {
  // Source: WakeInterference.hpp: behind the upstream centre the Huse deficit times the smoothstep
  // r^2 (3 - 2 r), r = 2 x / D, which is one from the rear surface x = D / 2 on; nothing level with or
  // ahead of the centre. Probed 0.05 m off the axis (y), far from the section change (z = -115 m, D = 0.2
  // m, C_d = 1). Continuity: between points 1 mm apart in x the deficit changes by less than 2 % of U
  // (its largest slope, about 0.6 U over the 0.1 m of the rise, gives 0.9 %); with the cut-off at x = 0 it
  // jumped by 0.6 U.
  Probe probe;
  const WakeCoefficients huse;  // k1 0.25, k2 1.0, k3 0.693, as WakeSpec's defaults
  double last = 0.0;
  for (int i = -50; i <= 400; ++i) {
    const double x = 1e-3 * i;
    const double deficit = probe.deficitAt(Vec3(x, 0.05, -115.0));
    const double r = std::clamp(2.0 * x / 0.2, 0.0, 1.0);
    const double expected =
        x > 0.0 ? r * r * (3.0 - 2.0 * r) * wakeAt(huse, x, 0.05, 1.0, 0.2, 0.2).deficit : 0.0;
    EXPECT_NEAR(deficit, expected, 1e-12) << "x = " << x;
    EXPECT_LT(std::abs(deficit - last), 0.02) << "x = " << x;
    last = deficit;
  }
}

TEST(WakeInterference, PassesAChangeOfTheUpstreamSectionContinuously) {
  // Source: WakeInterference.hpp: the upstream D and C_d are the means of D and C_d D over D_max = 0.6 m of
  // arc either side of the point's projection, so farther than 0.6 m from the section change the wake is
  // Huse's of the section there, and in between it passes from one to the other. Probed 3 m behind (x)
  // and on the wake's centre line, for z from 2 m below the change to 2 m above in steps of 5 mm: the
  // deficit changes by less than 1 % of U per step (the blend spreads the change from 0.229 U to 0.442 U
  // over 1.2 m: 0.09 % per step); with the element's own section it jumped by the whole 0.21 U where the
  // projection crossed the node.
  Probe probe;
  const WakeCoefficients huse;
  const double below = wakeAt(huse, 3.0, 0.0, 1.0, 0.2, 0.2).deficit;
  const double above = wakeAt(huse, 3.0, 0.0, 1.5, 0.6, 0.2).deficit;
  ASSERT_GT(above - below, 0.1);
  double last = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i <= 800; ++i) {
    const double z = kJunction - 2.0 + 5e-3 * i;
    const double deficit = probe.deficitAt(Vec3(3.0, 0.0, z));
    if (z < kJunction - 0.6 - 1e-9) {
      EXPECT_NEAR(deficit, below, 1e-12) << "z = " << z;
    } else if (z > kJunction + 0.6 + 1e-9) {
      EXPECT_NEAR(deficit, above, 1e-12) << "z = " << z;
    }
    EXPECT_GE(deficit, std::min(below, above) - 1e-12) << "z = " << z;
    EXPECT_LE(deficit, std::max(below, above) + 1e-12) << "z = " << z;
    if (i > 0) {
      EXPECT_LT(std::abs(deficit - last), 0.01) << "z = " << z;
    }
    last = deficit;
  }
}

// Huse's largest slope across the wake, u0 sqrt(2 k3 / e) / b (at y = b / sqrt(2 k3)), 3 m behind the thin
// section (u0 = 0.229 U, b = 0.218 m): 0.75 U per m; behind the thick one (0.442 U, 0.509 m): 0.62 U per m.
// A step of 1 mm moves a point by 1 mm relative to the wake, so a continuous wake changes by less than 1e-3
// U per step; the tests below allow twice that.
constexpr double kLargestStepPerMillimetre = 2e-3;

TEST(WakeInterference, PassesAKinkOfTheUpstreamLineContinuouslyAndWithoutMemory) {
  // Source: WakeInterference.hpp (the upstream axis: its chords with the tangent interpolated between the
  // node tangents; a point projects where d = p - q is normal to that tangent). The upstream line is bent at
  // its node at z = -115 m by 26.6 deg towards +y (each node above it moved by half its height above the
  // kink). A point 3 m behind it and 0.1 m to -y, on the kink's outer side, moves from z = -115.5 to -114.5 m
  // in 1 mm steps through the wedge outside the kink (0 < z + 115 < 0.05 m), where it is square to neither
  // chord; it stays in the wake (a deficit above 0.02 U: 0.31 m off the centre line at the top, 1.4 b).
  // Continuity: less than kLargestStepPerMillimetre per step. No memory: the same state gives the same
  // deficit (1e-12) whether the walk along the upstream line came from below (sweeping up) or from above
  // (sweeping down). Before, in the wedge the point took the node with the tangent of the element the walk
  // came from: the two sweeps differed there, and the deficit jumped where the wedge began and ended.
  Probe probe;
  const model::Line& up = probe.model.lines()[0];
  for (int n = up.firstNode; n <= up.lastNode(); ++n) {
    Vec3& x = probe.state.position[n];
    x.y() = std::max(0.0, 0.5 * (x.z() + 115.0));
  }
  constexpr int kSteps = 1000;
  std::vector<double> rising(kSteps + 1);
  double last = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i <= kSteps; ++i) {
    rising[static_cast<std::size_t>(i)] = probe.deficitAt(Vec3(3.0, -0.1, -115.5 + 1e-3 * i));
    if (i > 0) {
      EXPECT_LT(std::abs(rising[static_cast<std::size_t>(i)] - last), kLargestStepPerMillimetre)
          << "step " << i;
    }
    last = rising[static_cast<std::size_t>(i)];
  }
  EXPECT_GT(*std::min_element(rising.begin(), rising.end()), 0.02) << "the point left the wake";
  for (int i = kSteps; i >= 0; --i)
    EXPECT_NEAR(probe.deficitAt(Vec3(3.0, -0.1, -115.5 + 1e-3 * i)), rising[static_cast<std::size_t>(i)],
                1e-12)
        << "step " << i;
}

TEST(WakeInterference, FadesPastTheEndOfTheUpstreamLine) {
  // Source: WakeInterference.hpp: a point beyond an end of the upstream line projects onto that end, and its
  // distance across the wake includes its overshoot along the line, so it sees Huse's deficit at (x,
  // sqrt(y^2 + overshoot^2)). Probed 3 m behind the line's top end (z = -100 m; thick section, D = 0.6 m,
  // C_d = 1.5) and 0.1 m off the wake's centre line, from z = -101 to -98 m in 1 mm steps: below the end the
  // section's wake, above it that wake at the combined distance (1e-12: the same formula), and no step
  // larger than kLargestStepPerMillimetre. Before, the wake stopped at the end: a step of 0.43 U.
  Probe probe;
  const WakeCoefficients huse;
  double last = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i <= 3000; ++i) {
    const double z = -101.0 + 1e-3 * i;
    const double deficit = probe.deficitAt(Vec3(3.0, 0.1, z));
    const double across = std::hypot(0.1, std::max(0.0, z + 100.0));
    EXPECT_NEAR(deficit, wakeAt(huse, 3.0, across, 1.5, 0.6, 0.2).deficit, 1e-12) << "z = " << z;
    if (i > 0) {
      EXPECT_LT(std::abs(deficit - last), kLargestStepPerMillimetre) << "z = " << z;
    }
    last = deficit;
  }
}

/// The tandem with a downstream line of two 0.5 m elements whose middle node is free, in a uniform current;
/// Blevins's wake (deficit and lift) or Huse's (deficit only).
model::ModelSpec tandemWithFreeNode(const Vec3& middle, bool blevins = false) {
  model::ModelSpec spec = tandem();
  if (blevins) spec.wakes[0].model = model::WakeSpec::Model::Blevins;
  spec.environment.current = {{0.0, 1.0, 0.0}, {-200.0, 1.0, 0.0}};
  spec.lines[1] = test::simpleLine("down", "thin", 1.0, 2, model::EndKind::Fixed, middle - Vec3(0, 0, 0.5),
                                   model::EndKind::Fixed, middle + Vec3(0, 0, 0.5));
  return spec;
}

/// The largest difference between the hydrodynamic tangent's block of the free node and central differences
/// of its hydrodynamic force, relative to the block's largest entry, with the wake's drag in the tangent or
/// not.
double wakeTangentError(bool wakeDragStiffness, bool blevins = false, double currentFactor = 0.8,
                        bool symmetricParts = false) {
  const Vec3 middle(3.0, 0.12, -115.0);  // behind the thin section, off the wake's centre line
  const model::Model model(tandemWithFreeNode(middle, blevins));
  HydroLoads hydro(model);
  solver::AssemblyRequest request;
  request.dynamic = false;
  request.dragStiffness = true;  // the drag turning with the elements (here cancelling between the two)
  request.wakeDragStiffness = wakeDragStiffness;
  request.currentFactor = currentFactor;  // as in the statics' continuation
  const model::DofMap& dofs = model.dofs();
  model::State state = model.initialState();
  const int node = model.lines()[1].firstNode + 1;
  state.position[node] = middle;  // (the start shape of a line exactly as long as its span)
  solver::SystemMatrix matrix(dofs);
  VecX force = VecX::Zero(dofs.fullDofCount());
  hydro.addForces(state, request, force, &matrix);
  SparseMatrix k;
  matrix.build(k);
  const auto& eqDofs = dofs.equationDofs();
  std::vector<int> eq(3, -1);
  for (std::size_t i = 0; i < eqDofs.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (eqDofs[i] == dofs.firstDof(node) + c) eq[static_cast<std::size_t>(c)] = static_cast<int>(i);
  const Mat3 block = Mat3(k.toDense().block(eq[0], eq[0], 3, 3));
  // Central differences of the out-of-balance force; h = 1e-5 m against a wake 0.2 m wide (truncation
  // ~1e-9 relative) and forces of ~100 N (round-off ~1e-16 x 100 / 1e-5 = 1e-9 N/m).
  const double h = 1e-5;
  Mat3 difference;
  for (int c = 0; c < 3; ++c) {
    VecX plus = VecX::Zero(dofs.fullDofCount()), minus = VecX::Zero(dofs.fullDofCount());
    model::State s = state;
    s.position[node][c] += h;
    hydro.addForces(s, request, plus, nullptr);
    s.position[node][c] -= 2.0 * h;
    hydro.addForces(s, request, minus, nullptr);
    difference.col(c) = (plus - minus).segment<3>(dofs.firstDof(node)) / (2.0 * h);
  }
  if (symmetricParts)
    return (0.5 * (block + block.transpose()) - 0.5 * (difference + difference.transpose()))
               .cwiseAbs()
               .maxCoeff() /
           difference.cwiseAbs().maxCoeff();
  return (block - difference).cwiseAbs().maxCoeff() / difference.cwiseAbs().maxCoeff();
}

TEST(WakeInterference, DragThroughTheDeficitMakesTheTangentConsistent) {
  // Source: the definition of the tangent, d(out-of-balance)/d(position), against central differences
  // (tolerance 1e-6: both differences' errors are ~1e-9, see wakeTangentError). With
  // AssemblyRequest::wakeDragStiffness the drag's change through the deficit (WakeInterference::
  // velocityChangeGradient, HydroLoads) is in the tangent; without it the block misses it - the negative
  // stiffness of the wake-induced collapse (docs/theory.md 12.2) - by more than a tenth.
  EXPECT_LT(wakeTangentError(true), 1e-6);
  EXPECT_GT(wakeTangentError(false), 0.1);
}

TEST(WakeInterference, BlevinsLiftStiffnessFollowsTheFractionOfTheCurrent) {
  // Source: as above, with Blevins's wake, whose lift (the pull towards the wake's centre line) acts with the
  // drag fraction f = currentFactor^2 of the statics' continuation. The lift's stiffness goes in symmetrised
  // (the symmetric LDL^T; HydroLoads), so the symmetric parts are compared (1e-6 as above); the whole block
  // is off by the lift's antisymmetric part, the same fraction at every f (0.036 measured). Until 2026-12-06
  // the lift's stiffness was the full current's at every f: the symmetric parts were 0.5625 and 10.11 of the
  // largest entry off at currentFactor 0.8 and 0.3 (1 / f - 1).
  EXPECT_LT(wakeTangentError(true, true, 0.8, true), 1e-6);
  EXPECT_LT(wakeTangentError(true, true, 0.3, true), 1e-6);
  EXPECT_NEAR(wakeTangentError(true, true, 0.3), wakeTangentError(true, true, 0.8), 1e-6);
}

TEST(WakeInterference, TheWakeMovesWithTheUpstreamLine) {
  // Source: the definition of the tangent against central differences, for the coupling blocks between the
  // downstream line's free node and the upstream line's nodes (WakeGradient, docs/theory.md 12.2). The wake
  // depends on the downstream point's position relative to the upstream line, so translating the whole
  // upstream line by x changes the downstream force as translating the point by -x: the sum of the coupling
  // blocks over the upstream nodes against the central difference of that translation, 1e-6 (as the free
  // node's own block: both differences' errors ~1e-9, uniform current). Each node's block alone splits it by
  // the projection's weights and leaves out the upstream element's turning (not checked here).
  const Vec3 middle(3.0, 0.12, -115.0);
  const model::Model model(tandemWithFreeNode(middle));
  HydroLoads hydro(model);
  solver::AssemblyRequest request;
  request.dynamic = false;
  request.dragStiffness = true;
  request.wakeDragStiffness = true;
  request.currentFactor = 0.8;
  const model::DofMap& dofs = model.dofs();
  model::State state = model.initialState();
  const int node = model.lines()[1].firstNode + 1;
  state.position[node] = middle;
  solver::SystemMatrix matrix(dofs);
  VecX force = VecX::Zero(dofs.fullDofCount());
  hydro.addForces(state, request, force, &matrix);
  SparseMatrix k;
  matrix.build(k);
  const Eigen::MatrixXd dense = k.toDense();
  const model::Line& up = model.lines()[0];
  Mat3 sum = Mat3::Zero();
  for (int n = up.firstNode; n <= up.lastNode(); ++n)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const int row = dofs.equation(dofs.firstDof(node) + r), col = dofs.equation(dofs.firstDof(n) + c);
        if (row >= 0 && col >= 0) sum(r, c) += dense(row, col);
      }
  const double h = 1e-5;
  Mat3 difference;
  for (int c = 0; c < 3; ++c) {
    VecX plus = VecX::Zero(dofs.fullDofCount()), minus = VecX::Zero(dofs.fullDofCount());
    model::State s = state;
    for (int n = up.firstNode; n <= up.lastNode(); ++n) s.position[n][c] += h;
    hydro.addForces(s, request, plus, nullptr);
    for (int n = up.firstNode; n <= up.lastNode(); ++n) s.position[n][c] -= 2.0 * h;
    hydro.addForces(s, request, minus, nullptr);
    difference.col(c) = (plus - minus).segment<3>(dofs.firstDof(node)) / (2.0 * h);
  }
  ASSERT_GT(difference.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT((sum - difference).cwiseAbs().maxCoeff() / difference.cwiseAbs().maxCoeff(), 1e-6);
  // Without the coupling the tangent says the wake stays where it is when the upstream line moves: the
  // translation's effect is of the order of the node's own stiffness (here more than a tenth of it).
  double own = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      own = std::max(own, std::abs(dense(dofs.equation(dofs.firstDof(node) + r),
                                         dofs.equation(dofs.firstDof(node) + c))));
  EXPECT_GT(difference.cwiseAbs().maxCoeff(), 0.1 * own);
}

}  // namespace
}  // namespace tangle::hydro

// Consistent tangent of the contact (issue 14): the analytic derivatives of the closest-point distance
// (ContactKinematics) and the full contact stiffness matrix of LineContact (line-to-line Gauss points,
// blended and point-to-point contacts) against central finite differences of the force.
//
// Tolerance: central differences with step h have truncation error ~ h^2 f''' and round-off
// ~ eps |f| / h; with h = 1e-6 m on coordinates of order 1 m both are below 1e-6 of the entries; the
// tolerance 1e-5 of the largest entry leaves a margin of 10. Angles: 0 and 4 deg (line-to-line only),
// 8 deg, 25 and 90 deg
// (point-to-point only). Inside the band (10-20 deg) the tangent leaves out the derivative of the
// blending weight (it would make the matrix unsymmetric; docs/theory.md 9.3), so it is not tested there.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/contact/ContactKinematics.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

TEST(ContactKinematics, DistanceHessianMatchesFiniteDifferences) {
  const Vec3 a0(0.1, -0.2, 0.3), a1(1.2, 0.1, 0.2), b0(0.3, 0.8, -0.4), b1(0.9, -0.7, 0.5);
  for (int mode = 0; mode < 3; ++mode) {
    // 0: s fixed, t free (line-to-line Gauss point); 1: both free (crossing closest points); 2: both fixed.
    auto eval = [&](const Vec12& q, bool hess) {
      const Vec3 p0 = q.segment<3>(0), p1 = q.segment<3>(3), q0 = q.segment<3>(6), q1 = q.segment<3>(9);
      double s = 0.4, t = 0.6;
      if (mode == 0) t = contact::projectOnAxis((1 - s) * p0 + s * p1, q0, q1);
      if (mode == 1) {
        // Closest points of the two axes.
        const Vec3 m0 = p1 - p0, m1 = q1 - q0, r = p0 - q0;
        const double a = m0.dot(m0), b = m0.dot(m1), c = m1.dot(m1), d = m0.dot(r), e = m1.dot(r);
        const double det = a * c - b * b;
        s = (b * e - c * d) / det;
        t = (a * e - b * d) / det;
      }
      return contact::distanceKinematics(p0, p1, q0, q1, s, t, mode == 1, mode != 2, 1.0, hess);
    };
    Vec12 q;
    q << a0, a1, b0, b1;
    const contact::DistanceKinematics k = eval(q, true);
    const double h = 1e-6;
    Mat12 fd;
    Vec12 fdGrad;
    for (int j = 0; j < 12; ++j) {
      Vec12 qp = q, qm = q;
      qp[j] += h;
      qm[j] -= h;
      const auto kp = eval(qp, false), km = eval(qm, false);
      fd.col(j) = (kp.gradient - km.gradient) / (2 * h);
      fdGrad[j] = (kp.distance - km.distance) / (2 * h);
    }
    EXPECT_LT((fdGrad - k.gradient).cwiseAbs().maxCoeff(), 1e-8) << "mode " << mode;
    EXPECT_LT((fd - k.hessian).cwiseAbs().maxCoeff(), 1e-5 * k.hessian.cwiseAbs().maxCoeff())
        << "mode " << mode;
  }
}

// Two pinned cables; line B (the master) straight along x, line A bent over it at `angleDeg`.
struct TangentCase {
  double angleDeg;
  double depth;              // largest penetration [m]
  bool beams = false;        // steel beams (smooth centreline, SmoothCentreline.hpp) instead of cables
  bool distributed = false;  // contact.formulation: distributed (DistributedContact.hpp)
  /// Line B thick (radius 0.1 m) from its middle node on, A raised by 0.04 m and crossing there: the contact
  /// lies on B's shoulder, whose radius slope enters the gap's gradient (DistributedContact.hpp).
  bool shoulder = false;
};

class ContactTangent : public ::testing::TestWithParam<TangentCase> {};

TEST_P(ContactTangent, StiffnessMatrixMatchesFiniteDifferencesOfTheForce) {
  const TangentCase tc = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "tangent (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["c"] =
      tc.beams ? test::solidRodType("c", 0.1, 2.1e11, 7850.0) : test::cableType("c", 0.1, 20.0, 1e8);
  const double ang = degToRad(tc.angleDeg);
  const Vec3 dir(std::cos(ang), std::sin(ang), 0.0);
  const double lift = tc.shoulder ? 0.04 : 0.0;
  const Vec3 offset(tc.shoulder ? 0.003 : 0.13, 0.0, 0.0);
  spec.lines = {test::simpleLine("a", "c", 6.0, 12, model::EndKind::Pinned, Vec3(0, 0, 0.1) - 3.0 * dir,
                                 model::EndKind::Pinned, Vec3(0, 0, 0.1) + 3.0 * dir),
                test::simpleLine("b", "c", 6.0, 12, model::EndKind::Pinned, Vec3(-3, 0, 0),
                                 model::EndKind::Pinned, Vec3(3, 0, 0))};
  if (tc.shoulder) {
    spec.lineTypes["thick"] = tc.beams ? test::solidRodType("thick", 0.2, 2.1e11, 7850.0)
                                       : test::cableType("thick", 0.2, 20.0, 1e8);
    spec.lines[1].sections = {{"c", 3.0, 6}, {"thick", 3.0, 6}};
  }
  spec.contact.enabled = true;
  spec.contact.excludeConnections = false;  // the pinned ends are close to each other on purpose
  spec.contact.formulation =
      tc.distributed ? model::ContactFormulation::Distributed : model::ContactFormulation::Point;
  const model::Model m(spec);
  contact::LineContact contact(m, m.spec().contact, 0.01);
  model::State state = m.initialState();
  // Bend A down onto B: z = 0.1 - depth (1 - (s/3)^2) along it, plus a small lateral wave.
  const model::Line& a = m.lines()[0];
  for (int i = 0; i < a.nodeCount; ++i) {
    const double s = -3.0 + 6.0 * i / (a.nodeCount - 1);
    state.position[a.firstNode + i] =
        s * dir + offset + Vec3(0, 0.02 * std::sin(s), 0.1 + lift - tc.depth * (1 - s * s / 9.0) + 1e-4 * i);
  }
  const model::DofMap& dofs = m.dofs();
  auto forceAt = [&](const model::State& st, solver::SystemMatrix* matrix) {
    VecX f = VecX::Zero(dofs.fullDofCount());
    solver::AssemblyRequest request;
    contact.beginStep();
    contact.addForces(st, request, f, matrix);
    return f;
  };
  solver::SystemMatrix matrix(dofs);
  const VecX f0 = forceAt(state, &matrix);
  ASSERT_GT(f0.norm(), 0.0) << "no contact in the test state";
  SparseMatrix k;
  matrix.build(k);
  const Eigen::MatrixXd dense(k);
  const double h = 1e-6;
  double worst = 0.0, worstMaster = 0.0;
  std::string where;
  const model::Line& bLine = m.lines()[1];
  for (int node = 0; node < m.nodeCount(); ++node)
    for (int c = 0; c < 3; ++c) {
      const int dof = dofs.firstDof(node) + c;
      if (dofs.equation(dof) < 0) continue;
      model::State sp = state, sm = state;
      sp.position[node][c] += h;
      sm.position[node][c] -= h;
      const VecX col = (forceAt(sp, nullptr) - forceAt(sm, nullptr)) / (2 * h);
      for (int r = 0; r < dofs.fullDofCount(); ++r)
        if (dofs.equation(r) >= 0) {
          const double e = std::abs(col[r] - dense(dofs.equation(r), dofs.equation(dof)));
          // Moving an interior node of the master line kinks it; the slave points that then fall in
          // the kink's vertex region (convex) or in two elements' regions (concave) change the force
          // at first order, which the tangent leaves out (docs/theory.md 9.3): checked apart, at 2 %.
          // (The distributed formulation measures C1 centrelines: no kink, no exception.)
          const bool masterNode =
              !tc.distributed && node > bLine.firstNode && node < bLine.lastNode() && tc.angleDeg < 20.0;
          if (masterNode) {
            worstMaster = std::max(worstMaster, e);
            continue;
          }
          if (e > worst) {
            worst = e;
            where = fmt::format("row dof {} col dof {}: fd {} analytic {}", r, dof, col[r],
                                dense(dofs.equation(r), dofs.equation(dof)));
          }
        }
    }
  EXPECT_LT(worstMaster, 0.02 * dense.cwiseAbs().maxCoeff());
  // The distributed formulation's Gauss points sit on pieces of the contact interval whose ends (the
  // interval's, and where the penetration passes the law's p0 and p1) move with the nodes: the exact
  // integral's derivative has no term from them (the integrand vanishes with its slope at the interval's ends
  // and is C1 at the cuts), the quadrature's differs by its own error. Measured 2026-11-29: 4.7e-5 of the
  // largest entry for the parallel contact (its ends graze), 0.9-2.3e-6 at crossings (before the cuts at p0
  // and p1: 0.27-0.48 %).
  const double tolerance = tc.distributed ? 1e-4 : 1e-5;
  EXPECT_LT(worst, tolerance * dense.cwiseAbs().maxCoeff())
      << "largest entry " << dense.cwiseAbs().maxCoeff() << "; worst at " << where;
}

INSTANTIATE_TEST_SUITE_P(Angles, ContactTangent,
                         ::testing::Values(TangentCase{0.0, 0.01}, TangentCase{4.0, 0.01},
                                           TangentCase{8.0, 0.005}, TangentCase{25.0, 0.005},
                                           TangentCase{90.0, 0.005}, TangentCase{25.0, 0.005, true},
                                           TangentCase{90.0, 0.005, true}),
                         [](const ::testing::TestParamInfo<TangentCase>& p) {
                           return (p.param.beams ? "beams_deg" : "deg") +
                                  std::to_string(static_cast<int>(p.param.angleDeg));
                         });

// The distributed formulation (Gauss points along both lines against the other's C1 centreline).
INSTANTIATE_TEST_SUITE_P(
    Distributed, ContactTangent,
    ::testing::Values(TangentCase{0.0, 0.01, false, true}, TangentCase{8.0, 0.005, false, true},
                      TangentCase{25.0, 0.005, false, true}, TangentCase{90.0, 0.005, false, true},
                      TangentCase{90.0, 0.005, true, true}),
    [](const ::testing::TestParamInfo<TangentCase>& p) {
      return (p.param.beams ? "beams_deg" : "deg") + std::to_string(static_cast<int>(p.param.angleDeg));
    });

// The contact on a shoulder of line B (a section change, DistributedContact.hpp), where the master's radius
// r_B(t) moves with the projection. Until 2026-12-06 a known failure (1.5 % of the largest entry at 90 deg,
// cables and beams; 6.7 % at 25 deg). Measured 2026-12-06 (largest difference over the largest entry):
// - 90 deg, cables and beams: 6.9e-9. The slave's pieces were to be cut at its own shoulder ends, but the
//   cut was tested against the interval before its ends were set, and none was made.
// - 25 deg: 6.7 % -> 0.12 % with the pieces also cut where the master's projection passes its shoulder's
//   ends, -> 5.4e-6 with f r_B' Hess t in the tangent (projectionHessian).
INSTANTIATE_TEST_SUITE_P(Shoulder, ContactTangent,
                         ::testing::Values(TangentCase{90.0, 0.005, false, true, true},
                                           TangentCase{25.0, 0.005, false, true, true},
                                           TangentCase{90.0, 0.005, true, true, true}),
                         [](const ::testing::TestParamInfo<TangentCase>& p) {
                           return (p.param.beams ? "beams_deg" : "deg") +
                                  std::to_string(static_cast<int>(p.param.angleDeg)) + "_shoulder";
                         });

}  // namespace
}  // namespace tangle

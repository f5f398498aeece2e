/// @file MorisonTest.cpp
/// Relative-velocity Morison loads on a line element (tangle::hydro::morisonElementLoad).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/Morison.hpp"

namespace tangle::hydro {
namespace {

constexpr double kRho = 1025.0;

section::LineType testType() {
  section::LineType type;
  type.name = "test";
  type.outerDiameter = 0.1;
  type.buoyancyDiameter = 0.1;
  type.dragNormal = 1.2;
  type.dragAxial = 0.008;
  type.addedMassNormal = 1.0;
  type.addedMassAxial = 0.0;
  return type;
}

FluidKinematics flow(const Vec3& u, const Vec3& a = Vec3::Zero()) {
  FluidKinematics f;
  f.velocity = u;
  f.acceleration = a;
  return f;
}

// Source: hand calculation. Horizontal 10 m element along x, D = 0.1 m, Cdn = 1.2, still structure,
// 1 m/s current along +y (purely normal): 1/2 rho Cdn D |u| u = 0.5 * 1025 * 1.2 * 0.1 * 1 = 61.5 N/m,
// 615 N for the element, 307.5 N per node. Tolerance 1e-10 N (rounding of a few products).
TEST(Morison, NormalDragByHand) {
  const MorisonElementLoad load =
      morisonElementLoad(Vec3(0, 0, -10), Vec3(10, 0, -10), Vec3::Zero(), Vec3::Zero(), flow(Vec3(0, 1, 0)),
                         testType(), kRho, 1.0);
  EXPECT_NEAR(load.force1.y(), 307.5, 1e-10);
  EXPECT_NEAR(load.force2.y(), 307.5, 1e-10);
  EXPECT_NEAR(load.force1.x(), 0.0, 1e-12);
  EXPECT_NEAR(load.force1.z(), 0.0, 1e-12);
  // 2 m/s: quadratic, four times the force.
  const MorisonElementLoad load2 =
      morisonElementLoad(Vec3(0, 0, -10), Vec3(10, 0, -10), Vec3::Zero(), Vec3::Zero(), flow(Vec3(0, -2, 0)),
                         testType(), kRho, 1.0);
  EXPECT_NEAR(load2.force2.y(), -4.0 * 307.5, 1e-9);
}

// Source: hand calculation, OrcaFlex axial-drag convention 1/2 rho Cda (pi D) |u_a| u_a: with u = 2 m/s
// along the element: 0.5 * 1025 * 0.008 * pi * 0.1 * 4 = 1.64 pi N/m, times L/2 = 5 m per node.
// Tolerance 1e-12 N.
TEST(Morison, AxialDragByHand) {
  const MorisonElementLoad load =
      morisonElementLoad(Vec3(0, 0, -10), Vec3(10, 0, -10), Vec3::Zero(), Vec3::Zero(), flow(Vec3(2, 0, 0)),
                         testType(), kRho, 1.0);
  const double perNode = 5.0 * 0.5 * 1025.0 * 0.008 * kPi * 0.1 * 4.0;
  EXPECT_NEAR(load.force1.x(), perNode, 1e-12);
  EXPECT_NEAR(load.force2.x(), perNode, 1e-12);
  EXPECT_NEAR(load.force1.y(), 0.0, 1e-14);
}

// Source: hand decomposition for an oblique flow and a moving structure: relative velocity
// v_r = u - v_i split into the element axis (x) and the normal plane; node i uses its own velocity.
// Tolerance 1e-10 N.
TEST(Morison, ObliqueRelativeVelocityDecomposition) {
  const section::LineType type = testType();
  const Vec3 u(1.0, 2.0, -0.5);
  const Vec3 v1(0.2, 0.5, 0.1), v2(-0.3, 0.0, 0.4);
  const MorisonElementLoad load = morisonElementLoad(Vec3(5, 1, -20), Vec3(5, 1, -12), v1, v2, flow(u), type,
                                                     kRho, 1.0);  // along +z, L = 8
  auto expected = [&](const Vec3& v) {
    const Vec3 vr = u - v;
    const Vec3 vn(vr.x(), vr.y(), 0.0);
    const double va = vr.z();
    const Vec3 qn = 0.5 * kRho * type.dragNormal * type.outerDiameter * vn.norm() * vn;
    const Vec3 qa(0.0, 0.0, 0.5 * kRho * type.dragAxial * kPi * type.outerDiameter * std::abs(va) * va);
    return Vec3(4.0 * (qn + qa));
  };
  EXPECT_LT((load.force1 - expected(v1)).norm(), 1e-10);
  EXPECT_LT((load.force2 - expected(v2)).norm(), 1e-10);
  // Reversing the element does not change the loads (tangent sign is irrelevant).
  const MorisonElementLoad reversed =
      morisonElementLoad(Vec3(5, 1, -12), Vec3(5, 1, -20), v2, v1, flow(u), type, kRho, 1.0);
  EXPECT_LT((reversed.force1 - load.force2).norm(), 1e-10);
  EXPECT_LT((reversed.damping2 - load.damping1).norm(), 1e-10);
}

// Source: the damping returned must be the exact derivative of the returned force:
// G_i = d force_i / d x2 = -d force_i / d x1 (the drag's follower stiffness used in statics), checked by
// central finite differences of the force in the node positions with the fluid velocity and the
// submerged fraction held (no fluid acceleration: the inertia term is not in G). Step 1e-6 m on a 7 m
// element: truncation O(h^2) ~ 1e-12 relative, rounding ~1e-16 * 1e3 N / 1e-6 m ~ 1e-7 N/m; tolerance 1e-6
// of max |G| (~1e2 N/m), plus 1e-5 N/m for the flow along the element, where the normal drag |w_n| w_n
// (w_n = O(h)) has a kink in its second derivative and central differences err by about
// f L/2 kn (|u| / L)^2 h = 2.8 * 61.5 * 0.034 * 1e-6 = 6e-6 N/m. Cases: oblique flow (normal and axial drag), flow along the element (no normal
// part), flow normal to it (no axial part), with node velocities.
TEST(Morison, PositionJacobianEqualsFiniteDifferenceOfForce) {
  const section::LineType type = testType();
  const Vec3 x1(0.3, -1.0, -30.0), x2(6.0, 2.0, -26.0);
  const Vec3 axis = (x2 - x1).normalized();
  const Vec3 normal = axis.cross(Vec3::UnitZ()).normalized();
  const Vec3 v1(0.1, 0.4, -0.2), v2(-0.5, 0.2, 0.6);
  for (const Vec3& u : {Vec3(0.8, -0.6, 0.3), Vec3(1.3 * axis), Vec3(-0.9 * normal)}) {
    for (const bool moving : {false, true}) {
      const Vec3 w1 = moving ? v1 : Vec3::Zero(), w2 = moving ? v2 : Vec3::Zero();
      const MorisonElementLoad load =
          morisonElementLoad(x1, x2, w1, w2, flow(u), type, kRho, 0.8, false, true);
      const double scale = std::max(load.positionJacobian1.norm(), load.positionJacobian2.norm());
      ASSERT_GT(scale, 1.0);
      const double h = 1e-6;
      for (int node = 0; node < 2; ++node) {
        for (int j = 0; j < 3; ++j) {
          Vec3 dx = Vec3::Zero();
          dx[j] = h;
          const MorisonElementLoad plus =
              node == 0 ? morisonElementLoad(x1 + dx, x2, w1, w2, flow(u), type, kRho, 0.8)
                        : morisonElementLoad(x1, x2 + dx, w1, w2, flow(u), type, kRho, 0.8);
          const MorisonElementLoad minus =
              node == 0 ? morisonElementLoad(x1 - dx, x2, w1, w2, flow(u), type, kRho, 0.8)
                        : morisonElementLoad(x1, x2 - dx, w1, w2, flow(u), type, kRho, 0.8);
          const double sign = node == 0 ? -1.0 : 1.0;  // d/dx1 = -G, d/dx2 = +G
          const Vec3 dF1 = (plus.force1 - minus.force1) / (2 * h);
          const Vec3 dF2 = (plus.force2 - minus.force2) / (2 * h);
          const double tolerance = 1e-6 * scale + 1e-5;
          EXPECT_LT((dF1 - sign * load.positionJacobian1.col(j)).norm(), tolerance)
              << "u " << u.transpose() << " node " << node << " column " << j;
          EXPECT_LT((dF2 - sign * load.positionJacobian2.col(j)).norm(), tolerance)
              << "u " << u.transpose() << " node " << node << " column " << j;
        }
      }
    }
  }
}

// C_i = -d force_i / d v_i and d force_i / d v_j = 0 (i != j), checked by central finite differences
// (step 1e-6 m/s on velocities of O(1): truncation O(h^2) ~ 1e-12, rounding ~1e-16 * 1e3 N / 1e-6 ~ 1e-7;
// tolerance 1e-5 relative to max |C| ~ 1e2).
TEST(Morison, DampingEqualsFiniteDifferenceOfForce) {
  const section::LineType type = testType();
  const Vec3 x1(0.3, -1.0, -30.0), x2(6.0, 2.0, -26.0);
  const FluidKinematics fluid = flow(Vec3(0.8, -0.6, 0.3), Vec3(0.1, 0.2, -0.3));
  const Vec3 v1(0.1, 0.4, -0.2), v2(-0.5, 0.2, 0.6);
  const MorisonElementLoad load = morisonElementLoad(x1, x2, v1, v2, fluid, type, kRho, 0.8);
  const double h = 1e-6;
  const double scale = std::max(load.damping1.norm(), load.damping2.norm());
  ASSERT_GT(scale, 1.0);
  for (int node = 0; node < 2; ++node) {
    for (int j = 0; j < 3; ++j) {
      Vec3 dv = Vec3::Zero();
      dv[j] = h;
      const Vec3 vPlus = (node == 0 ? v1 : v2) + dv;
      const Vec3 vMinus = (node == 0 ? v1 : v2) - dv;
      const MorisonElementLoad plus = node == 0
                                          ? morisonElementLoad(x1, x2, vPlus, v2, fluid, type, kRho, 0.8)
                                          : morisonElementLoad(x1, x2, v1, vPlus, fluid, type, kRho, 0.8);
      const MorisonElementLoad minus = node == 0
                                           ? morisonElementLoad(x1, x2, vMinus, v2, fluid, type, kRho, 0.8)
                                           : morisonElementLoad(x1, x2, v1, vMinus, fluid, type, kRho, 0.8);
      const Vec3 dF1 = (plus.force1 - minus.force1) / (2 * h);
      const Vec3 dF2 = (plus.force2 - minus.force2) / (2 * h);
      if (node == 0) {
        EXPECT_LT((dF1 + load.damping1.col(j)).norm(), 1e-5 * scale) << "column " << j;
        EXPECT_LT(dF2.norm(), 1e-12 * scale);
      } else {
        EXPECT_LT((dF2 + load.damping2.col(j)).norm(), 1e-5 * scale) << "column " << j;
        EXPECT_LT(dF1.norm(), 1e-12 * scale);
      }
    }
  }
  // Symmetric positive semi-definite (drag only dissipates).
  for (const Mat3& c : {load.damping1, load.damping2}) {
    EXPECT_LT((c - c.transpose()).norm(), 1e-12 * scale);
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(c);
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * scale);
  }
}

// Source: |x| x is continuously differentiable with zero derivative at 0: with no normal relative
// velocity only the axial damping 2 * 1/2 rho Cda pi D |v_ra| L/2 t t^T remains. Tolerance 1e-12.
TEST(Morison, DampingWithoutNormalRelativeVelocity) {
  const section::LineType type = testType();
  const MorisonElementLoad load = morisonElementLoad(Vec3(0, 0, -10), Vec3(0, 0, -6), Vec3::Zero(),
                                                     Vec3::Zero(), flow(Vec3(0, 0, 1.5)), type, kRho, 1.0);
  Mat3 expected = Mat3::Zero();
  expected(2, 2) = 2.0 * 0.5 * kRho * type.dragAxial * kPi * type.outerDiameter * 1.5 * 2.0;
  EXPECT_LT((load.damping1 - expected).norm(), 1e-12);
  // No relative velocity at all: no force, no damping.
  const MorisonElementLoad still =
      morisonElementLoad(Vec3(0, 0, -10), Vec3(0, 0, -6), Vec3(0.3, 0, 0), Vec3(0.3, 0, 0),
                         flow(Vec3(0.3, 0, 0)), type, kRho, 1.0);
  EXPECT_EQ(still.force1, Vec3::Zero());
  EXPECT_EQ(still.damping1, Mat3::Zero());
}

// Source: DNV-RP-C205 (2010) sec. 6.2: added mass per unit length rho A Ca in the normal plane, rho A Caa
// along the axis; half of the element on each node. Tolerance 1e-10 kg.
TEST(Morison, AddedMassMatrix) {
  section::LineType type = testType();
  type.addedMassNormal = 1.0;
  type.addedMassAxial = 0.2;
  const double area = kPi * 0.01 / 4.0;
  const Vec3 x1(1, 2, -40), x2(4, 6, -40);  // along (0.6, 0.8, 0), L = 5
  const Vec3 t(0.6, 0.8, 0.0), n1(-0.8, 0.6, 0.0), n2(0, 0, 1);
  const MorisonElementLoad load =
      morisonElementLoad(x1, x2, Vec3::Zero(), Vec3::Zero(), flow(Vec3::Zero()), type, kRho, 1.0);
  const double m = kRho * area * 2.5;
  EXPECT_LT((load.addedMassPerNode * t - 0.2 * m * t).norm(), 1e-10);
  EXPECT_LT((load.addedMassPerNode * n1 - 1.0 * m * n1).norm(), 1e-10);
  EXPECT_LT((load.addedMassPerNode * n2 - 1.0 * m * n2).norm(), 1e-10);
  const Mat3 matrix = load.addedMassPerNode.matrix();
  EXPECT_LT((matrix - matrix.transpose()).norm(), 1e-12);
  const Vec3 a(0.3, -1.2, 2.0);
  EXPECT_LT((matrix * a - load.addedMassPerNode * a).norm(), 1e-12 * m);
}

// Source: Morison inertia term: rho A (1 + Can) a_n normally (Froude-Krylov + added mass), rho A_b (1 + Caa)
// a_a axially, with A_b from buoyancyDiameter. Tolerance 1e-10 N.
TEST(Morison, FluidInertiaForce) {
  section::LineType type = testType();
  type.addedMassNormal = 1.0;
  type.addedMassAxial = 0.0;
  type.buoyancyDiameter = 0.08;  // displaced area differs from the hydrodynamic one
  const double area = kPi * 0.1 * 0.1 / 4.0;
  const double displaced = kPi * 0.08 * 0.08 / 4.0;
  const Vec3 a(0.5, -0.4, 0.3);  // element along x: axial 0.5, normal (0, -0.4, 0.3)
  const MorisonElementLoad load = morisonElementLoad(Vec3(0, 0, -10), Vec3(2, 0, -10), Vec3::Zero(),
                                                     Vec3::Zero(), flow(Vec3::Zero(), a), type, kRho, 1.0);
  const Vec3 expected(kRho * displaced * 0.5, kRho * (displaced + area) * -0.4,
                      kRho * (displaced + area) * 0.3);
  EXPECT_LT((load.force1 - expected).norm(), 1e-10);  // L/2 = 1 m per node
  EXPECT_LT((load.force2 - expected).norm(), 1e-10);
  // buoyancyDiameter 0: falls back to the outer diameter.
  type.buoyancyDiameter = 0.0;
  const MorisonElementLoad fallback = morisonElementLoad(
      Vec3(0, 0, -10), Vec3(2, 0, -10), Vec3::Zero(), Vec3::Zero(), flow(Vec3::Zero(), a), type, kRho, 1.0);
  EXPECT_NEAR(fallback.force1.y(), kRho * 2.0 * area * -0.4, 1e-10);
}

// Source: every load is proportional to the wetted length; a fully emerged element gets nothing.
TEST(Morison, SubmergedFractionScalesLoadsAndEmergedElementHasNone) {
  const section::LineType type = testType();
  const FluidKinematics fluid = flow(Vec3(1, 0.5, 0), Vec3(0.2, 0, 0.1));
  const Vec3 x1(0, 0, -1), x2(3, 0, 1), v(0.1, -0.2, 0.3);
  const MorisonElementLoad full = morisonElementLoad(x1, x2, v, v, fluid, type, kRho, 1.0);
  const MorisonElementLoad part = morisonElementLoad(x1, x2, v, v, fluid, type, kRho, 0.25);
  EXPECT_LT((part.force1 - 0.25 * full.force1).norm(), 1e-12 * full.force1.norm());
  EXPECT_LT((part.damping2 - 0.25 * full.damping2).norm(), 1e-12 * full.damping2.norm());
  EXPECT_LT((part.addedMassPerNode.matrix() - 0.25 * full.addedMassPerNode.matrix()).norm(),
            1e-12 * full.addedMassPerNode.matrix().norm());
  const MorisonElementLoad dry = morisonElementLoad(Vec3(0, 0, 1), Vec3(3, 0, 2), v, v, fluid, type, kRho,
                                                    submergedFraction(1.0, 2.0, 0.0));
  EXPECT_EQ(dry.force1, Vec3::Zero());
  EXPECT_EQ(dry.force2, Vec3::Zero());
  EXPECT_EQ(dry.damping1, Mat3::Zero());
  EXPECT_EQ(dry.addedMassPerNode.matrix(), Mat3::Zero());
}

// Source: linear wetted fraction of a straight segment under a flat surface.
TEST(Morison, SubmergedFraction) {
  EXPECT_EQ(submergedFraction(-5.0, -1.0, 0.0), 1.0);
  EXPECT_EQ(submergedFraction(1.0, 5.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(submergedFraction(-1.0, 3.0, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(submergedFraction(3.0, -1.0, 0.0), 0.25);  // order of the ends is irrelevant
  EXPECT_DOUBLE_EQ(submergedFraction(-1.0, 3.0, 1.0), 0.5);   // wave crest at z = 1
  EXPECT_EQ(submergedFraction(-2.0, -2.0, -1.0), 1.0);        // horizontal, below a trough
  EXPECT_EQ(submergedFraction(-2.0, -2.0, -3.0), 0.0);        // horizontal, above the surface
}

// Source: the reference formulas of morisonElementLoad. morisonNodeForces (the assembly's force-only call)
// arranges them for a shorter dependency chain: forces and added mass equal to round-off (1e-13 of the
// largest force), over random elements (lengths 0.1-20 m, any orientation), relative velocities (normal,
// axial and mixed, including a zero one), fluid accelerations and wetted fractions. Coincident nodes throw.
TEST(Morison, NodeForcesEqualElementLoad) {
  const MorisonCoefficients c = morisonCoefficients(testType(), kRho);
  std::srand(7);
  const auto random = [] { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 x1(random() * 50.0, random() * 50.0, -100.0 + random() * 50.0);
    const Vec3 axis = Vec3(random(), random(), random()).normalized() * (0.1 + 10.0 * (1.0 + random()));
    const Vec3 x2 = x1 + axis;
    const Vec3 u(random(), random(), 0.2 * random());
    Vec3 v1(random(), random(), random()), v2(random(), random(), random());
    if (trial % 5 == 1) v1 = u;                            // no relative velocity at node 1
    if (trial % 5 == 2) v2 = u + 0.7 * axis.normalized();  // purely axial at node 2
    const FluidKinematics f = flow(u, trial % 2 ? Vec3(random(), random(), random()) : Vec3::Zero());
    const double wet = trial % 3 ? 1.0 : 0.5 * (1.0 + random());
    const MorisonElementLoad reference = morisonElementLoad(x1, x2, v1, v2, f, c, wet, false, false);
    const MorisonNodeForces forces = morisonNodeForces(x1, x2, v1, v2, f, c, wet);
    const double scale = std::max({reference.force1.norm(), reference.force2.norm(), 1e-3});
    EXPECT_LT((forces.force1 - reference.force1).norm(), 1e-13 * scale) << "trial " << trial;
    EXPECT_LT((forces.force2 - reference.force2).norm(), 1e-13 * scale) << "trial " << trial;
    EXPECT_LT((forces.addedMassPerNode.tangent - reference.addedMassPerNode.tangent).norm(), 1e-15);
    EXPECT_NEAR(forces.addedMassPerNode.normal, reference.addedMassPerNode.normal,
                1e-14 * reference.addedMassPerNode.normal);
    EXPECT_NEAR(forces.addedMassPerNode.axial, reference.addedMassPerNode.axial, 1e-14 * c.axialMass * 20.0);
  }
  EXPECT_THROW(morisonNodeForces(Vec3(1, 2, -3), Vec3(1, 2, -3), Vec3::Zero(), Vec3::Zero(),
                                 flow(Vec3::Zero()), c, 1.0),
               Error);
}

TEST(Morison, RejectsInvalidArguments) {
  const section::LineType type = testType();
  const FluidKinematics fluid = flow(Vec3(1, 0, 0));
  const Vec3 x(0, 0, -1), v = Vec3::Zero();
  EXPECT_THROW(morisonElementLoad(x, x, v, v, fluid, type, kRho, 1.0), Error);  // zero length
  EXPECT_THROW(morisonElementLoad(x, Vec3(1, 0, -1), v, v, fluid, type, kRho, 1.5), Error);
  EXPECT_THROW(morisonElementLoad(x, Vec3(1, 0, -1), v, v, fluid, type, kRho, -0.1), Error);
  EXPECT_THROW(morisonElementLoad(x, Vec3(1, 0, -1), v, v, fluid, type, -1.0, 1.0), Error);
  section::LineType bad = type;
  bad.outerDiameter = -0.1;
  EXPECT_THROW(morisonElementLoad(x, Vec3(1, 0, -1), v, v, fluid, bad, kRho, 1.0), Error);
}

}  // namespace
}  // namespace tangle::hydro

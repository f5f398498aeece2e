/// @file BarTest.cpp
/// Element-level tests of the two-node bar (tangle::element::Bar).

#include <gtest/gtest.h>

#include <random>

#include "tangle/core/Error.hpp"
#include "tangle/element/Bar.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle::element {
namespace {

constexpr double kEa = 4.0e8;  // EA [N], a typical 100 mm studless chain
constexpr double kL0 = 12.5;   // L0 [m]

TEST(BarTest, ConstructorRejectsNonPositiveInputs) {
  EXPECT_THROW(Bar(0.0, kL0), Error);
  EXPECT_THROW(Bar(-1.0, kL0), Error);
  EXPECT_THROW(Bar(kEa, 0.0), Error);
  EXPECT_THROW(Bar(kEa, -2.0), Error);
  EXPECT_NO_THROW(Bar(kEa, kL0));
}

// Source: Hooke's law on engineering strain, N = EA (l - L0) / L0; the nodal forces are -N e and
// +N e (Crisfield 1991, vol. 1, eq. 3.2). Exact closed form: tolerance is round-off (1e-12 relative).
TEST(BarTest, TensionAlongAxisGivesHookeForce) {
  const Bar bar(kEa, kL0);
  const Vec3 x1(1.0, 2.0, -3.0);
  const Vec3 e = Vec3(1.0, -2.0, 0.5).normalized();
  const double strain = 0.01;
  const Vec3 x2 = x1 + kL0 * (1.0 + strain) * e;
  const double n = kEa * strain;
  EXPECT_NEAR(bar.axialForce(x1, x2), n, 1e-12 * n);

  Vec6 f;
  Mat6 k;
  bar.compute(x1, x2, f, k);
  EXPECT_LE((f.head<3>() + n * e).norm(), 1e-12 * n);
  EXPECT_LE((f.tail<3>() - n * e).norm(), 1e-12 * n);
  // Axial stiffness along the bar: e^T K11 e = EA / L0 (geometric part is orthogonal to e).
  EXPECT_NEAR(e.dot(k.topLeftCorner<3, 3>() * e), kEa / kL0, 1e-12 * kEa / kL0);
  // Transverse stiffness is the geometric (string) stiffness N / l.
  const Vec3 t = e.unitOrthogonal();
  EXPECT_NEAR(t.dot(k.topLeftCorner<3, 3>() * t), n / (kL0 * (1.0 + strain)), 1e-9 * kEa / kL0);
}

// The axial law is linear in compression too (no slack cut-off in the element): the force is
// -EA |strain| with the same formula. Exact: round-off tolerance.
TEST(BarTest, CompressionIsLinear) {
  const Bar bar(kEa, kL0);
  const Vec3 x1 = Vec3::Zero();
  const Vec3 x2(0.0, 0.0, 0.98 * kL0);
  EXPECT_NEAR(bar.axialForce(x1, x2), -0.02 * kEa, 1e-12 * kEa);
}

// Consistency of the tangent: central differences of compute() at seeded random states in tension and
// compression. Truncation error of the central difference is h^2/6 |f'''| ~ h^2 EA / L0^3 and round-off
// is eps |f| / h; with h = 1e-4 L0 both are < 1e-8 of EA / L0, so 1e-7 * EA / L0 is a safe bound.
TEST(BarTest, TangentMatchesFiniteDifferencesOfForce) {
  const Bar bar(kEa, kL0);
  std::mt19937 rng(20240611u);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const double h = 1e-4 * kL0;
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 x1(10.0 * uni(rng), 10.0 * uni(rng), 10.0 * uni(rng));
    const Vec3 e = Vec3(uni(rng), uni(rng), uni(rng)).normalized();
    const Vec3 x2 = x1 + kL0 * (1.0 + 0.3 * uni(rng)) * e;
    Vec6 f;
    Mat6 k;
    bar.compute(x1, x2, f, k);
    EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * kEa / kL0);
    Mat6 kFd;
    for (int j = 0; j < 6; ++j) {
      Vec3 p1 = x1, p2 = x2, m1 = x1, m2 = x2;
      (j < 3 ? p1 : p2)[j % 3] += h;
      (j < 3 ? m1 : m2)[j % 3] -= h;
      Vec6 fp, fm;
      Mat6 unused;
      bar.compute(p1, p2, fp, unused);
      bar.compute(m1, m2, fm, unused);
      kFd.col(j) = (fp - fm) / (2.0 * h);
    }
    EXPECT_LE((k - kFd).cwiseAbs().maxCoeff(), 1e-7 * kEa / kL0) << "trial " << trial;
  }
}

// Objectivity: a large rigid rotation and translation of an unstretched bar leaves it force-free
// (exact kinematics; tolerance = round-off of coordinates ~1e3 m: 1e-9 relative to EA).
TEST(BarTest, RigidMotionGivesZeroForce) {
  const Bar bar(kEa, kL0);
  const Mat3 r = geometry::expMap(Vec3(1.1, -2.0, 0.7));
  const Vec3 shift(850.0, -1200.0, -300.0);
  const Vec3 x1 = shift;
  const Vec3 x2 = shift + r * Vec3(kL0, 0.0, 0.0);
  Vec6 f;
  Mat6 k;
  bar.compute(x1, x2, f, k);
  EXPECT_LE(f.norm(), 1e-9 * kEa);
  EXPECT_LE(std::abs(bar.axialForce(x1, x2)), 1e-9 * kEa);
  // Infinitesimal rigid rotation about node 1 is a zero-energy mode of the stress-free tangent.
  const Vec3 w(0.3, -0.2, 0.9);
  Vec6 mode;
  mode << Vec3::Zero(), w.cross(x2 - x1);
  EXPECT_LE((k * mode).norm(), 1e-9 * kEa / kL0 * mode.norm());
}

TEST(BarTest, CoincidentNodesThrow) {
  const Bar bar(kEa, kL0);
  Vec6 f;
  Mat6 k;
  EXPECT_THROW(bar.compute(Vec3::Ones(), Vec3::Ones(), f, k), Error);
}

}  // namespace
}  // namespace tangle::element

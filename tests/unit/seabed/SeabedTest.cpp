// Unit tests of the flat seabed's node reaction (Seabed): the force-only call against the full reaction,
// and the reaction against its closed form (the C1 onset and the linear law, the dashpot that never pulls,
// regularised Coulomb friction). References: the formulas of Seabed.hpp / theory manual; exact
// equality where the same arithmetic is promised, round-off (1e-12 relative) against hand-written forms.

#include <gtest/gtest.h>

#include <random>

#include "tangle/seabed/Seabed.hpp"

namespace tangle {
namespace {

seabed::SeabedSpec spec(double damping, double friction) {
  seabed::SeabedSpec s;
  s.normalStiffness = 2.0e5;
  s.damping = damping;
  s.frictionCoefficient = friction;
  s.frictionVelocity = 0.02;
  s.elasticFriction = false;  // the velocity-regularised dynamic law these tests check (friction_model: viscous)
  return s;
}

TEST(Seabed, ReactionForceIsTheReactionsForceBitForBit) {
  // Random nodes about the seabed (clear, in the smooth onset, fully in contact), moving up and down and
  // sliding slower and faster than the friction regularisation velocity; statics and dynamics.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> penetration(-0.004, 0.006), speed(-0.06, 0.06);
  const double depth = 100.0, radius = 0.05, tributary = 4.0;
  for (const double damping : {0.0, 3.0e3}) {
    for (const double friction : {0.0, 0.6}) {
      const seabed::Seabed bed(spec(damping, friction), depth);
      for (int k = 0; k < 400; ++k) {
        const Vec3 x(1.0, -2.0, -depth + radius - penetration(rng));
        const Vec3 v(speed(rng), speed(rng), speed(rng));
        for (const bool dynamic : {false, true}) {
          const Vec3 full = bed.reaction(x, v, tributary, radius, dynamic).force;
          const Vec3 alone = bed.reactionForce(x, v, tributary, radius, dynamic);
          EXPECT_EQ(alone.x(), full.x());
          EXPECT_EQ(alone.y(), full.y());
          EXPECT_EQ(alone.z(), full.z());
        }
      }
    }
  }
}

TEST(Seabed, NormalForceFollowsTheSmoothOnsetThenTheLinearLaw) {
  // N = k L d^2 / (2 d0) for d < d0, k L (d - d0 / 2) beyond (d0 = kSmoothPenetration): continuous with a
  // continuous slope at d0.
  const double depth = 50.0, radius = 0.1, tributary = 2.5, k = 2.0e5 * tributary;
  const double d0 = seabed::Seabed::kSmoothPenetration;
  const seabed::Seabed bed(spec(0.0, 0.0), depth);
  for (const double target : {-0.001, 0.0, 0.25 * d0, d0, 3.0 * d0}) {
    const Vec3 x(0.0, 0.0, -depth + radius - target);
    const double d = bed.penetration(x, radius);  // the target up to the round-off of z near -depth
    const double expected = d <= 0.0 ? 0.0 : d < d0 ? 0.5 * k * d * d / d0 : k * (d - 0.5 * d0);
    EXPECT_NEAR(bed.reactionForce(x, Vec3::Zero(), tributary, radius, true).z(), expected, 1e-12 * k * d0)
        << "penetration " << d;
  }
}

TEST(Seabed, DashpotNeverPullsAndFrictionOpposesSliding) {
  const double depth = 50.0, radius = 0.1, tributary = 2.0;
  const seabed::Seabed bed(spec(1.0e4, 0.5), depth);
  const Vec3 x(0.0, 0.0, -depth + radius - 0.004);  // beyond the smooth onset: N0 = k L (d - d0/2)
  const double n0 = 2.0e5 * tributary * (0.004 - 0.001);
  // Lifting off fast: the dashpot would pull; the reaction is zero, and so is the friction.
  const Vec3 lifting = bed.reactionForce(x, Vec3(0.3, 0.0, 1.0), tributary, radius, true);
  EXPECT_EQ(lifting.norm(), 0.0);
  // Sliding along +x faster than the regularisation velocity: -mu N along x; slower: proportional to speed.
  const Vec3 fast = bed.reactionForce(x, Vec3(0.5, 0.0, 0.0), tributary, radius, true);
  EXPECT_NEAR(fast.z(), n0, 1e-12 * n0);
  EXPECT_NEAR(fast.x(), -0.5 * n0, 1e-12 * n0);
  const Vec3 slow = bed.reactionForce(x, Vec3(0.01, 0.0, 0.0), tributary, radius, true);
  EXPECT_NEAR(slow.x(), -0.5 * n0 * 0.01 / 0.02, 1e-12 * n0);
  // Statics: no dashpot, no dynamic friction.
  const Vec3 statics = bed.reactionForce(x, Vec3(0.5, 0.0, -1.0), tributary, radius, false);
  EXPECT_EQ(statics.x(), 0.0);
  EXPECT_NEAR(statics.z(), n0, 1e-12 * n0);
}

}  // namespace
}  // namespace tangle

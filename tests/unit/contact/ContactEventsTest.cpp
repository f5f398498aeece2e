// The impact phase of a contact event and its two energy estimates (issue 29, docs/theory.md 9.10), on
// contact histories written down in closed form and fed to the tracker as committed states.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "tangle/contact/ContactEvents.hpp"

namespace tangle::contact {
namespace {

constexpr double kPi = 3.141592653589793;

/// One point contact between lines 0 and 1 along z with force f [N] and relative normal velocity u [m/s]
/// (< 0 approaching), split equally between the two points.
ContactSpot spot(double f, double u, double approach, double lower, double upper) {
  ContactSpot s;
  s.lineA = 0;
  s.lineB = 1;
  s.normal = Vec3::UnitZ();
  s.force = f;
  s.approachSpeed = approach;
  s.velocityA = s.velocityBeforeA = Vec3(0, 0, 0.5 * u);
  s.velocityB = s.velocityBeforeB = Vec3(0, 0, -0.5 * u);
  s.radii = 0.1;
  s.minRadius = 0.05;
  s.elementLength = 1.0;
  s.pairMass = 1.0;
  s.stiffness = 1e4;
  s.elementPairMass = lower;
  s.linePairMass = upper;
  return s;
}

/// Feeds the committed spots spotsAt(t) on [0, duration] in steps dt, then closes the event as separated.
ContactEvent runSpots(const std::function<std::vector<ContactSpot>(double)>& spotsAt, double duration,
                      double dt) {
  ContactEventTracker tracker(0.05, 0.2);
  const auto farApart = [](int, int, double, double, double, double) { return 1.0; };
  const int steps = static_cast<int>(std::round(duration / dt));
  for (int i = 1; i <= steps; ++i) tracker.update(i * dt, dt, true, spotsAt(i * dt), farApart);
  tracker.update((steps + 1) * dt, dt, true, {}, farApart);  // no contact: the surfaces have parted
  tracker.finish((steps + 1) * dt);
  EXPECT_EQ(tracker.events().size(), 1u);
  return tracker.events().front();
}

/// Feeds the history f(t), u(t) on [0, duration] in steps dt, then closes the event as separated.
ContactEvent run(const std::function<double(double)>& force, const std::function<double(double)>& velocity,
                 double v0, double duration, double dt, double lower = 0.1, double upper = 100.0) {
  return runSpots(
      [&](double t) { return std::vector<ContactSpot>{spot(force(t), velocity(t), v0, lower, upper)}; },
      duration, dt);
}

// Two rigid bodies of reduced mass m on a contact spring k: x = (v0 / w) sin(w t), F = k x, u = -v0 cos(w t)
// until the approach stops at t = pi / (2 w); then a sustained load F_s with no motion for 0.2 s. Eq. 5 over
// the phase: integral F dt / v0 = k v0 / w^2 / v0 = m; the work: integral F (-u) dt = 1/2 m v0^2. Over the
// whole event the paper's Eq. 5 takes in the sustained impulse F_s x 0.2 s as well. Tolerances: the
// trapezoidal sums over 1000 steps of the compression (relative error ~ (pi / 2000)^2 / 12), and the
// phase ending one step past maximum compression (1e-3 of the phase).
TEST(ContactEvents, ImpactPhaseGivesTheRigidBodyMassAndEnergyNotTheSustainedLoad) {
  const double m = 2.0, k = 8e4, v0 = 1.5, w = std::sqrt(k / m), tc = 0.5 * kPi / w, sustained = 300.0;
  const double dt = tc / 1000.0;
  const ContactEvent e =
      run([&](double t) { return t <= tc ? k * v0 / w * std::sin(w * t) : sustained; },
          [&](double t) { return t <= tc ? -v0 * std::cos(w * t) : 0.0; }, v0, tc + 0.2, dt);
  EXPECT_TRUE(e.impact);
  EXPECT_EQ(e.phaseEnd, "reversed");
  EXPECT_NEAR(e.phaseEndTime, tc, 2.0 * dt);
  EXPECT_EQ(e.energyMassBasis, "eq5");
  EXPECT_NEAR(e.eq5Mass, m, 3e-3 * m);
  EXPECT_NEAR(e.workMass, m, 3e-3 * m);
  EXPECT_NEAR(e.impactEnergy, 0.5 * m * v0 * v0, 3e-3 * 0.5 * m * v0 * v0);
  EXPECT_NEAR(e.phaseWork, 0.5 * m * v0 * v0, 3e-3 * 0.5 * m * v0 * v0);
  EXPECT_TRUE(e.energyWarning.empty()) << e.energyWarning;
  // The paper's Eq. 5 over the whole event: (m v0 + F_s 0.2 s) / v0, 21 times more.
  EXPECT_NEAR(e.eventEq5Mass, (m * v0 + sustained * 0.2) / v0, 0.01 * (m * v0 + sustained * 0.2) / v0);
}

// A force that peaks as the approach stops (F = F0 (t / T)^3 while u = -v0 (1 - t / T)): Eq. 5 gives
// F0 T / (4 v0), the work F0 v0 T / 20, i.e. a mass of F0 T / (10 v0): 2.5 times apart, beyond the factor
// 2 the report accepts. The warning must say so (the check of the check).
TEST(ContactEvents, DisagreeingEstimatesAreFlagged) {
  const double f0 = 1000.0, T = 0.01, v0 = 1.0;
  const ContactEvent e = run([&](double t) { return f0 * std::pow(t / T, 3); },
                             [&](double t) { return -v0 * (1.0 - t / T); }, v0, T, T / 2000.0);
  EXPECT_NEAR(e.eq5Mass, f0 * T / (4.0 * v0), 0.01 * f0 * T / (4.0 * v0));
  EXPECT_NEAR(e.workMass, f0 * T / (10.0 * v0), 0.01 * f0 * T / (10.0 * v0));
  EXPECT_NE(e.energyWarning.find("differ by more than a factor 2"), std::string::npos) << e.energyWarning;
}

// The mass bounds: the same rigid impact with an upper bound below the measured mass, and with a lower
// bound above it, is flagged.
TEST(ContactEvents, MassOutsideTheBoundsIsFlagged) {
  const double m = 2.0, k = 8e4, v0 = 1.5, w = std::sqrt(k / m), tc = 0.5 * kPi / w;
  const auto f = [&](double t) { return t <= tc ? k * v0 / w * std::sin(w * t) : 0.0; };
  const auto u = [&](double t) { return t <= tc ? -v0 * std::cos(w * t) : v0; };
  const ContactEvent heavy = run(f, u, v0, tc, tc / 1000.0, 0.1, 1.0);
  EXPECT_NE(heavy.energyWarning.find("exceeds"), std::string::npos) << heavy.energyWarning;
  const ContactEvent light = run(f, u, v0, tc, tc / 1000.0, 5.0, 100.0);
  EXPECT_NE(light.energyWarning.find("below"), std::string::npos) << light.energyWarning;
  const ContactEvent within = run(f, u, v0, tc, tc / 1000.0, 1.0, 3.0);
  EXPECT_TRUE(within.energyWarning.empty()) << within.energyWarning;
}

// An impulse-model jump from -v0 to e v0 at the first contact: the part of the impulse that stops the
// approach, I / (1 + e), does the work 1/2 I v0 / (1 + e) = 1/2 m v0^2 for I = (1 + e) m v0.
TEST(ContactEvents, ImpulseModelJumpGivesTheCompressionWork) {
  const double m = 3.0, v0 = 2.0, e = 0.5, impulse = (1.0 + e) * m * v0;
  ContactEventTracker tracker(0.05, 0.2);
  const auto farApart = [](int, int, double, double, double, double) { return 1.0; };
  ContactSpot s = spot(1.0, e * v0, v0, 0.1, 100.0);
  s.velocityBeforeA = Vec3(0, 0, -0.5 * v0);
  s.velocityBeforeB = Vec3(0, 0, 0.5 * v0);
  s.jumpImpulse = impulse;
  tracker.update(1e-3, 1e-3, true, {s}, farApart);
  tracker.update(2e-3, 1e-3, true, {}, farApart);
  tracker.finish(2e-3);
  ASSERT_EQ(tracker.events().size(), 1u);
  const ContactEvent& ev = tracker.events().front();
  EXPECT_EQ(ev.phaseEnd, "reversed");
  EXPECT_NEAR(ev.eq5Mass, m, 1e-3 * m);  // (I + the spring's 0.5 F dt) / ((1 + e) v0)
  EXPECT_NEAR(ev.phaseWork, 0.5 * m * v0 * v0, 1e-3 * 0.5 * m * v0 * v0);
}

// Friction where a patch's normals spread (docs/theory.md 9.10): two Gauss spots of one patch with normals
// tilted +-theta about z in the xz-plane, each with its friction tangent to its own normal and resisting
// the approach; lines A and B close along z as two rigid bodies of reduced mass m on a spring k (as the
// first test), the spring's force k x along z carried as a share (1 - beta) by the normal forces and beta by
// the friction's z components. Per spot the relative normal velocity is c w (c = cos theta, w the relative
// velocity along z), so the tracker sees the approach c v0, and (closed forms, from integral k x dt = m v0
// and integral k x (-w) dt = 1/2 m v0^2):
//   Eq. 5: integral (sum F_i + f . z) dt / (c v0) = m ((1 - beta) / c^2 + beta / c),
//   work mass: 2 integral sum F_i (-c w) dt / (c v0)^2 = m (1 - beta) / c^2 (the normal law's work only).
// Without friction's part the Eq. 5 mass would be m (1 - beta) / c^2: 30 % low here. Tolerances as the
// first test's.
TEST(ContactEvents, FrictionAlongTheMeanNormalIsPartOfTheImpulseNotOfTheWork) {
  const double m = 2.0, k = 8e4, v0 = 1.5, w = std::sqrt(k / m), tc = 0.5 * kPi / w, dt = tc / 1000.0;
  const double theta = 10.0 * kPi / 180.0, c = std::cos(theta), sn = std::sin(theta), beta = 0.3;
  const ContactEvent e = runSpots(
      [&](double t) {
        const double spring = k * v0 / w * std::sin(w * t);  // k x along z [N]
        const double closing = -v0 * std::cos(w * t);        // w [m/s]
        std::vector<ContactSpot> spots;
        for (const double side : {1.0, -1.0}) {
          ContactSpot s = spot(0.5 * (1.0 - beta) * spring / c, closing, c * v0, 0.1, 100.0);
          s.normal = Vec3(side * sn, 0.0, c);
          s.length = 0.1;  // a Gauss spot
          s.velocityWeight = s.force;
          const double friction = 0.5 * beta * spring / sn;  // |f| whose z component is beta k x / 2
          s.friction =
              friction * Vec3(-side * c, 0.0, sn);  // tangent to the spot's normal, resisting A's fall
          spots.push_back(s);
        }
        return spots;
      },
      tc, dt);
  EXPECT_NEAR(e.impactVelocity, c * v0, 1e-12);
  const double eq5 = m * ((1.0 - beta) / (c * c) + beta / c), work = m * (1.0 - beta) / (c * c);
  EXPECT_NEAR(e.eq5Mass, eq5, 3e-3 * eq5);
  EXPECT_NEAR(e.workMass, work, 3e-3 * work);
}

// One contact along a length whose middle lifts off: two lines touching along [0, 100] m (Gauss spots every
// metre on 1 m elements; the reach, two elements plus the radii, is 2.1 m), then only along [0, 10] and
// [90, 100] m, then apart. The rule (docs/theory.md 9.9): a patch continues the open
// event whose extent at the last committed state, grown by the reach, it overlaps. Both patches of the
// second state overlap the first state's [0, 100] m: one event throughout, one impact. (Until 2026-12-06
// the second patch was matched against the extent the first had just written, [0, 10] m, and opened an
// event of its own: two events, and a second impact had its ends been approaching. Had the middle touched
// again, the patch over the whole length would have joined the two.)
TEST(ContactEvents, AContactWhoseMiddleLiftsOffStaysOneEvent) {
  const auto along = [](double from, double to, double approach) {
    std::vector<ContactSpot> spots;
    for (double arc = from; arc <= to + 1e-9; arc += 1.0) {
      ContactSpot s = spot(100.0, approach > 0.0 ? -approach : 0.0, approach, 0.1, 100.0);
      s.arcA = s.arcB = arc;
      s.length = 1.0;
      s.velocityWeight = s.force;
      spots.push_back(s);
    }
    return spots;
  };
  ContactEventTracker tracker(0.05, 0.2);
  const auto touching = [](int, int, double, double, double, double) { return 0.0; };
  const auto farApart = [](int, int, double, double, double, double) { return 1.0; };
  const double dt = 0.01;
  tracker.update(1 * dt, dt, true, along(0.0, 100.0, 1.0), touching);  // first touch at 1 m/s
  std::vector<ContactSpot> ends = along(0.0, 10.0, 0.0), far = along(90.0, 100.0, 0.0);
  ends.insert(ends.end(), far.begin(), far.end());
  tracker.update(2 * dt, dt, true, ends, touching);
  tracker.update(3 * dt, dt, true, {}, farApart);
  tracker.finish(3 * dt);
  ASSERT_EQ(tracker.events().size(), 1u);
  const ContactEvent& e = tracker.events().front();
  EXPECT_TRUE(e.impact);
  EXPECT_NEAR(e.arcAMin, 0.0, 1e-12);
  EXPECT_NEAR(e.arcAMax, 100.0, 1e-12);
}

}  // namespace
}  // namespace tangle::contact

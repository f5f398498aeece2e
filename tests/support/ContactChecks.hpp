#pragma once
/// @file ContactChecks.hpp
/// Checks every contact test with impacts makes on its clash events (issue 29), and what presses between
/// two lines read the same way under either contact formulation (issue 43).

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "tangle/contact/ContactEvents.hpp"
#include "tangle/contact/DistributedContact.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::test {

/// Every impact's energy mass lies between the reduced mass of one element of each line at the impact
/// point and the reduced mass of the two whole lines with their added mass (none when a line is held;
/// docs/theory.md 9.10) (issue 29: the clash report's
/// impact energy must be an energy an engineer can sign; outside these bounds it is an artefact of the
/// measurement, as the 0.014 kg and 4.1e6 kg "effective masses" the issue found), and no impact carries
/// an energy warning (ContactEvents.hpp: Eq. 5 and the absorbed work agree within a factor 2).
inline void expectImpactEnergiesWithinBounds(const std::vector<contact::ContactEvent>& events) {
  for (const contact::ContactEvent& e : events) {
    if (!e.impact) continue;
    // What the mesh engaged lies between one element of each line and the whole lines; the impact's mass
    // (the mesh's, or the mesh-free continuum estimate where it holds, which may be less than one
    // element's on a coarse mesh: docs/theory.md 9.10) within the whole lines'.
    EXPECT_GE(e.meshMass, e.massLowerBound * (1.0 - 1e-9)) << "impact at t = " << e.startTime << " s";
    EXPECT_LE(e.meshMass, e.massUpperBound * (1.0 + 1e-9)) << "impact at t = " << e.startTime << " s";
    EXPECT_LE(e.energyMass, e.massUpperBound * (1.0 + 1e-9)) << "impact at t = " << e.startTime << " s";
    if (e.energyMassBasis != "continuum") {
      EXPECT_EQ(e.energyMass, e.meshMass);
    }
    EXPECT_TRUE(e.energyWarning.empty()) << "impact at t = " << e.startTime << " s: " << e.energyWarning;
  }
}

/// What presses between two lines at the last assembly of a LineContact, under either formulation: the
/// point formulation's contact points and line-to-line Gauss points (docs/theory.md 9.0-9.8), or the
/// distributed formulation's Gauss points (9.11).
struct PressedContact {
  int points = 0;            ///< points carrying a positive normal force [-]
  double normalForce = 0.0;  ///< sum of their normal forces [N]
  /// Normal-force-weighted mean of the points on `line` [m] (NaN when nothing presses; the point
  /// formulation's line-to-line Gauss points are left out of it).
  Vec3 centre = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  double arcMin = std::numeric_limits<double>::infinity();    ///< first pressing point along `line` [m]
  double arcMax = -std::numeric_limits<double>::infinity();   ///< last pressing point along `line` [m]
  double arcMean = std::numeric_limits<double>::quiet_NaN();  ///< normal-force-weighted mean arc [m]
  /// Smallest and largest ratio of a point's friction force to its normal force [-] (0 when none).
  double frictionRatioMin = 0.0, frictionRatioMax = 0.0;
};

/// Contact of `line` against `other` (line indices) at the last assembly of `contact`.
inline PressedContact pressedContact(const contact::LineContact& contact, int line, int other) {
  PressedContact r;
  Vec3 weighted = Vec3::Zero();
  double weights = 0.0, arcWeighted = 0.0;
  bool first = true;
  auto add = [&](int lineA, int lineB, double normal, const Vec3& friction, const Vec3& pointA,
                 const Vec3& pointB, double arcA, double arcB) {
    const bool asA = lineA == line && lineB == other, asB = lineB == line && lineA == other;
    if (!(asA || asB) || !(normal > 0.0)) return;
    ++r.points;
    r.normalForce += normal;
    const Vec3 point = asA ? pointA : pointB;
    if (point.allFinite()) {
      weighted += normal * point;
      weights += normal;
    }
    const double arc = asA ? arcA : arcB;
    arcWeighted += normal * arc;
    r.arcMin = std::min(r.arcMin, arc);
    r.arcMax = std::max(r.arcMax, arc);
    const double ratio = friction.norm() / normal;
    r.frictionRatioMin = first ? ratio : std::min(r.frictionRatioMin, ratio);
    r.frictionRatioMax = std::max(r.frictionRatioMax, ratio);
    first = false;
  };
  if (const contact::DistributedContact* d = contact.distributed()) {
    for (const contact::ContactSample& smp : d->samples())
      add(smp.lineA, smp.lineB, smp.lineForce * smp.length, smp.friction * smp.length, smp.curve.pointA,
          smp.curve.pointB, smp.arcA, smp.arcB);
  } else {
    const Vec3 nowhere =
        Vec3::Constant(std::numeric_limits<double>::quiet_NaN());  // a LineSample has no points
    for (const contact::ContactPoint& c : contact.contacts())
      add(c.lineA, c.lineB, c.normalForce, c.frictionForce, c.pointA, c.pointB, c.arcA, c.arcB);
    for (const contact::LineSample& smp : contact.lineSamples())
      add(smp.lineA, smp.lineB, smp.lineForce * smp.length, Vec3::Zero(), nowhere, nowhere, smp.arcA,
          smp.arcB);
  }
  if (weights > 0.0) r.centre = weighted / weights;
  if (r.points > 0) r.arcMean = arcWeighted / r.normalForce;
  return r;
}

/// Both contact formulations, for tests that run under either (issue 43).
inline auto bothFormulations() {
  return ::testing::Values(model::ContactFormulation::Point, model::ContactFormulation::Distributed);
}

/// Test-name suffix of a contact formulation: "point" or "distributed".
inline std::string formulationName(model::ContactFormulation f) {
  return f == model::ContactFormulation::Point ? "point" : "distributed";
}

/// Name generator of a suite instantiated over bothFormulations().
inline std::string formulationTestName(const ::testing::TestParamInfo<model::ContactFormulation>& p) {
  return formulationName(p.param);
}

}  // namespace tangle::test

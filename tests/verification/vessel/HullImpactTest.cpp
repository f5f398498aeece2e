// A free body drifting into a fixed hull (issue 46: "rebound velocity ratio equal to the restitution within
// 2 %; the contact impulse equals the change of momentum (mass plus added mass)").
//
// A free unit of mass m = 1e6 kg and surge added mass 2e5 kg, with no damping, current or lines on it, moves
// at v0 = 0.5 m/s towards the face of a fixed quay's box hull. Its hull is a sphere (a capsule with equal
// ends) on its reference point, or a box meeting the quay face to face. Closed forms (a rigid-body
// collision along a line through both centres, no rotation):
//  - the rebound speed is e v0 (the hysteretic law's loading and unloading branches, ContactLaw.hpp:
//    sqrt((1 - a) / (1 + a)) = e for any elastic law, so also for the sphere's points entering one by one);
//  - the impulse equals the change of momentum (m + A)(v0 + e v0), and the event's bodies' effective mass is
//    m + A (the quay is fixed).
// Tolerances 2 % (the issue's): the law's smoothing speed 0.005 m/s leaves (v_s / v0)^2 = 1e-4 of the energy
// out of its control, the generalized-alpha step about a 20th of the contact's half period dissipates a
// little of it (rho_inf), and the event's impulse is trapezoidal over the accepted steps.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/vessel/HullContact.hpp"

namespace tangle {
namespace {

constexpr double kMass = 1.0e6, kAdded = 2.0e5, kSpeed = 0.5;

std::string quayModel(double restitution, const std::string& unitHull, double friction = 0.0) {
  return fmt::format(R"(title: a free unit drifts into a quay
environment: {{water_depth: 100}}
line_types:
  - {{name: chain, outer_diameter: 0.1, mass_per_length: 50, axial_stiffness: 1.0e9}}
vessels:
  - name: quay
    mode: fixed
    position: [-20, 0, 0]
    hull:
      - {{shape: box, centre: [0, 0, -5], size: [10, 60, 20]}}
  - name: unit
    mode: free
    position: [0, 0, 0]
    mass: {m}
    inertia: [1.0e9, 1.0e9, 1.0e9]
    added_mass: [{a}, {a}, 1.0e6, 0, 0, 0]
    hydrostatic_stiffness: [0, 0, 1.0e7, 1.0e9, 1.0e9, 0]
    hull:
{hull}
hull_contact: {{restitution: {e}, stiffness: 1.0e7, friction: {mu}}}
lines:
  - name: elsewhere
    end_a: {{type: anchored, position: [300, 300, -100]}}
    end_b: {{type: anchored, position: [310, 300, -100]}}
    sections: [{{type: chain, length: 10, elements: 2}}]
statics: {{method: none}}
dynamics: {{duration: 8, time_step: 0.05, output_interval: 0.5, ramp_time: 0}}
)",
                     fmt::arg("m", kMass), fmt::arg("a", kAdded), fmt::arg("hull", unitHull),
                     fmt::arg("e", restitution), fmt::arg("mu", friction));
}

const std::string kSphere = "      - {shape: capsule, end_a: [-9, 0, 0], end_b: [-9, 0, 0], diameter: 10}";
const std::string kBox = "      - {shape: box, centre: [-10, 0, 0], size: [8, 20, 6]}";

struct Outcome {
  double rebound = 0.0;  ///< the unit's surge speed after the contact [m/s] (> 0 away from the quay)
  vessel::HullImpact event;
  int events = 0;
};

Outcome drift(double restitution, const std::string& hull) {
  analysis::Simulation sim(io::readModelString(quayModel(restitution, hull), "quay.yaml"));
  const model::Model& m = sim.model();
  // The unit at v0 towards the quay (-x): its leading face (sphere or box) at x = -14, 1 m from the quay's
  // face at x = -15, level with the unit's reference point (a central impact).
  const int dof = m.dofs().firstDof(m.vesselNode(1));
  sim.state().velocity[dof] = -kSpeed;
  const time::DynamicResult r = sim.runDynamics([](const model::State&, const VecX&) {});
  EXPECT_TRUE(r.completed) << r.message;
  Outcome out;
  out.rebound = sim.state().velocity[dof];
  const auto& events = sim.hullContact()->impacts().events();
  out.events = static_cast<int>(events.size());
  if (!events.empty()) out.event = events.front();
  return out;
}

class HullRebound : public ::testing::TestWithParam<double> {};

TEST_P(HullRebound, SphereReboundsAtTheRestitutionWithTheMomentumsImpulse) {
  const double e = GetParam();
  const Outcome o = drift(e, kSphere);
  ASSERT_EQ(o.events, 1) << "one contact, then the unit moves away";
  EXPECT_NEAR(o.rebound / (e * kSpeed), 1.0, 0.02) << "rebound " << o.rebound << " m/s";
  const double momentumChange = (kMass + kAdded) * (kSpeed + o.rebound);
  EXPECT_NEAR(o.event.impulse / momentumChange, 1.0, 0.02) << "impulse " << o.event.impulse << " N s";
  EXPECT_NEAR(o.event.impactVelocity / kSpeed, 1.0, 0.005);
  EXPECT_NEAR(o.event.reboundVelocity / o.rebound, 1.0, 0.02);
  EXPECT_NEAR(o.event.bodiesMass / (kMass + kAdded), 1.0, 1e-9) << "a central impact on a fixed hull";
  EXPECT_NEAR(o.event.eq5Mass / (kMass + kAdded), 1.0, 0.02);
  EXPECT_NEAR(o.event.impactEnergy / (0.5 * (kMass + kAdded) * kSpeed * kSpeed), 1.0, 0.01);
  EXPECT_TRUE(o.event.impact);
  EXPECT_FALSE(o.event.lineOnHull);
}

INSTANTIATE_TEST_SUITE_P(Restitutions, HullRebound, ::testing::Values(0.2, 0.5, 0.9));

TEST(HullImpact, BoxFaceToFaceReboundsAtTheRestitution) {
  const Outcome o = drift(0.5, kBox);
  ASSERT_EQ(o.events, 1);
  EXPECT_NEAR(o.rebound / (0.5 * kSpeed), 1.0, 0.02) << "rebound " << o.rebound << " m/s";
  EXPECT_NEAR(o.event.impulse / ((kMass + kAdded) * (kSpeed + o.rebound)), 1.0, 0.02);
  // Taken at the contact's force-weighted centre (the middle of the face), not at a corner.
  EXPECT_NEAR(o.event.bodiesMass / (kMass + kAdded), 1.0, 0.01);
  EXPECT_NEAR(o.event.eq5Mass / (kMass + kAdded), 1.0, 0.02);
}

}  // namespace
}  // namespace tangle

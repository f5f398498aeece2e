// Vessel verification, issue 5 item 3: a free vessel on a spread of four catenary mooring lines under a
// steady current load: the static offset found by the coupled solve must put the vessel in equilibrium
// with the mooring restoring force computed independently.
//
// Coupled model: the 45 000 t semisubmersible of examples/drilling-riser-drift (mass, hydrostatic
// heave/roll/pitch stiffness, current areas and OCIMF-style table Cx = 0.8 at heading 0), free, heading
// 0, with four chain-wire-chain legs of examples/catenary-mooring/model.yaml (250 m chain 76 mm, 780 m
// wire 96 mm, 100 m chain; 20/65/15 elements) from fairleads at (+-40, 0, -15) and (0, +-40, -15) m in
// vessel axes to anchors on the seabed 1000 m further out radially (345 m of water, frictionless
// seabed). A uniform current U along +x loads the vessel (OCIMF 1994, "Prediction of wind and current
// loads on VLCCs"; VesselLoads.hpp): F = R (1/2 rho V^2 Cx(beta) A_x, 1/2 rho V^2 Cy(beta) A_y, 0) with
// (V, beta) from the horizontal part of the flow in vessel axes R^T (U, 0, 0); here beta = 0 (no yaw
// or roll by symmetry), so with the pitch theta of the hull F = 1/2 rho U^2 Cx A_x cos^2(theta)
// (cos theta, 0, -sin theta): the nominal load plus a small vertical part (theta < 1e-3 rad here). The
// lines' drag coefficients are set to 0 so the current acts on the vessel only. Static solve -> pose.
//
// Independent restoring force: a second model with the same four lines but no vessel: end B of each
// line pinned at the fairlead position of the found pose (position + R * offset). Its static solve gives
// the forces the lines exert on their fairleads (LineSnapshot::endForceB); they do not involve
// VesselSystem at all (no link, no hydrostatics, no vessel node). Rigid-body equilibrium of the vessel
// (the restoring force of a spread mooring is the sum of the fairlead forces, e.g. Faltinsen 1990,
// "Sea loads on ships and offshore structures", ch. 8):
//   x:      sum F_x + F_current,x = 0
//   z:      sum F_z + F_current,z - K33 (z - z0) = 0            (heave restoring, VesselLoads)
//   pitch:  sum ((fairlead - reference) x F)_y - K55 theta_y = 0 (pitch restoring for a small tilt;
//           the current load acts at the reference point)
// each checked to 1 % (issue 5) of the applied (x), hydrostatic (z) and restoring (pitch) term.
// Also with a third model, the vessel `Fixed` at the found position (heading 0) and the lines on it:
// the surge balance to 1 %; a fixed vessel cannot be tilted (VesselSpec has a heading only), so its
// fairleads are off by |arm| theta < 0.04 m, worth < k_mooring * 0.04 m ~ 2 kN (< 2e-3 of the load at
// the levels below, where k_mooring < 5e4 N/m); measured < 1e-4.
//
// Why 1 % is loose here: both models mesh the lines identically and the equilibrium of a line between
// given ends is unique, so the balance is exact up to (a) the stiff link of the coupled model (100 EA / L
// of the end element): the end node sits |f| / k_link ~ 1e-4 m from the vessel point, which changes the
// line forces by ~ k_line * 1e-4 ~ 10 N (~1e-5 of the load); (b) the static tolerances (out-of-balance
// < 1e-6 of the largest element weight, ~0.01 N); (c) theta_y = the y component of the rotation vector
// vs the tilt-vector model: equal up to O(roll^2), and roll is zero by symmetry. Expected errors ~1e-5.
//
// Load levels and continuation: U = 0.1, 0.2, ..., 1.0 m/s (10 kN .. 1 MN; offsets 1.8 .. 72 m: this
// spread with 80 m of slack per leg is soft and hardens strongly). Each level restarts both static solves
// from the equilibrium of the previous level (Simulation::state() before solveStatics; same mesh).
// Started from the initial catenary shapes at zero offset, the coupled static solve does not converge
// for U >= 0.2 m/s (the Newton iteration overshoots into the taut range and the load incrementation of
// StaticSolver does not help: it scales the line weight only, not the vessel's current load, and the
// catenary offset depends on load / weight anyway), and the lines-only solve fails for some of the
// offset fairleads (e.g. U = 0.6, 0.8, 0.9, 1.0 m/s). The equilibrium found does not depend on the
// starting state (unique equilibrium, residual-based convergence test), so the restart does not weaken
// the check.
//
// Also checked: the offset and the independently computed restoring force both increase with the load
// (monotonic offset-restoring curve through the origin), and sway, roll and yaw stay zero by symmetry.

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle {
namespace {

constexpr double kPiValue = 3.141592653589793;
constexpr double kDepth = 345.0;
constexpr double kRho = 1025.0;
constexpr double kRadius = 40.0;        // fairlead radius from the reference point [m]
constexpr double kFairleadZ = -15.0;    // fairlead level in vessel axes [m]
constexpr double kAnchorSpan = 1000.0;  // horizontal fairlead-anchor distance at zero offset [m]
constexpr double kK33 = 1.5e7;          // heave stiffness [N/m]
constexpr double kK55 = 1.33e9;         // pitch stiffness [N m/rad]
constexpr double kCx = 0.8;
constexpr double kAreaX = 2500.0;       // [m^2]

/// The chain and wire of examples/catenary-mooring/model.yaml (sources there), drag switched off.
void addLineTypes(model::ModelSpec& spec) {
  section::LineType chain;
  chain.name = "chain76";
  chain.outerDiameter = 0.1368;
  chain.buoyancyDiameter = 0.1368;
  chain.contactDiameter = 0.1368;
  chain.massPerLength = 114.9;
  chain.axialStiffness = 4.93e8;
  chain.dragNormal = 0.0;
  chain.dragAxial = 0.0;
  chain.addedMassNormal = 1.0;
  chain.addedMassAxial = 0.5;
  section::LineType wire;
  wire.name = "wire96";
  wire.outerDiameter = 0.096;
  wire.buoyancyDiameter = 0.0831;
  wire.contactDiameter = 0.096;
  wire.massPerLength = 42.6;
  wire.axialStiffness = 7.9e8;
  wire.dragNormal = 0.0;
  wire.dragAxial = 0.0;
  wire.addedMassNormal = 1.0;
  spec.lineTypes[chain.name] = chain;
  spec.lineTypes[wire.name] = wire;
}

model::EnvironmentSpec environment(double currentSpeed) {
  model::EnvironmentSpec env;
  env.waterDepth = kDepth;
  env.waterDensity = kRho;
  env.seabed.normalStiffness = 1.0e5;
  env.seabed.frictionCoefficient = 0.0;
  if (currentSpeed > 0.0) env.current = {{0.0, currentSpeed, 0.0}, {-kDepth, currentSpeed, 0.0}};
  return env;
}

/// Fairlead of leg i in vessel axes (legs towards +x, +y, -x, -y).
Vec3 fairleadOffset(int i) {
  const double a = 0.5 * kPiValue * i;
  return Vec3(kRadius * std::cos(a), kRadius * std::sin(a), kFairleadZ);
}
Vec3 anchorPosition(int i) {
  const double a = 0.5 * kPiValue * i;
  // Resting on the seabed: one contact radius above it.
  return Vec3((kRadius + kAnchorSpan) * std::cos(a), (kRadius + kAnchorSpan) * std::sin(a), -kDepth + 0.5 * 0.1368);
}

model::LineSpec leg(int i, const model::EndSpec& fairlead) {
  model::LineSpec l;
  l.name = "leg" + std::to_string(i + 1);
  l.endA.kind = model::EndKind::Anchored;
  l.endA.position = anchorPosition(i);
  l.endB = fairlead;
  l.sections = {{"chain76", 250.0, 20}, {"wire96", 780.0, 65}, {"chain76", 100.0, 15}};
  l.contact = false;
  return l;
}

struct CoupledResult {
  Vec3 position;
  Mat3 rotation;
  std::array<Vec3, 4> fairleads;  // global fairlead positions of the found pose [m]
  int iterations = 0;
  model::State state;             // the equilibrium (start of the next load level)
};

/// Static equilibrium of the free moored vessel under the current speed; `start` (if given) is the
/// equilibrium of the previous load level, used as the starting state (load continuation, see above).
CoupledResult solveCoupled(double currentSpeed, model::State* start) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, coupled (test)";
  spec.environment = environment(currentSpeed);
  addLineTypes(spec);
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Free;
  v.mass = 4.5e7;
  v.inertia = Vec3(4.05e10, 4.05e10, 5.5e10);
  v.addedMass = {2.2e7, 2.2e7, 4.5e7, 2.0e10, 2.0e10, 2.5e10};
  v.hydrostaticStiffness = {0.0, 0.0, kK33, 1.33e9, kK55, 0.0};
  v.currentAreas = Vec3(kAreaX, kAreaX, 80.0);
  v.currentCoefficients.heading = {0.0, 0.5 * kPiValue, kPiValue, 1.5 * kPiValue};
  v.currentCoefficients.values = {Vec3(kCx, 0, 0), Vec3(0, kCx, 0), Vec3(-kCx, 0, 0), Vec3(0, -kCx, 0)};
  spec.vessels.push_back(v);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Vessel;
    e.vessel = "semisub";
    e.position = fairleadOffset(i);
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  if (start) {
    // Same mesh and node numbering at every load level: restart from the previous equilibrium.
    sim.state().position = start->position;
    sim.state().triad = start->triad;
  }
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << "U = " << currentSpeed << " m/s: " << r.message;
  CoupledResult out;
  const int node = sim.model().vesselNode(0);
  out.position = sim.state().position[node];
  out.rotation = sim.state().triad[node];
  for (int i = 0; i < 4; ++i) out.fairleads[i] = sim.vessels()->vesselPoint(sim.state(), 0, fairleadOffset(i));
  out.iterations = r.iterations;
  out.state = sim.state();
  return out;
}

/// Forces the four lines exert on fairleads pinned at the given global positions (no vessel in the model).
/// restart: start from `state` (the lines-only equilibrium of the previous load level) instead of the
/// initial catenary shapes; on return `state` is this equilibrium.
std::array<Vec3, 4> mooringForces(const std::array<Vec3, 4>& fairleads, bool restart, model::State& state,
                                  int* iterations) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, lines only (test)";
  spec.environment = environment(0.0);  // the lines have no drag anyway
  addLineTypes(spec);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Pinned;
    e.position = fairleads[i];
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  if (restart) {
    sim.state().position = state.position;
    sim.state().triad = state.triad;
    // The held fairleads must sit at their new positions.
    for (int i = 0; i < 4; ++i) sim.state().position[sim.model().lines()[i].lastNode()] = fairleads[i];
  }
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << "lines only: " << r.message;
  *iterations = r.iterations;
  state = sim.state();
  const std::vector<solver::LineSnapshot> lines = sim.snapshot();
  std::array<Vec3, 4> f;
  for (int i = 0; i < 4; ++i) f[i] = lines[i].endForceB;
  return f;
}

/// Forces the four lines exert on their fairleads on a `Fixed` vessel at `position`, heading 0 (the hull
/// tilt of the coupled solution cannot be given to a fixed vessel). Starts from `linesState` (the
/// lines-only equilibrium of the same level: same line node numbering, the vessel node comes last).
std::array<Vec3, 4> fixedVesselForces(const Vec3& position, const model::State& linesState) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, fixed (test)";
  spec.environment = environment(0.0);
  addLineTypes(spec);
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Fixed;
  v.position = position;
  spec.vessels.push_back(v);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Vessel;
    e.vessel = "semisub";
    e.position = fairleadOffset(i);
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  for (int n = 0; n < static_cast<int>(linesState.position.size()); ++n) {
    sim.state().position[n] = linesState.position[n];
    sim.state().triad[n] = linesState.triad[n];
  }
  for (int i = 0; i < 4; ++i) sim.state().position[sim.model().lines()[i].lastNode()] = position + fairleadOffset(i);
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << "fixed vessel: " << r.message;
  const std::vector<solver::LineSnapshot> lines = sim.snapshot();
  std::array<Vec3, 4> f;
  for (int i = 0; i < 4; ++i) f[i] = lines[i].endForceB;
  return f;
}

TEST(MooredVessel, StaticOffsetBalancesIndependentMooringRestoringForce) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<double> offsets, restoring;
  model::State previous, previousLines;
  for (int level = 1; level <= 10; ++level) {
    const double u = 0.1 * level;
    const CoupledResult c = solveCoupled(u, level > 1 ? &previous : nullptr);
    previous = c.state;
    int linesIterations = 0;
    const std::array<Vec3, 4> f = mooringForces(c.fairleads, level > 1, previousLines, &linesIterations);
    Vec3 sum = Vec3::Zero(), moment = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
      sum += f[i];
      moment += (c.fairleads[i] - c.position).cross(f[i]);
    }
    const double applied = 0.5 * kRho * u * u * kCx * kAreaX;  // nominal current load along +x [N]
    // The current load of the model at the found pose (file comment): flow in vessel axes, beta = 0.
    const Vec3 flow = c.rotation.transpose() * Vec3(u, 0.0, 0.0);
    EXPECT_LT(std::abs(std::atan2(flow.y(), flow.x())), 1e-9);
    const double v2 = flow.x() * flow.x() + flow.y() * flow.y();
    const Vec3 current = c.rotation * Vec3(0.5 * kRho * v2 * kCx * kAreaX, 0.0, 0.0);
    const Vec3 tilt = geometry::logMap(c.rotation);
    const double heave = -kK33 * c.position.z();             // hydrostatic heave force (z0 = 0) [N]
    const double pitch = -kK55 * tilt.y();                    // hydrostatic pitch moment [N m]
    const double ex = (sum.x() + current.x()) / current.x();
    const double ez = (sum.z() + current.z() + heave) / std::abs(heave);
    const double em = (moment.y() + pitch) / std::abs(pitch);
    std::printf("[ vessel   ] U %.1f m/s: load %7.1f kN, offset x %7.3f m, z %.4f m, pitch %+.5f rad, |roll|+|yaw| "
                "%.1e (%2d it); lines (%2d it): Fx %7.1f kN (error %+.2e; vs nominal %+.2e), Fz %.1f kN vs heave "
                "%.1f kN + current %.3f kN (error %+.2e), "
                "My %.4g N m (error %+.2e), |Fy| %.1e N\n",
                u, applied / 1e3, c.position.x(), c.position.z(), tilt.y(), std::abs(tilt.x()) + std::abs(tilt.z()),
                c.iterations, linesIterations, -sum.x() / 1e3, ex, (sum.x() + applied) / applied, sum.z() / 1e3,
                heave / 1e3, current.z() / 1e3, ez, moment.y(), em, std::abs(sum.y()));
    // The same with a Fixed vessel at the found position (no tilt): the fairleads are off by the tilt,
    // |arm| theta < 0.04 m, which changes the restoring force by < k_mooring * 0.04 m ~ 2e3 N.
    const std::array<Vec3, 4> ff = fixedVesselForces(c.position, previousLines);
    Vec3 sumFixed = Vec3::Zero();
    for (int i = 0; i < 4; ++i) sumFixed += ff[i];
    const double exFixed = (sumFixed.x() + current.x()) / current.x();
    std::printf("[ vessel   ]          fixed vessel at the found position: Fx %7.1f kN (error %+.2e)\n",
                -sumFixed.x() / 1e3, exFixed);
    EXPECT_NEAR(exFixed, 0.0, 0.01);
    EXPECT_NEAR(ex, 0.0, 0.01);  // issue 5: 1 %
    EXPECT_NEAR(ez, 0.0, 0.01);
    EXPECT_NEAR(em, 0.0, 0.01);
    // Symmetry about the x-z plane: no sway, roll or yaw (relative to the surge offset / pitch).
    EXPECT_LT(std::abs(c.position.y()), 1e-6 * c.position.x());
    EXPECT_LT(std::abs(tilt.x()) + std::abs(tilt.z()), 1e-6 * std::abs(tilt.y()));
    EXPECT_LT(std::abs(sum.y()), 1e-6 * applied);
    offsets.push_back(c.position.x());
    restoring.push_back(-sum.x());
  }
  // Monotonic offset-restoring curve through the origin (zero load: zero offset by symmetry).
  EXPECT_GT(offsets[0], 0.0);
  EXPECT_GT(restoring[0], 0.0);
  for (std::size_t k = 1; k < offsets.size(); ++k) {
    EXPECT_GT(offsets[k], offsets[k - 1]);
    EXPECT_GT(restoring[k], restoring[k - 1]);
    std::printf("[ vessel   ] offset %7.3f -> %7.3f m: tangent stiffness %.4g N/m\n", offsets[k - 1], offsets[k],
                (restoring[k] - restoring[k - 1]) / (offsets[k] - offsets[k - 1]));
  }
  std::printf("[ vessel   ] %.2f s wall\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
}

}  // namespace
}  // namespace tangle

namespace tangle {
namespace {

// Regression for a fixed bug: for a line end tied to a FREE vessel the end node is free, so its
// out-of-balance force is ~0 at equilibrium; Simulation::snapshot() now takes the link forces out
// (VesselSystem::endConnectionForces) so LineSnapshot::endForceB is the force the line exerts on the
// fairlead (before the fix: ~0.002 N against a ~3.1e5 N top tension). Expected: the fairlead forces of
// the pinned lines-only model within 1 % (the same line loads, so only round-off separates them).
TEST(MooredVessel, SnapshotReportsFairleadForcesOfFreeVesselEnds) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, snapshot (test)";
  spec.environment = environment(0.3);
  addLineTypes(spec);
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Free;
  v.mass = 4.5e7;
  v.hydrostaticStiffness = {0.0, 0.0, kK33, 1.33e9, kK55, 0.0};
  v.inertia = Vec3(4.05e10, 4.05e10, 5.5e10);
  v.currentAreas = Vec3(kAreaX, kAreaX, 80.0);
  v.currentCoefficients.heading = {0.0, 0.5 * kPiValue, kPiValue, 1.5 * kPiValue};
  v.currentCoefficients.values = {Vec3(kCx, 0, 0), Vec3(0, kCx, 0), Vec3(-kCx, 0, 0), Vec3(0, -kCx, 0)};
  spec.vessels.push_back(v);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Vessel;
    e.vessel = "semisub";
    e.position = fairleadOffset(i);
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  // U = 0.3 m/s needs a load continuation (see above): start from U = 0.2 m/s.
  model::State start = solveCoupled(0.1, nullptr).state;
  start = solveCoupled(0.2, &start).state;
  sim.state().position = start.position;
  sim.state().triad = start.triad;
  ASSERT_TRUE(sim.solveStatics().converged);
  std::array<Vec3, 4> fairleads;
  for (int i = 0; i < 4; ++i) fairleads[i] = sim.vessels()->vesselPoint(sim.state(), 0, fairleadOffset(i));
  model::State lines;
  int iterations = 0;
  const std::array<Vec3, 4> expected = mooringForces(fairleads, false, lines, &iterations);
  const std::vector<solver::LineSnapshot> snap = sim.snapshot();
  for (int i = 0; i < 4; ++i)
    EXPECT_LT((snap[i].endForceB - expected[i]).norm(), 0.01 * expected[i].norm()) << "leg " << i + 1;
}

}  // namespace
}  // namespace tangle

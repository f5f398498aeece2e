/// @file VesselLoadsTest.cpp
/// Loads on a free vessel (tangle::vessel::VesselLoads): hydrostatics, damping, current/wind drag, drift,
/// their derivatives (finite differences) and the mass matrix.

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/vessel/VesselLoads.hpp"

namespace tangle::vessel {
namespace {

Mat3 rotZ(double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); }
Mat3 rotX(double a) { return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix(); }
Mat3 rotY(double a) { return Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix(); }

/// Coefficient table with values at 0, 90, 180, 270 deg (simple OCIMF-like shape).
model::HeadingTable coefficientTable() {
  model::HeadingTable t;
  t.heading = {0.0, 0.5 * kPi, kPi, 1.5 * kPi};
  t.values = {Vec3(0.8, 0.0, 0.0), Vec3(0.0, 0.9, 0.1), Vec3(-0.7, 0.0, 0.0), Vec3(0.0, -0.9, -0.1)};
  return t;
}

model::VesselSpec vesselSpec() {
  model::VesselSpec v;
  v.name = "fpso";
  v.mode = model::VesselMode::Free;
  v.mass = 2.0e8;
  v.inertia = Vec3(1.0e11, 2.0e12, 2.1e12);
  v.addedMass = {2.0e7, 1.0e8, 1.5e8, 3.0e10, 1.0e12, 8.0e11};
  v.linearDamping = {1.0e5, 2.0e5, 3.0e6, 4.0e8, 5.0e9, 6.0e9};
  v.quadraticDamping = {1.0e6, 3.0e6, 0.0, 2.0e9, 0.0, 1.0e10};
  v.hydrostaticStiffness = {0.0, 0.0, 1.2e8, 3.0e9, 5.0e10, 0.0};
  v.currentCoefficients = coefficientTable();
  v.currentAreas = Vec3(1000.0, 5000.0, 300.0);
  v.windCoefficients = coefficientTable();
  v.windAreas = Vec3(800.0, 3000.0, 300.0);
  v.waveDrift.heading = {0.0, 0.5 * kPi, kPi, 1.5 * kPi};
  v.waveDrift.values = {Vec3(5e3, 0.0, 0.0), Vec3(1e3, 4e4, 2e5), Vec3(-1e4, 0.0, 0.0), Vec3(1e3, -4e4, -2e5)};
  return v;
}

model::EnvironmentSpec environment(double windSpeed = 0.0, double windAzimuth = 0.0) {
  model::EnvironmentSpec e;
  e.windSpeed = windSpeed;
  e.windAzimuth = windAzimuth;
  return e;
}

/// Vessel with only the current table (other loads zero).
model::VesselSpec currentOnly() {
  model::VesselSpec v = vesselSpec();
  v.linearDamping = {};
  v.quadraticDamping = {};
  v.hydrostaticStiffness = {};
  v.windCoefficients = {};
  v.waveDrift = {};
  return v;
}

// ---------------------------------------------------------------------------------------------
// Hydrostatics (Faltinsen 1990, ch. 2)
// ---------------------------------------------------------------------------------------------

// Source: F_z = -K33 (z - z0), M = -K44 phi about the vessel x axis for a pure roll phi (exact for the
// tilt definition used). Tolerance 1e-9 relative: a few rotations and one atan2, rounding only.
TEST(VesselLoads, HydrostaticHeaveAndRoll) {
  const VesselLoads loads(vesselSpec(), environment());
  const Vec3 p0(10.0, -5.0, 0.0);
  const Mat3 r0 = rotZ(0.7);
  const double phi = 0.1;
  const Mat3 r = r0 * rotX(phi);
  const BodyLoad b = loads.loads(p0 + Vec3(0.0, 0.0, 0.5), r, Vec6::Zero(), p0, r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  EXPECT_NEAR(b.force(2), -1.2e8 * 0.5, 1e-9 * 6e7);
  EXPECT_NEAR(b.force(0), 0.0, 1e-9);
  const Vec3 expected = -3.0e9 * phi * (r0 * Vec3::UnitX());
  EXPECT_LT((b.force.tail<3>() - expected).norm(), 1e-9 * expected.norm());
  // Pure pitch theta: M = -K55 theta about the vessel y axis.
  const double theta = -0.05;
  const BodyLoad c = loads.loads(p0, r0 * rotY(theta), Vec6::Zero(), p0, r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  const Vec3 expectedPitch = -5.0e10 * theta * (r0 * Vec3::UnitY());
  EXPECT_LT((c.force.tail<3>() - expectedPitch).norm(), 1e-9 * expectedPitch.norm());
}

// Source: hydrostatic restoring does not depend on yaw: a pure yaw gives no moment, and a yawed vessel
// with roll phi about its own x axis gets -K44 phi about that (current) axis.
TEST(VesselLoads, HydrostaticMomentIndependentOfYaw) {
  const VesselLoads loads(vesselSpec(), environment());
  const Mat3 r0 = rotZ(0.3);
  const BodyLoad yawOnly = loads.loads(Vec3::Zero(), rotZ(1.3), Vec6::Zero(), Vec3::Zero(), r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  EXPECT_LT(yawOnly.force.norm(), 1e-6);  // rounding of K ~ 5e10 times eps
  const double phi = 0.08;
  const Mat3 r = rotZ(1.3) * rotX(phi);
  const BodyLoad b = loads.loads(Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  const Vec3 expected = -3.0e9 * phi * (r * Vec3::UnitX());
  EXPECT_LT((b.force.tail<3>() - expected).norm(), 1e-9 * expected.norm());
}

/// Central-difference stiffness -d(force)/d(x, dtheta) with global rotation increments R <- exp(dtheta) R.
Mat6 finiteDifferenceStiffness(const VesselLoads& loads, const Vec3& p, const Mat3& r, const Vec6& v, const Vec3& p0,
                               const Mat3& r0, const Vec3& current, double a, double azimuth, double ramp) {
  Mat6 k;
  const double hx = 1e-4;
  const double hr = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Vec3 pp = p;
    Vec3 pm = p;
    Mat3 rp = r;
    Mat3 rm = r;
    double h = hx;
    if (j < 3) {
      pp(j) += h;
      pm(j) -= h;
    } else {
      h = hr;
      Vec3 d = Vec3::Zero();
      d(j - 3) = h;
      rp = geometry::expMap(d) * r;
      rm = geometry::expMap(-d) * r;
    }
    const Vec6 fp = loads.loads(pp, rp, v, p0, r0, current, a, azimuth, ramp).force;
    const Vec6 fm = loads.loads(pm, rm, v, p0, r0, current, a, azimuth, ramp).force;
    k.col(j) = -(fp - fm) / (2.0 * h);
  }
  return k;
}

// Source: definition of the tangent. State with roll, pitch and a yaw change, current, wind and drift at
// headings away from table knots, zero velocity (the damping force is then zero and its omitted rotation
// dependence vanishes). Tolerance 1e-6 of the largest entry: central-difference truncation O(h^2) and
// rounding eps |F| / h ~ 1e-10 |F| / 1e-6.
TEST(VesselLoads, StiffnessMatchesFiniteDifferences) {
  const VesselLoads loads(vesselSpec(), environment(20.0, 0.4));
  const Vec3 p0(0.0, 0.0, 0.0);
  const Mat3 r0 = rotZ(0.2);
  const Vec3 p(3.0, -2.0, -0.4);
  const Mat3 r = rotZ(0.6) * rotY(-0.03) * rotX(0.05);
  const Vec3 current(0.8, 1.1, 0.0);
  const double a = 3.0;
  const double azimuth = 2.2;
  const double ramp = 0.7;
  const BodyLoad b = loads.loads(p, r, Vec6::Zero(), p0, r0, current, a, azimuth, ramp);
  const Mat6 fd = finiteDifferenceStiffness(loads, p, r, Vec6::Zero(), p0, r0, current, a, azimuth, ramp);
  const double scale = fd.cwiseAbs().maxCoeff();
  EXPECT_LT((b.stiffness - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "analytic\n" << b.stiffness << "\nfd\n" << fd;
  // The heave and roll/pitch hydrostatic terms are there.
  EXPECT_NEAR(b.stiffness(2, 2), 1.2e8, 1e-6);
}

// Source: as above, for a tilt of 1e-5 rad, where the tilt angle uses its small-angle series (branch
// s < 1e-4 n_z). Hydrostatics only (no environment). Same tolerance.
TEST(VesselLoads, StiffnessMatchesFiniteDifferencesForTinyTilt) {
  const VesselLoads loads(vesselSpec(), environment());
  const Mat3 r0 = rotZ(-0.4);
  const Mat3 r = rotZ(0.1) * rotX(1e-5) * rotY(-0.7e-5);
  const BodyLoad b = loads.loads(Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  const Mat6 fd = finiteDifferenceStiffness(loads, Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), r0, Vec3::Zero(), 0.0,
                                            0.0, 0.0);
  const double scale = fd.cwiseAbs().maxCoeff();
  EXPECT_LT((b.stiffness - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "analytic\n" << b.stiffness << "\nfd\n" << fd;
}

// Source: statics of a rigid body (a submerged body, VesselSpec::displacedVolume): its weight -M g e_z at the
// reference point and its buoyancy rho g V e_z at R c_b give the force (0, 0, rho g V - M g) and the moment
// (R c_b) x (rho g V e_z); the stiffness is the central difference of that moment in the rotation (tolerance
// as above). Tilted by 0.3 rad, the buoyancy 2 m above the reference point rights it: the moment about x is
// -rho g V 2 sin(0.3) for a roll of +0.3 (a pendulum's), and the stiffness at rest upright is
// diag(rho g V 2, rho g V 2, 0) (metacentric height 2 m).
TEST(VesselLoads, SubmergedBodyCarriesItsWeightAndBuoyancy) {
  model::VesselSpec v;
  v.name = "buoy";
  v.mode = model::VesselMode::Free;
  v.mass = 8000.0;
  v.inertia = Vec3(2.0e4, 2.0e4, 1.0e4);
  v.displacedVolume = 12.0;
  v.centreOfBuoyancy = Vec3(0.0, 0.0, 2.0);
  const model::EnvironmentSpec env = environment();
  const VesselLoads loads(v, env);
  const double lift = env.waterDensity * env.gravity * 12.0;
  const BodyLoad upright = loads.loads(Vec3(1.0, 2.0, -50.0), Mat3::Identity(), Vec6::Zero(), Vec3::Zero(),
                                       Mat3::Identity(), Vec3::Zero(), 0.0, 0.0, 0.0);
  EXPECT_NEAR(upright.force(2), lift - 8000.0 * env.gravity, 1e-9 * lift);
  EXPECT_NEAR(upright.force.head<2>().norm() + upright.force.tail<3>().norm(), 0.0, 1e-9 * lift);
  EXPECT_NEAR(upright.stiffness(3, 3), 2.0 * lift, 1e-9 * lift);
  EXPECT_NEAR(upright.stiffness(4, 4), 2.0 * lift, 1e-9 * lift);
  EXPECT_NEAR(upright.stiffness(5, 5), 0.0, 1e-9 * lift);
  const Mat3 rolled = rotX(0.3);
  const BodyLoad tilted = loads.loads(Vec3::Zero(), rolled, Vec6::Zero(), Vec3::Zero(), Mat3::Identity(),
                                      Vec3::Zero(), 0.0, 0.0, 0.0);
  EXPECT_NEAR(tilted.force(3), -lift * 2.0 * std::sin(0.3), 1e-9 * lift);
  const Mat3 r = rotZ(0.4) * rotY(-0.2) * rotX(0.3);
  const BodyLoad b =
      loads.loads(Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), Mat3::Identity(), Vec3::Zero(), 0.0, 0.0, 0.0);
  const Mat6 fd = finiteDifferenceStiffness(loads, Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(),
                                            Mat3::Identity(), Vec3::Zero(), 0.0, 0.0, 0.0);
  EXPECT_LT((b.stiffness - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff())
      << "analytic\n"
      << b.stiffness << "\nfd\n"
      << fd;
}

// Source: at the equilibrium the rotational hydrostatic stiffness is R0 diag(K44, K55, 0) R0^T.
TEST(VesselLoads, HydrostaticStiffnessAtEquilibrium) {
  model::VesselSpec spec = vesselSpec();
  const VesselLoads loads(spec, environment());
  const Mat3 r0 = rotZ(0.9);
  const BodyLoad b = loads.loads(Vec3::Zero(), r0, Vec6::Zero(), Vec3::Zero(), r0, Vec3::Zero(), 0.0, 0.0, 0.0);
  const Mat3 expected = r0 * Vec3(3.0e9, 5.0e10, 0.0).asDiagonal() * r0.transpose();
  EXPECT_LT((b.stiffness.block<3, 3>(3, 3) - expected).norm(), 1e-12 * expected.norm());
}

// ---------------------------------------------------------------------------------------------
// Damping
// ---------------------------------------------------------------------------------------------

// Source: F = -B1 v - B2 |v| v per DOF in vessel axes, rotated to global. Tolerance 1e-12 relative.
TEST(VesselLoads, LinearAndQuadraticDampingInVesselAxes) {
  model::VesselSpec spec = vesselSpec();
  spec.currentCoefficients = {};
  spec.windCoefficients = {};
  const VesselLoads loads(spec, environment());
  const Mat3 r = rotZ(0.5);
  const Vec3 vb(-1.5, 0.4, 0.2);
  const Vec3 wb(0.01, 0.0, -0.02);
  Vec6 v;
  v << r * vb, r * wb;
  const BodyLoad b = loads.loads(Vec3::Zero(), r, v, Vec3::Zero(), r, Vec3::Zero(), 0.0, 0.0, 1.0);
  const Vec3 fb(-1.0e5 * -1.5 - 1.0e6 * 1.5 * -1.5, -2.0e5 * 0.4 - 3.0e6 * 0.4 * 0.4, -3.0e6 * 0.2);
  const Vec3 mb(-4.0e8 * 0.01 - 2.0e9 * 0.01 * 0.01, 0.0, -6.0e9 * -0.02 - 1.0e10 * 0.02 * -0.02);
  EXPECT_LT((b.force.head<3>() - r * fb).norm(), 1e-12 * fb.norm());
  EXPECT_LT((b.force.tail<3>() - r * mb).norm(), 1e-12 * mb.norm());
}

/// Central-difference damping -d(force)/d(velocity).
Mat6 finiteDifferenceDamping(const VesselLoads& loads, const Vec3& p, const Mat3& r, const Vec6& v, const Vec3& current,
                             double ramp) {
  Mat6 c;
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Vec6 vp = v;
    Vec6 vm = v;
    vp(j) += h;
    vm(j) -= h;
    const Vec6 fp = loads.loads(p, r, vp, p, r, current, 2.0, 1.0, ramp).force;
    const Vec6 fm = loads.loads(p, r, vm, p, r, current, 2.0, 1.0, ramp).force;
    c.col(j) = -(fp - fm) / (2.0 * h);
  }
  return c;
}

// Source: definition of the damping matrix; damping, relative-velocity current and wind drag together.
// Relative headings away from table knots. Tolerance 1e-6 of the largest entry (as for the stiffness).
TEST(VesselLoads, DampingMatrixMatchesFiniteDifferences) {
  const VesselLoads loads(vesselSpec(), environment(15.0, 2.5));
  const Mat3 r = rotZ(0.35) * rotX(0.02);
  Vec6 v;
  v << 0.3, -0.5, 0.1, 0.004, -0.002, 0.01;
  const Vec3 current(1.2, 0.3, 0.0);
  const BodyLoad b = loads.loads(Vec3::Zero(), r, v, Vec3::Zero(), r, current, 2.0, 1.0, 0.8);
  const Mat6 fd = finiteDifferenceDamping(loads, Vec3::Zero(), r, v, current, 0.8);
  const double scale = fd.cwiseAbs().maxCoeff();
  EXPECT_LT((b.damping - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "analytic\n" << b.damping << "\nfd\n" << fd;
}

// ---------------------------------------------------------------------------------------------
// Current drag (OCIMF 1994 form)
// ---------------------------------------------------------------------------------------------

// Source: F = 1/2 rho V^2 C(heading) A with the table values at 0 and 90 deg (hand computation).
// Tolerance 1e-9 relative: rounding only.
TEST(VesselLoads, CurrentDragHeadAndBeam) {
  const VesselLoads loads(currentOnly(), environment());
  const double q = 0.5 * 1025.0 * 1.5 * 1.5;
  // Current towards the bow (+x vessel, relative heading 0), vessel heading 0: Cx(0) = 0.8 pushes along +x.
  const BodyLoad head = loads.loads(Vec3::Zero(), Mat3::Identity(), Vec6::Zero(), Vec3::Zero(), Mat3::Identity(),
                                    Vec3(1.5, 0.0, 0.0), 0.0, 0.0, 1.0);
  Vec6 expectedHead = Vec6::Zero();
  expectedHead(0) = q * 0.8 * 1000.0;
  EXPECT_LT((head.force - expectedHead).norm(), 1e-9 * expectedHead.norm());
  // Beam current towards port (+y vessel, relative heading 90 deg): Cy = 0.9, Cmz = 0.1.
  const BodyLoad beam = loads.loads(Vec3::Zero(), Mat3::Identity(), Vec6::Zero(), Vec3::Zero(), Mat3::Identity(),
                                    Vec3(0.0, 1.5, 0.0), 0.0, 0.0, 1.0);
  Vec6 expectedBeam = Vec6::Zero();
  expectedBeam(1) = q * 0.9 * 5000.0;
  expectedBeam(5) = q * 0.1 * 5000.0 * 300.0;
  EXPECT_LT((beam.force - expectedBeam).norm(), 1e-9 * expectedBeam.norm());
  // Ramp multiplies the environmental load.
  const BodyLoad half = loads.loads(Vec3::Zero(), Mat3::Identity(), Vec6::Zero(), Vec3::Zero(), Mat3::Identity(),
                                    Vec3(0.0, 1.5, 0.0), 0.0, 0.0, 0.5);
  EXPECT_LT((half.force - 0.5 * expectedBeam).norm(), 1e-9 * expectedBeam.norm());
}

// Source: vessel heading 90 deg, current towards global +x: the flow goes towards the vessel's starboard
// side (-y vessel, relative heading 270 deg, Cy = -0.9, Cmz = -0.1). The force -0.9 q A_y along y_vessel is
// +0.9 q A_y along global +x (drag along the flow); yaw moment -0.1 q A_y L about global z.
TEST(VesselLoads, CurrentDragOnTurnedVessel) {
  const VesselLoads loads(currentOnly(), environment());
  const Mat3 r = rotZ(0.5 * kPi);
  const double q = 0.5 * 1025.0 * 1.0;
  const BodyLoad b = loads.loads(Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), r, Vec3(1.0, 0.0, 0.0), 0.0, 0.0, 1.0);
  Vec6 expected = Vec6::Zero();
  expected(0) = q * 0.9 * 5000.0;
  expected(5) = -q * 0.1 * 5000.0 * 300.0;
  EXPECT_LT((b.force - expected).norm(), 1e-9 * expected.norm());
}

// Source: drag depends on the relative velocity: a vessel moving with the current feels none; one moving
// at twice the current speed feels the same magnitude reversed (flow towards the stern, Cx(180) = -0.7).
TEST(VesselLoads, CurrentDragUsesRelativeVelocity) {
  const VesselLoads loads(currentOnly(), environment());
  const Vec3 current(1.0, 0.0, 0.0);
  Vec6 v = Vec6::Zero();
  v(0) = 1.0;
  const BodyLoad same = loads.loads(Vec3::Zero(), Mat3::Identity(), v, Vec3::Zero(), Mat3::Identity(), current, 0.0,
                                    0.0, 1.0);
  EXPECT_LT(same.force.norm(), 1e-9);
  v(0) = 2.0;
  const BodyLoad faster = loads.loads(Vec3::Zero(), Mat3::Identity(), v, Vec3::Zero(), Mat3::Identity(), current, 0.0,
                                      0.0, 1.0);
  EXPECT_NEAR(faster.force(0), -0.5 * 1025.0 * 0.7 * 1000.0, 1e-6);
}

// Source: wind uses the same form with the air density and EnvironmentSpec wind (hand computation).
TEST(VesselLoads, WindDrag) {
  model::VesselSpec spec = vesselSpec();
  spec.currentCoefficients = {};
  spec.waveDrift = {};
  const VesselLoads loads(spec, environment(20.0, 0.0));
  const BodyLoad b = loads.loads(Vec3::Zero(), Mat3::Identity(), Vec6::Zero(), Vec3::Zero(), Mat3::Identity(),
                                 Vec3::Zero(), 0.0, 0.0, 1.0);
  EXPECT_NEAR(b.force(0), 0.5 * 1.225 * 400.0 * 0.8 * 800.0, 1e-6);
  EXPECT_NEAR(b.force(1), 0.0, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Mean wave drift (Faltinsen 1990, ch. 5)
// ---------------------------------------------------------------------------------------------

// Source: F = D(beta) a^2; head sea (waves towards -x vessel, relative heading 180 deg) with
// D(180) = (-1e4, 0, 0). Doubling the amplitude multiplies the force by 4. Tolerance 1e-9 relative.
TEST(VesselLoads, DriftScalesWithAmplitudeSquared) {
  model::VesselSpec spec = vesselSpec();
  spec.currentCoefficients = {};
  spec.windCoefficients = {};
  const VesselLoads loads(spec, environment());
  const auto drift = [&](double a, double azimuth, const Mat3& r) {
    return loads.loads(Vec3::Zero(), r, Vec6::Zero(), Vec3::Zero(), r, Vec3::Zero(), a, azimuth, 1.0).force;
  };
  const Vec6 f1 = drift(1.5, kPi, Mat3::Identity());
  EXPECT_NEAR(f1(0), -1.0e4 * 2.25, 1e-9 * 2.25e4);
  EXPECT_LT(f1.tail<5>().norm(), 1e-9);
  const Vec6 f2 = drift(3.0, kPi, Mat3::Identity());
  EXPECT_LT((f2 - 4.0 * f1).norm(), 1e-9 * f2.norm());
  // Vessel heading 90 deg, waves towards global +y: relative heading 0, D(0) = (5e3, 0, 0) along vessel x = global y.
  const Vec6 f3 = drift(2.0, 0.5 * kPi, rotZ(0.5 * kPi));
  EXPECT_NEAR(f3(1), 5.0e3 * 4.0, 1e-9 * 2e4);
  EXPECT_NEAR(f3(0), 0.0, 1e-8);
}

// ---------------------------------------------------------------------------------------------
// Mass matrix
// ---------------------------------------------------------------------------------------------

// Source: M(R) = blockdiag(m I + R A_t R^T, R (I + A_r) R^T): symmetric, eigenvalues (invariants) m + A_ii
// and I_ii + A_ii, and R-covariant. Tolerance 1e-12 relative (rounding of 3x3 products).
TEST(VesselLoads, MassMatrixRotatesWithTheVessel) {
  const VesselLoads loads(vesselSpec(), environment());
  const Mat3 r = rotZ(0.8) * rotY(0.1) * rotX(-0.2);
  const Mat6 m = loads.massMatrix(r);
  EXPECT_LT((m - m.transpose()).norm(), 1e-12 * m.norm());
  const Mat3 coupling = m.block<3, 3>(0, 3);
  EXPECT_LT(coupling.norm(), 1e-12);
  Eigen::SelfAdjointEigenSolver<Mat3> et(m.block<3, 3>(0, 0));
  Eigen::SelfAdjointEigenSolver<Mat3> er(m.block<3, 3>(3, 3));
  const Vec3 expectedT(2.2e8, 3.0e8, 3.5e8);
  const Vec3 expectedR(1.3e11, 2.9e12, 3.0e12);
  EXPECT_LT((et.eigenvalues() - expectedT).norm(), 1e-12 * expectedT.norm());
  EXPECT_LT((er.eigenvalues() - expectedR).norm(), 1e-12 * expectedR.norm());
  const Mat3 rotational = m.block<3, 3>(3, 3);
  EXPECT_NEAR(rotational.trace(), expectedR.sum(), 1e-12 * expectedR.sum());
  // Covariance: the vessel-axis mass matrix is recovered by R^T M R.
  const Mat3 body = r.transpose() * m.block<3, 3>(3, 3) * r;
  EXPECT_NEAR(body(0, 0), 1.3e11, 1e-12 * 3e12);
  EXPECT_NEAR(body(1, 1), 3.0e12, 1e-12 * 3e12);
  EXPECT_NEAR(body(2, 2), 2.9e12, 1e-12 * 3e12);
  EXPECT_NEAR(body(0, 1), 0.0, 1e-12 * 3e12);
}

TEST(VesselLoads, RejectsInvalidInput) {
  model::VesselSpec spec = vesselSpec();
  spec.mass = -1.0;
  EXPECT_THROW(VesselLoads(spec, environment()), Error);
  spec = vesselSpec();
  std::swap(spec.currentCoefficients.heading[0], spec.currentCoefficients.heading[1]);
  EXPECT_THROW(VesselLoads(spec, environment()), Error);
  spec = vesselSpec();
  spec.quadraticDamping[2] = -5.0;
  EXPECT_THROW(VesselLoads(spec, environment()), Error);
}

}  // namespace
}  // namespace tangle::vessel

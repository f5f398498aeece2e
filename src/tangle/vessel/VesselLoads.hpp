#pragma once
/// @file VesselLoads.hpp
/// Loads on a free-floating vessel (6-DOF rigid body) in global axes about its reference point:
/// hydrostatic restoring, linear + quadratic damping, current and wind drag (OCIMF-style coefficient
/// tables), mean wave drift; and the 6x6 mass matrix. Equations and references: docs/theory.md (section 10).
///
/// Conventions. Global axes right-handed, z up. Vessel axes: x forward, y to port, z up, origin at the
/// reference point; `rotation` R maps vessel axes to global axes (v_global = R v_vessel). Rotation
/// increments are spatial (global) rotation vectors, R <- exp(dtheta) R (geometry/Rotation.hpp), so the
/// rotational columns of `stiffness` are derivatives with respect to such global increments.
/// A relative heading is the direction a flow travels TOWARDS, measured in vessel axes anticlockwise
/// (about vessel z) from the vessel x axis, in [0, 2 pi): 0 = flow from stern to bow (towards the bow),
/// pi/2 = flow from starboard towards port. Table coefficients act in vessel axes with positive values
/// pushing the vessel along +x_vessel, +y_vessel and turning it anticlockwise about +z_vessel: a flow
/// towards +x_vessel (heading 0) with Cx(0) = +1 gives a force along +x_vessel.
///
/// Not included for a floating unit: its weight and its buoyancy at the initial position (they balance each
/// other there; only the hydrostatic restoring about that equilibrium is modelled). A submerged body
/// (VesselSpec::displacedVolume) carries both: its weight at the reference point, its buoyancy at the centre
/// of buoyancy. Not included either: a centre-of-gravity offset (mass and inertia act about the reference
/// point), gyroscopic terms
/// omega x (I omega) (left to the integrator/assembler), wave-frequency (first-order) loads (the
/// first-order motion is superposed with RaoMotion instead).

#include <array>
#include <string>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::vessel {

/// Loads on the vessel and their derivatives, global axes, about the reference point.
struct BodyLoad {
  /// (Fx, Fy, Fz, Mx, My, Mz) acting ON the vessel [N, N m], global axes, about the reference point.
  Vec6 force = Vec6::Zero();
  /// -d(force)/d(x, y, z, dtheta_x, dtheta_y, dtheta_z) [N/m, N/rad; N m/m, N m/rad], dtheta the global
  /// rotation increment. Contains: hydrostatic heave/roll/pitch stiffness (exact derivative of the
  /// restoring model, including the tilt-dependent and "rotated moment" terms), and the rotation
  /// dependence of current, wind and drift loads (weathervaning stiffness, exact). Omitted: the rotation
  /// dependence of the damping forces (the damping force is rotated with the vessel; its derivative in
  /// dtheta is proportional to velocity x angle and is dropped). Not symmetric in general.
  Mat6 stiffness = Mat6::Zero();
  /// -d(force)/d(vx, vy, vz, wx, wy, wz) [N s/m, N s/rad; N m s/m, N m s/rad]: linear damping, linearised
  /// quadratic damping, linearised current and wind drag (exact derivatives of the models below).
  Mat6 damping = Mat6::Zero();
};

/// Environmental and damping loads on one free vessel. Immutable after construction, thread-safe.
class VesselLoads {
 public:
  /// Copies the data it needs. Tables that are empty are treated as zero loads; non-empty tables must be
  /// valid (vessel/HeadingTable.hpp). @throws tangle::Error on invalid tables, negative mass, inertia,
  /// areas, densities or damping coefficients (the message names the vessel and the field).
  VesselLoads(const model::VesselSpec& vessel, const model::EnvironmentSpec& environment);

  /// Loads on the vessel in the given state.
  /// @param position reference point [m], global
  /// @param rotation vessel-to-global rotation matrix [-]
  /// @param velocity (vx, vy, vz, wx, wy, wz) of the reference point, global [m/s, rad/s]
  /// @param initialPosition reference point at the hydrostatic equilibrium [m] (heave restoring about z0)
  /// @param initialRotation orientation at the hydrostatic equilibrium [-] (roll/pitch restoring about it)
  /// @param currentVelocity current velocity at the surface, global [m/s] (only x, y are used)
  /// @param waveAmplitude regular-wave amplitude H/2 [m] (mean drift only; a sea of several components or
  ///        directions: 0 here and addWaveDrift for each direction)
  /// @param waveAzimuth direction the waves travel towards, anticlockwise from global +x [rad]
  /// @param ramp factor in [0, 1] multiplying the environmental loads (current, wind, drift) and their
  ///        derivatives; hydrostatics and damping are never ramped
  ///
  /// Models (docs/theory.md (section 10)):
  /// - hydrostatics (Faltinsen 1990, "Sea loads on ships and offshore structures", ch. 2):
  ///   F_z = -K33 (z - z0); with n = R^T R0 e_z (the initial "up" seen in vessel axes) the tilt vector in
  ///   vessel axes is theta_b = atan2(s, n_z) / s (n_y, -n_x, 0), s = |(n_x, n_y)| (roll, pitch; = the
  ///   rotation vector of R0^T R when there is no yaw change, but free of yaw-roll mixing for a vessel
  ///   that has yawed); M = R (-K44 theta_b,x, -K55 theta_b,y, 0).
  /// - damping on the body velocity, per DOF in vessel axes (v_b = R^T v, w_b = R^T w):
  ///   F_b,i = -B1_i v_b,i - B2_i |v_b,i| v_b,i, rotated to global. It is NOT relative to the current:
  ///   current drag is applied with the relative velocity instead (practice of OrcaFlex and SIMA).
  /// - current drag (OCIMF 1994, "Prediction of wind and current loads on VLCCs", 2nd ed.):
  ///   u = current - vessel velocity (horizontal), u_b = R^T u, V^2 = u_bx^2 + u_by^2,
  ///   beta = atan2(u_by, u_bx); F_x = 1/2 rho V^2 Cx(beta) A_x, F_y = 1/2 rho V^2 Cy(beta) A_y,
  ///   M_z = 1/2 rho V^2 Cmz(beta) A_y L, in vessel axes, rotated to global. Yaw rate is neglected.
  /// - wind: same form with the air density, the wind from EnvironmentSpec (speed, azimuth), windAreas
  ///   and windCoefficients; the relative wind (wind - vessel velocity) is used (aerodynamic damping).
  /// - a submerged body's weight -M g e_z at the reference point and buoyancy rho g V e_z at r_b = R c_b
  ///   (VesselSpec::centreOfBuoyancy), constant: moment r_b x F_b, whose derivative in the rotation increment
  ///   gives the stiffness (r_b . F_b) I - r_b F_b^T (a pendulum's restoring, exact).
  /// - mean wave drift (Faltinsen 1990, ch. 5: proportional to the amplitude squared):
  ///   (F_x, F_y, M_z) = waveDrift(beta_w) * a^2 in vessel axes, beta_w = direction of wave travel in
  ///   vessel axes (azimuth - vessel yaw), rotated to global.
  BodyLoad loads(const Vec3& position, const Mat3& rotation, const Vec6& velocity, const Vec3& initialPosition,
                 const Mat3& initialRotation, const Vec3& currentVelocity, double waveAmplitude, double waveAzimuth,
                 double ramp) const;

  /// Adds the mean wave drift of the waves travelling towards `waveAzimuth` [rad] (anticlockwise from global
  /// +x) to `out`: (F_x, F_y, M_z) = waveDrift(beta_w) A in vessel axes, beta_w = waveAzimuth - vessel yaw,
  /// rotated to global (force [N], moment [N m]), with its derivative in the vessel's rotation; times `ramp`.
  /// A = `amplitudeSquared` [m^2]: a^2 of a regular wave; of a sea of components of amplitudes a_i the sum of
  /// a_i^2 over those travelling that way, and of a spectrum 2 m0 = Hs^2 / 8 (the mean of a sum of regular
  /// waves' second-order forces: Faltinsen 1990, ch. 5, F = 2 int S(omega) D(omega) d omega).
  void addWaveDrift(BodyLoad& out, const Mat3& rotation, double amplitudeSquared, double waveAzimuth,
                    double ramp) const;

  /// 6x6 mass matrix [kg, kg m^2] in global axes: translational m I + R diag(A11, A22, A33) R^T, rotational
  /// R diag(I44 + A44, I55 + A55, I66 + A66) R^T, no translation-rotation coupling (no centre-of-gravity
  /// offset in VesselSpec: the inertia is about the reference point). @param rotation vessel-to-global.
  Mat6 massMatrix(const Mat3& rotation) const;

 private:
  std::string m_name;
  double m_mass;
  Vec3 m_inertia;
  std::array<double, 6> m_addedMass;
  std::array<double, 6> m_linearDamping;
  std::array<double, 6> m_quadraticDamping;
  std::array<double, 6> m_hydrostatic;
  model::HeadingTable m_currentCoefficients;
  Vec3 m_currentScale;  // 1/2 rho_w (A_x, A_y, A_y L) [kg/m]
  model::HeadingTable m_windCoefficients;
  Vec3 m_windScale;     // 1/2 rho_a (A_x, A_y, A_y L) [kg/m]
  Vec3 m_windVelocity;  // global [m/s]
  model::HeadingTable m_waveDrift;
  double m_weight = 0.0;                   // a submerged body's M g [N] (0: a floating unit)
  double m_buoyancy = 0.0;                 // and its rho g V [N]
  Vec3 m_centreOfBuoyancy = Vec3::Zero();  // vessel axes [m]
};

}  // namespace tangle::vessel

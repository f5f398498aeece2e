#pragma once
/// @file RaoMotion.hpp
/// First-order (wave-frequency) vessel motion from response amplitude operators (RAOs), superposed on
/// the vessel's own (solved or prescribed) motion. Linear superposition of the responses to the wave
/// components of the sea (Faltinsen 1990, "Sea loads on ships and offshore structures", ch. 3;
/// Newman 1977, "Marine hydrodynamics", ch. 6). Equations: docs/theory.md (section 10).
///
/// Conventions.
/// - Wave component i: the motion formula uses the phase psi_i of the brief's contract,
///   motion_j = a_i |RAO_j| cos(omega_i t - k_i (x cos b_i + y sin b_i) + psi_i - lag_j).
///   The wave elevation it responds to is eta_i = a_i cos(omega_i t - k_i X + psi_i), so for a wave
///   written as in hydro::AiryWave / hydro::WaveComponent, eta = a cos(k X - omega t + phase),
///   psi_i = -phase (NEGATE the hydro phase when building a Component).
/// - Relative wave heading: the direction the wave travels TOWARDS in vessel axes, anticlockwise from the
///   vessel x axis: beta_i = b_i - vesselHeading, wrapped into [0, 2 pi) (0: waves travelling from stern
///   to bow, "following sea"; pi: head sea; pi/2: waves travelling towards port, from starboard).
/// - Phase LAG (OrcaFlex convention): with the formula above, the motion reaches its positive maximum
///   lag_j / omega_i seconds after the wave crest passes the reference point. With lag 0 the motion is
///   in phase with the elevation at the reference point.
/// - RAO units: surge, sway, heave [m/m]; roll, pitch, yaw [rad/m]; in vessel axes (x forward, y port,
///   z up; rotations right-handed about them); results are rotated to global axes with Rz(vesselHeading).
///
/// Interpolation of the RAO table: linear in wave period T = 2 pi / omega and periodic-linear in relative
/// heading (wrap-around between the last and the first heading), amplitude and phase lag interpolated
/// separately, the phase difference taken as the shortest angle (wrapped into (-pi, pi]) so that phases
/// near +-pi do not interpolate through 0. Outside the period range the nearest period is used (clamp).
/// Approximations: the vessel heading is fixed (the RAO heading is not updated as the vessel yaws);
/// the ramp is treated as a constant factor in the time derivatives; rotations are small angles.

#include <array>
#include <cstddef>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::vessel {

/// Wave-frequency motion of a vessel from RAOs. Immutable after construction, thread-safe.
class RaoMotion {
 public:
  /// One linear wave component: eta = amplitude cos(omega t - waveNumber (x cos azimuth + y sin azimuth) + phase).
  struct Component {
    double amplitude;   ///< a_i [m] (H/2 for a regular wave)
    double omega;       ///< angular frequency [rad/s], > 0
    double waveNumber;  ///< k_i [rad/m]
    double azimuth;     ///< direction of travel, anticlockwise from global +x [rad]
    double phase;       ///< psi_i [rad] in cos(omega t - k X + psi): = MINUS the hydro::AiryWave / WaveComponent phase
  };

  /// Motion of the reference point: (x, y, z) [m], (rx, ry, rz) small rotation angles [rad]; global axes.
  struct Motion {
    Vec6 displacement = Vec6::Zero();  ///< [m, rad]
    Vec6 velocity = Vec6::Zero();      ///< [m/s, rad/s]
    Vec6 acceleration = Vec6::Zero();  ///< [m/s^2, rad/s^2]
  };

  /// @param raos RAO table; a completely empty table (no periods, headings, amplitudes) means no motion
  /// @param vesselHeading heading of the vessel x axis, anticlockwise from global +x [rad]
  /// @param components the wave components of the sea (one for a regular Airy wave)
  /// @throws tangle::Error on an inconsistent table (sizes, unsorted or non-positive periods, headings not
  ///         strictly ascending in [0, 2 pi), non-finite values) or an invalid component (omega <= 0,
  ///         amplitude < 0)
  RaoMotion(const model::RaoTable& raos, double vesselHeading, std::vector<Component> components);

  /// Motion at time t [s] of the vessel whose reference point is at referencePoint [m] (only x, y are used,
  /// for the wave phase), multiplied by ramp [-]:
  ///   q_j = ramp sum_i a_i |RAO_j(T_i, beta_i)| cos(theta_i - lag_j(T_i, beta_i)),
  ///   dq_j/dt = -ramp sum_i a_i omega_i |RAO_j| sin(theta_i - lag_j),  d2q_j/dt2 = -ramp sum_i omega_i^2
  ///   (...),
  /// per DOF j in vessel axes, then translations and rotation vectors rotated to global.
  Motion at(double t, const Vec3& referencePoint, double ramp) const;

  /// RAO of one component: amplitude per unit wave amplitude [m/m, rad/m] and phase lag [rad] per DOF,
  /// interpolated at period [s] and relative heading [rad] (for tests and output).
  void interpolateRao(double period, double relativeHeading, std::array<double, 6>& amplitude,
                      std::array<double, 6>& phaseLag) const;

  /// Displacement of a point at offset r (vessel axes) from the reference point, first order:
  /// u_p = u + theta x (R r) [m]. @param rotation vessel-to-global rotation R of the (mean) vessel.
  static Vec3 pointDisplacement(const Motion& m, const Mat3& rotation, const Vec3& offset);
  /// Velocity of the point, first order: v_p = v + omega x (R r) [m/s].
  static Vec3 pointVelocity(const Motion& m, const Mat3& rotation, const Vec3& offset);
  /// Acceleration of the point, first order: a_p = a + alpha x (R r) [m/s^2] (the centripetal term
  /// omega x (omega x R r) is second order in the wave amplitude and dropped).
  static Vec3 pointAcceleration(const Motion& m, const Mat3& rotation, const Vec3& offset);

  /// Number of wave components [-].
  std::size_t componentCount() const { return m_components.size(); }

 private:
  struct ComponentResponse {
    double amplitude;       // a_i [m]
    double omega;           // [rad/s]
    double kx;              // k_i cos(b_i) [rad/m]
    double ky;              // k_i sin(b_i) [rad/m]
    double phase;           // psi_i [rad]
    std::array<double, 6> rao;  // |RAO_j| [m/m, rad/m]
    std::array<double, 6> lag;  // lag_j [rad]
  };

  model::RaoTable m_raos;
  bool m_empty;
  Mat3 m_rotation;  // Rz(vesselHeading)
  std::vector<Component> m_components;
  std::vector<ComponentResponse> m_responses;
};

}  // namespace tangle::vessel

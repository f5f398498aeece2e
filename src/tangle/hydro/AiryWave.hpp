#pragma once
/// @file AiryWave.hpp
/// Regular linear (Airy) wave in water of finite depth, plus the linear dispersion relation and the
/// depth-attenuation functions shared by the linear wave models.
/// Formulas: Dean & Dalrymple (1991), "Water wave mechanics for engineers and scientists", ch. 3-4;
/// DNV-RP-C205 (2010), sec. 3.2 (linear wave theory) and 3.3 (wave kinematics).

#include "tangle/core/Units.hpp"
#include "tangle/hydro/WaveField.hpp"

namespace tangle::hydro {

/// Wave number k [rad/m] solving the linear dispersion relation omega^2 = g k tanh(k h) exactly
/// (Newton iteration on y tanh y = omega^2 h / g, y = k h, to machine precision), starting from the
/// explicit approximation of Fenton & McKee (1990), "On calculating the lengths of water waves",
/// Coastal Engineering 14:499-513: k h ~ (omega^2 h/g) coth((omega^2 h/g)^(3/4))^(2/3)
/// (max. relative error ~1.5 %).
/// @param omega angular frequency [rad/s], > 0
/// @param depth water depth h [m], > 0 and finite
/// @param gravity g [m/s^2], > 0
/// @throws tangle::Error on invalid arguments
double solveDispersion(double omega, double depth, double gravity = kStandardGravity);

/// Depth-attenuation ratios of linear wave theory at a (stretched) level z' in [-h, 0].
struct DepthAttenuation {
  double horizontal;  ///< cosh(k (z' + h)) / sinh(k h) [-]
  double vertical;    ///< sinh(k (z' + h)) / sinh(k h) [-]
};

/// Depth attenuation at level zPrime [m] (clamped to [-h, 0]) for wave number k [rad/m] and depth h [m].
/// Evaluated in exponential form, exact and overflow-free for any k h (deep water included):
/// cosh(k(z+h))/sinh(kh) = e^{kz} (1 + e^{-2k(z+h)}) / (1 - e^{-2kh}),
/// sinh(k(z+h))/sinh(kh) = e^{kz} (1 - e^{-2k(z+h)}) / (1 - e^{-2kh}), with 1 - e^{-x} = -expm1(-x).
DepthAttenuation depthAttenuation(double k, double zPrime, double depth);

/// depthAttenuation times (1 - e^{-2kh}), for sums over components that fold that constant into their scales:
/// horizontal e^{kz'} (1 + e^{-2k(z'+h)}), vertical e^{kz'} (1 - e^{-2k(z'+h)}) at zPrime [m] with
/// heightAboveSeabed = z' + h >= 0 [m]; the seabed image term e^{-2k(z'+h)} is left out where it is below
/// half an ulp of 1 (2 k (z' + h) >= 40: deep-water short components). JonswapSea and ComponentSea.
DepthAttenuation unscaledAttenuation(double k, double zPrime, double heightAboveSeabed);

/// Level z' [m] in [-h, 0] at which the linear profile is evaluated for a point at z [m] under a
/// surface elevation eta [m], water depth h [m]; z is first clamped to >= -h. The point must be wet
/// (z <= eta). Wheeler (1970), "Method for calculating forces produced by irregular waves",
/// J. Petroleum Technology 22(3):359-367: z' = h (z - eta) / (h + eta). Vertical: z' = min(z, 0).
double stretchedLevel(double z, double eta, double depth, Stretching stretching);

/// Regular linear (Airy) wave of height H travelling towards azimuth beta in water of depth h:
///   eta = H/2 cos(theta),  theta = k (x cos(beta) + y sin(beta)) - omega t + phase,
///   u_h = (H/2) omega cosh(k(z'+h))/sinh(kh) cos(theta)    (along the direction of travel),
///   w   = (H/2) omega sinh(k(z'+h))/sinh(kh) sin(theta),
///   du_h/dt =  (H/2) omega^2 cosh(k(z'+h))/sinh(kh) sin(theta),
///   dw/dt   = -(H/2) omega^2 sinh(k(z'+h))/sinh(kh) cos(theta),
/// (Dean & Dalrymple 1991, ch. 3-4; DNV-RP-C205 2010, sec. 3.2), z' the stretched level (Wheeler by
/// default; DNV-RP-C205 2010, sec. 3.3).
/// Immutable, thread-safe.
class AiryWave final : public WaveField {
 public:
  /// @param height wave height H (crest to trough) [m], >= 0 and H/2 < depth
  /// @param period wave period T [s], > 0
  /// @param azimuth direction of travel, anticlockwise from +x [rad]
  /// @param waterDepth h [m], > 0
  /// @param gravity g [m/s^2], > 0
  /// @param phase phase angle in theta [rad] (eta(0,0,0) = H/2 cos(phase))
  /// @param stretching kinematics above/below mean level (Wheeler by default)
  /// @throws tangle::Error on invalid arguments
  AiryWave(double height, double period, double azimuth, double waterDepth, double gravity = kStandardGravity,
           double phase = 0.0, Stretching stretching = Stretching::Wheeler);

  /// Free-surface elevation eta = H/2 cos(theta) [m].
  double elevation(double x, double y, double t) const override;
  /// Velocity [m/s] and local acceleration [m/s^2] (formulas in the class comment); zero above the surface.
  FluidKinematics kinematics(const Vec3& p, double t) const override;
  FluidKinematics kinematics(const Vec3& p, double t, double& elevation) const override;

  double height() const { return m_height; }              ///< H [m]
  double period() const { return m_period; }              ///< T [s]
  double azimuth() const { return m_azimuth; }            ///< direction of travel [rad]
  double waterDepth() const { return m_depth; }           ///< h [m]
  double gravity() const { return m_gravity; }            ///< g [m/s^2]
  double phase() const { return m_phase; }                ///< phase [rad]
  Stretching stretching() const { return m_stretching; }  ///< stretching method
  double angularFrequency() const { return m_omega; }     ///< omega = 2 pi / T [rad/s]
  double waveNumber() const { return m_k; }               ///< k [rad/m] (dispersion relation)
  double wavelength() const { return 2.0 * kPi / m_k; }   ///< L = 2 pi / k [m]
  double phaseSpeed() const { return m_omega / m_k; }     ///< c = omega / k [m/s]

 private:
  double phaseAngle(double x, double y, double t) const;

  double m_height;
  double m_period;
  double m_azimuth;
  double m_depth;
  double m_gravity;
  double m_phase;
  Stretching m_stretching;
  double m_omega;
  double m_k;
  double m_attenuationScale;  // 1 / (1 - e^{-2kh}) [-] (depthAttenuation's denominator)
  double m_cosAzimuth;
  double m_sinAzimuth;
};

}  // namespace tangle::hydro

#pragma once
/// @file JonswapSea.hpp
/// Irregular long-crested sea: a sum of linear (Airy) components whose amplitudes follow a JONSWAP
/// spectrum, with repeatable random phases (and, by default, random frequencies within their bins).
/// Spectrum: DNV-RP-C205 (2010), "Environmental conditions and environmental loads", sec. 3.5.5.
/// Random-phase synthesis: e.g. Tucker, Challenor & Carter (1984), "Numerical simulation of a random
/// sea: a common error and its effect upon wave group statistics", Applied Ocean Research 6(2):118-122.

#include <cstdint>
#include <vector>

#include "tangle/core/Units.hpp"
#include "tangle/hydro/WaveField.hpp"

namespace tangle::hydro {

/// One linear component of an irregular sea:
/// eta_i = a_i cos(k_i (x cos(beta) + y sin(beta)) - omega_i t + phase_i).
struct WaveComponent {
  double omega = 0.0;       ///< angular frequency omega_i [rad/s]
  double waveNumber = 0.0;  ///< k_i [rad/m] from the finite-depth dispersion relation
  double amplitude = 0.0;   ///< a_i = sqrt(2 S(omega_i) d_omega) [m]
  double phase = 0.0;       ///< phase_i, uniform in [0, 2 pi) [rad]
};

/// Irregular long-crested sea from a JONSWAP spectrum (DNV-RP-C205 2010, sec. 3.5.5):
///   S(omega) = A_gamma S_PM(omega) gamma^exp(-0.5 ((omega - omega_p) / (sigma omega_p))^2),
///   S_PM(omega) = 5/16 Hs^2 omega_p^4 omega^-5 exp(-5/4 (omega/omega_p)^-4),
///   A_gamma = 1 - 0.287 ln(gamma), omega_p = 2 pi / Tp, sigma = 0.07 (omega <= omega_p), 0.09 otherwise.
/// The band [omegaMin, omegaMax] = [minFrequencyFactor, maxFrequencyFactor] * omega_p is split into N
/// equal bins of width d_omega; component i has frequency omega_i = omegaMin + (i + u_i) d_omega with
/// u_i uniform in [0, 1) when randomFrequencies (the record then never repeats exactly) or u_i = 1/2
/// otherwise (the record repeats every 2 pi / d_omega), amplitude a_i = sqrt(2 S(omega_i) d_omega)
/// (deterministic amplitudes) and a uniform random phase. Random numbers come from std::mt19937_64
/// seeded with `seed`, converted to doubles by the top 53 bits (independent of the standard library):
/// the first N draws are the phases, the next N the in-bin offsets. The kinematics are the sum of the
/// component kinematics (AiryWave.hpp), all evaluated at the stretched level of the total elevation
/// (Wheeler 1970 by default). Immutable, thread-safe.
class JonswapSea final : public WaveField {
 public:
  /// Construction parameters (designated initialisers recommended).
  struct Parameters {
    double significantHeight = 0.0;     ///< Hs [m], > 0
    double peakPeriod = 0.0;            ///< Tp [s], > 0
    double gamma = 3.3;                 ///< peak enhancement factor [-], in [1, 10] (DNV: usually 1-7)
    double azimuth = 0.0;               ///< direction of travel, anticlockwise from +x [rad]
    double waterDepth = 0.0;            ///< h [m], > 0
    double gravity = kStandardGravity;  ///< g [m/s^2]
    int componentCount = 100;           ///< N, number of components, >= 1
    std::uint64_t seed = 1;             ///< seed of std::mt19937_64 (same seed -> identical sea)
    double minFrequencyFactor = 0.5;    ///< omegaMin / omega_p [-], > 0
    double maxFrequencyFactor = 3.0;    ///< omegaMax / omega_p [-], > minFrequencyFactor
    bool randomFrequencies = true;      ///< random frequency within each bin (no repetition period)
    Stretching stretching = Stretching::Wheeler;  ///< kinematics up to the instantaneous surface
  };

  /// Builds the components. @throws tangle::Error on invalid parameters (message names the field).
  explicit JonswapSea(const Parameters& parameters);

  /// Free-surface elevation eta = sum_i a_i cos(theta_i) [m].
  double elevation(double x, double y, double t) const override;
  /// Sum of the component kinematics at the stretched level; zero above the surface.
  /// Cost: one sin/cos pair, one exp and one expm1 per component.
  FluidKinematics kinematics(const Vec3& p, double t) const override;
  FluidKinematics kinematics(const Vec3& p, double t, double& elevation) const override;

  /// Target JONSWAP spectral density S(omega) [m^2 s / rad], one-sided, in angular frequency omega [rad/s];
  /// 0 for omega <= 0.
  double spectralDensity(double omega) const;
  /// Variance of the synthesised elevation, sum_i a_i^2 / 2 [m^2] (the discretised m0).
  double componentVariance() const;
  /// The components (a copy; for output and tests).
  std::vector<WaveComponent> components() const;

  const Parameters& parameters() const { return m_parameters; }  ///< the construction parameters
  double peakFrequency() const { return m_omegaPeak; }           ///< omega_p = 2 pi / Tp [rad/s]
  double frequencyStep() const { return m_dOmega; }              ///< bin width d_omega [rad/s]
  /// A_gamma = 1 - 0.287 ln(gamma), DNV-RP-C205 (2010) sec. 3.5.5 [-].
  double normalisingFactor() const { return m_aGamma; }

 private:
  double phaseOffset(double x, double y) const;

  Parameters m_parameters;
  double m_omegaPeak;
  double m_dOmega;
  double m_aGamma;
  double m_cosAzimuth;
  double m_sinAzimuth;
  // Components, structure of arrays for the hot loops.
  std::vector<double> m_omega;              // omega_i [rad/s]
  std::vector<double> m_k;                  // k_i [rad/m]
  std::vector<double> m_amplitude;          // a_i [m]
  std::vector<double> m_phase;              // phase_i [rad]
  std::vector<double> m_velocityScale;      // a_i omega_i / (1 - e^{-2 k_i h}) [m/s]
  std::vector<double> m_accelerationScale;  // a_i omega_i^2 / (1 - e^{-2 k_i h}) [m/s^2]
};

}  // namespace tangle::hydro

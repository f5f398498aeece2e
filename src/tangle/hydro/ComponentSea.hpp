#pragma once
/// @file ComponentSea.hpp
/// A sea given as its linear (Airy) components, each with its own period, amplitude, phase and direction
/// (`environment.waves.type: components`): a measured or design spectrum's components, a short-crested sea,
/// a record's Fourier series, MoorDyn's wave_frequencies.txt (WaveKin 7). The same kinematics as JonswapSea
/// (Wheeler stretching by default), summed over components of any direction.

#include <vector>

#include "tangle/core/Units.hpp"
#include "tangle/hydro/WaveField.hpp"

namespace tangle::hydro {

/// A sum of linear components:
///   eta = sum_i a_i cos(theta_i),  theta_i = k_i (x cos(beta_i) + y sin(beta_i)) - omega_i t + phase_i,
/// k_i from the finite-depth dispersion relation; the velocity and acceleration of each along its own
/// direction of travel beta_i (AiryWave.hpp's formulas), all at the stretched level of the total elevation.
/// Immutable, thread-safe.
class ComponentSea final : public WaveField {
 public:
  /// One component as given.
  struct Component {
    double omega = 0.0;      ///< angular frequency [rad/s], > 0
    double amplitude = 0.0;  ///< a_i [m], >= 0
    double phase = 0.0;      ///< phase_i [rad]: eta_i(0, 0, 0) = a_i cos(phase_i)
    double azimuth = 0.0;    ///< direction of travel beta_i, anticlockwise from +x [rad]
  };

  /// @throws tangle::Error for an empty list or a component out of range (message names it).
  ComponentSea(std::vector<Component> components, double waterDepth, double gravity = kStandardGravity,
               Stretching stretching = Stretching::Wheeler);

  double elevation(double x, double y, double t) const override;
  FluidKinematics kinematics(const Vec3& p, double t) const override;
  FluidKinematics kinematics(const Vec3& p, double t, double& elevation) const override;

  const std::vector<Component>& components() const { return m_components; }
  /// Wave number k_i of component i [rad/m].
  double waveNumber(std::size_t i) const { return m_k[i]; }
  /// Variance of the elevation, sum_i a_i^2 / 2 [m^2] (m0; Hs = 4 sqrt(m0)).
  double variance() const;

 private:
  std::vector<Component> m_components;
  double m_depth;
  Stretching m_stretching;
  std::vector<double> m_k, m_cos, m_sin;                     // k_i [rad/m], cos and sin of beta_i
  std::vector<double> m_velocityScale, m_accelerationScale;  // a omega / (1 - e^{-2kh}), a omega^2 / (...)
};

}  // namespace tangle::hydro

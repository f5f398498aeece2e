/// @file JonswapSea.cpp
/// Irregular sea from a JONSWAP spectrum (formulas in JonswapSea.hpp).

#include "tangle/hydro/JonswapSea.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "tangle/core/Error.hpp"
#include "tangle/hydro/AiryWave.hpp"

namespace tangle::hydro {

namespace {

void require(bool ok, const char* what, const char* requirement, double value) {
  if (ok) return;
  std::ostringstream os;
  os.precision(17);
  os << "JonswapSea: " << what << " must be " << requirement << " (got " << value << ")";
  throw Error(os.str());
}

/// Uniform double in [0, 1) from the top 53 bits of one engine output (portable, unlike
/// std::uniform_real_distribution whose algorithm is left to the library).
double uniform01(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

}  // namespace

JonswapSea::JonswapSea(const Parameters& parameters) : m_parameters(parameters) {
  const Parameters& p = parameters;
  require(std::isfinite(p.significantHeight) && p.significantHeight > 0.0, "significantHeight [m]",
          "finite and > 0", p.significantHeight);
  require(std::isfinite(p.peakPeriod) && p.peakPeriod > 0.0, "peakPeriod [s]", "finite and > 0",
          p.peakPeriod);
  require(p.gamma >= 1.0 && p.gamma <= 10.0, "gamma [-]", "in [1, 10]", p.gamma);
  require(std::isfinite(p.azimuth), "azimuth [rad]", "finite", p.azimuth);
  require(std::isfinite(p.waterDepth) && p.waterDepth > 0.0, "waterDepth [m]", "finite and > 0",
          p.waterDepth);
  require(std::isfinite(p.gravity) && p.gravity > 0.0, "gravity [m/s^2]", "finite and > 0", p.gravity);
  require(p.componentCount >= 1 && p.componentCount <= 100000, "componentCount", "in [1, 100000]",
          p.componentCount);
  require(std::isfinite(p.minFrequencyFactor) && p.minFrequencyFactor > 0.0, "minFrequencyFactor [-]",
          "finite and > 0", p.minFrequencyFactor);
  require(std::isfinite(p.maxFrequencyFactor) && p.maxFrequencyFactor > p.minFrequencyFactor,
          "maxFrequencyFactor [-]", "finite and > minFrequencyFactor", p.maxFrequencyFactor);

  m_omegaPeak = 2.0 * kPi / p.peakPeriod;
  m_aGamma = 1.0 - 0.287 * std::log(p.gamma);
  m_cosAzimuth = std::cos(p.azimuth);
  m_sinAzimuth = std::sin(p.azimuth);
  const double omegaMin = p.minFrequencyFactor * m_omegaPeak;
  const double omegaMax = p.maxFrequencyFactor * m_omegaPeak;
  const auto n = static_cast<std::size_t>(p.componentCount);
  m_dOmega = (omegaMax - omegaMin) / static_cast<double>(n);

  std::mt19937_64 engine(p.seed);
  m_phase.resize(n);
  for (std::size_t i = 0; i < n; ++i) m_phase[i] = 2.0 * kPi * uniform01(engine);
  std::vector<double> offset(n, 0.5);
  if (p.randomFrequencies) {
    for (std::size_t i = 0; i < n; ++i) offset[i] = uniform01(engine);
  }

  m_omega.resize(n);
  m_k.resize(n);
  m_amplitude.resize(n);
  m_velocityScale.resize(n);
  m_accelerationScale.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double omega = omegaMin + (static_cast<double>(i) + offset[i]) * m_dOmega;
    const double k = solveDispersion(omega, p.waterDepth, p.gravity);
    const double a = std::sqrt(2.0 * spectralDensity(omega) * m_dOmega);
    const double inverseDenominator = -1.0 / std::expm1(-2.0 * k * p.waterDepth);  // 1/(1 - e^{-2kh})
    m_omega[i] = omega;
    m_k[i] = k;
    m_amplitude[i] = a;
    m_velocityScale[i] = a * omega * inverseDenominator;
    m_accelerationScale[i] = a * omega * omega * inverseDenominator;
  }
}

double JonswapSea::spectralDensity(double omega) const {
  // Below omega_p / 6 the factor exp(-5/4 (omega_p/omega)^4) < e^-1620 underflows to 0 anyway; the
  // early return only avoids inf * 0 for omega -> 0.
  if (!(omega > m_omegaPeak / 6.0)) return 0.0;
  const double hs = m_parameters.significantHeight;
  const double r = m_omegaPeak / omega;  // omega_p / omega
  const double r4 = r * r * r * r;
  const double pm = 5.0 / 16.0 * hs * hs * r4 * r / m_omegaPeak * std::exp(-1.25 * r4);
  const double sigma = omega <= m_omegaPeak ? 0.07 : 0.09;
  const double q = (omega - m_omegaPeak) / (sigma * m_omegaPeak);
  return m_aGamma * pm * std::pow(m_parameters.gamma, std::exp(-0.5 * q * q));
}

double JonswapSea::componentVariance() const {
  double sum = 0.0;
  for (double a : m_amplitude) sum += 0.5 * a * a;
  return sum;
}

std::vector<WaveComponent> JonswapSea::components() const {
  std::vector<WaveComponent> result(m_omega.size());
  for (std::size_t i = 0; i < result.size(); ++i) {
    result[i] = WaveComponent{m_omega[i], m_k[i], m_amplitude[i], m_phase[i]};
  }
  return result;
}

double JonswapSea::phaseOffset(double x, double y) const { return x * m_cosAzimuth + y * m_sinAzimuth; }

double JonswapSea::elevation(double x, double y, double t) const {
  const double s = phaseOffset(x, y);
  double eta = 0.0;
  for (std::size_t i = 0; i < m_omega.size(); ++i) {
    eta += m_amplitude[i] * std::cos(m_k[i] * s - m_omega[i] * t + m_phase[i]);
  }
  return eta;
}

FluidKinematics JonswapSea::kinematics(const Vec3& p, double t) const {
  double eta = 0.0;
  return kinematics(p, t, eta);
}

FluidKinematics JonswapSea::kinematics(const Vec3& p, double t, double& elevation) const {
  const std::size_t n = m_omega.size();
  const double s = phaseOffset(p.x(), p.y());
  const double depth = m_parameters.waterDepth;

  // Pass 1: component phases and total elevation (cos/sin kept for pass 2).
  constexpr std::size_t kStackComponents = 256;
  std::array<double, 2 * kStackComponents> stackBuffer;
  std::vector<double> heapBuffer;
  double* cs = stackBuffer.data();
  if (n > kStackComponents) {
    heapBuffer.resize(2 * n);
    cs = heapBuffer.data();
  }
  double eta = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = m_k[i] * s - m_omega[i] * t + m_phase[i];
    const double c = std::cos(theta);
    cs[2 * i] = c;
    cs[2 * i + 1] = std::sin(theta);
    eta += m_amplitude[i] * c;
  }
  elevation = eta;  // = this->elevation(p.x, p.y, t): the same terms in the same order
  FluidKinematics result;
  if (!wetForKinematics(p.z(), eta, m_parameters.stretching)) return result;  // dry point

  // Pass 2: component kinematics at the stretched level (depthAttenuation in exponential form).
  const double zPrime = stretchedLevel(p.z(), eta, depth, m_parameters.stretching);
  const double heightAboveSeabed = zPrime + depth;  // >= 0
  double uh = 0.0;
  double w = 0.0;
  double duh = 0.0;
  double dw = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // Times 1/(1 - e^{-2kh}) in the scales.
    const auto [horizontal, vertical] = unscaledAttenuation(m_k[i], zPrime, heightAboveSeabed);
    const double c = cs[2 * i];
    const double sn = cs[2 * i + 1];
    uh += m_velocityScale[i] * horizontal * c;
    w += m_velocityScale[i] * vertical * sn;
    duh += m_accelerationScale[i] * horizontal * sn;
    dw -= m_accelerationScale[i] * vertical * c;
  }
  result.velocity = Vec3(uh * m_cosAzimuth, uh * m_sinAzimuth, w);
  result.acceleration = Vec3(duh * m_cosAzimuth, duh * m_sinAzimuth, dw);
  return result;
}

}  // namespace tangle::hydro

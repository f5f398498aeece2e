/// @file ComponentSea.cpp
/// A sea of given linear components (formulas in ComponentSea.hpp).
#include "tangle/hydro/ComponentSea.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/hydro/AiryWave.hpp"

namespace tangle::hydro {

ComponentSea::ComponentSea(std::vector<Component> components, double waterDepth, double gravity,
                           Stretching stretching)
    : m_components(std::move(components)), m_depth(waterDepth), m_stretching(stretching) {
  if (m_components.empty()) throw Error("ComponentSea: no components");
  if (!(std::isfinite(waterDepth) && waterDepth > 0.0))
    throw Error(fmt::format("ComponentSea: waterDepth [m] must be finite and > 0 (got {})", waterDepth));
  for (std::size_t i = 0; i < m_components.size(); ++i) {
    const Component& c = m_components[i];
    if (!(std::isfinite(c.omega) && c.omega > 0.0 && std::isfinite(c.amplitude) && c.amplitude >= 0.0 &&
          std::isfinite(c.phase) && std::isfinite(c.azimuth)))
      throw Error(
          fmt::format("ComponentSea: component {} needs omega > 0, amplitude >= 0 and finite phase and "
                      "azimuth (got omega {}, amplitude {}, phase {}, azimuth {})",
                      i, c.omega, c.amplitude, c.phase, c.azimuth));
    const double k = solveDispersion(c.omega, waterDepth, gravity);
    const double inverseDenominator = -1.0 / std::expm1(-2.0 * k * waterDepth);  // 1 / (1 - e^{-2kh})
    m_k.push_back(k);
    m_cos.push_back(std::cos(c.azimuth));
    m_sin.push_back(std::sin(c.azimuth));
    m_velocityScale.push_back(c.amplitude * c.omega * inverseDenominator);
    m_accelerationScale.push_back(c.amplitude * c.omega * c.omega * inverseDenominator);
  }
}

double ComponentSea::variance() const {
  double sum = 0.0;
  for (const Component& c : m_components) sum += 0.5 * c.amplitude * c.amplitude;
  return sum;
}

double ComponentSea::elevation(double x, double y, double t) const {
  double eta = 0.0;
  for (std::size_t i = 0; i < m_components.size(); ++i) {
    const Component& c = m_components[i];
    eta += c.amplitude * std::cos(m_k[i] * (x * m_cos[i] + y * m_sin[i]) - c.omega * t + c.phase);
  }
  return eta;
}

FluidKinematics ComponentSea::kinematics(const Vec3& p, double t) const {
  double eta = 0.0;
  return kinematics(p, t, eta);
}

FluidKinematics ComponentSea::kinematics(const Vec3& p, double t, double& elevation) const {
  const std::size_t n = m_components.size();
  std::vector<double> cs(2 * n);
  double eta = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Component& c = m_components[i];
    const double theta = m_k[i] * (p.x() * m_cos[i] + p.y() * m_sin[i]) - c.omega * t + c.phase;
    cs[2 * i] = std::cos(theta);
    cs[2 * i + 1] = std::sin(theta);
    eta += c.amplitude * cs[2 * i];
  }
  elevation = eta;  // the same terms in the same order as elevation()
  FluidKinematics result;
  if (!wetForKinematics(p.z(), eta, m_stretching)) return result;
  const double zPrime = stretchedLevel(p.z(), eta, m_depth, m_stretching);
  const double heightAboveSeabed = zPrime + m_depth;
  for (std::size_t i = 0; i < n; ++i) {
    // Times 1/(1 - e^{-2kh}) in the scales.
    const auto [horizontal, vertical] = unscaledAttenuation(m_k[i], zPrime, heightAboveSeabed);
    const double c = cs[2 * i], s = cs[2 * i + 1];
    const double uh = m_velocityScale[i] * horizontal * c;
    const double duh = m_accelerationScale[i] * horizontal * s;
    result.velocity += Vec3(uh * m_cos[i], uh * m_sin[i], m_velocityScale[i] * vertical * s);
    result.acceleration += Vec3(duh * m_cos[i], duh * m_sin[i], -m_accelerationScale[i] * vertical * c);
  }
  return result;
}

}  // namespace tangle::hydro

/// @file AiryWave.cpp
/// Regular linear wave, dispersion relation and depth attenuation (formulas in AiryWave.hpp).

#include "tangle/hydro/AiryWave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "tangle/core/Error.hpp"

namespace tangle::hydro {

namespace {

std::string describe(const char* what, const char* requirement, double value) {
  std::ostringstream os;
  os.precision(17);
  os << what << " must be " << requirement << " (got " << value << ")";
  return os.str();
}

void require(bool ok, const char* where, const char* what, const char* requirement, double value) {
  if (!ok) throw Error(std::string(where) + ": " + describe(what, requirement, value));
}

}  // namespace

double solveDispersion(double omega, double depth, double gravity) {
  constexpr const char* kWhere = "solveDispersion";
  require(std::isfinite(omega) && omega > 0.0, kWhere, "angular frequency [rad/s]", "finite and > 0", omega);
  require(std::isfinite(depth) && depth > 0.0, kWhere, "water depth [m]", "finite and > 0", depth);
  require(std::isfinite(gravity) && gravity > 0.0, kWhere, "gravity [m/s^2]", "finite and > 0", gravity);

  // Dimensionless form: y tanh(y) = x0, y = k h, x0 = omega^2 h / g.
  const double x0 = omega * omega * depth / gravity;
  require(std::isfinite(x0) && x0 > 0.0, kWhere, "omega^2 h / g", "finite and > 0", x0);
  // Fenton & McKee (1990) explicit approximation: y = x0 coth(x0^(3/4))^(2/3).
  double y = x0 / std::pow(std::tanh(std::pow(x0, 0.75)), 2.0 / 3.0);
  if (!(std::isfinite(y) && y > 0.0)) y = std::max(std::sqrt(x0), x0);  // not reached for x0 > 0; safety

  // Newton on f(y) = y tanh(y) - x0 (f is convex and increasing for y > 0: quadratic convergence).
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double e = std::exp(-2.0 * y);
    const double th = std::tanh(y);
    const double sech2 = 4.0 * e / ((1.0 + e) * (1.0 + e));  // 1/cosh^2, overflow-free
    const double f = y * th - x0;
    const double df = th + y * sech2;
    const double dy = f / df;
    y -= dy;
    if (std::abs(dy) <= 2.0 * kEps * y) break;
  }
  if (!(std::isfinite(y) && y > 0.0) || std::abs(y * std::tanh(y) - x0) > 1e-12 * x0) {
    throw ConvergenceError(std::string(kWhere) + ": " +
                           describe("Newton iteration on y tanh y = x0", "convergent", x0));
  }
  return y / depth;
}

namespace {
/// 1 / (1 - e^{-2kh}) [-], the denominator of depthAttenuation: a constant of a wave.
double attenuationScale(double k, double depth) { return -1.0 / std::expm1(-2.0 * k * depth); }

/// depthAttenuation with its denominator given.
DepthAttenuation scaledAttenuation(double k, double zPrime, double depth, double inverseDenominator) {
  const double z = std::clamp(zPrime, -depth, 0.0);
  const double e1 = std::exp(k * z);                     // e^{kz} <= 1
  const double em = std::expm1(-2.0 * k * (z + depth));  // e^{-2k(z+h)} - 1, in (-1, 0]
  return {e1 * (2.0 + em) * inverseDenominator, -e1 * em * inverseDenominator};
}
}  // namespace

DepthAttenuation depthAttenuation(double k, double zPrime, double depth) {
  return scaledAttenuation(k, zPrime, depth, attenuationScale(k, depth));
}

DepthAttenuation unscaledAttenuation(double k, double zPrime, double heightAboveSeabed) {
  constexpr double kNegligibleExponent = 40.0;  // e^{-40} = 4.3e-18 < half an ulp of 1
  const double e1 = std::exp(k * zPrime);
  const double x = 2.0 * k * heightAboveSeabed;
  if (!(x < kNegligibleExponent)) return {e1, e1};
  const double em = std::expm1(-x);
  return {e1 * (2.0 + em), -e1 * em};
}

double stretchedLevel(double z, double eta, double depth, Stretching stretching) {
  const double zc = std::max(z, -depth);
  switch (stretching) {
    case Stretching::Wheeler: {
      const double wetHeight = depth + eta;
      if (wetHeight <= 0.0) return -depth;
      return std::clamp(depth * (zc - eta) / wetHeight, -depth, 0.0);
    }
    case Stretching::Vertical:
    case Stretching::None:
      return std::min(zc, 0.0);
  }
  return std::min(zc, 0.0);
}

AiryWave::AiryWave(double height, double period, double azimuth, double waterDepth, double gravity,
                   double phase, Stretching stretching)
    : m_height(height),
      m_period(period),
      m_azimuth(azimuth),
      m_depth(waterDepth),
      m_gravity(gravity),
      m_phase(phase),
      m_stretching(stretching) {
  constexpr const char* kWhere = "AiryWave";
  require(std::isfinite(height) && height >= 0.0, kWhere, "wave height [m]", "finite and >= 0", height);
  require(std::isfinite(period) && period > 0.0, kWhere, "wave period [s]", "finite and > 0", period);
  require(std::isfinite(azimuth), kWhere, "wave azimuth [rad]", "finite", azimuth);
  require(std::isfinite(waterDepth) && waterDepth > 0.0, kWhere, "water depth [m]", "finite and > 0",
          waterDepth);
  require(std::isfinite(gravity) && gravity > 0.0, kWhere, "gravity [m/s^2]", "finite and > 0", gravity);
  require(std::isfinite(phase), kWhere, "wave phase [rad]", "finite", phase);
  require(0.5 * height < waterDepth, kWhere, "wave amplitude H/2 [m]", "smaller than the water depth",
          0.5 * height);
  m_omega = 2.0 * kPi / period;
  m_k = solveDispersion(m_omega, waterDepth, gravity);
  m_attenuationScale = attenuationScale(m_k, waterDepth);
  m_cosAzimuth = std::cos(azimuth);
  m_sinAzimuth = std::sin(azimuth);
}

double AiryWave::phaseAngle(double x, double y, double t) const {
  return m_k * (x * m_cosAzimuth + y * m_sinAzimuth) - m_omega * t + m_phase;
}

double AiryWave::elevation(double x, double y, double t) const {
  return 0.5 * m_height * std::cos(phaseAngle(x, y, t));
}

FluidKinematics AiryWave::kinematics(const Vec3& p, double t) const {
  double eta = 0.0;
  return kinematics(p, t, eta);
}

FluidKinematics AiryWave::kinematics(const Vec3& p, double t, double& elevation) const {
  const double theta = phaseAngle(p.x(), p.y(), t);
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double amplitude = 0.5 * m_height;
  const double eta = amplitude * c;  // = elevation(p.x, p.y, t), the same operations
  elevation = eta;
  FluidKinematics result;
  if (!wetForKinematics(p.z(), eta, m_stretching)) return result;  // dry point: no fluid

  const double zPrime = stretchedLevel(p.z(), eta, m_depth, m_stretching);
  const DepthAttenuation att = scaledAttenuation(m_k, zPrime, m_depth, m_attenuationScale);
  const double aw = amplitude * m_omega;
  const double aw2 = aw * m_omega;
  const double uh = aw * att.horizontal * c;
  const double duh = aw2 * att.horizontal * s;
  result.velocity = Vec3(uh * m_cosAzimuth, uh * m_sinAzimuth, aw * att.vertical * s);
  result.acceleration = Vec3(duh * m_cosAzimuth, duh * m_sinAzimuth, -aw2 * att.vertical * c);
  return result;
}

}  // namespace tangle::hydro

/// @file SyropeAxialLaw.cpp
#include "tangle/element/SyropeAxialLaw.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tangle/core/Error.hpp"

namespace tangle::element {

namespace {
/// xi(tau) of the working curve (tau = T / Tmax in [0, 1]) and d xi / d tau: the closed-form inverses of
/// MoorDyn's three forms.
struct Xi {
  double value;
  double slope;
};
Xi inverseWorkingCurve(WorkingCurveForm form, double k2, double tau) {
  switch (form) {
    case WorkingCurveForm::Quadratic: {
      // tau = xi (k2 xi + 1 - k2): the root in [0, 1].
      if (std::abs(k2) < 1e-12) return {tau, 1.0};
      const double b = 1.0 - k2;
      if (!(tau > 0.0)) return {0.0, 1.0 / std::max(b, 1e-12)};  // (k2 = 1: a vertical tangent at zero)
      const double xi = 2.0 * tau / (b + std::sqrt(b * b + 4.0 * k2 * tau));  // (stable form of the root)
      return {xi, 1.0 / std::max(2.0 * k2 * xi + b, 1e-12)};
    }
    case WorkingCurveForm::Exponential: {
      // tau = (exp(k2 xi) - 1) / (exp(k2) - 1).
      const double e = std::expm1(k2);
      return {std::log1p(tau * e) / k2, e / (k2 * (1.0 + tau * e))};
    }
    case WorkingCurveForm::Linear:
    default:
      return {tau, 1.0};
  }
}
double workingCurveTension(WorkingCurveForm form, double k2, double xi) {
  switch (form) {
    case WorkingCurveForm::Quadratic:
      return xi * (k2 * xi + 1.0 - k2);
    case WorkingCurveForm::Exponential:
      return std::expm1(k2 * xi) / std::expm1(k2);
    case WorkingCurveForm::Linear:
    default:
      return xi;
  }
}
}  // namespace

SyropeAxialLaw::SyropeAxialLaw(SyropeConstants c) : m_c(std::move(c)) {
  if (!m_c.originalCurve) throw Error("SYROPE law: no original working curve");
  const std::vector<double>& strain = m_c.originalCurve->x();
  const std::vector<double>& tension = m_c.originalCurve->y();
  if (tension.front() != 0.0 || strain.front() < 0.0)
    throw Error("SYROPE law: the original working curve must start at zero tension and a strain >= 0");
  for (std::size_t i = 1; i < tension.size(); ++i)
    if (!(tension[i] > tension[i - 1]))
      throw Error(
          fmt::format("SYROPE law: the original working curve's tension must increase (point {})", i));
  if (!(m_c.dynamicStiffness > 0.0) || !(m_c.dynamicStiffnessSlope >= 0.0) || !(m_c.slowDamping > 0.0) ||
      !(m_c.dynamicDamping >= 0.0))
    throw Error("SYROPE law: alpha and BA must be > 0, beta and BA_d >= 0");
  if (m_c.form == WorkingCurveForm::Linear ? !(m_c.k1 >= 0.0) : !(m_c.k1 >= 0.0 && m_c.k1 < 1.0))
    throw Error(
        fmt::format("SYROPE law: k1 = {} out of range (>= 0; below 1 for the quadratic and exponential "
                    "working curves)",
                    m_c.k1));
  if (m_c.form == WorkingCurveForm::Quadratic && !(std::abs(m_c.k2) <= 1.0))
    throw Error(fmt::format("SYROPE law: a quadratic working curve needs -1 <= k2 <= 1 (got {})", m_c.k2));
  if (m_c.form == WorkingCurveForm::Exponential && !(std::abs(m_c.k2) > 1e-9 && std::abs(m_c.k2) < 50.0))
    throw Error(fmt::format("SYROPE law: an exponential working curve needs k2 != 0 (got {})", m_c.k2));
  m_inverse = std::make_shared<const core::PiecewiseLinear>(tension, strain);
  // MoorDyn's check (Line::setup): the slow strain increases along the OWC.
  for (std::size_t i = 1; i < tension.size(); ++i)
    if (!(strain[i] - dynamicStrain(tension[i]) > strain[i - 1] - dynamicStrain(tension[i - 1])))
      throw Error(
          fmt::format("SYROPE law: the slow strain does not increase along the original working curve "
                      "at point {} (the dynamic stiffness alpha + beta T is below the curve's slope)",
                      i));
}

double SyropeAxialLaw::owcStrain(double tension, double* slope) const {
  const core::PiecewiseLinear::Sample s = m_inverse->at(tension);
  if (slope) *slope = s.slope;
  return s.value;
}

double SyropeAxialLaw::dynamicStrain(double tension) const {
  const double a = m_c.dynamicStiffness, b = m_c.dynamicStiffnessSlope;
  return b > 0.0 ? std::log1p(b * tension / a) / b : tension / a;
}

double SyropeAxialLaw::slackStrain(double maxTension) const {
  const double epsMax = owcStrain(maxTension, nullptr);
  const double eps0 = m_c.originalCurve->x().front();
  if (m_c.form == WorkingCurveForm::Linear && m_c.k1 >= 1.0) return epsMax - maxTension / m_c.k1;
  return eps0 + m_c.k1 * (epsMax - eps0);
}

SyropeAxialLaw::CurveStrain SyropeAxialLaw::curveStrain(double tension, double maxTension) const {
  if (tension > maxTension || !(maxTension > 0.0)) {
    double slope = 0.0;
    const double strain = owcStrain(std::max(tension, 0.0), &slope);
    return {strain, slope};
  }
  const double epsMax = owcStrain(maxTension, nullptr), epsMin = slackStrain(maxTension);
  const Xi xi = inverseWorkingCurve(m_c.form, m_c.k2, std::max(tension, 0.0) / maxTension);
  return {epsMin + xi.value * (epsMax - epsMin), (epsMax - epsMin) * xi.slope / maxTension};
}

double SyropeAxialLaw::staticTension(double strain, double maxTension) const {
  if (strain <= curveStrain(0.0, maxTension).strain) return 0.0;
  // X is increasing: bracket, then Newton kept inside the bracket (bisection where it leaves it).
  double lo = 0.0, hi = std::max(maxTension, 1.0);
  while (curveStrain(hi, maxTension).strain < strain && hi < 1e300) hi *= 2.0;
  double t = 0.5 * (lo + hi);
  for (int k = 0; k < 200; ++k) {
    const CurveStrain c = curveStrain(t, maxTension);
    const double f = c.strain - strain;
    (f < 0.0 ? lo : hi) = t;
    double next = c.slope > 0.0 ? t - f / c.slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-14 * std::max(t, 1.0)) return next;
    t = next;
  }
  return t;
}

std::shared_ptr<const core::PiecewiseLinear> SyropeAxialLaw::staticCurve(double maxTension) const {
  if (!(maxTension > 0.0)) {
    // Never loaded: the OWC itself (from (0, 0)).
    std::vector<double> x = m_c.originalCurve->x(), y = m_c.originalCurve->y();
    if (x.front() > 0.0) {
      x.insert(x.begin(), 0.0);
      y.insert(y.begin(), 0.0);
    }
    return std::make_shared<const core::PiecewiseLinear>(std::move(x), std::move(y));
  }
  const double epsMax = owcStrain(maxTension, nullptr), epsMin = slackStrain(maxTension);
  if (!(epsMin >= 0.0) || !(epsMax > epsMin))
    throw Error(
        fmt::format("SYROPE law: the working curve of Tmax = {} N spans strains {} to {}: it must start "
                    "at a strain >= 0 (check k1 and Tmax)",
                    maxTension, epsMin, epsMax));
  std::vector<double> x{0.0}, y{0.0};
  if (epsMin > 0.0) {
    // Slack below the working curve: a millionth of its mean slope keeps a statics' tangent regular (as a
    // cable's compression factor does).
    x.push_back(epsMin);
    y.push_back(1e-6 * maxTension * epsMin / (epsMax - epsMin));
  }
  constexpr int kSamples = 256;
  for (int i = 1; i <= kSamples; ++i) {
    const double xi = double(i) / kSamples;
    x.push_back(epsMin + xi * (epsMax - epsMin));
    y.push_back(maxTension * workingCurveTension(m_c.form, m_c.k2, xi));
  }
  const std::vector<double>& owcX = m_c.originalCurve->x();
  const std::vector<double>& owcY = m_c.originalCurve->y();
  for (std::size_t i = 0; i < owcX.size(); ++i)
    if (owcX[i] > x.back()) {
      x.push_back(owcX[i]);
      y.push_back(owcY[i]);
    }
  return std::make_shared<const core::PiecewiseLinear>(std::move(x), std::move(y));
}

SyropeAxialLaw::Step SyropeAxialLaw::step(double strain, double strainRate, double x0, double maxTension,
                                          double dt) const {
  const double c = m_c.slowDamping + m_c.dynamicDamping;
  const double alpha = m_c.dynamicStiffness, beta = m_c.dynamicStiffnessSlope;
  // g(T) = c (Z(T) - x0) / dt - (eps - X(T)) (alpha + beta T) - BA_d eps' = 0 (backward Euler in the mean
  // tension T).
  struct Residual {
    double value, slope, slowStrain, slowSlope;
  };
  const auto residual = [&](double t) {
    const CurveStrain x = curveStrain(t, maxTension);
    const double d = alpha + beta * t;
    const double z = x.strain - dynamicStrain(t), zSlope = x.slope - 1.0 / d;
    return Residual{c * (z - x0) / dt - (strain - x.strain) * d - m_c.dynamicDamping * strainRate,
                    c * zSlope / dt + x.slope * d - (strain - x.strain) * beta, z, zSlope};
  };
  const Residual atZero = residual(0.0);
  if (atZero.value >= 0.0) {
    // Slack: no mean tension; x moves by the dynamic branch alone, c x' = (eps - eps_min) alpha + BA_d eps'.
    const double epsMin = curveStrain(0.0, maxTension).strain;
    const double drive = (strain - epsMin) * alpha + m_c.dynamicDamping * strainRate;
    const double x = x0 + dt * drive / c;
    return {x, 0.0, m_c.slowDamping * drive / c, m_c.slowDamping * alpha / c,
            m_c.slowDamping * m_c.dynamicDamping / c};
  }
  double lo = 0.0, hi = std::max(maxTension, 1.0);
  while (residual(hi).value < 0.0 && hi < 1e300) hi *= 2.0;
  double t = std::clamp(staticTension(strain, maxTension), lo, hi);
  Residual r = residual(t);
  for (int k = 0; k < 200; ++k) {
    (r.value < 0.0 ? lo : hi) = t;
    double next = r.slope > 0.0 ? t - r.value / r.slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - t) <= 1e-13 * std::max(t, 1.0);
    t = next;
    r = residual(t);
    if (done) break;
  }
  // N = T + BA x' with x' = ((eps - X(T)) (alpha + beta T) + BA_d eps') / c at the solution (no division of a
  // tiny x - x0 by a tiny dt); dT/d eps = (alpha + beta T) / g', dT/d eps' = BA_d / g'.
  const double d = alpha + beta * t;
  const double rate =
      ((strain - curveStrain(t, maxTension).strain) * d + m_c.dynamicDamping * strainRate) / c;
  const double dNdT = 1.0 + m_c.slowDamping * r.slowSlope / dt;
  return {r.slowStrain, t, t + m_c.slowDamping * rate, dNdT * d / r.slope,
          dNdT * m_c.dynamicDamping / r.slope};
}

}  // namespace tangle::element

#include "tangle/analysis/SnCurve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tangle::analysis {

namespace {
constexpr double kPaPerMPa = 1e6;
}

SnCurve SnCurve::dnvD(double thickness) {
  SnCurve c;
  c.name = "DNV D (air)";
  c.m1 = 3.0;
  c.logA1 = 12.164;
  c.m2 = 5.0;
  c.logA2 = 15.606;
  c.kneeCycles = 1e7;
  c.thicknessExponent = 0.20;
  c.referenceThickness = 0.025;
  c.thickness = thickness;
  return c;
}

double SnCurve::cyclesToFailure(double range) const {
  if (!(range > 0.0)) return std::numeric_limits<double>::infinity();
  // DNV-RP-C203 eq. (2.4.3): log N = log a - m log(S (t / t_ref)^k), S in MPa, t / t_ref >= 1.
  const double correction = std::pow(std::max(1.0, thickness / referenceThickness), thicknessExponent);
  const double logS = std::log10(range / kPaPerMPa * correction);
  const double n1 = logA1 - m1 * logS;
  if (singleSlope || n1 <= std::log10(kneeCycles)) return std::pow(10.0, n1);
  return std::pow(10.0, logA2 - m2 * logS);
}

double SnCurve::kneeRange() const {
  const double correction = std::pow(std::max(1.0, thickness / referenceThickness), thicknessExponent);
  return std::pow(10.0, (logA1 - std::log10(kneeCycles)) / m1) * kPaPerMPa / correction;
}

double TnCurve::cyclesToFailure(double tensionRange) const {
  if (!(tensionRange > 0.0)) return std::numeric_limits<double>::infinity();
  return aD / std::pow(tensionRange / breakingStrength, m);
}

double minerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve) {
  double d = 0.0;
  for (const RainflowCycle& c : cycles) d += c.count / curve.cyclesToFailure(c.range);
  return d;
}

double minerDamage(const std::vector<RainflowCycle>& cycles, const TnCurve& curve) {
  double d = 0.0;
  for (const RainflowCycle& c : cycles) d += c.count / curve.cyclesToFailure(c.range);
  return d;
}

}  // namespace tangle::analysis

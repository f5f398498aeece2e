#include "tangle/contact/ContactLaw.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/core/Units.hpp"

namespace tangle::contact {

namespace {
constexpr double kMaxZeta = 0.999;

double separationPhase(double zeta) {
  const double sq = std::sqrt(1.0 - zeta * zeta);
  return kPi - std::atan2(2.0 * zeta * sq, 1.0 - 2.0 * zeta * zeta);
}
}  // namespace

double restitutionOfDampingRatio(double zeta) {
  zeta = std::clamp(zeta, 0.0, kMaxZeta);
  const double a = zeta / std::sqrt(1.0 - zeta * zeta);
  const double tau = separationPhase(zeta);
  return std::exp(-a * tau) * (a * std::sin(tau) - std::cos(tau));
}

double minimumRestitution() { return restitutionOfDampingRatio(kMaxZeta); }

double dampingRatioForRestitution(double e) {
  if (e >= 1.0) return 0.0;
  if (e <= minimumRestitution()) return kMaxZeta;
  double lo = 0.0, hi = kMaxZeta;  // e decreases with zeta
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (restitutionOfDampingRatio(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double contactDuration(double stiffness, double mass, double zeta) {
  zeta = std::clamp(zeta, 0.0, kMaxZeta);
  const double omegaD = std::sqrt(stiffness / mass) * std::sqrt(1.0 - zeta * zeta);
  return separationPhase(zeta) / omegaD;
}

}  // namespace tangle::contact

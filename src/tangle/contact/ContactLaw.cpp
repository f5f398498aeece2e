#include "tangle/contact/ContactLaw.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/core/Units.hpp"

namespace tangle::contact {

namespace {
/// Largest damping ratio used: e(100) = 2.5e-5, as close to a plastic impact (e = 0) as needed.
constexpr double kMaxZeta = 100.0;
/// Half-width of the band around zeta = 1 treated as critical damping (closed forms below and above
/// lose accuracy as sqrt(|1 - zeta^2|) -> 0; both tend to the critical values).
constexpr double kCriticalBand = 1e-9;

double separationPhase(double zeta) {
  const double sq = std::sqrt(1.0 - zeta * zeta);
  return kPi - std::atan2(2.0 * zeta * sq, 1.0 - 2.0 * zeta * zeta);
}
}  // namespace

double restitutionOfDampingRatio(double zeta) {
  zeta = std::clamp(zeta, 0.0, kMaxZeta);
  if (std::abs(zeta - 1.0) <= kCriticalBand) return std::exp(-2.0);
  if (zeta > 1.0) {
    // Overdamped: roots r1,2 = omega0 (-zeta +- s), s = sqrt(zeta^2 - 1); the force k x + c x' vanishes
    // where r2^2 exp(r2 t) = r1^2 exp(r1 t), and there x'/v0 = -q exp(r1 t) with q = r1 / r2:
    // e = q^(zeta / s).
    const double s = std::sqrt(zeta * zeta - 1.0);
    return std::exp(zeta / s * std::log((zeta - s) / (zeta + s)));
  }
  const double a = zeta / std::sqrt(1.0 - zeta * zeta);
  const double tau = separationPhase(zeta);
  return std::exp(-a * tau) * (a * std::sin(tau) - std::cos(tau));
}

double minimumRestitution() { return restitutionOfDampingRatio(kMaxZeta); }

double dampingRatioForRestitution(double e) {
  if (e >= 1.0) return 0.0;
  if (e <= minimumRestitution()) return kMaxZeta;
  double lo = 0.0, hi = kMaxZeta;  // e decreases with zeta
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, lo); ++i) {
    const double mid = 0.5 * (lo + hi);
    (restitutionOfDampingRatio(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double contactDuration(double stiffness, double mass, double zeta) {
  zeta = std::clamp(zeta, 0.0, kMaxZeta);
  const double omega0 = std::sqrt(stiffness / mass);
  if (std::abs(zeta - 1.0) <= kCriticalBand) return 2.0 / omega0;
  if (zeta > 1.0) {
    const double s = std::sqrt(zeta * zeta - 1.0);
    return std::log((zeta + s) / (zeta - s)) / (omega0 * s);
  }
  return separationPhase(zeta) / (omega0 * std::sqrt(1.0 - zeta * zeta));
}

}  // namespace tangle::contact

#include "tangle/contact/ContinuumImpactMass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tangle/contact/ReducedMass.hpp"

namespace tangle::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.141592653589793;

/// T + S and k1 [1/m] at omega, or T + S <= 0 for a slack cable.
struct Wave {
  double tPlusS = 0.0, s = 0.0, k1 = 0.0;
};
Wave wave(const LineAtPoint& line, double omega) {
  const double t = line.tension, ei = std::max(0.0, line.bendingStiffness), mu = line.massPerLength;
  Wave w;
  w.s = std::sqrt(t * t + 4.0 * ei * mu * omega * omega);
  w.tPlusS = t + w.s;
  // k1^2 = 2 mu w^2 / (T + S): free of the cancellation of (-T + S) / (2 EI) for a cable.
  if (w.tPlusS > 0.0) w.k1 = std::sqrt(2.0 * mu * omega * omega / w.tPlusS);
  return w;
}
}  // namespace

std::complex<double> pointImpedance(const LineAtPoint& line, double omega) {
  if (!(omega > 0.0) || !(line.massPerLength > 0.0)) return {0.0, 0.0};
  const Wave w = wave(line, omega);
  if (!(w.tPlusS > 0.0)) return {0.0, 0.0};  // a slack cable: no restoring force, no waves
  const double ratio =
      2.0 * std::sqrt(std::max(0.0, line.bendingStiffness) * line.massPerLength) * omega / w.tPlusS;
  return 2.0 * w.k1 * w.s / (omega * std::complex<double>(1.0, -ratio));
}

double participatingMass(const LineAtPoint& line, double omega) {
  if (line.held) return kInf;
  return omega > 0.0 ? std::abs(pointImpedance(line, omega)) / omega : 0.0;
}

double groupSpeed(const LineAtPoint& line, double omega) {
  if (!(omega > 0.0) || !(line.massPerLength > 0.0)) return 0.0;
  const Wave w = wave(line, omega);
  if (!(w.tPlusS > 0.0)) return 0.0;
  // EI k^4 + T k^2 = mu w^2  =>  d w / d k = (2 EI k^3 + T k) / (mu w).
  const double k = w.k1, ei = std::max(0.0, line.bendingStiffness);
  return (2.0 * ei * k * k * k + line.tension * k) / (line.massPerLength * omega);
}

double crossingForce(const std::function<double(double)>& perLength, double radii, double sine, double p) {
  if (!(p > 0.0) || !(radii > 0.0) || !(sine > 0.0)) return 0.0;
  constexpr int n = 48;  // even (Simpson)
  const double half = std::sqrt(2.0 * radii * p), h = half / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = i * h;
    const double weight = i == 0 || i == n ? 1.0 : i % 2 == 1 ? 4.0 : 2.0;
    sum += weight * perLength(std::max(0.0, p - w * w / (2.0 * radii)));
  }
  return 2.0 / sine * sum * h / 3.0;
}

double regularisedCrossingWork(double stiffness, double depth, double radii, double sine, double p) {
  if (!(p > 0.0) || !(radii > 0.0) || !(sine > 0.0) || !(depth > 0.0)) return 0.0;
  // With u = p - q: the regularised part integral_{max(0, p - p0)}^{p} (p - u)^2 sqrt(u) du and the linear
  // part integral_0^{p - p0} (p - p0 / 2 - u) sqrt(u) du.
  const double beyond = std::max(0.0, p - depth);
  const auto g = [p](double u) {
    return std::sqrt(u) * u * (2.0 / 3.0 * p * p - 0.8 * p * u + 2.0 / 7.0 * u * u);
  };
  const double regularised = 0.5 / depth * (g(p) - g(beyond));
  const double linear = std::sqrt(beyond) * beyond * (2.0 / 3.0 * (p - 0.5 * depth) - 0.4 * beyond);
  return 2.0 * std::sqrt(2.0 * radii) / sine * stiffness * (regularised + linear);
}

ContinuumImpact continuumImpact(const LineAtPoint& a, const LineAtPoint& b, const PenetrationForce& force,
                                double approachSpeed) {
  ContinuumImpact r;
  if (!(approachSpeed > 0.0) || (a.held && b.held)) return r;
  // The law's force F and work W = integral F dp on a geometric grid of penetrations from 0.1 nm to 1 m
  // (4 % steps; F linear within a step: exact for a linear law, ~1e-4 relative for a curved one): the
  // deepest penetration of an impact is where W reaches the approach's kinetic energy.
  std::vector<double> p, f, work;
  for (double q = 1e-10; q <= 1.0; q *= 1.04) {
    const double fq = std::max(0.0, force(q));
    work.push_back(work.empty() ? 0.5 * fq * q : work.back() + 0.5 * (fq + f.back()) * (q - p.back()));
    p.push_back(q);
    f.push_back(fq);
  }
  const auto deepest = [&](double energy, double& pStar, double& fStar) {
    const auto it = std::lower_bound(work.begin(), work.end(), energy);
    if (it == work.end() || it == work.begin()) return false;
    // Within the cell F is linear (the trapezoidal rule's own assumption): W = W0 + F0 x + g x^2 / 2.
    const std::size_t i = static_cast<std::size_t>(it - work.begin());
    const double width = p[i] - p[i - 1], g = (f[i] - f[i - 1]) / width, rest = energy - work[i - 1];
    const double x = g > 0.0 ? 2.0 * rest / (f[i - 1] + std::sqrt(f[i - 1] * f[i - 1] + 2.0 * g * rest))
                             : (f[i - 1] > 0.0 ? rest / f[i - 1] : 0.0);
    pStar = p[i - 1] + std::min(x, width);
    fStar = f[i - 1] + g * std::min(x, width);
    return pStar > 0.0 && fStar > 0.0;
  };
  // Fixed point w -> sqrt(F(p*) / (m_pair(w) p*)): its slope d ln w' / d ln w is 1/2 for a string on a
  // linear law, 1/4 for a beam, 0 for a rigid body (and smaller on a law that stiffens), so it contracts.
  double omega = 100.0, pStar = 0.0, fStar = 0.0, m = 0.0;
  bool converged = false;
  for (int iteration = 0; iteration < 300 && !converged; ++iteration) {
    m = reducedMass(participatingMass(a, omega), participatingMass(b, omega));
    if (!(m > 0.0) || !std::isfinite(m)) return r;
    if (!deepest(0.5 * m * approachSpeed * approachSpeed, pStar, fStar)) return r;
    const double next = std::sqrt(fStar / (m * pStar));
    converged = std::abs(std::log(next / omega)) < 1e-11;
    omega = next;
  }
  if (!converged) return r;
  r.defined = true;
  r.omega = omega;
  r.duration = kPi / omega;
  r.massA = participatingMass(a, omega);
  r.massB = participatingMass(b, omega);
  r.pairMass = reducedMass(r.massA, r.massB);
  r.lengthA = a.massPerLength > 0.0 ? r.massA / a.massPerLength : 0.0;
  r.lengthB = b.massPerLength > 0.0 ? r.massB / b.massPerLength : 0.0;
  deepest(0.5 * r.pairMass * approachSpeed * approachSpeed, r.penetration, r.peakForce);
  r.energy = 0.5 * r.pairMass * approachSpeed * approachSpeed;
  return r;
}

}  // namespace tangle::contact
